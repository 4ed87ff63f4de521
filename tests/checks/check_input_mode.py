#!/usr/bin/env python3
"""`ausroll FILE.prm --check-input` builds and checks a scene, prints its sizes and writes nothing.

Usage: check_input_mode.py AUSROLL SOURCE_DIR

prm/disk_rolling_quick.prm (2D) and prm/upsetting_3d.prm (3D) must exit 0, print the size lines
(cells, DoFs, quadrature points, estimated memory, load steps) with the cell count of the
mesh, the measured cost of one Newton iteration (a positive CPU time) and the estimated time per
step as a range (low < high; how good the range is, is a benchmark, not this test), and leave the working directory as it was (no output directory); the same scene with a
refused entry (Model/Quadrature points = 1 with Q2) must exit 2 with the entry named, again
writing nothing.
"""

import os
import re
import shutil
import subprocess
import sys


def run(ausroll, work, *args):
    before = sorted(os.listdir(work))
    result = subprocess.run([ausroll] + list(args), cwd=work, capture_output=True, text=True,
                            errors="replace", timeout=300)
    created = sorted(set(os.listdir(work)) - set(before))
    return result, created


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    work = os.path.join(os.getcwd(), "work")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = 0
    for scene in ("disk_rolling_quick.prm", "upsetting_3d.prm"):
        prm = os.path.join(source, "prm", scene)
        result, created = run(ausroll, work, prm, "--check-input")
        text = result.stdout
        problems = []
        if result.returncode != 0:
            problems.append(f"exit {result.returncode}")
        for label in ("cells:", "DoFs:", "quadrature points:", "estimated memory:",
                      "load steps:"):
            if label not in text:
                problems.append(f"no '{label}' line")
        iteration = re.search(r"one Newton iteration:\s+([0-9.e+-]+) s CPU", text)
        if not iteration or not float(iteration.group(1)) > 0:
            problems.append("no measured Newton iteration")
        per_step = re.search(r"time per step:\s+([0-9.e+-]+) to ([0-9.e+-]+) s CPU", text)
        if not per_step or not 0 < float(per_step.group(1)) < float(per_step.group(2)):
            problems.append("no time per step range")
        cells = re.search(r"cells:\s+([0-9.e+]+)", text)
        if not cells or float(cells.group(1)) < 1:
            problems.append("no cell count")
        if created:
            problems.append("created " + ", ".join(created))
        if problems:
            failures += 1
            print(f"FAIL {scene}: {'; '.join(problems)}\n{text}\n{result.stderr}")
        else:
            print(f"ok   {scene}: exit 0, nothing written\n{text}")
    prm = os.path.join(source, "prm", "upsetting_3d.prm")
    result, created = run(ausroll, work, prm, "--check-input", "--set",
                          "Model/Polynomial degree=2", "--set", "Model/Quadrature points=1")
    if result.returncode != 2 or "Model/Quadrature points" not in result.stderr or created:
        failures += 1
        print(f"FAIL refused entry: exit {result.returncode}, created {created}\n{result.stderr}")
    else:
        print(f"ok   refused entry: exit 2, {result.stderr.strip()[:200]}")
    shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
