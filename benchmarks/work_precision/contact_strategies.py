#!/usr/bin/env python3
"""Contact strategies (active set, nested active set, load increment ratio) on the Hertz and
indentation scenes, and the figures of doc/scenes/hertz.md and doc/scenes/indentation.md.

For each scene and strategy: load steps (sub-steps of the load increment ratio included), Newton
iterations, user CPU and wall time of ausroll, and the error:
  hertz                largest |error| of a and p0 over the thesis loads P >= 1779.2 N/mm
                       (for both Hertz scenes: outputs with at least 5 closed nodes, as the checks)
                       (plane-strain Hertz, fit of the nodal pressures to the ellipse)
  indentation_elastic  largest |error| of a and p0 over the steps, Hertz for the measured force
  indentation          elastic-plastic, to d = 0.25 mm (t = 0.5, 10 steps): largest relative
                       deviation of the punch force from a reference run (active set, 20 steps)
                       at the depths d > 0.05 mm of the run
A run is stopped after --timeout seconds (the table then gives the depth/load it reached).
Figures: hertz_pressure.png (pressure vs Hertz at each load), indentation_force_depth.png,
indentation_width_depth.png, indentation_hertz.png (elastic pressure vs Hertz).

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/work_precision/contact_strategies.py [--ausroll build/ausroll]
        [--work /tmp/contact_strategies] [--figures doc/figures] [--data doc/data] [--reuse]
Prints a markdown table (pasted into doc/scenes/*.md and doc/studies/benchmarks_journal.md) and writes
DATA/contact_strategies.csv.
"""

import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import runner  # noqa: E402

E, NU, SIGMA_Y = 210000.0, 0.3, 700.0
STRATEGIES = ["active set", "nested active set", "load increment ratio"]


def hertz_table(run, radius, load, coordinate, min_load=0.0, nominal_dt=None):
    """[(P, ea, ep, fit, ref, lines)] for every contact CSV of @p run with P >= min_load (only at
    the nominal step ends t = k nominal_dt if given: the load increment ratio also writes its
    sub-steps, which end when a node has just closed with zero pressure)."""
    out = []
    for t, lines in runner.contact_files(run.out):
        if nominal_dt and abs(t / nominal_dt - round(t / nominal_dt)) > 1e-6:
            continue
        P = load(run, t)
        if P <= 0 or P < min_load * (1 - 1e-9) or len(runner.check_hertz.closed_nodes(lines)) < 5:
            continue  # as the checks: at least 5 closed nodes
        ea, ep, fit, ref = runner.hertz_errors(lines, P, radius, E, NU, coordinate)
        out.append((P, ea, ep, fit, ref, lines))
    return out


def punch_load(run, t):
    row = min(run.rows, key=lambda r: abs(float(r["time"]) - t))
    return -2 * float(row["die_punch_force_y"])


def force_depth(run):
    return ([-float(r["die_punch_y"]) for r in run.rows],
            [-float(r["die_punch_force_y"]) for r in run.rows],
            [float(r["die_punch_contact_width"]) for r in run.rows])


