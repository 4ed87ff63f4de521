#!/usr/bin/env python3
"""The disk experiment of the thesis with heating on against the isothermal quick scene.

Runs prm/disk_rolling_heated.prm (the temperature field on: plastic and frictional heating,
contact conductance to the die, thermal strain; one disk revolution in 3 s) and
prm/disk_rolling_quick.prm (the same mesh, steps and adaptivity, isothermal) and prints, for both:
the mean die force |F| over 60-300 degrees of steady rolling (as doc/scenes/disk_rolling.md), the
residual radial displacement of the rim after unloading (trough = smallest, lobe = largest, from
the last profile_NNNN.csv), the largest and the final temperature of the disk, and the CPU time.

Usage: benchmarks/disk_rolling/heating.py AUSROLL WORK [--set ENTRY=VALUE ...] (the --set entries go to the
heated run, e.g. --set "Contact/Die 0/Motion/Rolling/Revolution angle=..." for another speed)
"""

import argparse
import csv
import os
import resource
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(ausroll, prm, directory, extra):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    command = [ausroll, os.path.join(ROOT, "prm", prm), "--overwrite", "--set",
               f"Output/Directory={directory}", "--set", "Output/Verbosity=quiet"]
    for entry in extra:
        command += ["--set", entry]
    result = subprocess.run(command, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit(f"{prm}: ausroll exit {result.returncode}: {result.stdout[-500:]}{result.stderr[-500:]}")
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def answers(directory, cpu):
    rows = list(csv.DictReader(open(os.path.join(directory, "history.csv"))))
    forces = [float(r["die_roll_force_magnitude"]) for r in rows
              if 60.0 <= float(r["die_roll_revolution"]) <= 300.0]
    profiles = sorted(f for f in os.listdir(directory) if f.startswith("profile_") and f.endswith(".csv"))
    last = list(csv.DictReader(open(os.path.join(directory, profiles[-1]))))
    u = [float(r["radial_displacement"]) for r in last]
    result = {"mean |F| 60-300 deg (N/mm)": sum(forces) / len(forces), "trough (mm)": min(u),
              "lobe (mm)": max(u), "CPU (s)": cpu}
    if "T_max" in rows[0]:
        result["T_max during the run (C)"] = max(float(r["T_max"]) for r in rows)
        result["T_mean at the end (C)"] = float(rows[-1]["T_mean"])
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("ausroll")
    parser.add_argument("work")
    parser.add_argument("--set", action="append", default=[], dest="entries")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    hot_dir, iso_dir = os.path.join(args.work, "heated"), os.path.join(args.work, "isothermal")
    hot = answers(hot_dir, run(args.ausroll, "disk_rolling_heated.prm", hot_dir, args.entries))
    # the status passes of the heated scene (it pins the quick scene's settings of before
    # 2026-12-07), so that the two runs differ by the temperature field alone
    iso = answers(iso_dir, run(args.ausroll, "disk_rolling_quick.prm", iso_dir,
                               ["Solver/Status pass tolerance=1e-4",
                                "Solver/Status pass gap tolerance=1e-10"]))
    print("| quantity | heated | isothermal | heated - isothermal |")
    print("|---|---:|---:|---:|")
    for key, value in hot.items():
        other = iso.get(key)
        diff = f"{value - other:+.4g}" if other is not None and key != "CPU (s)" else ""
        print(f"| {key} | {value:.6g} | {other:.6g} | {diff} |" if other is not None
              else f"| {key} | {value:.6g} | | |")


if __name__ == "__main__":
    main()
