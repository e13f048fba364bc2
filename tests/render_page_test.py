#!/usr/bin/env python3
"""render --page and --caption (issue #23 item 8): the printed page's size read back by pdfinfo, the tick labels'
type measured by pdftotext -bbox, the caption found in the PDF's text, the SVG's <desc> and the PNG's bottom band,
the column's panels one above another and a caption's overlong path broken inside it, and a bad --page refused
with one line naming the allowed pages and nothing written.
Usage: render_page_test.py FRICTIONVIZ SCRATCH_DIR"""
import json, os, re, shutil, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_files import check, failures, png_rows, words  # noqa: E402

fv, scratch = sys.argv[1], sys.argv[2]
shutil.rmtree(scratch, ignore_errors=True)
def render(out, *args):
    os.makedirs(out, exist_ok=True)
    return subprocess.run([fv, "render", "--figure", "fig5", "--out", out, *args], capture_output=True, text=True)



# Page sizes in points: A4 is 210 x 297 mm (595.276 x 841.89 pt), Letter 8.5 x 11 in (612 x 792 pt).
for page, size in (("a4", (595.276, 841.89)), ("letter", (612.0, 792.0))):
    out = os.path.join(scratch, page)
    r = render(out, "--format", "png,svg,pdf", "--page", page, "--caption")
    check(r.returncode == 0, f"--page {page} renders (exit {r.returncode}: {r.stderr.strip()})")
    info = subprocess.run(["pdfinfo", os.path.join(out, "fig5.pdf")], capture_output=True, text=True).stdout
    m = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", info)
    check(m is not None and abs(float(m.group(1)) - size[0]) < 0.01 and abs(float(m.group(2)) - size[1]) < 0.01,
          f"--page {page}: the PDF page is {size[0]} x {size[1]} pt ({m.group(0) if m else info!r})")
    # The tick labels (numbers) print 8-11 pt tall (a word box is the font's line: about 1.16 em).
    bbox = subprocess.run(["pdftotext", "-bbox", os.path.join(out, "fig5.pdf"), "-"], capture_output=True,
                          text=True).stdout
    heights = [float(b) - float(a) for a, b, t in
               re.findall(r'yMin="([\d.]+)" xMax="[\d.]+" yMax="([\d.]+)">([−\-]?[\d.]+)</word>', bbox)]
    check(len(heights) >= 6 and all(8 <= x <= 11 for x in heights),
          f"--page {page}: {len(heights)} tick labels, heights {min(heights, default=0):.2f}-"
          f"{max(heights, default=0):.2f} pt within 8-11")
    caption = json.load(open(os.path.join(out, "fig5.json")))["caption"]
    text = " ".join(subprocess.run(["pdftotext", os.path.join(out, "fig5.pdf"), "-"], capture_output=True,
                                   text=True).stdout.split())
    check(" ".join(caption.split()[:8]) in text and " ".join(caption.split()[-4:]) in text,
          f"--page {page}: the caption's first and last words are in the PDF's text")
    svg = open(os.path.join(out, "fig5.svg"), encoding="utf-8").read()
    check("<desc>" + caption.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") + "</desc>" in svg,
          f"--page {page}: the caption is the SVG's <desc>")
    w = re.search(r'<svg[^>]* width="([\d.]+)pt"', svg)
    check(w is not None and abs(float(w.group(1)) - size[0]) < 0.01, f"--page {page}: the SVG is {size[0]} pt wide")

# The column: 3.3 in wide.
out = os.path.join(scratch, "column")
r = render(out, "--format", "pdf", "--page", "column")
info = subprocess.run(["pdfinfo", os.path.join(out, "fig5.pdf")], capture_output=True, text=True).stdout
check(re.search(r"Page size:\s+237.6 x", info) is not None, "--page column: the page is 3.3 in (237.6 pt) wide")



# Two panels on the column: one above the other across its width (side by side they were 160 units each), the
# page taller than a one-panel figure's.
r = subprocess.run([fv, "render", "--figure", "fig4", "--format", "pdf", "--page", "column", "--out", out],
                   capture_output=True, text=True)
fig4 = words(os.path.join(out, "fig4.pdf"))
first = [w for w in fig4 if w[4] == "velocity"]    # the first panel's title: "velocity v/v_v and friction ..."
second = [w for w in fig4 if w[4] == "against"]    # the second's: "friction against v_b over one period"
check(r.returncode == 0 and first and second and second[0][1] > first[0][3] + 100,
      f"--page column: fig4's second panel is under the first ({first[:1]}, {second[:1]})")
