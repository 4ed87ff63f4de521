#!/usr/bin/env python3
"""The finished flank of prm/gear_ausrolling_finished.prm beside the rolled one.

Usage: /usr/bin/python3 benchmarks/gear_ausrolling/finished_flank.py OUTPUT_DIR [--scale 0.9973324]
           [--rolled-time 0.12] [--plot FILE.png]

Reads a run of the chain (VTU with `Output/Write VTU = true`; a VTU is written at each stage's end)
and prints key=value words and a table:
  rolled    the flank at the end of the rolling stage (t = --rolled-time, the tooth at the bath
            temperature) against the design involute, as scripts/gear_flank_analysis.py measures it;
  finished  the flank of the last output (20 C, transformed) against the involute scaled by
            --scale, the free strain of the gear body from the bath to 20 C (the uniform size
            change a die design allows for; prm/gear_ausrolling_finished.prm gives 0.9973324);
each with d_n min/max and the ISO 1328-1 F_alpha, f_f_alpha, f_H_alpha (um) over the evaluation
range of gear_flank_analysis.py; and, from the depth probes (depth_<name>_NNNN.csv, the columns of
io::LineProbes with temperature, martensite, bainite and carbon), the hoop stress stress_tt and the
phases at 0, 0.05, 0.2 and 0.5 mm below the pitch point and the root of the rolled flank (probes
pitch_right, root_right) for both states. --plot draws the depth profiles (stress_tt, martensite,
carbon) of both states.
"""

import argparse
import csv
import glob
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import gear_flank_analysis as gfa  # noqa: E402
from convergence_study import interpolate  # noqa: E402


def iso_at(args, scale, time):
    """d_n range and ISO 1328 quantities (mm) of the output step closest to time (None: last)."""
    args.scale = scale
    results, rp = gfa.analyse(args)
    steps = sorted({(r[0], r[1]) for r in results})
    step = steps[-1][0] if time is None else min(steps, key=lambda s: abs(s[1] - time))[0]
    rows = [r for r in results if r[0] == step]
    rb, rt = gfa.gear_data(args)[1:3]
    r0, r1 = gfa.evaluation_range(rows, rb, rt, args)
    values = gfa.iso1328(rows, rb, r0, r1)[step]
    iso = gfa.iso_summary(values, rb, r0, r1)
    iso["time"] = rows[0][1]
    iso["d_n_min"] = min(r[4] for r in rows)
    iso["d_n_max"] = max(r[4] for r in rows)
    return iso


def depth_profile(directory, name, time):
    """Rows of the depth probe file written closest to time (None: the last)."""
    files = sorted(glob.glob(os.path.join(directory, f"depth_{name}_*.csv")))
    if not files:
        return None
    tables = []
    for f in files:
        rows = list(csv.DictReader(open(f)))
        if rows:
            tables.append((float(rows[0]["time"]), rows))
    if time is None:
        return tables[-1][1]
    return min(tables, key=lambda t: abs(t[0] - time))[1]


def at_depth(rows, column, s):
    return interpolate([float(r["s"]) for r in rows], [float(r[column]) for r in rows], s)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("--rolled-time", type=float, default=0.12)
    p.add_argument("--plot")
    gfa.add_gear_options(p)
    args = p.parse_args()
    scale = args.scale if args.scale != 1.0 else 0.9973324
    rolled = iso_at(args, 1.0, args.rolled_time)
    finished = iso_at(args, scale, None)
    words = {}
    print(f"evaluation range L_alpha: R {finished['L_alpha_R0']:.3f} ... {finished['L_alpha_R1']:.3f} mm")
    print("| state | t (s) | d_n (um) | F_alpha (um) | f_f_alpha (um) | f_H_alpha (um) |")
    print("|---|---:|---|---:|---:|---:|")
    for label, iso in (("rolled", rolled), ("finished", finished)):
        print(f"| {label} | {iso['time']:.4g} | {1e3 * iso['d_n_min']:.2f} ... {1e3 * iso['d_n_max']:.2f} | "
              f"{1e3 * iso['F_alpha']:.2f} | {1e3 * iso['f_f_alpha']:.2f} | {1e3 * iso['f_H_alpha']:.2f} |")
        for key in ("d_n_min", "d_n_max", "F_alpha", "f_f_alpha", "f_H_alpha"):
            words[f"{label}_{key}"] = iso[key]
    print("| probe | state | depth (mm) | stress_tt (MPa) | martensite | carbon (wt%) |")
    print("|---|---|---:|---:|---:|---:|")
    profiles = {}
    for probe in ("pitch_right", "root_right"):
        for label, time in (("rolled", args.rolled_time), ("finished", None)):
            rows = depth_profile(args.directory, probe, time)
            if rows is None:
                continue
            profiles[(probe, label)] = rows
            for s in (0.0, 0.05, 0.2, 0.5):
                stt = at_depth(rows, "stress_tt", s)
                fm = at_depth(rows, "martensite", s) if "martensite" in rows[0] else float("nan")
                c = at_depth(rows, "carbon", s) if "carbon" in rows[0] else float("nan")
                print(f"| {probe} | {label} | {s:g} | {stt:.1f} | {fm:.3f} | {c:.3f} |")
                words[f"{label}_{probe}_stress_tt_{s:g}"] = stt
                words[f"{label}_{probe}_martensite_{s:g}"] = fm
    print(" ".join(f"{k}={v:.8g}" for k, v in words.items()))
    if args.plot and profiles:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        for (probe, label), rows in profiles.items():
            s = [float(r["s"]) for r in rows]
            style = "-" if label == "finished" else "--"
            name = f"{probe.split('_')[0]}, {label}"
            axes[0].plot(s, [float(r["stress_tt"]) for r in rows], style, label=name)
            if "martensite" in rows[0]:
                axes[1].plot(s, [float(r["martensite"]) for r in rows], style, label=name)
                axes[2].plot(s, [float(r["carbon"]) for r in rows], style, label=name)
        axes[0].set_ylabel("hoop stress stress_tt (MPa)")
        axes[1].set_ylabel("martensite fraction")
        axes[2].set_ylabel("carbon (wt%)")
        for a in axes:
            a.set_xlabel("depth below the initial flank (mm)")
            a.grid(True, alpha=0.3)
        axes[0].legend(fontsize=8)
        fig.suptitle("gear ausrolling: rolled (t = 0.12 s, 250 C) and finished (20 C) depth profiles")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=90)
        print(f"figure: {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
