#!/usr/bin/env bash
# The main job: builds, then opens the interactive window where there is a display; where there is none,
# renders every registered figure (PNG + CSV + caption JSON; `frictionviz render --list`) into screenshots/,
# headless, fig19 with the synthetic example data. Installs and builds only what that needs (scripts/build.sh app:
# the app's packages, the frictionviz target); scripts/test.sh adds the rest to the same build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh app
FV=build/app/frictionviz
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec $FV gui
fi
mkdir -p screenshots
$FV render --figure all --data tests/data/synthetic_two_angles_rdisp2_i0.csv --amplitude 0.7 --out screenshots
$FV gui --headless --frames 150 --script tests/gui_script.txt --screenshot screenshots/app.png
echo "No display: figures rendered into screenshots/ (PNG with the data behind each one as CSV, caption as JSON)."