h4 = float(re.search(r"Page size:\s+[\d.]+ x ([\d.]+)", subprocess.run(
    ["pdfinfo", os.path.join(out, "fig4.pdf")], capture_output=True, text=True).stdout).group(1))
h5 = float(re.search(r"Page size:\s+[\d.]+ x ([\d.]+)", info).group(1))
check(h4 > 1.6 * h5, f"--page column: fig4's page ({h4:.0f} pt) is taller than fig5's ({h5:.0f} pt)")

# A caption with a word wider than the column (a data file's path) is broken inside the page, not run off it.
deep = os.path.join(scratch, "a_directory_with_a_long_name_for_measurements", "and-another-level")
os.makedirs(deep, exist_ok=True)
data = os.path.join(deep, "friction_ratio_measurements_at_two_angles.csv")
shutil.copy(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "synthetic_two_angles_rdisp2_i0.csv"),
            data)
r = subprocess.run([fv, "render", "--figure", "rx", "--model", "rigid", "--theta", "45", "--data", data, "--format",
                    "pdf", "--page", "column", "--caption", "--out", out], capture_output=True, text=True)
rx = words(os.path.join(out, "rx.pdf"))
outside = [w for w in rx if w[0] < -0.01 or w[2] > 237.6 + 0.01]
caption_text = "".join(w[4] for w in rx)
check(r.returncode == 0 and not outside and "friction_ratio_measurements_at_two_angles.csv" in caption_text,
      f"--page column --caption: a {len(data)}-character path broken inside the page ({outside[:2]})")

# A PNG with --caption is the figure (the same pixels) with a band under it that has ink.
plain, capt = os.path.join(scratch, "plain"), os.path.join(scratch, "capt")
render(plain)
render(capt, "--caption")
w0, h0, rows0 = png_rows(os.path.join(plain, "fig5.png"))
w1, h1, rows1 = png_rows(os.path.join(capt, "fig5.png"))
check(w1 == w0 and h1 > h0 + 30, f"--caption: the PNG is {w1}x{h1}, taller than {w0}x{h0}")
check(rows1[:h0] == rows0, "--caption: the figure above the band is the PNG without it, pixel for pixel")
ink = sum(1 for row in rows1[h0:] for i in range(0, len(row), 4) if row[i] < 128)
check(ink > 500, f"--caption: the band under the figure has ink ({ink} dark pixels)")

# A bad page: exit 2, one line naming the allowed pages, nothing written.
bad = os.path.join(scratch, "bad")
r = render(bad, "--page", "a5")
check(r.returncode == 2 and r.stderr.count("\n") == 1 and "a4, letter, column" in r.stderr and
      not os.listdir(bad), f"--page a5 refused: exit {r.returncode}, {r.stderr.strip()!r}")

# A spec file keeps the page and the caption: --spec ID.json draws the same PDF again (SOURCE_DATE_EPOCH fixes
# its date), and a bad page in one is refused.
env = dict(os.environ, SOURCE_DATE_EPOCH="0")
first, again = os.path.join(scratch, "spec1"), os.path.join(scratch, "spec2")
for d in (first, again):
    os.makedirs(d, exist_ok=True)
subprocess.run([fv, "render", "--figure", "fig5", "--format", "pdf", "--page", "letter", "--caption", "--out", first],
               env=env, capture_output=True)
params = json.load(open(os.path.join(first, "fig5.json")))["parameters"]
check(params.get("page") == "letter" and params.get("caption") is True, f"ID.json keeps page and caption ({params})")
r = subprocess.run([fv, "render", "--spec", os.path.join(first, "fig5.json"), "--out", again], env=env,
                   capture_output=True, text=True)
check(r.returncode == 0 and open(os.path.join(first, "fig5.pdf"), "rb").read() ==
      open(os.path.join(again, "fig5.pdf"), "rb").read(), "--spec ID.json draws the same page and caption, byte for byte")
plain_params = json.load(open(os.path.join(plain, "fig5.json")))["parameters"]
check("page" not in plain_params and "caption" not in plain_params, "without them ID.json has no page or caption key")
bad_spec = os.path.join(scratch, "bad.json")
open(bad_spec, "w").write('{"id": "fig5", "page": "a3"}')
r = subprocess.run([fv, "render", "--spec", bad_spec, "--out", bad], capture_output=True, text=True)
check(r.returncode == 2 and "a4, letter, column" in r.stderr and not os.listdir(bad),
      f"a spec's bad page refused: exit {r.returncode}, {r.stderr.strip()!r}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
