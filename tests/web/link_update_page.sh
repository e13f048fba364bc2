#!/usr/bin/env bash
# The page keeps its address a share link: opened with LINK, a click on the θ = 60° preset must
# leave the address with theta=60 and the link's other values, and that address, opened as a new page, shows
# what `gui --headless --link` shows for it (a copied address reopens the same setup).
#   link_update_page.sh SITE_DIR FRICTIONVIZ FV_PNG_COMPARE OUTDIR LINK
set -euo pipefail
site=$1 exe=$2 compare=$3 out=$4 link=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$site/frictionviz.js" "$site/frictionviz.wasm" "$site/index.html" "$here/page_input.js" "$tmp/"
cp "$here/link_update.html" "$tmp/link.html"
bash "$here/screenshot.sh" "$tmp" "link.html$link" "$out/link-update.png" 1280 800 6000 1 |
  tee "$out/link-update-console.txt"
after=$(grep -ao "fv-link: after ?[^\"' ]*" "$out/link-update-console.txt" | tail -1 | sed 's/^fv-link: after //')
echo "address after the click: ${after:-none}"
for kv in theta=60 zeta=0.45 rdisp=8 i=0 model=dahl; do
  case "&${after#\?}&" in
    *"&$kv&"*) ;;
    *) echo "the address after the click lacks $kv: '$after'" >&2; exit 1 ;;
  esac
done
# The address reopened: the page against the desktop app from the same link (app_page_vs_headless.sh's
# tolerance).
bash "$here/screenshot.sh" "$tmp" "index.html$after" "$out/link-reopened-web.png" 1280 800 10000 1
"$exe" gui --headless --frames 600 --link "$after" --screenshot "$out/link-reopened-headless.png" >/dev/null
"$compare" "$out/link-reopened-web.png" "$out/link-reopened-headless.png" 32 0.03 \
  "$out/link-reopened-web-vs-headless.diff.png"
