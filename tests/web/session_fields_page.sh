#!/usr/bin/env bash
# A link with every session field the link carries beyond the parameters (the units, paused, trail, zoom, pan,
# follow, panel, speed), none at its default: the page must read each key and write the same link back for the
# state it shows (the body's data-fv-link: link -> state -> link, the same text), and its screenshot must
# match `gui --headless --link` from the same link (app_page_vs_headless.sh's tolerance: 32 levels, at most 3%
# of the pixels; measured 0.0014%). play=0: both show the animation's first frame. The same link with the default
# units instead differs in the panel's A, f, v_v, v_b and z_ss, which the comparison of the panel sees.
#   session_fields_page.sh SITE_DIR FRICTIONVIZ FV_PNG_COMPARE OUTDIR LINK
set -euo pipefail
site=$1 exe=$2 compare=$3 out=$4 link=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
bash "$here/screenshot.sh" "$site" "$link" "$out/session-fields-page.html" 1280 800 4000
shown=$(grep -ao 'data-fv-link="[^"]*"' "$out/session-fields-page.html" | head -1 |
  sed 's/^data-fv-link="//; s/"$//; s/&amp;/\&/g')
echo "opened with:     $link"
echo "the page's link: ${shown:-none}"
if [ "$shown" != "$link" ]; then
  echo "the page's link of its state is not the link it was opened with" >&2
  exit 1
fi
bash "$here/screenshot.sh" "$site" "$link" "$out/session-fields-web.png" 1280 800 10000 1
"$exe" gui --headless --frames 600 --link "$link" --screenshot "$out/session-fields-headless.png" >/dev/null
"$compare" "$out/session-fields-web.png" "$out/session-fields-headless.png" 32 0.03 \
  "$out/session-fields-web-vs-headless.diff.png"
# The units are on screen: in the panel (left 340 px), the page matches the desktop app from the same link
# (measured 0.004% of the pixels differ) and not the desktop app with the default amplitude and frequency
# (0.17%: the numbers of A, f, v_v, v_b and z_ss): at most 0.05% may differ.
"$compare" "$out/session-fields-web.png" "$out/session-fields-headless.png" 32 0.0005 \
  "$out/session-fields-panel.diff.png" 0,0,340,800
default_units=$(printf '%s' "$link" | sed 's/&amplitude=[^&]*//; s/&frequency=[^&]*//')
"$exe" gui --headless --frames 600 --link "$default_units" --screenshot "$out/session-fields-default-units.png" \
  >/dev/null
if "$compare" "$out/session-fields-web.png" "$out/session-fields-default-units.png" 32 0.0005 \
  "$out/session-fields-default-units.diff.png" 0,0,340,800 >/dev/null 2>&1; then
  echo "the page's panel with amplitude and frequency from the link matches the default units' panel" >&2
  exit 1
fi
echo "the page's panel differs from the default units' panel, as it should"
