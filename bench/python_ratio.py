#!/usr/bin/env python3
"""frictionviz.ratio (the Python module) against `frictionviz sweep` on the same points and threads.

    PYTHONPATH=BUILD/python /usr/bin/python3 bench/python_ratio.py BUILD/app/frictionviz [POINTS] [THREADS]

The points are the sweep's grid (zeta FROM:TO:COUNT x ten angles, rdisp 2, i 1), fed to ratio() as broadcast
arrays (zeta exactly as the sweep's JSON gives it); the sweep writes CSV to /dev/null. The two run alternately,
twice each, and each line gives wall and CPU time: on a shared machine the CPU time is the steadier figure. The
issue's target: ratio within 1.2x of sweep. Ends with whether the numbers are equal bit for bit. A benchmark,
not a test: it prints figures.
"""

import json
import resource
import subprocess
import sys
import time

import numpy as np

import frictionviz as fv

exe = sys.argv[1]
points = int(sys.argv[2]) if len(sys.argv) > 2 else 100000
threads = int(sys.argv[3]) if len(sys.argv) > 3 else 2
thetas = [0, 20, 40, 60, 80, 90, 100, 120, 150, 180]
nz = points // len(thetas)
args = [exe, "sweep", "--zeta", f"0.01:3:{nz}", "--theta", ",".join(map(str, thetas)), "--rdisp", "2", "--i",
        "1", "--threads", str(threads)]
rows = json.loads(subprocess.run(args + ["--format", "json"], capture_output=True, text=True).stdout)
zeta = np.array([r["zeta"] for r in rows[:nz]])  # zeta fastest, then theta: the first nz rows span zeta
theta = np.array(thetas, dtype=float)[:, None]


def children_cpu():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


print(f"points {nz * len(thetas)}, threads {threads}")
for rep in range(2):
    c0, t0 = children_cpu(), time.perf_counter()
    subprocess.run(args + ["--out", "/dev/null"], stderr=subprocess.DEVNULL)
    t_cli, cpu_cli = time.perf_counter() - t0, children_cpu() - c0
    p0, t0 = time.process_time(), time.perf_counter()
    res = fv.ratio(zeta, theta, 2.0, 1.0, threads=threads)
    t_py, cpu_py = time.perf_counter() - t0, time.process_time() - p0
    print(f"sweep {t_cli:7.2f} s wall {cpu_cli:7.2f} s cpu | ratio {t_py:7.2f} s wall {cpu_py:7.2f} s cpu | "
          f"ratio/sweep wall {t_py / t_cli:.3f}, cpu {cpu_py / cpu_cli:.3f}   (target <= 1.2)")
want = np.array([np.nan if r["r_x"] is None else r["r_x"] for r in rows]).reshape(len(thetas), nz)
same = np.array_equal(res.r_x, want, equal_nan=True) and res.status.ravel().tolist() == [r["status"] for r in rows]
print(f"r_x and status equal to the sweep's bit for bit: {same}; failed points: {len(res.failed)}")
