"""Shared helpers of the work-precision and contact-strategy studies: run a variant of a shipped
scene, time it (user CPU time of the child and wall time), and read its results.

A variant is prm/<base>.prm with entries overridden by scripts/prm_variant.py; it runs in
WORK/<name>/ with VTU output off. CPU time is the user time of the ausroll process
(resource.getrusage of the children), which, unlike wall time, is not inflated when other jobs share
the cores.
"""

import csv
import glob
import math
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "checks"))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "studies"))
import check_hertz  # noqa: E402  (fit of the contact pressure to the Hertz ellipse)
from study import pyplot  # noqa: E402,F401  (matplotlib with the Agg backend, or None)


class Run:
    """Result of one variant: history rows, user CPU and wall seconds, output directory."""

    def __init__(self, rows, cpu, wall, out, ok):
        self.rows, self.cpu, self.wall, self.out, self.ok = rows, cpu, wall, out, ok

    def total(self, column):
        return sum(float(r[column]) for r in self.rows)

    def last(self, column):
        return float(self.rows[-1][column])

    def steps(self):
        """Load steps (sub-steps of the load increment ratio included; row 0 is the initial state)."""
        return len(self.rows) - 1


def run_variant(ausroll, work, base, name, overrides, reuse=False, timeout=None):
    """Run prm/<base>.prm with @p overrides ("Section/Entry = value") in work/name; a run that
    takes longer than @p timeout seconds is stopped (ok = False, the history so far is kept)."""
    out = os.path.join(work, name)
    os.makedirs(out, exist_ok=True)
    prm = os.path.join(work, name + ".prm")
    timing = os.path.join(out, "timing.txt")
    history = os.path.join(out, "history.csv")
    if reuse and os.path.exists(timing) and os.path.exists(history):
        cpu, wall, ok = open(timing).read().split()
        return Run(list(csv.DictReader(open(history))), float(cpu), float(wall), out, ok == "1")
    for f in glob.glob(os.path.join(out, "contact_*.csv")):
        os.remove(f)
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "prm_variant.py"),
                    os.path.join(ROOT, "prm", base + ".prm"), prm, f"Output/Directory = {out}",
                    "Output/Write VTU = false", "Output/Verbosity = quiet"] + overrides, check=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    start = time.time()
    try:
        result = subprocess.run([ausroll, prm, "--overwrite"], capture_output=True, text=True, timeout=timeout)
        log_text, ok = result.stdout + result.stderr, result.returncode == 0
        if not ok:
            print(f"  {name}: ausroll exit {result.returncode}: {result.stderr.strip()[-300:]}")
    except subprocess.TimeoutExpired:
        log_text, ok = f"stopped after {timeout} s\n", False
        print(f"  {name}: stopped after {timeout} s")
    wall = time.time() - start
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    with open(os.path.join(out, "run.log"), "w") as log:
        log.write(log_text)
    rows = list(csv.DictReader(open(history))) if os.path.exists(history) else []
    with open(timing, "w") as f:
        f.write(f"{cpu} {wall} {int(ok)}\n")
    return Run(rows, cpu, wall, out, ok)


def contact_files(out):
    """(time, lines) of every contact_NNNN.csv in @p out, in output order."""
    result = []
    for f in sorted(glob.glob(os.path.join(out, "contact_*.csv"))):
        lines = open(f).read().splitlines()
        result.append((float(lines[0].split("=")[1].split(";")[0]), lines))
    return result


def hertz_errors(lines, P, radius, E, nu, coordinate):
    """Relative errors (a, p0) of the Hertz fit of one contact CSV against the load P, plus the
    fit (p0, a) and reference (a_ref, p0_ref); errors are nan if the pressure is not elliptic."""
    rows = check_hertz.closed_nodes(lines)
    a_ref, p0_ref = check_hertz.hertz(P, radius, E, nu)
    fit = check_hertz.fit_ellipse(rows, coordinate) if len(rows) >= 2 else None
    if fit is None:
        return math.nan, math.nan, None, (a_ref, p0_ref)
    p0, a = fit
    return a / a_ref - 1, p0 / p0_ref - 1, (p0, a), (a_ref, p0_ref)
