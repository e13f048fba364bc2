#!/usr/bin/env bash
# Configures and builds into build/ (Release, warnings as errors). Extra arguments go to cmake.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFV_WERROR=ON "$@" >/dev/null
cmake --build build -j"$(nproc)"
