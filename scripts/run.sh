#!/usr/bin/env bash
# The main job: builds, then renders every figure of the paper (PNG + CSV) into screenshots/, headless.
# (The interactive window, where there is a display, arrives with the app; see README.)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
FV=build/app/frictionviz
mkdir -p screenshots
$FV render --figure all --out screenshots
$FV render --figure scene --zeta 0.3 --theta 30 --rdisp 2 --i 1 --out screenshots
echo "Figures are in screenshots/ (PNG with the data behind each one as CSV)."
