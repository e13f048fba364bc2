#!/usr/bin/env python3
"""Rewrites the output under every "$ frictionviz ..." example of README.md with what the built program prints
(build/app/frictionviz). Run it on purpose after a change of output, review the diff, commit; the CTest
readme_examples checks that README and program agree."""
import pathlib
import subprocess
import sys

root = pathlib.Path(__file__).resolve().parent.parent
exe = sys.argv[1] if len(sys.argv) > 1 else str(root / "build/app/frictionviz")
readme = root / "README.md"
lines = readme.read_text().split("\n")
out, i = [], 0
while i < len(lines):
    line = lines[i]
    out.append(line)
    i += 1
    if line.startswith("$ frictionviz "):
        run = subprocess.run([exe] + line[len("$ frictionviz "):].split(), capture_output=True, text=True)
        out += run.stdout.rstrip("\n").split("\n")
        while not lines[i].startswith("```"):
            i += 1
readme.write_text("\n".join(out))
