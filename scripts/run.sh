#!/usr/bin/env bash
# The main job: builds, then opens the interactive window where there is a display; where there is none,
# renders every figure of the paper (PNG + CSV) into screenshots/, headless.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
FV=build/app/frictionviz
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec $FV gui
fi
mkdir -p screenshots
$FV render --figure all --out screenshots
$FV render --figure scene --zeta 0.3 --theta 30 --rdisp 2 --i 1 --out screenshots
$FV render --figure map --rdisp 2 --i 1 --out screenshots
$FV render --figure fig19 --data tests/data/synthetic_two_angles_rdisp2_i0.csv --amplitude 0.7 --out screenshots
$FV gui --headless --frames 150 --script tests/gui_script.txt --screenshot screenshots/app.png
echo "No display: figures rendered into screenshots/ (PNG with the data behind each one as CSV)."
