#!/usr/bin/env python3
"""Checks the layout the app's page published (web/app_main.cpp: the body's data-fv-layout, from
chromium --dump-dom) for a window of WIDTH x HEIGHT CSS pixels at devicePixelRatio DPR:

- the canvas fills the window (its CSS box is the window's; for a page narrower than Chromium's narrowest
  window, 500, the canvas's CSS width is pinned to the page's by page_fits.sh) and its backing store is the CSS size times the
  ratio the app draws at, min(DPR, 3), rounded; the app's logical page is that CSS size;
- every part the app draws (the panel, the top view, the force plot, the lower panel) lies inside the page,
  none overlaps another, each large enough to read (a plot at least 120 x 90 CSS pixels, the panel at least
  300 x 150): nothing cut off or unreachable; the panel's rows beyond its height are reached by scrolling it
  (its scroll range is reported, and the panel is then a scrolling window);
- a narrow window (less than 720 CSS pixels) has the panel across the top (`stacked`), a wide one down the
  left edge.

With SHOT.png, the canvas the page saved into its DOM (data-fv-shot, page_fits_shot.js) is written there.

    page_fits.py DOM.html WIDTH HEIGHT DPR [SHOT.png]
"""
import base64
import html
import json
import re
import sys


def main():
    dom, width, height, dpr = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    text = open(dom, encoding="utf-8", errors="replace").read()
    m = re.search(r'data-fv-layout="([^"]*)"', text)
    if not m:
        sys.exit(f"{dom}: the page published no layout (no data-fv-layout on its body)")
    lay = json.loads(html.unescape(m.group(1)))
    app = lay["app"]
    errors = []

    def expect(ok, what):
        if not ok:
            errors.append(what)

    ratio = min(dpr, 3.0)
    # Chromium's windows are at least 500 wide: page_fits.sh pins a narrower canvas's CSS width instead.
    expect(lay["window"] == [max(width, 500), height],
           f"window {lay['window']}, expected {[max(width, 500), height]}")
    expect(lay["canvas_css"] == [0, 0, width, height],
           f"canvas CSS box {lay['canvas_css']}, expected the window [0, 0, {width}, {height}]")
    want_backing = [round(width * ratio), round(height * ratio)]
    expect(lay["canvas"] == want_backing, f"canvas backing store {lay['canvas']}, expected {want_backing}")
    expect(app["framebuffer"] == want_backing, f"app framebuffer {app['framebuffer']}, expected {want_backing}")
    expect(abs(app["ratio"] - ratio) < 1e-3, f"app pixel ratio {app['ratio']}, expected {ratio}")
    expect(abs(app["page"][0] - width) < 1 and abs(app["page"][1] - height) < 1,
           f"app page {app['page']} CSS px, expected {width} x {height}")
    expect(app["stacked"] == (width < 720), f"stacked = {app['stacked']} at width {width}")
    parts = {"controls": (300, 150), "top_view": (120, 90), "force": (120, 90), "lower": (120, 90)}
    if "top_view_b" in app:  # compare mode: B's top view beside A's
        parts["top_view_b"] = (120, 90)
    for name, (min_w, min_h) in parts.items():
        x0, y0, x1, y1 = app[name]
        expect(x0 >= 0 and y0 >= 0 and x1 <= width and y1 <= height,
               f"{name} {app[name]} reaches outside the page {width} x {height}")
        expect(x1 - x0 >= min_w and y1 - y0 >= min_h,
               f"{name} {app[name]} is smaller than {min_w} x {min_h} CSS px")
    names = list(parts)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            ra, rb = app[a], app[b]
            overlap = ra[0] < rb[2] and rb[0] < ra[2] and ra[1] < rb[3] and rb[1] < ra[3]
            expect(not overlap, f"{a} {ra} overlaps {b} {rb}")
    expect(app["controls_scroll_max"] >= 0, "negative scroll range")
    print(f"{width:g}x{height:g} at {dpr:g}: canvas {lay['canvas']}, stacked {app['stacked']}, panel {app['controls']} "
          f"(scrolls {app['controls_scroll_max']:g} px), top view {app['top_view']}, force {app['force']}, "
          f"lower {app['lower']}" + (f", B's top view {app['top_view_b']}" if "top_view_b" in app else ""))
    if len(sys.argv) > 5:
        shot = re.search(r'data-fv-shot="data:image/png;base64,([^"]*)"', text)
        if shot:
            with open(sys.argv[5], "wb") as f:
                f.write(base64.b64decode(shot.group(1)))
        else:
            print(f"(no picture of the canvas in {dom})")
    if errors:
        sys.exit("\n".join(errors))


if __name__ == "__main__":
    main()
