#!/usr/bin/env python3
"""frictionviz.ratio (the Python module) against `frictionviz sweep` on the same points and threads.

    PYTHONPATH=BUILD/python /usr/bin/python3 bench/python_ratio.py BUILD/app/frictionviz [POINTS] [THREADS]

The points are the sweep's grid (zeta FROM:TO:COUNT x a list of theta, rdisp 2, i 1), fed to ratio() as
broadcast arrays; the sweep writes CSV to /dev/null. Prints both wall times (best of REPEATS), their ratio (the
issue's target: within 1.2x) and whether the numbers agree. A benchmark, not a test: it prints figures.
"""

import subprocess
import sys
import time

import numpy as np

import frictionviz as fv

exe = sys.argv[1]
points = int(sys.argv[2]) if len(sys.argv) > 2 else 100000
threads = int(sys.argv[3]) if len(sys.argv) > 3 else 2
repeats = 2
thetas = [0, 20, 40, 60, 80, 90, 100, 120, 150, 180]
nz = points // len(thetas)
args = ["sweep", "--zeta", f"0.01:3:{nz}", "--theta", ",".join(map(str, thetas)), "--rdisp", "2", "--i", "1",
        "--threads", str(threads)]

def best(f):
    t = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = f()
        t.append(time.perf_counter() - t0)
    return min(t), out

t_cli, _ = best(lambda: subprocess.run([exe, *args, "--out", "/dev/null"], check=False))
# The sweep's zeta values exactly (its JSON/CSV carry them; linspace may round differently): from one CSV run.
csv = subprocess.run([exe, *args], capture_output=True, text=True).stdout.splitlines()
rows = [r.split(",") for r in csv[1:]]
zeta = np.array([float(r[4]) for r in rows[:nz]])  # zeta fastest, theta next: the first nz rows span zeta
theta = np.array(thetas, dtype=float)[:, None]
t_py, res = best(lambda: fv.ratio(zeta, theta, 2.0, 1.0, threads=threads))
rx_cli = np.array([float(r[5]) if r[5] else np.nan for r in rows]).reshape(len(thetas), nz)
agree = np.allclose(res.r_x, rx_cli, rtol=0, atol=1e-11, equal_nan=True)  # CSV has 12 digits
print(f"points {res.r_x.size}, threads {threads}")
print(f"frictionviz sweep  {t_cli:8.3f} s")
print(f"frictionviz.ratio  {t_py:8.3f} s")
print(f"ratio / sweep      {t_py / t_cli:8.3f}   (target <= 1.2)")
print(f"values agree (12 digits of the CSV): {agree}; failed points: {len(res.failed)}")
