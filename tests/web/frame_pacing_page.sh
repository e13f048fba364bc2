#!/usr/bin/env bash
# The page's frame pacing (tests/web/frame_pacing.html), in real time in headless Chromium: with nobody at
# the page and the curves done, at most 32 frames a second (30 and the animation frames' jitter) but still
# drawing (at least 5 a second: the animation runs); mouse moves over the canvas seen by the page's pacing
# (at least half of the frames while the mouse moves every 8 ms drawn for input, at the first animation frame
# after it); while the curves are computed, frames drawn for that work. The upper bound on the idle rate
# cannot fail for a slow machine (a loaded machine draws fewer frames, not more).
#   frame_pacing_page.sh SITE_DIR OUTDIR
set -euo pipefail
site=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
source "$here/serve.sh"
fv_realtime_site "$site" "$here/frame_pacing.html" "$here/page_input.js"
fv_open_realtime frame_pacing.html
for _ in $(seq 1 900); do
  grep -aq 'fv-pace: done' "$tmp/chromium.log" && break
  kill -0 "$browser" 2>/dev/null || break
  sleep 0.1
done
grep -a 'fv-pace: ' "$tmp/chromium.log" | sed 's/^.*fv-pace: //; s/", source:.*$//' | tee "$out/frame-pacing.txt"
grep -q '^done' "$out/frame-pacing.txt" || { echo "the page did not finish in 90 s" >&2; exit 1; }
# name: N frames in S s, R per second; causes {...}
field() { sed -n "s/^$1: .*, \\([0-9.]*\\) per second; causes \\({[^}]*}\\)$/\\$2/p" "$out/frame-pacing.txt"; }
count() { field "$1" 2 | grep -o "\"$2\":[0-9]*" | cut -d: -f2 || true; }
fail=0
idle_rate=$(field idle 1) input_rate=$(field input 1)
total_input=$(sed -n 's/^input: \([0-9]*\) frames.*/\1/p' "$out/frame-pacing.txt")
awk -v r="$idle_rate" 'BEGIN { exit !(r <= 32 && r >= 5) }' ||
  { echo "idle: $idle_rate frames a second, allowed 5 to 32 (30 a second when only the animation moves)" >&2; fail=1; }
[ -z "$(count idle input)" ] || { echo "idle: frames drawn for input, with nobody at the page" >&2; fail=1; }
[ -n "$(count settle work)" ] || { echo "settle: no frame drawn for the curves' work" >&2; fail=1; }
input_frames=$(count input input)
awk -v n="${input_frames:-0}" -v t="${total_input:-0}" 'BEGIN { exit !(t > 0 && n >= t / 2) }' ||
  { echo "input: ${input_frames:-0} of ${total_input:-0} frames drawn for input while the mouse moved every 8 ms" >&2; fail=1; }
echo "idle $idle_rate frames/s, with mouse moves $input_rate frames/s"
exit $fail
