#!/usr/bin/env bash
# A link that opens a guided lesson step (?lesson=3): the page sets up the step as the Lessons menu does and
# shows its card. Checked three ways:
#   - the link of the state on screen (the body's data-fv-link) carries lesson=3 and the step's setup as
#     app/gui/lessons.json gives it (read here with python, not from the program);
#   - the page against the desktop app's headless screenshot from the same link (`gui --link '?lesson=3'`;
#     app_page_vs_headless.sh's tolerance: 32 levels, at most 3% of the pixels; measured 0.9%); the card fills
#     the top of the panel, so a page without it differs by far more (the same setup without the card: 9.8%);
#   - a step that does not exist (?lesson=99&zeta=0.45): a notice naming the allowed steps, the rest of the
#     link applied (zeta=0.45 in the state's link), no lesson;
#   - the Lessons menu and the card's Next button clicked in the page (tests/web/lesson_menu.html, mouse events
#     on the canvas): the address must say lesson=3 with step 3's setup after the menu, lesson=4 after Next.
#   lesson_link_page.sh SITE_DIR FRICTIONVIZ FV_PNG_COMPARE OUTDIR LESSONS_JSON
set -euo pipefail
site=$1 exe=$2 compare=$3 out=$4 lessons=$5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
link_of() { # the body's data-fv-link in a DOM dump
  grep -ao 'data-fv-link="[^"]*"' "$1" | head -1 | sed 's/^data-fv-link="//; s/"$//; s/&amp;/\&/g'
}
has_keys() { # LINK KEY=VALUE...: every pair is in the link's query
  local l=$1
  shift
  for kv in "$@"; do
    case "&${l#\?}&" in
      *"&$kv&"*) ;;
      *) echo "the link '$l' lacks $kv" >&2; return 1 ;;
    esac
  done
}
# Step 3's setup from the lessons file, as share-link keys (theta in degrees, numbers as JSON writes them).
mapfile -t expected < <(/usr/bin/python3 - "$lessons" <<'PY'
import json, sys
u = json.load(open(sys.argv[1]))["steps"][2]["setup"]
num = lambda v: repr(float(v)).rstrip("0").rstrip(".") if float(v) != int(v) else str(int(v))
print("lesson=3")
for key in ("zeta", "theta", "rdisp", "i"):
    print(f"{key}={num(u[key])}")
print(f"model={u['model']}")
if u.get("panel", "curves") != "curves":
    print(f"panel={u['panel']}")
PY
)
echo "expected in the link: ${expected[*]}"
bash "$here/screenshot.sh" "$site" "?lesson=3" "$out/lesson-page.html" 1280 800 4000
shown=$(link_of "$out/lesson-page.html")
echo "the page's link: ${shown:-none}"
has_keys "$shown" "${expected[@]}"

bash "$here/screenshot.sh" "$site" "?lesson=3" "$out/lesson-web.png" 1280 800 10000 1
"$exe" gui --headless --frames 600 --link "?lesson=3" --screenshot "$out/lesson-headless.png" >/dev/null
"$compare" "$out/lesson-web.png" "$out/lesson-headless.png" 32 0.03 "$out/lesson-web-vs-headless.diff.png"

bash "$here/screenshot.sh" "$site" "?lesson=99&zeta=0.45" "$out/lesson-bad-page.html" 1280 800 4000
shown=$(link_of "$out/lesson-bad-page.html")
echo "the page's link after ?lesson=99&zeta=0.45: ${shown:-none}"
has_keys "$shown" zeta=0.45
case "$shown" in *lesson=*) echo "a step that does not exist was kept: '$shown'" >&2; exit 1 ;; esac
steps=$(/usr/bin/python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["steps"]))' "$lessons")
notice="lesson = 99 is out of range; allowed: lesson in [1, $steps]; ignored"
if ! grep -a 'id="status"' "$out/lesson-bad-page.html" | grep -qF "$notice"; then
  echo "the page does not say: $notice" >&2
  grep -a 'id="status"' "$out/lesson-bad-page.html" >&2 || echo "(no status line in the page)" >&2
  exit 1
fi
echo "page says: $notice"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$site/frictionviz.js" "$site/frictionviz.wasm" "$here/page_input.js" "$tmp/"
cp "$here/lesson_menu.html" "$tmp/menu.html"
bash "$here/screenshot.sh" "$tmp" "menu.html" "$out/lesson-menu-next.png" 1280 800 5000 1 |
  tee "$out/lesson-menu-console.txt"
after_menu=$(grep -ao "fv-lesson: menu ?[^\"' ]*" "$out/lesson-menu-console.txt" | tail -1 | sed 's/^fv-lesson: menu //')
after_next=$(grep -ao "fv-lesson: next ?[^\"' ]*" "$out/lesson-menu-console.txt" | tail -1 | sed 's/^fv-lesson: next //')
echo "after the menu: ${after_menu:-none}; after Next: ${after_next:-none}"
has_keys "$after_menu" "${expected[@]}"
has_keys "$after_next" lesson=4
