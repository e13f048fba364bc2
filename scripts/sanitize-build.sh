#!/usr/bin/env bash
# The instrumented build that scripts/test-sanitize.sh and scripts/fuzz.sh share, in build-sanitize/: clang,
# AddressSanitizer + UndefinedBehaviorSanitizer on every target (FV_SANITIZE) and libFuzzer's coverage
# instrumentation (FV_FUZZ, which needs clang), so that the test suite and the fuzz targets come from one
# compilation (two instrumented builds of the whole app took ~35 min of a CI run). Arguments: targets to build
# (none: everything). Warnings stay warnings here (the normal build, scripts/build.sh, makes them errors). No
# Python module: an instrumented extension cannot be loaded by the uninstrumented interpreter.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh sanitize
dir=${FV_SANITIZE_DIR:-build-sanitize} # the tree (an absolute path or one under the repository)
# A build-sanitize/ configured by an earlier version of this script with gcc: start again with clang (CMake
# cannot switch the compiler of a configured tree).
if [ -f "$dir/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang' "$dir/CMakeCache.txt"; then
  rm -rf "$dir"
fi
# Line tables only: reports keep file:line, and objects are a third the size of -g ones (faster links).
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ \
  -DFV_SANITIZE=address,undefined -DFV_FUZZ=ON -DFV_PYTHON=OFF >/dev/null
if [ $# -eq 0 ]; then
  cmake --build "$dir" -j"$(nproc)"
else
  cmake --build "$dir" -j"$(nproc)" --target "$@"
fi