def interpolate(xs, ys, x):
    for i in range(1, len(xs)):
        if xs[i] >= x - 1e-12:
            return ys[i - 1] + (ys[i] - ys[i - 1]) * (x - xs[i - 1]) / (xs[i] - xs[i - 1])
    return math.nan


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ausroll", default=os.path.join(runner.ROOT, "build", "ausroll"))
    p.add_argument("--work", default="/tmp/contact_strategies")
    p.add_argument("--data", default=os.path.join(runner.ROOT, "doc", "data"))
    p.add_argument("--figures", default=os.path.join(runner.ROOT, "doc", "figures"))
    p.add_argument("--reuse", action="store_true")
    p.add_argument("--timeout", type=float, default=200)
    a = p.parse_args()
    os.makedirs(a.data, exist_ok=True)
    os.makedirs(a.figures, exist_ok=True)

    def run(base, name, overrides):
        r = runner.run_variant(a.ausroll, a.work, base, name, ["Output/Interval = 1"] + overrides,
                               a.reuse, a.timeout)
        print(f"  {name}: {r.steps()} steps, {int(r.total('newton_iterations'))} Newton, "
              f"{r.cpu:.1f} s CPU, {r.wall:.1f} s wall")
        return r

    records, runs = [], {}
    full = run("indentation", "indentation_full", [])  # the shipped scene, to d = 1 mm
    half = ["Loading/End time = 0.5"]
    reference = run("indentation", "indentation_reference", half + ["Loading/Number of steps = 20"])
    ref_d, ref_f, _ = force_depth(reference)
    for strategy in STRATEGIES:
        tag = strategy.replace(" ", "_")
        o = [f"Contact/Strategy = {strategy}"]
        for scene, base in (("hertz", "hertz"), ("indentation_elastic", "indentation_elastic"),
                            ("indentation", "indentation")):
            r = run(base, f"{scene}_{tag}",
                    o + (half + ["Loading/Number of steps = 10"] if scene == "indentation" else []))
            runs[scene, strategy] = r
            if scene == "hertz":
                table = hertz_table(r, 254, lambda run, t: 1779.2 * t, "s", 1779.2, 1.0)
                err = max((max(abs(e[1]), abs(e[2])) for e in table), default=math.nan)
            elif scene == "indentation_elastic":
                table = hertz_table(r, 10, punch_load, "x", nominal_dt=0.25)
                err = max((max(abs(e[1]), abs(e[2])) for e in table if e[0] > 0), default=math.nan)
            else:
                d, f, _ = force_depth(r)
                err = max((abs(fi / interpolate(ref_d, ref_f, di) - 1)
                           for di, fi in zip(d, f) if di > 0.05), default=math.nan)
            records.append({"scene": scene, "strategy": strategy, "steps": r.steps(),
                            "newton_iterations": int(r.total("newton_iterations")),
                            "cpu_seconds": round(r.cpu, 2), "wall_seconds": round(r.wall, 2),
                            "error": f"{err:.3g}",
                            "reached": "end" if r.ok else f"t = {r.last('time'):.4g} (stopped)"})
    with open(os.path.join(a.data, "contact_strategies.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(records[0]))
        w.writeheader()
        w.writerows(records)
    print("\n| scene | strategy | steps | Newton iterations | CPU (s) | wall (s) | error | reached |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for r in records:
        print(f"| {r['scene']} | {r['strategy']} | {r['steps']} | {r['newton_iterations']} | "
              f"{r['cpu_seconds']} | {r['wall_seconds']} | {float(r['error']):.2%} | {r['reached']} |")

    print("\nHertz (active set):")
    for P, ea, ep, fit, ref, _ in hertz_table(runs["hertz", "active set"], 254,
                                              lambda run, t: 1779.2 * t, "s"):
        print(f"  P = {P:8.1f}: a = {fit[1]:.4f} (Hertz {ref[0]:.4f}, {ea:+.2%}), "
              f"p0 = {fit[0]:.1f} (Hertz {ref[1]:.1f}, {ep:+.2%})")
    print("Elastic indentation (active set):")
    for P, ea, ep, fit, ref, _ in hertz_table(runs["indentation_elastic", "active set"], 10,
                                              punch_load, "x"):
        print(f"  P = {P:8.1f}: a = {fit[1]:.4f} (Hertz {ref[0]:.4f}, {ea:+.2%}), "
              f"p0 = {fit[0]:.1f} (Hertz {ref[1]:.1f}, {ep:+.2%})")
    d, f, w = force_depth(full)
    p_lim = (2 + math.pi) * SIGMA_Y / math.sqrt(3)
    print("Elastic-plastic indentation (active set): depth, force (half model), a, p_m / (2+pi)k")
    for di, fi, wi in zip(d, f, w):
        if wi > 0:
            print(f"  {di:6.3f} {fi:10.1f} {wi:7.3f} {fi / wi / p_lim:7.3f}")
    figures(a.figures, runs, reference, full)
    return 0


def pressure_plot(ax, table, coordinate, title):
    for i, (P, ea, ep, fit, ref, lines) in enumerate(table):
        rows = [r for r in csv.DictReader(l for l in lines if not l.startswith("#"))]
        xs = [float(r[coordinate]) for r in rows]
        ps = [float(r["p_n"]) for r in rows]
        ax.plot(xs, ps, "o", ms=3, color=f"C{i}", label=f"P = {P:.0f} N/mm")
        a_ref, p0_ref = ref
        xr = [a_ref * k / 100 for k in range(101)]
        ax.plot(xr, [p0_ref * math.sqrt(max(0.0, 1 - (x / a_ref) ** 2)) for x in xr], "-",
                color=f"C{i}", lw=0.8)
    ax.set_xlabel(f"{coordinate} (mm)")
    ax.set_ylabel("contact pressure (MPa)")
    ax.set_title(title)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)


def figures(directory, runs, reference, full):
    plt = runner.pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    table = hertz_table(runs["hertz", "active set"], 254, lambda run, t: 1779.2 * t, "s")
    pressure_plot(ax, table, "s", "Hertz: nodal pressures (dots) vs Hertz (lines)")
    ax.set_xlim(0, 1.3 * max(e[4][0] for e in table))
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "hertz_pressure.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    table = hertz_table(runs["indentation_elastic", "active set"], 10, punch_load, "x")
    pressure_plot(ax, table, "x", "elastic indentation: pressures (dots) vs Hertz (lines)")
    ax.set_xlim(0, 1.3 * max(e[4][0] for e in table))
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "indentation_hertz.png"), dpi=110)

    p_lim = (2 + math.pi) * SIGMA_Y / math.sqrt(3)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    d, f, w = force_depth(full)
    ax1.plot(d, [2 * x / 1000 for x in f], "k.-", ms=3, lw=0.8, label="prm/indentation.prm (active set)")
    ax2.plot(d, [x / wi / p_lim if wi > 0 else math.nan for x, wi in zip(f, w)], "k.-", ms=3,
             lw=0.8, label="prm/indentation.prm (active set)")
    for i, strategy in enumerate(STRATEGIES):
        d, f, w = force_depth(runs["indentation", strategy])
        ax1.plot(d, [2 * x / 1000 for x in f], "o" if i == 0 else "x", ms=4,
                 label=f"{strategy}, 10 steps to 0.25 mm")
    ax1.set_xlabel("depth d (mm)")
    ax1.set_ylabel("punch force P (kN per mm, whole punch)")
    ax1.grid(True, lw=0.3)
    ax1.legend(fontsize=8)
    ax2.axhline(1.0, color="grey", ls=":", label="(2 + pi) k")
    ax2.set_xlabel("depth d (mm)")
    ax2.set_ylabel("mean pressure P / (2 a) / ((2 + pi) k)")
    ax2.grid(True, lw=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle("elastic-plastic indentation, R = 10 mm, sigma_y = 700, H' = 300 MPa, mu = 0.3")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "indentation_force_depth.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    d, f, w = force_depth(full)
    ax.plot(d, w, "o-", ms=3, label="elastic-plastic, mu = 0.3")
    de, fe, we = force_depth(runs["indentation_elastic", "active set"])
    ax.plot(de, we, "s-", ms=3, label="elastic, frictionless")
    dr = [k / 100 for k in range(101)]
    ax.plot(dr, [math.sqrt(2 * 10 * x) for x in dr], "k:", label="sqrt(2 R d) (no pile-up/sink-in)")
    ax.set_xlabel("depth d (mm)")
    ax.set_ylabel("contact half-width a (mm)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "indentation_width_depth.png"), dpi=110)
    print(f"figures in {directory}")


if __name__ == "__main__":
    sys.exit(main())
