#!/usr/bin/env bash
# The app's page (the browser build's site) opened with a share link in its address, in headless Chromium on
# a HiDPI screen (devicePixelRatio 2: the page draws at 2560 x 1600), against the desktop app's headless
# screenshot started from the same link at the same scale (`gui --link --scale 2`): the page runs 10 s
# of virtual time (600 frames of 1/60 s), the desktop 600 frames. The panel, the readouts and the r_x(zeta)
# plot agree; the moving parts (top view, force plot) are a few frames apart, since the page's frame count
# over the budget is not exact. A pixel counts as different past 32 levels in a channel, and at most 3% of
# them may (measured 1.5% at the defaults; a missing panel row alone is 4%). First the size budget of the page:
# frictionviz.wasm at most 3 MB.
#   app_page_vs_headless.sh SITE_DIR FRICTIONVIZ FV_PNG_COMPARE OUTDIR LINK
set -euo pipefail
site=$1 exe=$2 compare=$3 out=$4 link=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
size=$(stat -c %s "$site/frictionviz.wasm")
echo "frictionviz.wasm: $size bytes (budget 3000000)"
if [ "$size" -gt 3000000 ]; then
  echo "frictionviz.wasm is over its 3 MB budget" >&2
  exit 1
fi
bash "$here/screenshot.sh" "$site" "$link" "$out/app-web.png" 1280 800 10000 2
"$exe" gui --headless --frames 600 --scale 2 --link "$link" --screenshot "$out/app-headless.png" >/dev/null
"$compare" "$out/app-web.png" "$out/app-headless.png" 32 0.03 "$out/app-web-vs-headless.diff.png"
