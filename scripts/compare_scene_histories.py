#!/usr/bin/env python3
"""Run scenes with two ausroll executables and compare their history.csv (refactoring check).

  scripts/compare_scene_histories.py --before OLD/ausroll [--after NEW/ausroll] \
      --work /tmp/compare [--rtol 1e-10] [--reuse-before] SCENE.prm ...

Each SCENE.prm runs in WORK/before/<name>/ and WORK/after/<name>/ (one run at a time, under
`nice`, 8 GB address-space limit, 900 s timeout); the first history.csv found under each run
directory is compared with tests/checks/compare_histories.py (every column except wall_seconds,
each difference relative to the column's largest value). With --reuse-before the runs of the
old executable already in WORK/before are kept (run the old build once, compare many times).
Prints one line per scene (rows, max relative difference, CPU seconds of both runs) and exits
1 if any scene differs by more than --rtol or fails to run.
"""

import argparse
import os
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "..", "tests", "checks", "compare_histories.py")


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (8_000_000 * 1024, 8_000_000 * 1024))
    os.nice(10)


def run(exe, prm, directory):
    """Run exe prm in directory; return (status, CPU seconds of the child)."""
    os.makedirs(directory, exist_ok=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(directory, "log.txt"), "w") as log:
        try:
            status = subprocess.run([exe, os.path.abspath(prm)], cwd=directory, stdout=log,
                                    stderr=subprocess.STDOUT, timeout=900,
                                    preexec_fn=limit_memory).returncode
        except subprocess.TimeoutExpired:
            status = "timeout"
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return status, cpu


def find_history(directory):
    for root, _, files in sorted(os.walk(directory)):
        if "history.csv" in files:
            return os.path.join(root, "history.csv")
    return None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--before", required=True, help="ausroll executable before the change")
    p.add_argument("--after", help="ausroll executable after the change (omitted: only run "
                   "--before, to be reused with --reuse-before later)")
    p.add_argument("--work", required=True, help="directory for the runs")
    p.add_argument("--rtol", type=float, default=1e-10)
    p.add_argument("--reuse-before", action="store_true")
    p.add_argument("scenes", nargs="+")
    a = p.parse_args()

    failed = 0
    print(f"{'scene':40s} {'result':8s} {'max rel diff':>12s} {'cpu before':>10s} {'cpu after':>10s}")
    for prm in a.scenes:
        name = os.path.splitext(os.path.basename(prm))[0]
        dirs = {k: os.path.join(a.work, k, name) for k in ("before", "after")}
        cpu = {"before": float("nan"), "after": float("nan")}
        ok = True
        for key, exe in (("before", a.before), ("after", a.after)):
            if exe is None or (key == "before" and a.reuse_before and find_history(dirs[key])):
                continue
            status, cpu[key] = run(exe, prm, dirs[key])
            if status != 0:
                print(f"{name:40s} {key} run failed (exit {status}), see {dirs[key]}/log.txt")
                ok = False
        if not ok:
            failed += 1
            continue
        if a.after is None:
            print(f"{name:40s} {'ran':8s} {'':>12s} {cpu['before']:10.1f}")
            continue
        ha, hb = find_history(dirs["before"]), find_history(dirs["after"])
        if ha is None or hb is None:
            print(f"{name:40s} no history.csv")
            failed += 1
            continue
        out = subprocess.run([sys.executable, COMPARE, ha, hb, "--rel-tol", str(a.rtol)],
                             capture_output=True, text=True)
        text = out.stdout.strip().splitlines()
        diff = "?"
        for line in text:
            if "max relative difference" in line:
                diff = line.split("max relative difference")[1].split(";")[0].split()[0]
        result = "equal" if out.returncode == 0 else "DIFFER"
        failed += out.returncode != 0
        print(f"{name:40s} {result:8s} {diff:>12s} {cpu['before']:10.1f} {cpu['after']:10.1f}")
        if out.returncode != 0:
            print("    " + " | ".join(text))
        sys.stdout.flush()
    print("all scenes equal" if not failed else f"{failed} scene(s) differ or failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
