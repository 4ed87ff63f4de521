#!/usr/bin/env python3
"""Work-precision study: error against cost for uniform, a-priori graded and adaptive meshes.

Scenes and errors (all against independent references):
  thick_cylinder  prm/thick_cylinder.prm to p = 180 MPa (10 steps): error of the outer radial
                  displacement u(b) against the 1D solution tests/checks/reference/
                  thick_cylinder_load.csv.
  hertz           prm/hertz.prm (5 load steps to P = 8896 N/mm): errors of the contact half-width a
                  and the peak pressure p0 (fit of the nodal pressures to the ellipse) at the last
                  load against plane-strain Hertz.
  indentation     prm/indentation_elastic.prm (frictionless elastic punch, 4 steps): a and p0 at
                  the last step against Hertz for the measured punch force.
Mesh sequences:
  uniform   no local refinement, Geometry/Global refinements = 0, 1, 2, ...
  graded    a-priori local refinement towards the first contact point (Geometry/Local
            refinements = k; the shipped scenes use this), contact scenes only
  adaptive  coarse start, Adaptivity subsection: contact band + Kelly (contact scenes; initial
            cycles before the first step, then after every step) or plastic strain + Kelly (thick
            cylinder, after every step), Adaptivity/Maximum level = L.
Cost is the user CPU time of the ausroll process (one MPI rank, one thread; wall time is recorded
too but is unreliable on a shared machine).

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/work_precision/work_precision.py [scene ...]
        [--ausroll build/ausroll] [--work /tmp/work_precision] [--data doc/data]
        [--figures doc/figures] [--reuse] [--quick]
Writes DATA/work_precision_<scene>.csv and FIGURES/work_precision_<scene>.png (error against CPU
time, log-log) and prints, for the Hertz scene, the CPU time each sequence needs for a 1 % error
in p0 (interpolated in the log-log plot; extrapolated from the last two meshes when the sequence
does not get there, marked as such). --quick runs the two cheapest meshes of each sequence (ctest).
"""

import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import runner  # noqa: E402

E, NU = 210000.0, 0.3


def thick_cylinder_error(run, ref):
    """|u(b)(p = 180) / u_ref - 1| at the last row (t = 1)."""
    p = run.last("pressure_0")
    xs, ys = ref
    for i in range(1, len(xs)):
        if xs[i] >= p:
            u_ref = ys[i - 1] + (ys[i] - ys[i - 1]) * (p - xs[i - 1]) / (xs[i] - xs[i - 1])
            return {"error_u": run.last("outer_ux") / u_ref - 1}
    raise SystemExit("pressure beyond the reference")


def contact_error(run, radius, load_of_run, coordinate):
    """Errors of a and p0 at the last contact CSV of @p run."""
    files = runner.contact_files(run.out)
    if not files:
        return {"error_a": math.nan, "error_p0": math.nan}
    t, lines = files[-1]
    ea, ep, _, _ = runner.hertz_errors(lines, load_of_run(run, t), radius, E, NU, coordinate)
    return {"error_a": ea, "error_p0": ep}


def hertz_load(run, t):
    return 1779.2 * t


def punch_load(run, t):
    row = min(run.rows, key=lambda r: abs(float(r["time"]) - t))
    return -2 * float(row["die_punch_force_y"])


def scenes():
    """name -> (base prm, common overrides, {sequence: [(label, overrides)]}, error function)."""
    ref_path = os.path.join(runner.ROOT, "tests", "checks", "reference", "thick_cylinder_load.csv")
    ref_rows = list(csv.DictReader(open(ref_path)))
    ref = ([float(r["pressure"]) for r in ref_rows], [float(r["u_outer"]) for r in ref_rows])

    def adaptive(indicators, levels, initial, extra=()):
        return [(f"L{L}", ["Adaptivity/Interval = 1", f"Adaptivity/Indicators = {indicators}",
                           f"Adaptivity/Maximum level = {L}",
                           f"Adaptivity/Initial refinement cycles = {L if initial else 0}"]
                 + list(extra)) for L in levels]

    contact_adaptive = ["Geometry/Local refinements = 0", "Adaptivity/Contact band = 0.1"]
    return {
        "thick_cylinder": (
            "thick_cylinder",
            ["Loading/End time = 1", "Loading/Number of steps = 10", "Postprocess/Line probes = ",
             "Output/Interval = 0", "Geometry/Quarter ring/Radial cells = 4",
             "Geometry/Quarter ring/Angular cells = 2"],
            {"uniform": [(f"g{g}", [f"Geometry/Global refinements = {g}"]) for g in range(0, 5)],
             "adaptive": adaptive("plastic strain, Kelly", range(1, 6), False,
                                  ["Geometry/Global refinements = 0",
                                   "Adaptivity/Refine fraction = 0.3",
                                   "Adaptivity/Coarsen fraction = 0"])},
            lambda run: thick_cylinder_error(run, ref)),
        "hertz": (
            "hertz", ["Output/Interval = 0"],
            {"uniform": [(f"g{g}", ["Geometry/Local refinements = 0",
                                    f"Geometry/Global refinements = {g}"]) for g in range(2, 8)],
             "graded": [(f"k{k}", [f"Geometry/Local refinements = {k}"]) for k in range(4, 11)],
             "adaptive": [(label, o + contact_adaptive)
                          for label, o in adaptive("contact, Kelly", range(6, 13), True)]},
            lambda run: contact_error(run, 254, hertz_load, "s")),
        "indentation": (
            "indentation_elastic", ["Output/Interval = 0"],
            {"uniform": [(f"g{g}", ["Geometry/Local refinements = 0",
                                    f"Geometry/Global refinements = {g}"]) for g in range(0, 5)],
             "graded": [(f"k{k}", [f"Geometry/Local refinements = {k}"]) for k in range(2, 8)],
             "adaptive": [(label, o + contact_adaptive)
                          for label, o in adaptive("contact, Kelly", range(3, 9), True)]},
            lambda run: contact_error(run, 10, punch_load, "x")),
    }


