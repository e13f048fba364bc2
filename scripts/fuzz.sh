#!/usr/bin/env bash
# Fuzzes the measurements CSV reader, the command-line parser, the output-path policy, the session reader and
# the script parser and the share link with libFuzzer (clang, ASan + UBSan): builds the fuzz targets (scripts/sanitize-build.sh,
# in build-sanitize/, the build the sanitizer test suite uses) and runs each for SECONDS (default 60), starting
# from the seed corpus tests/fuzz/corpus/TARGET/. New inputs go to build-fuzz/corpus/TARGET/ (the seeds are not
# touched); a crash is saved as build-fuzz/artifacts/TARGET/crash-* and makes the script fail.
# Reproduce one: build-sanitize/tests/fuzz/TARGET build-fuzz/artifacts/TARGET/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
# The fuzz targets of the instrumented build the sanitizer test suite uses (built only where missing).
bash scripts/sanitize-build.sh fuzz_measurements fuzz_cli fuzz_output_path fuzz_session fuzz_script fuzz_share_link
# intercept_tls_get_addr=0: see scripts/test-sanitize.sh (LeakSanitizer tracer crash at exit with GCC <= 13).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
for target in fuzz_measurements fuzz_cli fuzz_output_path fuzz_session fuzz_script fuzz_share_link; do
  corpus=build-fuzz/corpus/$target
  artifacts=build-fuzz/artifacts/$target
  mkdir -p "$corpus" "$artifacts"
  log=build-fuzz/$target.log
  echo "fuzz: $target for ${seconds} s (log: $log)"
  # -close_fd_mask=3: the target's own stdout/stderr (help texts, one-line usage errors) are silenced;
  # libFuzzer's report and any sanitizer report still go to the log.
  if "${FV_SANITIZE_DIR:-build-sanitize}"/tests/fuzz/$target "$corpus" tests/fuzz/corpus/$target -max_total_time="$seconds" \
      -max_len=4096 -timeout=10 -rss_limit_mb=2048 -close_fd_mask=3 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -n 1)
    echo "fuzz: $target OK: $runs runs, $cov, corpus $(ls "$corpus" | wc -l) files, no crash"
  else
    status=1
    echo "fuzz: $target FAILED; crash inputs:"
    ls "$artifacts"
    grep -E 'ERROR|SUMMARY|runtime error|broken guarantee|exit code|deadly signal' "$log" | head -n 20
  fi
done
exit $status
