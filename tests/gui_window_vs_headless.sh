#!/usr/bin/env bash
# Runs the real window under Xvfb with a scripted set of slider changes, takes a screenshot of the last frame,
# renders the same script headless (OSMesa) and requires the two pictures to be identical.
set -euo pipefail
exe=$1 compare=$2 script=$3 out=$4
mkdir -p "$out"
rm -f "$out/window.png" "$out/headless.png"
xvfb-run -a -s "-screen 0 1280x800x24" "$exe" gui --frames 150 --script "$script" --screenshot "$out/window.png"
"$exe" gui --headless --frames 150 --script "$script" --screenshot "$out/headless.png"
"$compare" "$out/window.png" "$out/headless.png" 0 0 "$out/window-vs-headless.diff.png"
