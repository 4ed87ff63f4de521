#!/usr/bin/env python3
"""A full disk while writing a checkpoint or a VTU file ends the run with a message naming the
step and the file (exit 3); the previous checkpoint, history.csv and the solution.pvd written so
far stay intact, and a resume without the limit finishes.

Usage: check_full_disk.py AUSROLL SOURCE_DIR

A full disk is imitated by the process's file-size limit (RLIMIT_FSIZE, `ulimit -f`) with SIGXFSZ
ignored: a write past the limit is cut short or fails with EFBIG, as a write to a full file system
is cut short or fails with ENOSPC. Both reach ausroll the same way (a short write or an error
from the system call), so the handling of one is the handling of the other. (PMIx is told to keep
its data in memory, PMIX_MCA_gds=hash: its shared-memory store is a file that the limit would
refuse during MPI_Init.)

Scene: tests/checks/scenes/block_slide.prm with 3 global refinements (512 cells, 1.6 MB
checkpoint data), a checkpoint every 2 steps, stopped after step 5 (Checkpoint/Abort after step):
its checkpoint holds step 4. Cases, each on a copy of that output directory:
 1. a limit below the checkpoint's estimated size: refused before p4est writes (p4est would abort
    the process), naming the file-size limit;
 2. a limit between the estimate (a lower bound) and the real size of the data file: deal.II
    writes a short file without an error; the check after writing finds it incomplete;
 3. after either, a resume without the limit continues from the step-4 checkpoint and gives the
    same history as the uninterrupted run (to the last digit);
 4. VTU output (4 global refinements, two steps) with a limit between the sizes of the first and the second solution file: the run
    stops at the second, naming it; solution.pvd lists only the complete first file.
About 6 s.
"""

import os
import resource
import shutil
import signal
import subprocess
import sys
import xml.etree.ElementTree as ET


def run(ausroll, prm, cwd, args, limit=None):
    env = dict(os.environ, PMIX_MCA_gds="hash")

    def restrict():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    return subprocess.run([ausroll, prm] + args, cwd=cwd, capture_output=True, text=True,
                          errors="replace", timeout=300, env=env,
                          preexec_fn=restrict if limit is not None else None)


def rows_without_wall_time(text):
    """The rows of a history.csv without its wall_seconds column (the only one that differs
    between runs)."""
    lines = text.splitlines()
    drop = lines[0].split(",").index("wall_seconds")
    return [",".join(c for i, c in enumerate(l.split(",")) if i != drop) for l in lines]


def same_file(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    here = os.getcwd()
    prm = os.path.join(here, "scene.prm")
    with open(prm, "w", encoding="utf-8") as f:
        f.write(f"include {source}/tests/checks/scenes/block_slide.prm\n"
                "subsection Geometry\n  set Global refinements = 3\nend\n"
                "subsection Checkpoint\n  set Interval = 2\nend\n")
    failures = []

    def check(name, condition, detail=""):
        print(("ok   " if condition else "FAIL ") + name + (f": {detail}" if detail else ""))
        if not condition:
            failures.append(name)

    # the uninterrupted run, and the interrupted one whose step-4 checkpoint the cases resume
    full = os.path.join(here, "full")
    base = os.path.join(here, "base")
    for d in (full, base):
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
    r = run(ausroll, prm, full, [])
    check("uninterrupted run", r.returncode == 0, r.stderr.strip())
    r = run(ausroll, prm, base, ["--set", "Checkpoint/Abort after step=5"])
    check("interrupted run stops after step 5", r.returncode == 99, r.stderr.strip())
    data = os.path.join(base, "out", "checkpoint", "mesh_fixed.data")
    size = os.path.getsize(data)
    with open(os.path.join(full, "out", "history.csv"), encoding="utf-8") as f:
        full_history = f.read()

    # (name, file-size limit, message fragment)
    cases = [
        ("limit below the checkpoint's size", size // 2,
         "step 6: cannot write a checkpoint into 'out': its largest file needs about"),
        ("limit between the estimate and the written size", size - 1000,
         "step 6: the checkpoint file 'out/checkpoint.new/mesh_fixed.data' was written "
         "incompletely"),
    ]
    for name, limit, expect in cases:
        work = os.path.join(here, "case")
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(base, work)
        out = os.path.join(work, "out")
        r = run(ausroll, prm, work, ["--resume"], limit)
        check(f"{name}: exit 3", r.returncode == 3, f"exit {r.returncode}")
        check(f"{name}: message", expect in r.stderr and "previous checkpoint is kept" in r.stderr,
              r.stderr.strip())
        check(f"{name}: no crash", "internal error" not in r.stderr and r.returncode >= 0)
        check(f"{name}: the step-4 checkpoint is unchanged",
              same_file(os.path.join(out, "checkpoint", "mesh_fixed.data"), data)
              and not os.path.exists(os.path.join(out, "checkpoint.new")))
        with open(os.path.join(out, "history.csv"), encoding="utf-8") as f:
            rows = rows_without_wall_time(f.read())
        check(f"{name}: history.csv keeps steps 0-6",
              rows == rows_without_wall_time(full_history)[:len(rows)] and rows[-1].startswith("6,"),
              rows[-1][:40])
        r = run(ausroll, prm, work, ["--resume"])
        with open(os.path.join(out, "history.csv"), encoding="utf-8") as f:
            history = f.read()
        check(f"{name}: a resume without the limit finishes with the uninterrupted history",
              r.returncode == 0
              and rows_without_wall_time(history) == rows_without_wall_time(full_history),
              r.stderr.strip())

    # VTU: sizes from a run without the limit, then a limit between the first and second file
    vtu = os.path.join(here, "vtu")
    shutil.rmtree(vtu, ignore_errors=True)
    os.makedirs(vtu)
    args = ["--set", "Output/Write VTU=true", "--set", "Checkpoint/Interval=0",
            "--set", "Geometry/Global refinements=4", "--set", "Loading/End time=0.5",
            "--set", "Loading/Number of steps=2"]
    r = run(ausroll, prm, vtu, args)
    out = os.path.join(vtu, "out")
    first, second = (os.path.getsize(os.path.join(out, f"solution_000{i}.0.vtu")) for i in (0, 1))
    others = max(os.path.getsize(os.path.join(out, n)) for n in os.listdir(out)
                 if not n.startswith("solution_") and os.path.isfile(os.path.join(out, n)))
    lower = max(first, others)
    check("VTU sizes allow the case", r.returncode == 0 and second > lower + 100,
          f"first {first}, second {second}, other files up to {others}")
    shutil.rmtree(vtu)
    os.makedirs(vtu)
    r = run(ausroll, prm, vtu, args, (lower + second) // 2)
    check("VTU: exit 3 naming the file", r.returncode == 3 and
          "cannot write the solution files 'out/solution_0001*.vtu'" in r.stderr, r.stderr.strip())
    pvd = ET.parse(os.path.join(out, "solution.pvd")).getroot()
    files = [d.get("file") for d in pvd.iter("DataSet")]
    check("VTU: solution.pvd lists the complete first file only", files == ["solution_0000.pvtu"],
          str(files))
    with open(os.path.join(out, "history.csv"), encoding="utf-8") as f:
        rows = f.read().splitlines()
    check("VTU: history.csv keeps the rows of steps 0 and 1", len(rows) == 3
          and rows[2].startswith("1,"), f"{len(rows)} lines")

    for d in ("case", "vtu", "full", "base"):
        shutil.rmtree(os.path.join(here, d), ignore_errors=True)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
