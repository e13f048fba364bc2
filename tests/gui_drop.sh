#!/usr/bin/env bash
# Drag-and-drop end to end (a CSV as data, a .json as a session): the real window under Xvfb receives a file dropped by an XDND source
# (tests/tools/xdnd_drop), and its last frame must equal the headless render of the same session with the
# file loaded by the script instead. The animation is paused, so the frame the drop lands on does not matter.
set -euo pipefail
exe=$1 compare=$2 drop=$3 data=$4 out=$5
mkdir -p "$out"
rm -f "$out/drop-window.png" "$out/drop-headless.png"
printf '0 pause\n' >"$out/drop-window-script.txt"
printf '0 pause\n1 load %s\n' "$data" >"$out/drop-headless-script.txt"
# drop_into_window FILE SHOT: the window under Xvfb, paused, FILE dropped onto it, its last frame saved as SHOT.
# 300 scripted frames (no frame pacing) last two seconds or more; the drop lands within ~0.2 s of the
# window appearing.
drop_into_window() {
  xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
    "$0" gui --frames 300 --script "$1" --screenshot "$2" &
    app=$!
    if ! "$3" frictionviz "$4" 20; then kill "$app" 2>/dev/null; exit 1; fi
    wait "$app"' "$exe" "$out/drop-window-script.txt" "$2" "$drop" "$1"
}
drop_into_window "$data" "$out/drop-window.png"
"$exe" gui --headless --frames 300 --script "$out/drop-headless-script.txt" --screenshot "$out/drop-headless.png"
"$compare" "$out/drop-window.png" "$out/drop-headless.png" 0 0 "$out/drop-window-vs-headless.diff.png"

# A dropped .json opens as a session (not as data): the window's last frame against the headless render of the
# same session opened by the script. The session is paused, so the frame the drop lands on does not matter.
session="$out/dropped-session.json"
printf '{"version": 1, "zeta": 0.41, "theta": 35, "rdisp": 6, "i": 0.5, "playing": false}\n' >"$session"
rm -f "$out/drop-session-window.png" "$out/drop-session-headless.png"
printf '1 open-session %s\n' "$session" >"$out/drop-session-headless-script.txt"
drop_into_window "$session" "$out/drop-session-window.png"
"$exe" gui --headless --frames 300 --script "$out/drop-session-headless-script.txt" \
  --screenshot "$out/drop-session-headless.png"
"$compare" "$out/drop-session-window.png" "$out/drop-session-headless.png" 0 0 \
  "$out/drop-session-window-vs-headless.diff.png"
# and it is not the default screen: the session's parameters were applied.
if "$compare" "$out/drop-session-window.png" "$out/drop-window.png" 0 0 /dev/null >/dev/null 2>&1; then
  echo "gui_drop: the dropped session changed nothing" >&2
  exit 1
fi
