#!/usr/bin/env python3
"""Mesh convergence of the thick cylinder (prm/thick_cylinder.prm: plane strain quarter ring,
perfectly plastic von Mises, pressure up to 0.99 p_c in 50 steps) against the independent 1D
radial solution benchmarks/reference/thick_cylinder_1d.cc.

For uniform meshes (Q1 and Q2, global refinements of the 8 x 4 ring) it records the maximum
relative error of u(b) along the whole load path (points with p >= 1 MPa), the DoFs, the CPU and
wall time of the run and the Newton iterations per step; it writes a CSV,
doc/figures/thick_cylinder_convergence.png (error vs DoFs, error vs CPU time, Newton iterations
per step) and doc/figures/thick_cylinder_hoop.png (hoop stress along the radius at p = 180 MPa vs
the reference) and prints markdown tables.

The reference is recomputed here (g++ builds thick_cylinder_1d; 2000 quadratic elements, 1000
pressure steps), so that its own error (< 1e-6 in u(b)) stays below the 2D errors.

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/thick_cylinder/convergence.py [--ausroll build/ausroll]
        [--work /tmp/ausroll_thick_cylinder] [--q1 0,1,2,3,4] [--q2 0,1,2,3] [--reuse]
"""

import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import ausroll_run  # noqa: E402

SIGMA_Y = 240.0


def reference(work, reuse):
    """(load rows, profile rows) of the 1D solution, computed in work/reference."""
    out = os.path.join(work, "reference")
    os.makedirs(out, exist_ok=True)
    prefix = os.path.join(out, "thick_cylinder")
    if not (reuse and os.path.exists(prefix + "_load.csv")):
        exe = os.path.join(out, "thick_cylinder_1d")
        subprocess.run(["g++", "-O2", "-std=c++17", "-o", exe,
                        os.path.join(ausroll_run.ROOT, "benchmarks", "reference",
                                     "thick_cylinder_1d.cc")], check=True)
        subprocess.run([exe, "--steps", "1000", "--elements", "2000", "--no-checks",
                        "--out-prefix", prefix], check=True, stdout=subprocess.DEVNULL)
    load = ausroll_run.read_history(prefix + "_load.csv")
    profile = ausroll_run.read_history(prefix + "_profile.csv")
    return ([(float(r["pressure"]), float(r["u_outer"])) for r in load],
            [(float(r["r"]), float(r["sigma_theta"])) for r in profile])


