#!/usr/bin/env python3
"""Temperatures and answers of prm/gear_ausrolling.prm against the rolling speed.

Usage: benchmarks/gear_ausrolling/speed_sweep.py AUSROLL WORK [--mesh uniform|shipped]
                                                 [--factors 0.25 0.5 1 2 4]

Runs the scene with its time line compressed by each FACTOR (1: the shipped 23.3 rpm of the gear,
14 deg of rolling in 0.1 s; 2: twice as fast), once with the heat sources and the die and oil
exchange on and once with them off (Contact conductance, Taylor-Quinney coefficient, Friction
heat partition, Thermal expansion and the oil convection set to zero: the isothermal answer at
the bath temperature), and prints per factor: the coolest and hottest temperature of the run,
the largest plastic heating, the peak die force and the residual flank deviation d_n_min
(scripts/gear_flank_analysis.py) of both, with CPU seconds. --mesh uniform (default) runs the
twice-refined uniform tooth with 60 steps (seconds per run; d_n about 1 um off the resolved
value, doc/scenes/gear_rolling.md); shipped runs the adaptive scene as shipped (minutes).
"""

import argparse
import csv
import os
import resource
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def run(ausroll, settings, directory):
    command = [ausroll, os.path.join(ROOT, "prm", "gear_ausrolling.prm"), "--overwrite",
               "--set", f"Output/Directory={directory}", "--set", "Output/Verbosity=quiet"]
    for s in settings:
        command += ["--set", s]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    result = subprocess.run(command, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{result.stderr[-2000:]}")
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    with open(os.path.join(directory, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    flank = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "gear_flank_analysis.py"),
                            directory], capture_output=True, text=True).stdout
    d_n = float([w for w in flank.split() if w.startswith("d_n_min=")][-1].split("=")[1])
    return {"T_min": min(float(r["T_min"]) for r in rows), "T_max": max(float(r["T_max"]) for r in rows),
            "heat": max(float(r["heat_plastic"]) for r in rows),
            "F_peak": max(float(r["die_die_force_magnitude"]) for r in rows), "d_n": d_n * 1000.0,
            "cpu": cpu}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("ausroll")
    p.add_argument("work")
    p.add_argument("--mesh", choices=["uniform", "shipped"], default="uniform")
    p.add_argument("--factors", type=float, nargs="+", default=[0.25, 0.5, 1.0, 2.0, 4.0])
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    mesh = [] if a.mesh == "shipped" else [
        "Adaptivity/Initial refinement cycles=0", "Adaptivity/Interval=0", "Loading/Number of steps=60"]
    off = ["Thermal/Contact conductance=0", "Thermal/Taylor-Quinney coefficient=0",
           "Thermal/Friction heat partition=0", "Thermal/Thermal expansion=0",
           "Thermal/Condition 0/Heat transfer coefficient=1e-12"]
    print("factor  rpm    T_min   T_max  heat_max   F_peak(hot/iso)    d_n_min um (hot/iso)  CPU s")
    for s in a.factors:
        d = 0.01 / s   # feed and withdrawal time
        r = 0.1 / s    # rolling time
        timing = [f"Contact/Die 0/Motion/Rolling/Revolution angle=-8 + 14 * min(max(t - {d}, 0) / {r}, 1)",
                  f"Contact/Die 0/Motion/Rolling/Feed=0.1 * min(min(t / {d}, 1), max(({2 * d + r} - t) / {d}, 0))",
                  f"Loading/End time={2 * d + r}"]
        hot = run(a.ausroll, mesh + timing, os.path.join(a.work, f"hot_{s}"))
        iso = run(a.ausroll, mesh + timing + off, os.path.join(a.work, f"iso_{s}"))
        rpm = 14.0 / 360.0 / r * 60.0
        print(f"{s:6.2f} {rpm:5.1f} {hot['T_min']:8.2f} {hot['T_max']:7.2f} {hot['heat']:9.1f} "
              f"{hot['F_peak']:8.2f}/{iso['F_peak']:8.2f}  {hot['d_n']:8.3f}/{iso['d_n']:8.3f}  "
              f"{hot['cpu']:6.1f}/{iso['cpu']:6.1f}", flush=True)


if __name__ == "__main__":
    main()
