#!/usr/bin/env bash
# The app's page fits every window (issue #23): opened in headless Chromium at a Chromebook's 1024 x 640, a
# desktop's 1920 x 1080 at devicePixelRatio 1 and 2, and a phone's 390 x 844 at 3, the layout the page
# publishes must pass tests/web/page_fits.py (canvas = window, backing store = CSS size x ratio, every panel
# inside the page and large enough, the panel on top on the phone). FV_WEB_SHOTS=1 also saves a screenshot of
# each size into OUTDIR (page-fits-WxH@DPR.png) to look at.
#   page_fits.sh SITE_DIR OUTDIR
set -euo pipefail
site=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
link="?zeta=0.45&theta=30&rdisp=8&i=0&model=dahl"
for size in 1024x640@1 1920x1080@1 1920x1080@2 390x844@3; do
  w=${size%%x*} rest=${size#*x}
  h=${rest%@*} dpr=${size#*@}
  bash "$here/screenshot.sh" "$site" "index.html$link" "$out/page-fits-$size.html" "$w" "$h" 3000 "$dpr" >/dev/null
  python3 "$here/page_fits.py" "$out/page-fits-$size.html" "$w" "$h" "$dpr"
  if [ "${FV_WEB_SHOTS:-0}" = 1 ]; then
    bash "$here/screenshot.sh" "$site" "index.html$link" "$out/page-fits-$size.png" "$w" "$h" 6000 "$dpr" >/dev/null
  fi
done
