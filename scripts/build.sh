#!/usr/bin/env bash
# Configures and builds into build/ (Release, warnings as errors).
#   scripts/build.sh [CMAKE_ARGS..]       everything: the app, the tests and the benchmarks (test packages)
#   scripts/build.sh app [CMAKE_ARGS..]   the frictionviz executable only (the main job, scripts/run.sh)
# Both share build/, so that the app built by run.sh is not compiled again by test.sh: the test targets only add
# to the tree (BUILD_TESTING changes no compile flag of the app's objects). `app` installs only the app's
# packages, and a tree it configures first leaves the tests out (BUILD_TESTING=OFF), since their configuration
# needs Catch2 and X11; a tree that already has them keeps them.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = app ]; then
  shift
  bash scripts/setup.sh app
  testing=()
  [ -f build/CMakeCache.txt ] || testing=(-DBUILD_TESTING=OFF)
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFV_WERROR=ON "${testing[@]}" "$@" >/dev/null
  cmake --build build -j"$(nproc)" --target frictionviz
  exit 0
fi
bash scripts/setup.sh test
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFV_WERROR=ON -DBUILD_TESTING=ON "$@" >/dev/null
cmake --build build -j"$(nproc)"