def load_path_error(run, ref):
    """Largest |u(b) - u_ref(b)| / |u_ref(b)| over the steps with p >= 1 MPa."""
    ps, us = [p for p, _ in ref], [u for _, u in ref]
    worst = 0.0
    for row in run.rows:
        p = float(row["pressure_0"])
        if p < 1.0:
            continue
        u_ref = ausroll_run.interpolate(ps, us, p)
        worst = max(worst, abs(float(row["outer_ux"]) - u_ref) / abs(u_ref))
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ausroll", default=os.path.join(ausroll_run.ROOT, "build", "ausroll"))
    ap.add_argument("--work", default="/tmp/ausroll_thick_cylinder")
    ap.add_argument("--q1", default="0,1,2,3,4", help="global refinements for Q1")
    ap.add_argument("--q2", default="0,1,2,3", help="global refinements for Q2")
    ap.add_argument("--step-check", default="2,2",
                    help="DEGREE,REFINEMENTS of one extra run with 4x the load steps (200), which "
                         "separates the load-increment error from the mesh error ('' = none)")
    ap.add_argument("--reuse", action="store_true", help="reuse runs in the work directory")
    ap.add_argument("--figures", default=os.path.join(ausroll_run.ROOT, "doc", "figures"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    ref_load, ref_profile = reference(args.work, args.reuse)
    base = os.path.join(ausroll_run.ROOT, "prm", "thick_cylinder.prm")

    results = []
    variants = [(d, int(r), 50) for d, levels in ((1, args.q1), (2, args.q2))
                for r in levels.split(",") if r]
    if args.step_check:
        d, r = (int(x) for x in args.step_check.split(","))
        variants.append((d, r, 200))
    for degree, r, steps in variants:
        name = f"q{degree}_r{r}" + ("" if steps == 50 else f"_{steps}steps")
        run = ausroll_run.run_variant(
            args.ausroll, base, args.work, name,
            [f"Geometry/Global refinements = {r}", f"Model/Polynomial degree = {degree}",
             f"Loading/Number of steps = {steps}", f"Output/Interval = {steps // 5}"],
            reuse=args.reuse)
        if not run.ok:
            print(f"  {name}: failed (exit {run.returncode})")
            continue
        newton = [int(row["newton_iterations"]) for row in run.rows[1:]]
        res = {"degree": degree, "refinements": r, "dofs": int(run.rows[-1]["dofs"]),
               "error": load_path_error(run, ref_load), "cpu_s": run.cpu,
               "wall_s": run.wall, "steps": len(newton), "name": name, "newton_total": sum(newton),
               "newton_mean": sum(newton) / len(newton), "newton_max": max(newton),
               "cutbacks": sum(int(row["cutbacks"]) for row in run.rows[1:]), "run": run}
        results.append(res)
        print(f"  {name}: {res['dofs']} DoFs, error {res['error']:.2e}, "
              f"{run.cpu:.1f} s CPU, {run.wall:.1f} s wall, Newton {sum(newton)}",
              flush=True)

    keys = ["name", "degree", "refinements", "dofs", "error", "cpu_s", "wall_s", "steps",
            "newton_total", "newton_mean", "newton_max", "cutbacks"]
    ausroll_run.write_csv(os.path.join(args.work, "thick_cylinder_convergence.csv"), keys, results)
    print(ausroll_run.markdown_table(
        ["element", "refinements", "load steps", "DoFs", "max rel. error u(b)", "CPU s", "wall s",
         "Newton it. (total / mean / max per step)", "cutbacks"],
        [[f"Q{r['degree']}", r["refinements"], r["steps"], r["dofs"], f"{r['error']:.2e}",
          f"{r['cpu_s']:.1f}", f"{r['wall_s']:.1f}",
          f"{r['newton_total']} / {r['newton_mean']:.2f} / {r['newton_max']}", r["cutbacks"]]
         for r in results]))

    # Newton iterations per step for the scene's own mesh (Q2, 1 refinement) and the finest ones
    print("\nNewton iterations per step (p in MPa):")
    uniform = [r for r in results if r["steps"] == 50]
    shown = [r for r in uniform if (r["degree"], r["refinements"]) == (2, 1)]
    shown += [max((r for r in uniform if r["degree"] == d), key=lambda r: r["dofs"])
              for d in (1, 2) if any(r["degree"] == d for r in uniform)]
    for res in shown:
        rows = res["run"].rows[1:]
        print(f"  Q{res['degree']} r{res['refinements']}: " + " ".join(
            f"{float(x['pressure_0']):.0f}:{x['newton_iterations']}" for x in rows))

    # hoop stress at 180 MPa (output 4 = step 40, t = 1)
    hoop = {}
    for res in uniform:
        probe = os.path.join(args.work, res["name"], "probe_radial_0004.csv")
        if os.path.exists(probe):
            pts = [(float(r["x"]), float(r["stress_yy"])) for r in ausroll_run.read_history(probe)]
            rs, ss = [p[0] for p in ref_profile], [p[1] for p in ref_profile]
            err = max(abs(s - ausroll_run.interpolate(rs, ss, x))
                      / max(abs(ausroll_run.interpolate(rs, ss, x)), SIGMA_Y) for x, s in pts)
            hoop[(res["degree"], res["refinements"])] = (pts, err)
    print("\nhoop stress at p = 180 MPa, max |error| / max(|sigma_ref|, sigma_y):")
    for (d, r), (_, err) in sorted(hoop.items()):
        print(f"  Q{d} r{r}: {err:.2e}")

    plt = ausroll_run.pyplot()
    if plt is None:
        return 0
    os.makedirs(args.figures, exist_ok=True)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.3))
    for d, style in ((1, "s-"), (2, "o-")):
        sel = [r for r in uniform if r["degree"] == d]
        if not sel:
            continue
        axes[0].loglog([r["dofs"] for r in sel], [r["error"] for r in sel], style, label=f"Q{d}")
        axes[1].loglog([r["cpu_s"] for r in sel], [r["error"] for r in sel], style, label=f"Q{d}")
    axes[0].set_xlabel("DoFs")
    axes[1].set_xlabel("CPU time of the run (s, one process)")
    for ax in axes[:2]:
        ax.set_ylabel("max relative error of u(b) along the load path")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    for res in shown:
        rows = res["run"].rows[1:]
        axes[2].plot([float(x["pressure_0"]) for x in rows],
                     [int(x["newton_iterations"]) for x in rows], ".-",
                     label=f"Q{res['degree']}, {res['dofs']} DoFs")
    axes[2].set_xlabel("pressure (MPa)")
    axes[2].set_ylabel("Newton iterations per step")
    axes[2].grid(True, alpha=0.3)
    axes[2].legend()
    fig.suptitle("Thick cylinder (plane strain, perfectly plastic), uniform meshes, "
                 "50 load steps to 0.99 p_c")
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "thick_cylinder_convergence.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot([p[0] for p in ref_profile], [p[1] for p in ref_profile], "k-", lw=2,
            label="1D reference")
    for key in sorted(hoop):
        if key in ((2, 1), (1, 2)) or key == max(hoop):
            pts, err = hoop[key]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "--",
                    label=f"Q{key[0]}, {key[1]} refinement(s) (max error {err:.1%})")
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("hoop stress (MPa)")
    ax.set_title("Thick cylinder: hoop stress at p = 180 MPa (plastic front at r = 161 mm)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "thick_cylinder_hoop.png"), dpi=120)
    print(f"figures: {args.figures}/thick_cylinder_convergence.png, thick_cylinder_hoop.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
