#!/usr/bin/env bash
# Sharing and sessions in the browser (issue #23), tests/web/share_session.html driving the page:
# - Copy link puts the whole address (the page's origin and path, then the share link) on the clipboard, or,
#   where the browser refuses (headless Chromium does), into the box the page shows with it selected;
# - a session file dropped onto the page that does not read changes nothing (the address stays) and the
#   status line says why, as the desktop app does; one that reads is opened: the address becomes its link
#   (model, theta, panel and speed from the file);
# - File > Open session… opens the browser's file input for .json; the session chosen (saved during lesson
#   step 8) opens with the step's card and its example points (the status line counts them).
#   share_session_page.sh SITE_DIR OUTDIR LINK
set -euo pipefail
site=$1 out=$2 link=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$site/frictionviz.js" "$site/frictionviz.wasm" "$here/page_input.js" "$tmp/"
cp "$here/share_session.html" "$tmp/share.html"
bash "$here/screenshot.sh" "$tmp" "share.html$link" "$out/share-session.png" 1280 800 10000 1 |
  tee "$out/share-session-console.txt"
log=$out/share-session-console.txt
fail=0
# The address copied: by the clipboard ("frictionviz: copied ADDRESS") or in the page's box.
want="/share.html$link"
copied=$(grep -ao 'frictionviz: copied [^"]*\|fv-share: copy box [^"]*' "$log" | sed 's/^frictionviz: copied //; s/^fv-share: copy box //' |
  grep -v '^(none)$' | head -1 || true)
case $copied in
  http://127.0.0.1:*"$want") echo "copied: $copied" ;;
  *) echo "Copy link gave '${copied:-nothing}', expected http://127.0.0.1:PORT$want" >&2; fail=1 ;;
esac
bad=$(grep -ao 'fv-share: after bad: [^"]*' "$log" | tail -1)
case $bad in
  "fv-share: after bad: $link status "*"bad.json"*"version 2 is not one this frictionviz reads"*"(session not opened; nothing changed)"*)
    echo "$bad" ;;
  *) echo "a bad session dropped: expected the address unchanged and the reason, got '$bad'" >&2; fail=1 ;;
esac
good=$(grep -ao 'fv-share: after good: [^"]*' "$log" | tail -1)
for kv in theta=45 model=rigid panel=map speed=2; do
  case "&$(printf '%s' "$good" | sed 's/^fv-share: after good: ?//; s/ status .*//')&" in
    *"&$kv&"*) ;;
    *) echo "the session dropped did not open ($kv missing): '$good'" >&2; fail=1 ;;
  esac
done
case $good in *"opened session"*"class.json"*) echo "$good" ;; *) echo "no 'opened session' in: $good" >&2; fail=1 ;; esac
grep -aq 'fv-share: file input opened, accept .*\.json' "$log" ||
  { echo "File > Open session… did not open the browser's file input for .json" >&2; fail=1; }
input=$(grep -ao 'fv-share: after input: [^"]*' "$log" | tail -1)
for kv in theta=60 rdisp=3 i=0 lesson=8; do
  case "&$(printf '%s' "$input" | sed 's/^fv-share: after input: ?//; s/ status .*//')&" in
    *"&$kv&"*) ;;
    *) echo "the session chosen in the file input did not open ($kv missing): '$input'" >&2; fail=1 ;;
  esac
done
case $input in
  *"opened session"*"lesson8.json"*"16 points"*) echo "$input" ;;
  *) echo "expected 'opened session lesson8.json' with the step's 16 example points in: $input" >&2; fail=1 ;;
esac
exit $fail
