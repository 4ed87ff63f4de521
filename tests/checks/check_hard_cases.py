#!/usr/bin/env python3
"""Short versions of the hard cases of issue 17 (doc/scenes/hard_cases.md), each past the point
where it failed or was cut back before the fixes; about 40 s of CPU in all.

1. Punch (prm/hard_punch.prm on its coarsest mesh, Local refinements = 2, to d = 1 mm): finishes
   with at most 2 cutbacks (before: 3 on this mesh, 16-30 on the others, the finest stopped at
   d = 0.41 mm) and a median of at most 3 Newton iterations per step (the goal of issue 17; 4
   with the defaults of before 2026-12-06: Residual tolerance 1e-9, Target Newton iterations 6).
   The force at 1 mm within 5 % of the value extrapolated from the three meshes of the benchmark
   (Richardson, 4864 N/mm; this mesh is 3.1 % low, the discretisation error of its 0.625 mm
   cells at the contact edge), and the mean pressure F / a between the plane-strain
   compression limit 2k of the slab (k = sigma_y / sqrt 3; no indentation is possible below the
   yield pressure) and Prandtl's (2 + pi) k (the largest constraint a flat punch on a half-space
   reaches; the thin slab on a frictionless base is less constrained).
2. Upsetting with the platen on the top face only (Candidate boundaries = 3), F-bar, Q2 8 x 6.
   (a) With Contact/Penetrating boundaries = warn, to 25 % (before: no convergence at 22.3 %):
   passes 22.3 % and either reaches 25 % or stops (exit 3) with a failure message that repeats
   the fold (the folded corner, J < 0.2, is beyond use: with the defaults of before it reached
   25 %, with the current ones it stops at 24.2 %), and warns that the mesh folds, at
   the top outer corner (r > 19 mm, z > 14 mm), at a reduction between 10 and 20 % (measured
   13.25 %): the force of a folding mesh must not look converged.
3. Upsetting as shipped with the predictor and the adaptive step control: median Newton
   iterations per step at most 3 (before: 4), no cutback, force at 30 % within 2 % of the Q2
   16 x 12 reference of doc/scenes/upsetting.md (1682.0 kN; the same tolerance as
   check/upsetting).
4. Indentation (prm/indentation.prm with the predictor and the adaptive step control) to
   t = 0.75 (d = 0.5625 mm): at most 2 cutbacks (before: 7 up to there, 16 in all), a median of
   at most 3 Newton iterations per step (before: 5), and the
   mean pressure within 15 % of (2 + pi) k from d = 0.15 mm (the criterion and reasons of
   check/indentation_force_depth, 12 % there; the smaller adaptive steps also sample the depths
   just before the next node closes, where a lags by one node spacing, 0.16 mm at a = 1.74 mm:
   measured 0.876 there, 0.91-0.98 elsewhere).
5. Elastic frictionless punch (prm/hard_punch.prm, Local refinements = 2, yield stress 1e7)
   with and without `Contact/Curvature tangent`, both solved to 1e-9 of the force level (the
   term restores the quadratic rate of the last iterations, which the default tolerance 1e-6
   mostly stops before: 49 against 51 iterations there): the same force at 1 mm (1e-7), and
   the curvature term saves at least a quarter of the iterations (measured 58 against 134),
   median at most 3.
   Also in 2. (a): the side surface (boundary 1, not a candidate) passing through the platen is
   reported with the entry to change. (b) With the default Penetrating boundaries = add, to 30 %:
   boundary 1 becomes a candidate when it first passes through the platen (said once, with the
   entry), no cutback, and the force at 30 % within 0.5 % of the shipped scene's (3.; measured
   1700.9 against 1699.7 kN: the side enters contact one detection, at most 1 % of a cell,
   later).
6. Upsetting with the top face prescribed (u_r = 0, u_z = -0.15 t on boundary 3, no platen: the
   peer's model), Q2 with 2 x 2 Gauss points and no F-bar, on 8 x 6 and 16 x 12: reaches 30 %
   with at most 2 cutbacks (measured 0) and no fold warning (F-bar with 3 x 3 points stops at
   23 % and 19 %), and the force at 30 % within 1 % of 1461.3 kN, the 64 x 48 value (the four
   meshes 8 x 6 ... 64 x 48 spread by 0.8 % without a monotone trend; doc/scenes/hard_cases.md
   section 3a).

Usage: check_hard_cases.py AUSROLL SOURCE_DIR
"""

