#!/usr/bin/env bash
# The app's page fits every window: opened in headless Chromium at a laptop's 1280 x 800, a Chromebook's 1024 x 640, a
# desktop's 1920 x 1080 at devicePixelRatio 1 and 2, and phones' 390 x 844 at 3 and 360 x 640 at 2, the layout the page
# publishes must pass tests/web/page_fits.py (canvas = window, backing store = CSS size x ratio, every panel
# inside the page and large enough, the panel on top on the phone). Headless Chromium's viewport is shorter
# than its --window-size (tests/web/screenshot.sh): a first page measures by how much, and each size is then
# opened with a window that much larger, so the page is the size asked for (the phone's width: below). Each page's canvas after 90
# frames is saved as OUTDIR/page-fits-WxH@DPR.png (from the page itself, page_fits_shot.js) to look at.
#   page_fits.sh SITE_DIR OUTDIR
set -euo pipefail
site=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$site/frictionviz.js" "$site/frictionviz.wasm" "$tmp/"
sed 's|<script src="frictionviz.js"></script>|<script src="page_fits_shot.js"></script>\n&|' "$site/index.html" >"$tmp/index.html"
cp "$here/page_fits_shot.js" "$tmp/"
printf '%s\n' '<!doctype html><body><script>document.body.setAttribute("data-viewport",' \
  'innerWidth + "x" + innerHeight);</script></body>' >"$tmp/viewport.html"
export FV_FOLLOW_WINDOW=1
bash "$here/screenshot.sh" "$tmp" viewport.html "$out/viewport.html" 1024 640 500 >/dev/null
vp=$(grep -o 'data-viewport="[0-9]*x[0-9]*"' "$out/viewport.html" | grep -o '[0-9]*x[0-9]*')
dw=$((1024 - ${vp%x*})) dh=$((640 - ${vp#*x}))
echo "headless Chromium's viewport at a 1024x640 window: $vp; windows are opened ${dw}x${dh} larger"
# The last two: compare mode (a link with B), two top views beside each other, on the Chromebook and the phone.
for size in 1280x800@1 1024x640@1 1920x1080@1 1920x1080@2 390x844@3 360x640@2 compare:1024x640@1 compare:390x844@3; do
  link="?zeta=0.45&theta=30&rdisp=8&i=0&model=dahl"
  case $size in compare:*) size=${size#compare:} link="$link&b.theta=90" ;; esac
  w=${size%%x*} rest=${size#*x}
  h=${rest%@*} dpr=${size#*@}
  page=index.html ww=$((w + dw))
  # Chromium's windows are at least 500 CSS pixels wide: a narrower page (the phone) is a window of 500 with
  # the canvas's CSS width pinned to the page's (the app follows the canvas's box, whatever sets it).
  if [ "$w" -lt 500 ]; then
    sed "s|</head>|<style>canvas { width: ${w}px !important; }</style></head>|" "$tmp/index.html" >"$tmp/narrow.html"
    page=narrow.html ww=500
  fi
  name=$size
  case $link in *b.theta*) name=compare-$size ;; esac
  bash "$here/screenshot.sh" "$tmp" "$page$link" "$out/page-fits-$name.html" "$ww" $((h + dh)) 3000 "$dpr" >/dev/null
  python3 "$here/page_fits.py" "$out/page-fits-$name.html" "$w" "$h" "$dpr" "$out/page-fits-$name.png"
done
