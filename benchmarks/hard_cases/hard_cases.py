#!/usr/bin/env python3
"""Hard cases of issue 17 on mesh sequences (doc/scenes/hard_cases.md, doc/studies/benchmarks_journal.md):

  punch      prm/hard_punch.prm, Local refinements = 2, 3, 4 (cells of 0.625, 0.31, 0.156 mm
             under the punch), to d = 1 mm;
  upsetting  prm/upsetting.prm (platen contact on the top face and the free surface, F-bar) with
             the predictor and the adaptive step control, Q2 8 x 6, 16 x 12, 32 x 24, 64 x 48,
             to 30 %;
  upsetting_shipped  the same meshes with the stepping of the file (120 equal steps, the
             linear predictor: the peer code's increments);
  curvature  Contact/Curvature tangent: the elastic frictionless punch with the old and the new
             tangent, the plastic punch (refinements 3) with the new one;
  top_only   the upsetting with the platen on the top face only (Candidate boundaries = 3) on
             8 x 6, 16 x 12, 32 x 24: the side surface becomes a candidate when it reaches the
             platen (Contact/Penetrating boundaries = add, the default) and the run finishes
             like the shipped scene; with "warn" (8 x 6) it warns and fails before 30 % (24.2 %
             with the defaults of 2026-12-06).
  events     where the Newton solves go (doc/studies/hard_cases.md, section 11): the punch
  events_indentation  (refinements 2 and 3, and 2 with Target Newton iterations = 4) and
             prm/indentation.prm as shipped. "events" is not among the default cases: "punch"
             runs refinements 2 and 3 already.

Every run writes a verbose log (Output/Verbosity = verbose); the log of a run with the adaptive
step control is split by event_steps.py into steps with and without contact status changes (one
more Markdown row per run).

With --old the same meshes run with the stepping of before (Step control = halving, Predictor =
none, Contact/Strategy = active set). Prints one Markdown row per run (steps, cutbacks, Newton
iterations per step: median and max, CPU seconds, force) and, where three meshes finished, the
Richardson extrapolation of the force with the observed order. No pass/fail: the assertions on
the short versions are in tests/checks/check_hard_cases.py.

Usage: hard_cases.py --ausroll build/ausroll --work DIR [--old] [--cases punch upsetting]
"""

import argparse
import csv
import math
import os
import resource
import statistics
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import event_steps  # noqa: E402  (benchmarks/hard_cases/event_steps.py)

UPSETTING_MESHES = [(f"{nx} x {ny}", [f"Geometry/Rectangle/Cells = {nx}, {ny}"])
                    for nx, ny in ((8, 6), (16, 12), (32, 24), (64, 48))]
CASES = {
    "punch": ("hard_punch.prm", "die_punch_force_y", 1.0, [
        ("refinements 2", ["Geometry/Local refinements = 2"]),
        ("refinements 3", ["Geometry/Local refinements = 3"]),
        ("refinements 4", ["Geometry/Local refinements = 4"])]),
    "upsetting": ("upsetting.prm", "die_platen_force_y", 1e-3, UPSETTING_MESHES),
    "upsetting_shipped": ("upsetting.prm", "die_platen_force_y", 1e-3, UPSETTING_MESHES),
    # the curvature term of the slip-node tangent (Contact/Curvature tangent), elastic and
    # plastic punch; and the upsetting with the platen on the top face only (warns that the
    # side surface passes through the platen, then folds)
    "curvature": ("hard_punch.prm", "die_punch_force_y", 1.0, [
        ("elastic, refinements 2, old tangent",
         ["Geometry/Local refinements = 2", "Material/Yield stress = 1e7",
          "Contact/Die 0/Friction = frictionless"]),
        ("elastic, refinements 2, curvature tangent",
         ["Geometry/Local refinements = 2", "Material/Yield stress = 1e7",
          "Contact/Die 0/Friction = frictionless", "Contact/Curvature tangent = true"]),
        ("refinements 3, curvature tangent",
         ["Geometry/Local refinements = 3", "Contact/Curvature tangent = true"])]),
    "top_only": ("upsetting.prm", "die_platen_force_y", 1e-3, [
        ("8 x 6", ["Geometry/Rectangle/Cells = 8, 6", "Contact/Die 0/Candidate boundaries = 3"]),
        ("16 x 12", ["Geometry/Rectangle/Cells = 16, 12",
                     "Contact/Die 0/Candidate boundaries = 3"]),
        ("32 x 24", ["Geometry/Rectangle/Cells = 32, 24",
                     "Contact/Die 0/Candidate boundaries = 3"]),
        ("8 x 6, warn", ["Geometry/Rectangle/Cells = 8, 6",
                         "Contact/Die 0/Candidate boundaries = 3",
                         "Contact/Penetrating boundaries = warn"])]),
    "events": ("hard_punch.prm", "die_punch_force_y", 1.0, [
        ("refinements 2", ["Geometry/Local refinements = 2"]),
        ("refinements 2, target 4", ["Geometry/Local refinements = 2",
                                     "Loading/Adaptive/Target Newton iterations = 4"]),
        ("refinements 3", ["Geometry/Local refinements = 3"])]),
    "events_indentation": ("indentation.prm", "die_punch_force_y", 1.0, [
        ("as shipped", [])]),
}
DEFAULT_CASES = [case for case in CASES if case != "events"]
ADAPTIVE = ["Loading/Predictor = linear extrapolation", "Loading/Step control = adaptive"]
NEW = {"punch": [], "upsetting": ADAPTIVE, "upsetting_shipped": [], "curvature": [],
       "top_only": ADAPTIVE, "events": [], "events_indentation": []}
