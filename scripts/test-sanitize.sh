#!/usr/bin/env bash
# Builds the whole project and its tests with AddressSanitizer + UndefinedBehaviorSanitizer (gcc, the default
# compiler) into build-sanitize/ and runs the test suite there through CTest. Any sanitizer report aborts the
# process that made it, so it fails the test. Extra arguments go to ctest (e.g. -R Measurement).
# Leak reports from inside Mesa/X11/GLFW are suppressed by tests/sanitize/lsan.supp (third-party libraries only).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
root=$(pwd)
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# Warnings are errors in the normal build (scripts/build.sh); here gcc's sanitizer instrumentation gives false
# -Wmaybe-uninitialized and similar, so they stay warnings.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFV_SANITIZE=address,undefined >/dev/null
cmake --build build-sanitize -j"$(nproc)"
cd build-sanitize
ctest --output-on-failure -j"$(nproc)" "$@"
