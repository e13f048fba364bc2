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
  # Chromium's helper processes may still be writing into the profile for a moment after it exits (seen once
  # in scripts/bench-web.sh: "Directory not empty"); the shot is taken by then, so that is no failure.
  rm -rf "$tmp" 2>/dev/null || { sleep 1; rm -rf "$tmp"; } || true
}
trap cleanup EXIT
# The site's index.html with its canvas fixed at WIDTH x HEIGHT CSS pixels (the page as it was before it
# followed the window), unless FV_FOLLOW_WINDOW=1: headless Chromium gives a page a viewport shorter than
# --window-size (it keeps 87 px of the window for a toolbar it does not draw; --test-type drops the warning bar
# that took 56 px more) and resizes it to the window for the shot with no frame in between, so a canvas that
# follows the window would be shot stretched. The tests that compare pixels want the WIDTH x HEIGHT page; the
# page-fit test (page_fits.sh) follows the window and reads the app's layout instead of shooting.
if [ "${FV_FOLLOW_WINDOW:-0}" != 1 ] && [ -f "$site/index.html" ]; then
  mkdir "$tmp/site"
  cp -r "$site"/. "$tmp/site"/
  sed -i "s|</head>|<style>canvas { position: absolute !important; width: ${width}px !important; height: ${height}px !important; }</style></head>|" \
    "$tmp/site/index.html"
  site=$tmp/site
fi
source "$(dirname "$0")/serve.sh"
fv_serve "$site" "$tmp/server.log"
rm -f "$out"
action=(--screenshot="$out")
case $out in *.html) action=(--dump-dom) ;; esac
# (Debian's chromium wrapper prints a harmless shell error about memory size on large machines: filtered.)
timeout 120 chromium --headless --no-sandbox --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader \
  --user-data-dir="$tmp/profile" --no-first-run --hide-scrollbars --window-size="$width,$height" \
  --force-device-scale-factor="$dpr" --test-type \
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
