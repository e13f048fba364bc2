#!/usr/bin/env bash
# Builds everything (scripts/build.sh: the test group of packages, every target) and runs the whole test suite
# through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