OLD = ["Loading/Step control = halving", "Loading/Predictor = none",
       "Contact/Strategy = active set"]


def run(ausroll, work, name, base, overrides):
    prm = os.path.join(work, name + ".prm")
    out = os.path.join(work, name)
    subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "prm_variant.py"),
                    os.path.join(SOURCE, "prm", base), prm, f"Output/Directory = {out}",
                    "Output/Write VTU = false", "Output/Verbosity = verbose"] + overrides,
                   check=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(out + ".log", "w") as log:
        status = subprocess.run([ausroll, prm, "--overwrite"], stdout=log, stderr=subprocess.STDOUT).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))[1:]
    with open(out + ".log", errors="replace") as f:
        lines = f.readlines()
    warned = any("warning: the mesh folds" in line for line in lines)
    # (solves, status changes) per step from the step-control lines (adaptive stepping only)
    return status, rows, cpu, warned, event_steps.read_steps(lines)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ausroll", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--old", action="store_true")
    p.add_argument("--cases", nargs="+", default=DEFAULT_CASES)
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    print("| case | mesh | status | end | steps | cutbacks | Newton median / max | CPU s | force | "
          "fold warning |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---|")
    for case in a.cases:
        base, column, scale, meshes = CASES[case]
        forces = []
        for label, overrides in meshes:
            name = f"{case}_{label.replace(' ', '')}" + ("_old" if a.old else "")
            status, rows, cpu, warned, steps = run(a.ausroll, a.work, name, base,
                                                   overrides + (OLD if a.old else NEW[case]))
            newton = [int(float(r["newton_iterations"])) for r in rows]
            cutbacks = sum(int(float(r["cutbacks"])) for r in rows)
            force = -scale * float(rows[-1][column]) if rows else float("nan")
            end = float(rows[-1]["time"]) if rows else 0.
            if status == 0:
                forces.append(force)
            print(f"| {case}{' (old)' if a.old else ''} | {label} | {status} | {end:.4g} | "
                  f"{len(rows)} | {cutbacks} | {statistics.median(newton) if newton else 0} / "
                  f"{max(newton) if newton else 0} | {cpu:.0f} | {force:.1f} | "
                  f"{'yes' if warned else 'no'} |", flush=True)
            if steps:
                split = event_steps.summary(steps)
                ev, other = split["events"], split["others"]
                print(f"|   | {label}: steps with status changes {ev['steps']} ({ev['solves']} "
                      f"solves, median {ev['median']:g}); without {other['steps']} "
                      f"({other['solves']} solves, median {other['median']:g}) | | | | | | | | |",
                      flush=True)
        if case in ("curvature", "top_only", "events", "events_indentation"):
            continue
        forces = forces[-3:]  # the three finest meshes that finished
        ratio = ((forces[1] - forces[0]) / (forces[2] - forces[1])
                 if len(forces) == 3 and forces[2] != forces[1] else 0.)
        if len(forces) == 3 and ratio > 1:
            order = math.log(ratio) / math.log(2)
            extrapolated = forces[2] + (forces[2] - forces[1]) / (ratio - 1)
            print(f"\n{case}: monotone, observed order {order:.2f}, extrapolated force "
                  f"{extrapolated:.1f} +- {abs(extrapolated - forces[2]):.1f}\n")
        elif len(forces) == 3:
            print(f"\n{case}: forces {', '.join(f'{f:.1f}' for f in forces)}: the differences "
                  f"do not shrink with the mesh (ratio {ratio:.2f}), no extrapolation\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
