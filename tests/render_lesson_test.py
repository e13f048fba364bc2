#!/usr/bin/env python3
"""render --lesson N draws the step as the app shows it, and prints as a handout (issue #23).

Every step of app/gui/lessons.json (read here, not through the program): its PDF's text carries the lower panel
the step sets (each panel known by a title only it draws: the mechanism's "mechanism now", the loop's "vibration
displacement", the map's "vibration angle", the curves' "friction ratio") and no other, the top view's frame
(ground: "on the floor", body: "moves with the body") and, for a step with setup B, both setups; its JSON names
the panel. The map of step 7 is in the PNG's lower right as the colour map's yellow, where step 6 (curves) has
none, and the app (`gui --headless --lesson 7`) shows it there too. `--page a4 --caption` gives an A4 PDF whose
tick labels print at 8-11 pt, with the step's title and text as its caption (the PDF's text, the SVG's <desc>,
the PNG's band under the unchanged picture); `--page column` is 3.3 in wide with nothing outside it. A bad page
exits 2 with one line, nothing written.
Usage: render_lesson_test.py FRICTIONVIZ LESSONS_JSON SCRATCH_DIR"""
import json, os, re, shutil, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_files import check, failures, png_rows, words  # noqa: E402

fv, lessons_json, scratch = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(scratch, ignore_errors=True)
steps = json.load(open(lessons_json, encoding="utf-8"))["steps"]
def render(out, *args):
    os.makedirs(out, exist_ok=True)
    return subprocess.run([fv, "render", *args, "--out", out], capture_output=True, text=True)


def pdf_text(pdf):
    """The PDF's text, runs of white space as one space."""
    return " ".join(subprocess.run(["pdftotext", pdf, "-"], capture_output=True, text=True).stdout.split())


# What only each lower panel draws: its title or an axis title (fv/live_panels.cpp).
PANEL_MARK = {"why": "mechanism now", "loop": "vibration displacement", "map": "vibration angle",
              "curves": "friction ratio", "setup": "the experiment"}

for k, step in enumerate(steps, 1):
    setup = step["setup"]
    panel, frame = setup.get("panel", "curves"), setup.get("frame", "body")
    out = os.path.join(scratch, f"step{k}")
    r = render(out, "--lesson", str(k), "--format", "png,pdf", "--size", "960x600")
    check(r.returncode == 0, f"--lesson {k} renders (exit {r.returncode}: {r.stderr.strip()})")
    if r.returncode != 0:
        continue
    text = pdf_text(os.path.join(out, f"lesson-{k}.pdf"))
    shown = [p for p, mark in PANEL_MARK.items() if mark in text]
    check(shown == [panel], f"--lesson {k} ({step['id']}): the lower panel is {panel}, as the step sets it "
                            f"(drawn: {shown})")
    mark = "on the floor" if frame == "ground" else "moves with the body"
    check(mark in text, f"--lesson {k}: the top view in the {frame} frame ({mark!r})")
    if "b" in setup:
        check(text.count("A: θ") >= 1 and text.count("B: θ") >= 1, f"--lesson {k}: compare mode, A's and B's setup")
    else:
        check("B: θ" not in text, f"--lesson {k}: no setup B")
    j = json.load(open(os.path.join(out, f"lesson-{k}.json"), encoding="utf-8"))
    check(j.get("panel") == panel, f"--lesson {k}: lesson-{k}.json names the panel ({j.get('panel')})")


def yellow_share(path, x0, y0):
    """The share of the pixels right of x0 and below y0 (fractions of the size) that are the colour map's top end
    (viridis' yellow, about (253, 231, 37)): the map's high r_x."""
    w, h, rows = png_rows(path)
    n = hits = 0
    for row in rows[int(y0 * h):]:
        for i in range(int(x0 * w) * 4, w * 4, 4):
            n += 1
            hits += row[i] > 200 and row[i + 1] > 190 and row[i + 2] < 100
    return hits / max(n, 1)


best, compliance = [k for k, s in enumerate(steps, 1) if s["setup"].get("panel") == "map"], \
    [k for k, s in enumerate(steps, 1) if s["setup"].get("panel", "curves") == "curves" and "b" not in s["setup"]]
if best and compliance:
    m, c = best[0], compliance[0]
    on_map = yellow_share(os.path.join(scratch, f"step{m}", f"lesson-{m}.png"), 0.5, 0.62)
    on_curves = yellow_share(os.path.join(scratch, f"step{c}", f"lesson-{c}.png"), 0.5, 0.62)
    check(on_map > 0.05 and on_curves < 0.001,
          f"the map's colours in the lower right: {on_map:.3f} of step {m}'s (map), {on_curves:.4f} of step {c}'s")
    # The app shows the same step's map in its lower right (the panel beside the force plot). Its map is computed
    # on a worker thread while the frames run: 900 frames at 1/60 s leave it 15 s.
    shot = os.path.join(scratch, "app.png")
    r = subprocess.run([fv, "gui", "--headless", "--lesson", str(m), "--frames", "900", "--screenshot", shot],
                       capture_output=True, text=True)
    app = yellow_share(shot, 0.6, 0.62) if r.returncode == 0 else 0
    check(app > 0.05, f"gui --lesson {m} shows the map there too ({app:.3f}; exit {r.returncode})")

