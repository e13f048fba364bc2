#!/usr/bin/env bash
# The app's frame times (a benchmark, not a test): 300 frames with a slider dragged every frame and every layer
# visible (bench/gui_all_layers.txt), headless on llvmpipe, at 1280x800 and at 1920x1080 --scale 1.5
# (target: p95 <= 16 ms). Wall times measure the machine too: run it on an idle machine. The second
# run of each size draws on the app's thread (LP_NUM_THREADS=0): its CPU time per frame is the cost of a frame
# that the machine's load hardly changes (compare builds with it on a shared machine).
#   scripts/bench-gui.sh [SCRIPT]   another script on top of the drag (bench/gui_compare.txt: compare mode on)
set -euo pipefail
cd "$(dirname "$0")/.."
FV=build/app/frictionviz
[ -x "$FV" ] || bash scripts/build.sh app >/dev/null
SCRIPT=${1:-bench/gui_all_layers.txt}
uptime
for args in "--size 1280x800" "--size 1920x1080 --scale 1.5"; do
  # shellcheck disable=SC2086
  "$FV" gui --headless --bench 300 $args --script "$SCRIPT" | head -n 2
  # shellcheck disable=SC2086
  LP_NUM_THREADS=0 "$FV" gui --headless --bench 300 $args --script "$SCRIPT" | tail -n 1
done
