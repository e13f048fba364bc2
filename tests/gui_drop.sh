#!/usr/bin/env bash
# Drag-and-drop end to end: the real window under Xvfb receives a file dropped by an XDND source
# (tests/tools/xdnd_drop), and its last frame must equal the headless render of the same session with the
# file loaded by the script instead. The animation is paused, so the frame the drop lands on does not matter.
set -euo pipefail
exe=$1 compare=$2 drop=$3 data=$4 out=$5
mkdir -p "$out"
rm -f "$out/drop-window.png" "$out/drop-headless.png"
printf '0 pause\n' >"$out/drop-window-script.txt"
printf '0 pause\n1 load %s\n' "$data" >"$out/drop-headless-script.txt"
# 300 scripted frames (no frame pacing) last two seconds or more; the drop lands within ~0.2 s of the
# window appearing.
xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
  "$0" gui --frames 300 --script "$1/drop-window-script.txt" --screenshot "$1/drop-window.png" &
  app=$!
  if ! "$2" frictionviz "$3" 20; then kill "$app" 2>/dev/null; exit 1; fi
  wait "$app"' "$exe" "$out" "$drop" "$data"
"$exe" gui --headless --frames 300 --script "$out/drop-headless-script.txt" --screenshot "$out/drop-headless.png"
"$compare" "$out/drop-window.png" "$out/drop-headless.png" 0 0 "$out/drop-window-vs-headless.diff.png"