# The handout: --page a4 --caption. A4 is 210 x 297 mm (595.276 x 841.89 pt).
k = next((k for k, s in enumerate(steps, 1) if s["setup"].get("frame") == "ground"), 1)
step = steps[k - 1]
out = os.path.join(scratch, "a4")
r = render(out, "--lesson", str(k), "--format", "png,svg,pdf", "--page", "a4", "--caption")
check(r.returncode == 0 and "page a4" in r.stdout, f"--lesson {k} --page a4 --caption renders (exit "
                                                   f"{r.returncode}: {r.stderr.strip()}; {r.stdout.strip()})")
pdf = os.path.join(out, f"lesson-{k}.pdf")
info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
m = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", info)
check(m is not None and abs(float(m.group(1)) - 595.276) < 0.01 and abs(float(m.group(2)) - 841.89) < 0.01,
      f"--page a4: the PDF page is 595.276 x 841.89 pt ({m.group(0) if m else info!r})")
# Tick labels: numbers on a line of numbers only (not the "0" of a title's "F_x > 0", nor the parameters line).
boxes = words(pdf)
number = re.compile(r"[−\-]?[\d.]+")
heights = [w[3] - w[1] for w in boxes if number.fullmatch(w[4]) and
           all(number.fullmatch(v[4]) for v in boxes if abs(v[1] - w[1]) < 0.3)]
check(len(heights) >= 10 and all(8 <= x <= 11 for x in heights),
      f"--page a4: {len(heights)} tick labels, heights {min(heights, default=0):.2f}-{max(heights, default=0):.2f} "
      f"pt within 8-11")
inside = [w for w in words(pdf) if w[0] < 47 or w[2] > 595.276 - 47]
check(not inside, f"--page a4: every word within the 2/3 in margins ({inside[:2]})")
text = pdf_text(pdf)
title, body = f"Lesson {k}: {step['title']}", " ".join(step["text"].split())
caption = f"{title}. {step['text']}"
check(f"{title}. {body}" in text, f"--page a4 --caption: the step's title and text are the PDF's caption")
# The caption is under the figure: its first word below every word of the figure (the title begins both: the
# caption's is the last).
first = " ".join(caption.split()[:3])
cap = [i for i in range(len(boxes) - 2) if " ".join(b[4] for b in boxes[i:i + 3]) == first]
fig_bottom = max((b[3] for b in boxes[:cap[-1]]), default=0) if cap else 0
check(bool(cap) and boxes[cap[-1]][1] >= fig_bottom - 0.5,
      f"--page a4 --caption: the caption starts under the figure ({boxes[cap[-1]][1] if cap else None} pt, the "
      f"figure ends at {fig_bottom} pt)")
svg = open(os.path.join(out, f"lesson-{k}.svg"), encoding="utf-8").read()
check("<desc>" + caption.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") + "</desc>" in svg,
      "--page a4 --caption: the caption is the SVG's <desc>")
plain = os.path.join(scratch, "plain")
render(plain, "--lesson", str(k))
w0, h0, rows0 = png_rows(os.path.join(plain, f"lesson-{k}.png"))
w1, h1, rows1 = png_rows(os.path.join(out, f"lesson-{k}.png"))
check(w1 == w0 == 1280 and h0 == 800 and h1 > h0 + 30, f"--caption: the PNG is {w1}x{h1}, the picture's {w0}x{h0} "
                                                       "and a band under it")
check(rows1[:h0] == rows0, "--caption: the picture above the band is the PNG without it, pixel for pixel")
ink = sum(1 for row in rows1[h0:] for i in range(0, len(row), 4) if row[i] < 128)
check(ink > 500, f"--caption: the band under the picture has ink ({ink} dark pixels)")

# A column: 3.3 in (237.6 pt) wide, the compare step's two top views and its caption inside it.
k = next((k for k, s in enumerate(steps, 1) if "b" in s["setup"]), 1)
out = os.path.join(scratch, "column")
r = render(out, "--lesson", str(k), "--format", "pdf", "--page", "column", "--caption")
pdf = os.path.join(out, f"lesson-{k}.pdf")
info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
check(r.returncode == 0 and re.search(r"Page size:\s+237.6 x", info) is not None,
      f"--lesson {k} --page column: the page is 237.6 pt wide ({r.stderr.strip()})")
outside = [w for w in words(pdf) if w[0] < -0.01 or w[2] > 237.6 + 0.01]
check(not outside, f"--page column: every word inside the column ({outside[:2]})")

# A bad page: exit 2, one line naming the allowed pages, nothing written.
bad = os.path.join(scratch, "bad")
r = render(bad, "--lesson", "3", "--page", "a5", "--caption")
check(r.returncode == 2 and r.stderr.count("\n") == 1 and "a4, letter, column" in r.stderr and not os.listdir(bad),
      f"--lesson 3 --page a5 refused: exit {r.returncode}, {r.stderr.strip()!r}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
