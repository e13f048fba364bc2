#!/usr/bin/env bash
# The test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize-build.sh: clang,
# build-sanitize/, shared with scripts/fuzz.sh) and run there through CTest. Any sanitizer report aborts the
# process that made it, so it fails the test. Extra arguments go to ctest (e.g. -R Measurement).
# Left out: the tests labelled `long` (Catch tag [long]: solver sweeps over many points, 3-30 s each in the
# normal build and minutes each instrumented; the same code paths run here in the shorter tests, e.g. the
# 300-point property test) - the normal build (scripts/test.sh) runs them. Leak reports from inside
# Mesa/X11/GLFW are suppressed by tests/sanitize/lsan.supp (third-party libraries only).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
# intercept_tls_get_addr=0: the sanitizer runtime's __tls_get_addr interceptor (GCC's up to 13, clang 14's)
# can take a malloc'd dynamic TLS block for a pre-2.25 glibc header and read garbage as its bounds;
# LeakSanitizer's tracer then dies at exit ("Tracer caught signal 11", exit 1, no leak reported). Measured
# here: 3 of 24 `gui --headless` runs under load without it, 0 of 48 with it. (Mudlet hit the same:
# github.com/Mudlet/Mudlet/pull/9930.)
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
bash scripts/sanitize-build.sh
cd "${FV_SANITIZE_DIR:-build-sanitize}"
ctest --output-on-failure -j"$(nproc)" -LE long "$@"