import csv
import math
import os
import statistics
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)

SIGMA_Y = 700.0
PUNCH_EXTRAPOLATED = 4864.0  # N/mm, benchmarks/hard_cases (meshes 2, 3, 4: 4713, 4814, 4847)
UPSETTING_REFERENCE_30 = 1682.0  # kN, Q2 16x12, 0.25 % steps
# kN, top face prescribed, Q2 2x2 points, 64 x 48 (8x6 ... 64x48: 1458.6, 1469.8, 1460.3, 1461.3)
TOP_PRESCRIBED_30 = 1461.3


def run(ausroll, source, base, name, overrides, base_path=None):
    prm = f"{name}.prm"
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    base_path or os.path.join(source, "prm", base), prm, f"Output/Directory = {name}",
                    "Output/Write VTU = false", "Output/Verbosity = normal"] + overrides,
                   check=True)
    result = subprocess.run([ausroll, prm, "--overwrite"], capture_output=True, text=True)
    with open(os.path.join(name, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return result, rows


def summary(rows):
    steps = rows[1:]
    newton = [int(float(r["newton_iterations"])) for r in steps]
    cutbacks = sum(int(float(r["cutbacks"])) for r in steps)
    return len(steps), cutbacks, statistics.median(newton) if newton else 0


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    check = Checklist()
    k = SIGMA_Y / math.sqrt(3)

    # 1. punch
    result, rows = run(ausroll, source, "hard_punch.prm", "punch",
                       ["Geometry/Local refinements = 2"])
    steps, cutbacks, median = summary(rows)
    last = rows[-1]
    force, width = -float(last["die_punch_force_y"]), float(last["die_punch_contact_width"])
    print(f"punch: status {result.returncode}, {steps} steps, {cutbacks} cutbacks, median Newton "
          f"{median}, t = {float(last['time'])}, F = {force:.1f} N/mm, a = {width:.3f} mm, "
          f"F/a = {force / width:.0f} MPa")
    check("punch: finished at d = 1 mm", result.returncode == 0
          and abs(float(last["time"]) - 1) < 1e-9)
    check("punch: at most 2 cutbacks", cutbacks <= 2)
    check("punch: median Newton iterations per step <= 3 at the default tolerance (before: 4)",
          median <= 3)
    check("punch: force within 5 % of the extrapolated value",
          abs(force / PUNCH_EXTRAPOLATED - 1) <= 0.05)
    check("punch: 2k <= F/a <= (2 + pi) k", 2 * k <= force / width <= (2 + math.pi) * k)

    # 2. upsetting, platen on the top face only: folds at the corner, must say so
    result, rows = run(ausroll, source, "upsetting.prm", "top_only",
                       ["Contact/Die 0/Candidate boundaries = 3",
                        "Contact/Penetrating boundaries = warn", "Loading/End time = 25",
                        "Loading/Number of steps = 100",
                        "Loading/Predictor = linear extrapolation",
                        "Loading/Step control = adaptive"])
    warning = [line for line in result.stdout.splitlines() if "warning: the mesh folds" in line]
    print(f"top face only: status {result.returncode}, t = {float(rows[-1]['time'])}")
    print("\n".join(warning))
    reached = float(rows[-1]["time"])
    finished = result.returncode == 0 and abs(reached - 25) < 1e-9
    stopped_on_fold = (result.returncode == 3 and "Earlier, the mesh folds" in result.stderr
                       + result.stdout)
    check("top face only: passes 22.3 % (the failure before) and reaches 25 % or stops (exit 3) "
          "with a message that repeats the fold", reached > 22.3 and (finished or stopped_on_fold))
    ok = False
    if warning:
        try:
            where = warning[0].split("quadrature point (")[1].split(")")[0].split()
            when = float(warning[0].split(", t = ")[1].split()[0])
            ok = float(where[0]) > 19 and float(where[1]) > 14 and 10 <= when <= 20
        except (IndexError, ValueError):
            ok = False
    check("top face only: warns of the fold at the top outer corner between 10 and 20 %", ok)
    # the free side surface (boundary 1) is not a candidate and passes through the platen
    through = [line for line in result.stdout.splitlines()
               if "boundary 1 of the workpiece passes through die 0 'platen'" in line]
    print("\n".join(through))
    ok = False
    if through:
        try:
            ok = float(through[0].split(", t = ")[1].split(":")[0]) <= 25
        except (IndexError, ValueError):
            ok = False
    check("top face only: says that boundary 1 passes through the platen, naming the entry",
          ok and "Add 1 to Contact/Die 0/Candidate boundaries" in through[0])

    # 2b. the same with the default Penetrating boundaries = add: boundary 1 becomes a candidate
    # of the platen when it first passes through it, the step is solved again, and the run is
    # the shipped scene's (checked against it in 3.)
    result, rows = run(ausroll, source, "upsetting.prm", "top_only_add",
                       ["Contact/Die 0/Candidate boundaries = 3",
                        "Loading/Predictor = linear extrapolation",
                        "Loading/Step control = adaptive"])
    steps, cutbacks, median = summary(rows)
    top_only_force = -1e-3 * float(rows[-1]["die_platen_force_y"])
    notes = [line for line in result.stdout.splitlines()
             if "note: boundary 1 of the workpiece passes through die 0 'platen'" in line]
    print(f"top face only, boundaries added: status {result.returncode}, {steps} steps, "
          f"{cutbacks} cutbacks, median Newton {median}, F(30 %) = {top_only_force:.1f} kN")
    print("\n".join(notes))
    check("top face only, add: finishes at 30 % without cutback", result.returncode == 0
          and abs(float(rows[-1]["time"]) - 30) < 1e-9 and cutbacks == 0)
    check("top face only, add: says once that boundary 1 is now a candidate, naming the entry",
          len(notes) == 1 and "it is now a candidate of that die" in notes[0]
          and "Add 1 to Contact/Die 0/Candidate boundaries" in notes[0])

    # 3. upsetting as shipped, predictor + adaptive step control
    result, rows = run(ausroll, source, "upsetting.prm", "upsetting",
                       ["Loading/Predictor = linear extrapolation",
                        "Loading/Step control = adaptive"])
    steps, cutbacks, median = summary(rows)
    force = -1e-3 * float(rows[-1]["die_platen_force_y"])
    print(f"upsetting: status {result.returncode}, {steps} steps, {cutbacks} cutbacks, median "
          f"Newton {median}, F(30 %) = {force:.1f} kN")
    check("upsetting: finished", result.returncode == 0)
    check("upsetting: median Newton iterations <= 3, no cutback", median <= 3 and cutbacks == 0)
    check("upsetting: force at 30 % within 2 % of Q2 16x12",
          abs(force / UPSETTING_REFERENCE_30 - 1) <= 0.02)
    # the side surface enters contact one detection later than in the shipped scene (at most
    # 1 % of a cell deep, then the step is solved again): measured 1700.9 against 1699.7 kN
    check("top face only, add: force at 30 % within 0.5 % of the shipped scene's",
          abs(top_only_force / force - 1) <= 0.005)

    # 4. indentation, predictor + adaptive step control
    result, rows = run(ausroll, source, "indentation.prm", "indentation",
                       ["Loading/End time = 0.75", "Loading/Number of steps = 15",
                        "Loading/Predictor = linear extrapolation",
                        "Loading/Step control = adaptive"])
    steps, cutbacks, median = summary(rows)
    print(f"indentation: status {result.returncode}, {steps} steps, {cutbacks} cutbacks, median "
          f"Newton {median}")
    check("indentation: finished at t = 0.75", result.returncode == 0
          and abs(float(rows[-1]["time"]) - 0.75) < 1e-9)
    check("indentation: at most 2 cutbacks", cutbacks <= 2)
    check("indentation: median Newton iterations per step <= 3 at the default tolerance "
          "(before: 5)", median <= 3)
    pressure = subprocess.run([sys.executable,
                               os.path.join(os.path.dirname(__file__), "check_indentation.py"),
                               "indentation/history.csv", "--yield-stress", str(SIGMA_Y),
                               "--from-depth", "0.15", "--tol", "0.15"],
                              capture_output=True, text=True)
    print(pressure.stdout.splitlines()[-1] if pressure.stdout else pressure.stderr)
    check("indentation: force rises, p_m within 15 % of (2 + pi) k", pressure.returncode == 0)
    # 5. elastic frictionless punch: the curvature term of the slip-node tangent
    runs = {}
    for flag in ("false", "true"):
        result, rows = run(ausroll, source, "hard_punch.prm", f"elastic_curvature_{flag}",
                           ["Geometry/Local refinements = 2", "Material/Yield stress = 1e7",
                            "Contact/Die 0/Friction = frictionless",
                            f"Contact/Curvature tangent = {flag}",
                            "Solver/Residual tolerance = 1e-9"])
        steps, cutbacks, median = summary(rows)
        total = sum(int(float(r["newton_iterations"])) for r in rows[1:])
        force = -float(rows[-1]["die_punch_force_y"])
        runs[flag] = (result.returncode, total, median, force)
        print(f"elastic punch, Curvature tangent = {flag}: status {result.returncode}, {steps} "
              f"steps, {total} Newton iterations, median {median}, F = {force:.6f} N/mm")
    check("elastic punch: both tangents finish", runs["false"][0] == 0 and runs["true"][0] == 0)
    check("elastic punch: the same force at d = 1 mm (1e-7: frictionless elastic contact is "
          "path independent, both runs converge to 1e-9 of the force level)",
          abs(runs["true"][3] / runs["false"][3] - 1) <= 1e-7)
    check("elastic punch: the curvature term saves at least a quarter of the iterations "
          "(measured 58 against 134) and the median is at most 3",
          runs["true"][1] <= 0.75 * runs["false"][1] and runs["true"][2] <= 3)

    # 6. upsetting with the top face prescribed (u_r = 0, u_z = -0.15 t, no platen): the peer's
    # model. Q2 with 2 x 2 Gauss points (reduced integration, as the peer's quadratic element)
    # and no F-bar reaches 30 % on every mesh; F-bar with 3 x 3 points stops at 23 % (8 x 6).
    for cells in ("8, 6", "16, 12"):
        name = "top_prescribed_" + cells.replace(", ", "x")
        with open(f"{name}_bc.prm", "w", encoding="utf-8") as f:
            f.write(f"include {source}/prm/upsetting.prm\n"
                    "subsection Boundary conditions\n  set Number of conditions = 3\n"
                    "  subsection Condition 2\n    set Boundary id = 3\n"
                    "    set Type = displacement\n    set Components = x, y\n"
                    "    set Value = 0; -0.15*t\n  end\nend\n"
                    "subsection Contact\n  set Number of dies = 0\nend\n")
        result, rows = run(ausroll, source, "", name,
                           [f"Geometry/Rectangle/Cells = {cells}",
                            "Model/Quadrature points = 2",
                            "Model/Volumetric locking treatment = none",
                            "Postprocess/Reaction boundaries = 3"], base_path=f"{name}_bc.prm")
        steps, cutbacks, median = summary(rows)
        force = -1e-3 * float(rows[-1]["reaction_3_y"])
        folds = "the mesh folds" in result.stdout + result.stderr
        print(f"top face prescribed, Q2 2x2, {cells}: status {result.returncode}, {steps} steps, "
              f"{cutbacks} cutbacks, median Newton {median}, F(30 %) = {force:.1f} kN")
        check(f"top face prescribed {cells}: reaches 30 % with at most 2 cutbacks and no fold",
              result.returncode == 0 and abs(float(rows[-1]["time"]) - 30) < 1e-9
              and cutbacks <= 2 and not folds)
        check(f"top face prescribed {cells}: force at 30 % within 1 % of the finest meshes' "
              f"{TOP_PRESCRIBED_30} kN (the spread of 8 x 6 ... 64 x 48 is 0.8 %)",
              abs(force / TOP_PRESCRIBED_30 - 1) <= 0.01)
    return check.exit_status()


if __name__ == "__main__":
    sys.exit(main())
