#!/usr/bin/env python3
"""Helpers shared by the timing and convergence studies in benchmarks/: run a variant of a shipped
.prm (optionally under mpirun), measure wall and CPU time of the child process, and parse the
history and the verbose Newton log (linear solve time and Krylov iterations per call).

Not a script: imported by benchmarks/solver_study/solver_study.py,
benchmarks/thick_cylinder/convergence.py and benchmarks/parallel/parallel_timing.py.
"""

import csv
import os
import re
import resource
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "studies"))
from study import interpolate, pyplot  # noqa: E402,F401  (re-exported for the studies)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# one thread per process: the timings compare algorithms, not thread pools
SERIAL_ENV = dict(os.environ, DEAL_II_NUM_THREADS="1", OMP_NUM_THREADS="1",
                  OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                  OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1",
                  OMPI_MCA_mpi_yield_when_idle="1")
# a single rank without the yield: the singleton still calls sched_yield() in its MPI progress
# loop, and on a loaded machine every yield gives the rest of the time slice away (the 3D disk
# level-0 run of benchmarks/convergence/convergence.sh, 2 steps, 2026-12-07, load 14 on 2 cores:
# 1.0 s CPU in 46 s wall with the yield, 0.9 s CPU in 6.8 s wall without)
ONE_RANK_ENV = {k: v for k, v in SERIAL_ENV.items() if k != "OMPI_MCA_mpi_yield_when_idle"}

LINEAR_LINE = re.compile(r"linear solve: (\d+) iterations, ([0-9.]+) s wall, ([0-9.]+) s CPU")


class Run:
    """Result of one ausroll run: history rows, times, per-solve records, exit status."""

    def __init__(self, name, rows, wall, cpu, solves, returncode, log):
        self.name = name
        self.rows = rows              # history.csv rows (dicts of strings), step 0 included
        self.wall = wall              # wall time of the whole process (s)
        self.cpu = cpu                # user + system CPU time of the process and its children (s)
        self.solves = solves          # [(krylov iterations, wall s, CPU s)] per linear solve
        self.returncode = returncode
        self.log = log

    @property
    def ok(self):
        return self.returncode == 0 and len(self.rows) > 1

    def column(self, name):
        return [float(r[name]) for r in self.rows]


def run_variant(ausroll, base_prm, work, name, overrides, np=1, reuse=False, timeout=None):
    """Run base_prm with @p overrides ("Section/Entry = value", given to ausroll as --set) with
    its output in work/name (the command and the verbose log in work/name/run.log) and return a
    Run."""
    out = os.path.join(work, name)
    os.makedirs(out, exist_ok=True)
    log_path = os.path.join(out, "run.log")
    history = os.path.join(out, "history.csv")
    meta = os.path.join(out, "times.txt")
    if reuse and os.path.exists(meta) and os.path.exists(history):
        wall, cpu, rc = open(meta).read().split()
        log = open(log_path).read()
        return Run(name, read_history(history), float(wall), float(cpu), parse_solves(log),
                   int(rc), log)
    # the overrides go on the command line (ausroll --set, checked like the file)
    command = [ausroll, base_prm, "--overwrite"]
    for o in [f"Output/Directory = {out}", "Output/Write VTU = false",
              "Output/Verbosity = verbose"] + overrides:
        command += ["--set", o]
    if np > 1:
        command = ["mpirun", "-np", str(np)] + command
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    try:
        result = subprocess.run(command, capture_output=True, text=True,
                                env=SERIAL_ENV if np > 1 else ONE_RANK_ENV,
                                timeout=timeout)
        rc, log = result.returncode, result.stdout + result.stderr
    except subprocess.TimeoutExpired as e:
        rc, log = -9, (e.stdout or b"").decode(errors="replace") + "\n(timeout)\n"
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(log_path, "w") as f:
        f.write(" ".join(f"'{c}'" if " " in c else c for c in command) + "\n" + log)
    with open(meta, "w") as f:
        f.write(f"{wall} {cpu} {rc}\n")
    return Run(name, read_history(history) if rc != -9 else [], wall, cpu, parse_solves(log), rc,
               log)


def read_history(path):
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def parse_solves(log):
    return [(int(m.group(1)), float(m.group(2)), float(m.group(3)))
            for m in LINEAR_LINE.finditer(log)]


def write_csv(path, keys, records):
    """Write the dicts @p records as CSV with columns @p keys (other entries ignored)."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for rec in records:
            w.writerow(rec)
    print(f"CSV: {path}")


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---:" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)
