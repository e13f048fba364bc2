#!/usr/bin/env bash
# Times the browser build in headless Chromium (software WebGL 2, as the web tests): the first frame after
# navigation start, and slider edits made with mouse events on the canvas, from the event to the end of the
# frame that shows the new state. Prints the numbers; not a pass/fail test (targets: first frame
# <= 3 s, slider to frame <= 33 ms). Real time, not virtual: run it on a quiet machine (uptime is printed).
#   scripts/bench-web.sh [SITE_DIR]      (default build-web/site; scripts/build-web.sh makes it)
# FV_BENCH_QUERY: a share link to open the page with, e.g. '?b.theta=0' (compare mode: B at theta = 0 beside A;
# the page then drags zeta on compare mode's row). It also prints the page's own work per edit and per frame
# by phase (FrameWork, app/gui/platform.hpp), which depends less on the machine's load than the wall times.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh browser
site=${1:-build-web/site}
[ -f "$site/frictionviz.wasm" ] || { echo "bench-web: no site in $site (run scripts/build-web.sh)" >&2; exit 2; }
source tests/web/serve.sh
fv_realtime_site "$site" bench/web/bench.html tests/web/page_input.js
echo "load: $(uptime)"
fv_open_realtime "bench.html${FV_BENCH_QUERY:-}"
# CPU time (ms, user + system) of the browser's processes of a kind (--type=gpu-process, renderer): the GPU
# process draws the page's WebGL with SwiftShader, on the CPU. Per frame drawn, it depends far less on the
# machine's load than wall times do.
descendants() { local c; for c in $(pgrep -P "$1"); do echo "$c"; descendants "$c"; done; }
cpu_ms() {
  local total=0 pid
  for pid in $(descendants "$browser"); do
    tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -q -- "--type=$1" || continue
    total=$(( total + $(awk '{ sub(/^.*\) /, ""); print $12 + $13 }' "/proc/$pid/stat" 2>/dev/null || echo 0) ))
  done
  echo $(( total * 1000 / $(getconf CLK_TCK) ))
}
gpu0="" renderer0=""
for _ in $(seq 1 1200); do
  if [ -z "$gpu0" ] && grep -aq 'fv-bench: drag starts' "$tmp/chromium.log"; then
    gpu0=$(cpu_ms gpu-process) renderer0=$(cpu_ms renderer)
  fi
  grep -aq 'fv-bench: done' "$tmp/chromium.log" && break
  if ! kill -0 "$browser" 2>/dev/null; then break; fi
  sleep 0.1
done
gpu1=$(cpu_ms gpu-process) renderer1=$(cpu_ms renderer)
grep -a 'fv-bench: ' "$tmp/chromium.log" | grep -v 'drag starts' | sed 's/^.*fv-bench: /  /; s/", source:.*$//'
frames=$(grep -ao 'frame interval dragging ([0-9]*)' "$tmp/chromium.log" | grep -o '[0-9]*' | tail -n 1)
if [ -n "$gpu0" ] && [ -n "$frames" ] && [ "$frames" -gt 0 ]; then
  awk -v g=$((gpu1 - gpu0)) -v r=$((renderer1 - renderer0)) -v n="$frames" 'BEGIN {
    printf "  CPU per frame while dragging (%d frames): GPU process %.1f ms, renderer %.1f ms (SwiftShader draws in the GPU process)\n", n, g / n, r / n }'
fi
grep -aq 'fv-bench: done' "$tmp/chromium.log" || { echo "bench-web: the page did not finish in 120 s" >&2; exit 1; }
if grep -aq 'fv-bench: the link did not read' "$tmp/chromium.log"; then
  echo "bench-web: FV_BENCH_QUERY is not a share link the app reads (nothing measured)" >&2
  exit 2
fi
