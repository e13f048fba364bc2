#!/usr/bin/python3
"""Runs the benchmarks and rewrites the current table in docs/benchmarks.md (between its markers).

Benchmarks print figures; this collects the headline of each into one table with the date, the commit and the
machine's load, so that the docs hold the current numbers and their history is the git log of that file, not
prose. Standard library only (the machine's /usr/bin/python3).

    scripts/bench-table.py [--build DIR] [--quick]    # --quick: fewer repetitions (a rough table in ~2 min)
"""
import argparse
import datetime
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "benchmarks.md")
BEGIN, END = "<!-- bench-table:begin -->", "<!-- bench-table:end -->"


def run(cmd, env=None):
    """Runs cmd; returns (stdout, wall seconds, CPU seconds of the child: user + system, all threads)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env={**os.environ, **(env or {})})
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.exit(f"bench-table: {' '.join(cmd)} failed ({p.returncode}): {p.stderr.strip()[-400:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p.stdout, wall, cpu


def median_runs(cmd, n):
    walls, cpus = [], []
    for _ in range(n):
        _, w, c = run(cmd)
        walls.append(w)
        cpus.append(c)
    return statistics.median(walls), statistics.median(cpus)


def render_all(fv, formats, n):
    with tempfile.TemporaryDirectory() as out:
        return median_runs([fv, "render", "--figure", "all", "--format", formats, "--out", out], n)


def solver(build, args=("--quick",)):
    text, _, _ = run([os.path.join(build, "bench", "fv_domain_speed"), *args, "--no-map"])
    overall = re.search(r"Overall\n.*\n\s*\S+\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)", text)
    failures = re.search(r"Failures \(status not ok or non-finite\): (\d+) of (\d+)", text)
    answers = re.search(r"answers \(exit 0\) above 2 ms: (\d+) of (\d+); the slowest ([\d.]+) ms", text)
    if not overall or not failures or not answers:
        sys.exit("bench-table: fv_domain_speed's output changed; update scripts/bench-table.py")
    return overall.groups(), failures.groups(), answers.groups()


def map_one_core(build):
    text, _, _ = run([os.path.join(build, "bench", "fv_domain_speed"), "--map-only", "--map-threads", "1",
                      "--map-rdisp", "2"])
    row = re.search(r"^\s+2\s+([\d.]+)\s+([\d.]+)\s+(\d+)", text, re.M)
    if not row:
        sys.exit("bench-table: fv_domain_speed --map-only's output changed; update scripts/bench-table.py")
    return row.group(2)


def animate(build):
    text, _, _ = run([os.path.join(build, "bench", "fv_animate_speed")])
    rows = re.findall(r"^(gif|mp4)\s+(\w+)\s+([\d.]+)\s+([\d.]+)", text, re.M)
    return {(f, v): (w, c) for f, v, w, c in rows}


def app_frames(fv, size_args, frames, script="bench/gui_all_layers.txt"):
    base = [fv, "gui", "--headless", "--bench", str(frames), *size_args, "--script", script]
    wall, _, _ = run(base)
    cpu, _, _ = run(base, env={"LP_NUM_THREADS": "0"})
    w = re.search(r"p50 ([\d.]+) ms, p95 ([\d.]+) ms", wall)
    c = re.findall(r"CPU time of the app's thread per frame: p50 ([\d.]+) ms", cpu)
    if not w or not c:
        sys.exit("bench-table: gui --bench's output changed; update scripts/bench-table.py")
    return w.group(1), w.group(2), c[-1]


def browser():
    """The browser build's first frame, and its slider to frame time alone and in compare mode (median, p95,
    and the page's own work per edit at p95, which depends less on the machine's load)."""
    site = os.path.join(ROOT, "build-web", "site")
    if not os.path.isfile(os.path.join(site, "frictionviz.wasm")):
        return None
    out = {}
    for mode, query in (("alone", ""), ("compare", "?b.theta=0")):
        text, _, _ = run(["bash", "scripts/bench-web.sh", site], env={"FV_BENCH_QUERY": query})
        first = re.search(r"first frame[^\d]*([\d.]+) ?(m?s)", text)
        slider = re.search(r"slider edits \d+: median ([\d.]+) ms, p95 ([\d.]+) ms", text)
        work = re.search(r"page work per edit \d+: median [\d.]+ ms, p95 ([\d.]+) ms", text)
        out[mode] = (first.group(1) + " " + first.group(2) if first else "?",
                     f"median {slider.group(1)} ms, p95 {slider.group(2)} ms" if slider else "?",
                     work.group(1) if work else "?")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    fv = os.path.join(build, "app", "frictionviz")
    n = 1 if args.quick else 3
    load_before = os.getloadavg()[0]

    rows = []
    w, c = render_all(fv, "png", n)
    rows.append(("`render --figure all`, 1280×800 PNG", f"{w:.2f} s wall, {c:.2f} s CPU", "≤ 5 s"))
    w, c = render_all(fv, "png,svg,pdf", n)
    rows.append(("the same, PNG + SVG + PDF", f"{w:.2f} s wall, {c:.2f} s CPU", ""))
    for label, sargs in (("quick domain grid (`fv_domain_speed --quick`)", ("--quick",)),
                         ("whole domain grid (`fv_domain_speed`)", ("--repeats", "1")),
                         ("3000 random points (`fv_domain_speed --random 3000`)", ("--random", "3000", "--repeats", "1")),
                         ("the same from sliding (`--start sliding`)",
                          ("--random", "3000", "--repeats", "1", "--start", "sliding"))):
        (points, med, p95, mx), (failed, total), (above, answers, slowest) = solver(build, sargs)
        rows.append((f"solver per point, {label}",
                     f"median {med} ms, p95 {p95} ms, max {mx} ms CPU; {failed} of {total} not verified; "
                     f"answers above 2 ms: {above} of {answers} (the slowest {slowest} ms)",
                     "answers ≤ 2 ms"))
    rows.append(("(ζ, θ) map, 200 × 91 cells, r_disp 2, i 1, one core", f"{map_one_core(build)} s CPU", "≤ 1 s"))
    anim = animate(build)
    for (fmt, view), (aw, ac) in sorted(anim.items()):
        rows.append((f"`animate`, 2 periods 640×400 30 fps, {fmt.upper()} {view}", f"{aw} s wall, {ac} s CPU",
                     "≤ 5 s"))
    frames = 100 if args.quick else 300
    for label, size in (("1280×800", ["--size", "1280x800"]),
                        ("1920×1080 at scale 1.5", ["--size", "1920x1080", "--scale", "1.5"])):
        for what, script in (("every layer", "bench/gui_all_layers.txt"),
                             ("every layer, compare on", "bench/gui_compare.txt")):
            p50, p95, cpu = app_frames(fv, size, frames, script)
            rows.append((f"app frame, {what}, {label} (headless llvmpipe)",
                         f"p50 {p50} ms, p95 {p95} ms wall; {cpu} ms CPU on one thread", "p95 ≤ 16 ms"))
    web = browser()
    if web:
        first, slider, work = web["alone"]
        rows.append(("browser: first frame; ζ slider to frame (headless Chromium)",
                     f"{first}; {slider}; the page's work per edit p95 {work} ms", "p95 ≤ 33 ms"))
        _, slider, work = web["compare"]
        rows.append(("the same in compare mode (`?b.theta=0`)",
                     f"{slider}; the page's work per edit p95 {work} ms", "p95 ≤ 33 ms"))
    else:
        rows.append(("browser: first frame; ζ slider to frame (headless Chromium)",
                     "not measured (no build-web/site)", ""))

    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    load_after = os.getloadavg()[0]
    table = [BEGIN,
             f"Measured {datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC at commit `{commit}` on {os.cpu_count()} "
             f"cores, load average {load_before:.1f} before and {load_after:.1f} after"
             f"{' (--quick: one run each)' if args.quick else ' (medians of 3 runs where repeated)'}.",
             "", "| what | measured | target |", "| --- | --- | --- |"]
    table += [f"| {a} | {b} | {t} |" for a, b, t in rows]
    table.append(END)
    with open(DOC, encoding="utf-8") as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc:
        sys.exit(f"bench-table: {DOC} has no {BEGIN} … {END} markers")
    head, rest = doc.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(DOC + ".tmp", "w", encoding="utf-8") as f:
        f.write(head + "\n".join(table) + tail)
    os.replace(DOC + ".tmp", DOC)
    print("\n".join(table))


if __name__ == "__main__":
    main()