def time_to_reach(points, target):
    """CPU time at which |error| first reaches @p target along a sequence [(cpu, error)], by
    log-log interpolation; extrapolated from the last two points if it never does.
    Returns (seconds or nan, extrapolated?)."""
    pts = [(c, abs(e)) for c, e in points if c > 0 and e == e and e != 0]
    for k, (c, e) in enumerate(pts):
        if e <= target:
            if k == 0:
                return c, False
            c0, e0 = pts[k - 1]
            r = math.log(e / e0) / math.log(c / c0)
            return c0 * (target / e0) ** (1 / r), False
    if len(pts) >= 2:
        (c0, e0), (c1, e1) = pts[-2], pts[-1]
        if e1 < e0 and c1 > c0:
            r = math.log(e1 / e0) / math.log(c1 / c0)
            return c1 * (target / e1) ** (1 / r), True
    return math.nan, True


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("scenes", nargs="*", default=["thick_cylinder", "hertz", "indentation"])
    p.add_argument("--ausroll", default=os.path.join(runner.ROOT, "build", "ausroll"))
    p.add_argument("--work", default="/tmp/work_precision")
    p.add_argument("--data", default=os.path.join(runner.ROOT, "doc", "data"))
    p.add_argument("--figures", default=os.path.join(runner.ROOT, "doc", "figures"))
    p.add_argument("--reuse", action="store_true", help="reuse runs of an earlier call in --work")
    p.add_argument("--quick", action="store_true", help="two cheapest meshes per sequence")
    a = p.parse_args()
    os.makedirs(a.data, exist_ok=True)
    os.makedirs(a.figures, exist_ok=True)
    all_scenes = scenes()
    status = 0
    for name in a.scenes:
        base, common, sequences, error = all_scenes[name]
        print(f"== {name}")
        records = []
        for method, meshes in sequences.items():
            for label, overrides in meshes[:2] if a.quick else meshes:
                run = runner.run_variant(a.ausroll, a.work, base, f"{name}_{method}_{label}",
                                         common + overrides, a.reuse)
                if not run.ok or len(run.rows) < 2:
                    status = 1
                    continue
                rec = {"scene": name, "method": method, "mesh": label,
                       "cells": int(run.last("cells")), "dofs": int(run.last("dofs")),
                       "steps": run.steps(), "newton_iterations": int(run.total("newton_iterations")),
                       "cpu_seconds": round(run.cpu, 3), "wall_seconds": round(run.wall, 3)}
                rec.update({k: f"{v:.6g}" for k, v in error(run).items()})
                records.append(rec)
                print("  " + ", ".join(f"{k}={v}" for k, v in rec.items() if k != "scene"))
        if not records:
            continue
        keys = list(records[0])
        with open(os.path.join(a.data, f"work_precision_{name}.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(records)
        error_keys = [k for k in keys if k.startswith("error_")]
        main_error = "error_p0" if "error_p0" in error_keys else error_keys[0]
        reach = {}
        for method in sequences:
            pts = [(r["cpu_seconds"], float(r[main_error])) for r in records if r["method"] == method]
            reach[method] = time_to_reach(pts, 0.01)
            t, extra = reach[method]
            print(f"  {method}: 1 % {main_error} at {t:.3g} s CPU" + (" (extrapolated)" if extra else ""))
        if "adaptive" in reach and "uniform" in reach:
            ratio = reach["uniform"][0] / reach["adaptive"][0]
            print(f"  uniform / adaptive CPU time for 1 % {main_error}: {ratio:.3g}")
        plot(a.figures, name, records, sequences, error_keys)
    return status


def plot(figures, name, records, sequences, error_keys):
    plt = runner.pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    styles = {"error_p0": "-", "error_a": "--", "error_u": "-"}
    labels = {"error_p0": "p0", "error_a": "a", "error_u": "u(b)"}
    for i, method in enumerate(sequences):
        rows = [r for r in records if r["method"] == method]
        for key in error_keys:
            pts = [(r["cpu_seconds"], abs(float(r[key]))) for r in rows
                   if float(r[key]) == float(r[key]) and float(r[key]) != 0]
            if pts:
                ax.loglog(*zip(*pts), styles[key], marker="o", color=f"C{i}",
                          label=f"{method}: {labels[key]}")
    ax.axhline(0.01, color="grey", lw=0.8, ls=":")
    ax.set_xlabel("user CPU time of ausroll (s)")
    ax.set_ylabel("relative error")
    ax.set_title(f"work-precision: {name}")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(figures, f"work_precision_{name}.png")
    fig.savefig(path, dpi=110)
    print(f"  figure: {path}")


if __name__ == "__main__":
    sys.exit(main())
