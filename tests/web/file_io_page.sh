#!/usr/bin/env bash
# The browser's file input and downloads (tests/web/file_io.html drives the File menu with mouse events):
# Export trace CSV reaches the browser as a text/csv Blob with the trace's header; Open data file… takes a
# CSV through the page's file input into the same reader as the desktop app's: the page's screenshot against
# `gui --headless --frames 600 --data FILE` of the same file under the same name, with the tolerance of
# app_page_vs_headless.sh. On a HiDPI screen (devicePixelRatio 2,
# against --scale 2): the clicks, in CSS pixels, must land on the menu drawn at twice the pixels.
#   file_io_page.sh SITE_DIR FRICTIONVIZ FV_PNG_COMPARE OUTDIR DATA_CSV
set -euo pipefail
site=$1 exe=$2 compare=$3 out=$4 data=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$site/frictionviz.js" "$site/frictionviz.wasm" "$tmp/"
cp "$here/file_io.html" "$tmp/index.html"
cp "$here/page_input.js" "$tmp/"
cp "$data" "$tmp/data.csv"
bash "$here/screenshot.sh" "$tmp" "" "$out/file-io-web.png" 1280 800 10000 2 | tee "$out/file-io-console.txt"
fail=0
grep -q 'fv-io: download text/csv [1-9][0-9]* bytes, first line tau,Px,Py,Tx,Ty,z,Fx,Fy' "$out/file-io-console.txt" ||
  { echo "no trace CSV download from File > Export trace CSV" >&2; fail=1; }
grep -q 'fv-io: file input opened, accept .csv' "$out/file-io-console.txt" ||
  { echo "File > Open data file… did not open the browser's file input" >&2; fail=1; }
[ "$fail" -eq 0 ] || exit 1
# The same file name as the page's (data.csv): the status line and the panel's rows are then the same (a
# longer name wrapped the status line onto a second row, and the panel grew a scrollbar the page did not have).
"$exe" gui --headless --frames 600 --scale 2 --data "$tmp/data.csv" --screenshot "$out/file-io-headless.png" >/dev/null
"$compare" "$out/file-io-web.png" "$out/file-io-headless.png" 32 0.03 "$out/file-io-web-vs-headless.diff.png"
