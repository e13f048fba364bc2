#!/usr/bin/env bash
# Screenshot of a page of the browser build in headless Chromium with software WebGL 2 (ANGLE on SwiftShader),
# the page served from 127.0.0.1 by python3's http.server on a free port; both stop before this script ends.
# With OUT ending in .html, the page's DOM as it stands at the end (--dump-dom) instead of a screenshot.
#   screenshot.sh SITE_DIR PATH_AND_QUERY OUT.png|OUT.html WIDTH HEIGHT [VIRTUAL_MS [DEVICE_SCALE]]
# Under --virtual-time-budget (VIRTUAL_MS, default 10000) Chromium runs the page's timers and animation frames
# on a virtual clock, so the shot is taken after the page has drawn, without waiting in real time.
# DEVICE_SCALE (default 1): the page's devicePixelRatio, a HiDPI screen; the shot is WIDTH x HEIGHT times it.
set -euo pipefail
site=$1 query=$2 out=$3 width=$4 height=$5 budget=${6:-10000} dpr=${7:-1}
tmp=$(mktemp -d)
server=""
cleanup() {
  if [ -n "$server" ]; then kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true; fi
  rm -rf "$tmp"
}
trap cleanup EXIT
source "$(dirname "$0")/serve.sh"
fv_serve "$site" "$tmp/server.log"
rm -f "$out"
action=(--screenshot="$out")
case $out in *.html) action=(--dump-dom) ;; esac
# (Debian's chromium wrapper prints a harmless shell error about memory size on large machines: filtered.)
timeout 120 chromium --headless --no-sandbox --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader \
  --user-data-dir="$tmp/profile" --no-first-run --hide-scrollbars --window-size="$width,$height" \
  --force-device-scale-factor="$dpr" \
  --virtual-time-budget="$budget" --enable-logging=stderr "${action[@]}" "http://127.0.0.1:$port/$query" \
  >"$tmp/stdout" 2>"$tmp/chromium.log" || { cat "$tmp/chromium.log" >&2; exit 1; }
case $out in *.html) cp "$tmp/stdout" "$out" ;; esac
# The page's console (its printf and errors) for the test log.
grep -a 'CONSOLE' "$tmp/chromium.log" | sed 's/^.*CONSOLE[^"]*/console: /' || true
if [ ! -s "$out" ]; then
  echo "screenshot.sh: nothing written to $out" >&2
  cat "$tmp/chromium.log" >&2
  exit 1
fi
