#!/usr/bin/env python3
"""Linear solver study: the thick cylinder (prm/thick_cylinder.prm, Q2, plane strain, von Mises)
loaded in one step to p = 180 MPa (partly plastic: several Newton iterations with the consistent
tangent) on uniform meshes of ~10^3 ... 10^6 DoFs, with every `Solver/Linear solver` option:
direct MUMPS, direct KLU, GMRES + ML AMG, CG + ML AMG (the small-strain von Mises tangent is
symmetric). Records CPU and wall time per linear solve, Krylov iterations, Newton iterations and
u(b) (all solvers must agree). Writes a CSV and doc/figures/solver_study.png; prints a markdown
table. Not a pass/fail test (label benchmark); a solver that fails or is slower than --timeout is
reported as such.

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/solver_study/solver_study.py [--ausroll build/ausroll]
        [--work /tmp/ausroll_solver_study] [--refinements 1,3,5,6] [--reuse]
Timings: one process, one thread (the machine may be shared: the CPU times are the reliable ones).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import ausroll_run  # noqa: E402

SOLVERS = {
    "MUMPS": ["Solver/Linear solver/Type = direct",
              "Solver/Linear solver/Direct solver package = MUMPS"],
    "KLU": ["Solver/Linear solver/Type = direct",
            "Solver/Linear solver/Direct solver package = KLU"],
    "GMRES+AMG": ["Solver/Linear solver/Type = iterative",
                  "Solver/Linear solver/Iterative method = GMRES"],
    "CG+AMG": ["Solver/Linear solver/Type = iterative",
               "Solver/Linear solver/Iterative method = CG"],
}


def one_step(refinements, degree):
    """Overrides of prm/thick_cylinder.prm: uniform mesh, one load step to 180 MPa, no output."""
    return [f"Geometry/Global refinements = {refinements}", f"Model/Polynomial degree = {degree}",
            "Loading/End time = 1", "Loading/Number of steps = 1", "Output/Interval = 0",
            "Postprocess/Line probes = "]


# AMG settings tried for GMRES + AMG (Solver/Linear solver/AMG ...): the default first
AMG_VARIANTS = {
    "default (Chebyshev, 2 sweeps, threshold 0.02)": [],
    "threshold 1e-4": ["Solver/Linear solver/AMG aggregation threshold = 1e-4"],
    "threshold 0": ["Solver/Linear solver/AMG aggregation threshold = 0"],
    "Chebyshev, 4 sweeps": ["Solver/Linear solver/AMG smoother sweeps = 4"],
    "symmetric Gauss-Seidel, 2 sweeps": ["Solver/Linear solver/AMG smoother = symmetric Gauss-Seidel"],
    "ILU": ["Solver/Linear solver/AMG smoother = ILU"],
}


def amg_tuning(args, base, refinements):
    """GMRES + AMG with each of AMG_VARIANTS on the meshes @p refinements; prints a table."""
    rows = []
    for r in refinements:
        for k, (label, extra) in enumerate(AMG_VARIANTS.items()):
            run = ausroll_run.run_variant(
                args.ausroll, base, args.work, f"amg_q{args.degree}_r{r}_{k}",
                one_step(r, args.degree) + SOLVERS["GMRES+AMG"] + extra,
                reuse=args.reuse, timeout=args.timeout)
            if not run.ok or not run.solves:
                rows.append([label, r, "failed", "", ""])
                continue
            n = len(run.solves)
            rows.append([label, run.rows[-1]["dofs"], f"{sum(x[0] for x in run.solves) / n:.1f}",
                         f"{sum(x[2] for x in run.solves) / n:.3g}", f"{run.cpu:.3g}"])
            print(f"  AMG {label}, r{r}: {rows[-1][2:]}", flush=True)
    print(ausroll_run.markdown_table(
        ["GMRES + AMG setting", "DoFs", "Krylov it./solve", "CPU s/solve", "run CPU s"], rows))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ausroll", default=os.path.join(ausroll_run.ROOT, "build", "ausroll"))
    ap.add_argument("--work", default="/tmp/ausroll_solver_study")
    ap.add_argument("--refinements", default="1,3,5,6",
                    help="global refinements of the 8 x 4 quarter ring (Q2: 1.1e3, 1.7e4, "
                         "2.6e5, 1.05e6 DoFs)")
    ap.add_argument("--solvers", default=",".join(SOLVERS))
    ap.add_argument("--degree", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=1800.,
                    help="seconds per run; slower runs are reported as timed out")
    ap.add_argument("--skip-after-timeout", action="store_true", default=True,
                    help="do not try larger meshes with a solver that timed out")
    ap.add_argument("--amg-tuning", default="",
                    help="refinements (e.g. 3,4) on which to try the AMG settings AMG_VARIANTS "
                         "with GMRES instead of the solver comparison")
    ap.add_argument("--reuse", action="store_true", help="reuse runs in the work directory")
    ap.add_argument("--reuse-only", action="store_true",
                    help="only collect the runs already in the work directory (no new runs)")
    ap.add_argument("--csv", default=None, help="CSV output (default: WORK/solver_study.csv)")
    ap.add_argument("--figure", default=os.path.join(ausroll_run.ROOT, "doc", "figures",
                                                    "solver_study.png"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    base = os.path.join(ausroll_run.ROOT, "prm", "thick_cylinder.prm")
    if args.amg_tuning:
        amg_tuning(args, base, [int(x) for x in args.amg_tuning.split(",")])
        return 0
    solvers = args.solvers.split(",")
    records, given_up = [], set()
    for r in [int(x) for x in args.refinements.split(",")]:
        for s in solvers:
            if s in given_up:
                continue
            name = f"q{args.degree}_r{r}_{s.replace('+', '_')}"
            if args.reuse_only and not os.path.exists(os.path.join(args.work, name, "times.txt")):
                continue
            run = ausroll_run.run_variant(
                args.ausroll, base, args.work, name,
                one_step(r, args.degree) + SOLVERS[s],
                reuse=args.reuse or args.reuse_only, timeout=args.timeout)
            rec = {"solver": s, "refinements": r, "ok": run.ok, "returncode": run.returncode,
                   "wall_s": run.wall, "cpu_s": run.cpu, "solves": len(run.solves)}
            if run.ok:
                last = run.rows[-1]
                rec.update(dofs=int(last["dofs"]), newton=int(last["newton_iterations"]),
                           cutbacks=int(last["cutbacks"]), u_b=float(last["outer_ux"]))
            if run.solves:
                rec.update(solve_wall_s=sum(x[1] for x in run.solves) / len(run.solves),
                           solve_cpu_s=sum(x[2] for x in run.solves) / len(run.solves),
                           krylov=sum(x[0] for x in run.solves) / len(run.solves))
            records.append(rec)
            print(f"  {name}: rc {run.returncode}, {rec.get('dofs', '?')} DoFs, "
                  f"{len(run.solves)} solves, "
                  f"{rec.get('solve_cpu_s', float('nan')):.3f} s CPU/solve, "
                  f"{rec.get('krylov', 0):.1f} Krylov it/solve, total {run.cpu:.1f} s CPU, "
                  f"{run.wall:.1f} s wall", flush=True)
            if not run.ok:
                given_up.add(s)

    keys = ["solver", "refinements", "dofs", "ok", "returncode", "newton", "cutbacks", "solves",
            "krylov", "solve_cpu_s", "solve_wall_s", "cpu_s", "wall_s", "u_b"]
    ausroll_run.write_csv(args.csv or os.path.join(args.work, "solver_study.csv"), keys, records)

    # u(b) of every solver against MUMPS on the same mesh
    ref = {rec["refinements"]: rec["u_b"] for rec in records
           if rec["solver"] == "MUMPS" and "u_b" in rec}
    rows = []
    for rec in records:
        if "dofs" not in rec:
            rows.append([rec["solver"], "-", "failed" if rec["returncode"] != -9 else "timeout",
                         "", "", "", "", f"{rec['cpu_s']:.0f}", ""])
            continue
        diff = (abs(rec["u_b"] - ref[rec["refinements"]]) / abs(ref[rec["refinements"]])
                if rec["refinements"] in ref else float("nan"))
        rows.append([rec["solver"], rec["dofs"], rec["newton"], f"{rec.get('krylov', 0):.1f}",
                     f"{rec['solve_cpu_s']:.3g}", f"{rec['solve_wall_s']:.3g}",
                     f"{rec['cpu_s']:.3g}", f"{rec['wall_s']:.3g}", f"{diff:.1e}"])
    print(ausroll_run.markdown_table(
        ["solver", "DoFs", "Newton it.", "Krylov it./solve", "CPU s/solve", "wall s/solve",
         "run CPU s", "run wall s", "u(b) vs MUMPS"], rows))

    plt = ausroll_run.pyplot()
    if plt is None:
        return 0
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for s in solvers:
        pts = sorted((rec["dofs"], rec["solve_cpu_s"], rec["cpu_s"]) for rec in records
                     if rec["solver"] == s and "dofs" in rec)
        if not pts:
            continue
        axes[0].loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=s)
        axes[1].loglog([p[0] for p in pts], [p[2] for p in pts], "o-", label=s)
    axes[0].set_title("CPU time per linear solve")
    axes[1].set_title("CPU time of the run (1 load step to 180 MPa)")
    for ax in axes:
        ax.set_xlabel("DoFs")
        ax.set_ylabel("s")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle(f"Thick cylinder, Q{args.degree}, plane strain, one process")
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.figure), exist_ok=True)
    fig.savefig(args.figure, dpi=120)
    print(f"figure: {args.figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
