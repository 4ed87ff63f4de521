#!/usr/bin/env python3
"""Process stages (`Stages`) checks on scenes/stage_quench.prm, each with its tolerance and why:

lumped     the block quenched from 850 C into the 250 C bath (h = 2), held, then cooled in 20 C
           air (h = 0.2): with the Biot number 2.2e-5 the temperature is uniform, and summing the
           backward-Euler heat equation over the nodes (partition of unity) gives the lumped
           recursion T_n+1 = (T_n + (dt / tau) T_a) / (1 + dt / tau), tau = rho c A / (h P), with
           the stage's T_a and h, exactly for a uniform field: T_mean of every row within 1e-4 K
           of it (the field is uniform to O(Bi (T - T_a)), which changes the heat flow by that
           relative amount: 3e-3 K with k = 1000 times steel's, Bi = 2.2e-5; the scene's
           conductivity is 1e5 times steel's, Bi = 2.2e-7: measured below). Against the
           exponential decay of each stage from the T_mean at its start (the closed form), the
           difference is backward Euler's first-order error: halving every stage's step must
           halve it (ratio 1.7 to 2.3).
switching  the stage ends are load-step ends: rows at t = 2, 3 and 13 (to 1e-12 s); the steps are
           0.1 s in the quench, 1 s (Loading's grid) in the hold and 0.5 s in the cooling; the
           history's column 'stage' is 0 for t <= 2, 1 for 2 < t <= 3 and 2 after; the log
           prints one line per stage start naming it.
single     the scene with one stage covering the run and no overrides equals the scene without
           stages in every column (the steps of Loading alone), and has the column 'stage' = 0.
resume     the run interrupted after step 30 (in the cooling stage; checkpoints every 4 steps,
           so it resumes from step 28 at t = 6.5 s) and resumed gives the uninterrupted history to
           the last digit; also on 2 MPI ranks (the resumed run on 2 ranks against the serial
           uninterrupted one: every column within 1e-8 of its largest magnitude, as check/thermal's
           np2: another partition, the same algebra, CG to 1e-12).

Usage: check_stages.py AUSROLL SOURCE_DIR [CASE ...]
"""

import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_thermal import history, run  # noqa: E402  (one way to run and read a scene)
from checklist import Checklist  # noqa: E402

RHO_C = 7.85e-9 * 4.6e8
AREA, PERIMETER = 4.0, 8.0
# (name, start, end, step, T_ambient, h)
STAGES = [("quench", 0.0, 2.0, 0.1, 250.0, 2.0), ("hold", 2.0, 3.0, 1.0, 250.0, 2.0),
          ("cooling", 3.0, 13.0, 0.5, 20.0, 0.2)]
T0 = 850.0


def without_stages(prm):
    """The text of PRM without its subsection Stages."""
    out, depth = [], 0
    for line in open(prm):
        words = line.split()
        if depth == 0 and words[:2] == ["subsection", "Stages"]:
            depth = 1
        elif depth > 0:
            depth += 1 if words[:1] == ["subsection"] else -1 if words[:1] == ["end"] else 0
        else:
            out.append(line)
    return "".join(out)


def stage_of(t):
    for k, stage in enumerate(STAGES):
        if t <= stage[2] + 1e-12:
            return k
    return len(STAGES) - 1


def lumped(times):
    """Backward-Euler lumped temperatures at TIMES (the rows' times, from 0)."""
    recursion = [T0]
    for t0, t1 in zip(times, times[1:]):
        _, _, _, _, ambient, h = STAGES[stage_of(t1)]
        a = (t1 - t0) / (RHO_C * AREA / (h * PERIMETER))
        recursion.append((recursion[-1] + a * ambient) / (1.0 + a))
    return recursion


def exponential_error(times, mean):
    """Per stage, the largest |T_mean - closed form| where the closed form is the exponential
    decay of the stage from the computed T_mean at the stage's start."""
    errors = []
    for _, start, end, _, ambient, h in STAGES:
        tau = RHO_C * AREA / (h * PERIMETER)
        T_start = next(m for t, m in zip(times, mean) if abs(t - start) < 1e-12)
        errors.append(max(abs(m - ambient - (T_start - ambient) * math.exp(-(t - start) / tau))
                          for t, m in zip(times, mean) if start < t <= end + 1e-12))
    return errors


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    cases = sys.argv[3:] or ["lumped", "switching", "single", "resume"]
    prm = os.path.join(source, "tests", "checks", "scenes", "stage_quench.prm")
    checks = Checklist()
    whole = run(ausroll, prm, [], "whole")
    rows = history("whole")
    times = [float(r["time"]) for r in rows]

    if "lumped" in cases:
        mean = [float(r["T_mean"]) for r in rows]
        worst = max(abs(a - b) for a, b in zip(mean, lumped(times)))
        print(f"lumped: largest |T_mean - backward-Euler recursion| = {worst:.3e} K")
        checks("lumped: T_mean equals the lumped backward-Euler recursion to 1e-4 K", worst < 1e-4)
        # the closed form: first-order convergence with the step, stage by stage
        halved = ["Stages/Stage 0/Step size=0.05", "Stages/Stage 2/Step size=0.25",
                  "Loading/Number of steps=26"]
        run(ausroll, prm, halved, "halved")
        fine = history("halved")
        coarse_errors = exponential_error(times, mean)
        fine_errors = exponential_error([float(r["time"]) for r in fine],
                                        [float(r["T_mean"]) for r in fine])
        for stage, e1, e2 in zip(STAGES, coarse_errors, fine_errors):
            print(f"lumped: stage {stage[0]}: largest |T_mean - exponential| {e1:.4f} K, "
                  f"with half the step {e2:.4f} K (ratio {e1 / e2:.3f})")
            checks(f"lumped: stage {stage[0]} converges to the closed form at first order "
                   "(error ratio 1.7 to 2.3 for half the step)", 1.7 < e1 / e2 < 2.3)

    if "switching" in cases:
        for end in (2.0, 3.0, 13.0):
            checks(f"switching: a row at the stage end t = {end:g}",
                   any(abs(t - end) < 1e-12 for t in times))
        steps = [(stage_of(t1), t1 - t0) for t0, t1 in zip(times, times[1:])]
        for k, stage in enumerate(STAGES):
            sizes = [dt for s, dt in steps if s == k]
            ok = sizes and all(abs(dt - stage[3]) < 1e-12 for dt in sizes)
            checks(f"switching: {len(sizes)} steps of {stage[3]:g} s in stage {stage[0]}", ok)
        column = [int(float(r["stage"])) for r in rows]
        checks("switching: the history's stage column follows the stage ends",
               column == [stage_of(t) for t in times])
        for k, stage in enumerate(STAGES):
            checks(f"switching: the log names the start of stage {k} ({stage[0]})",
                   f"Stage {k} ({stage[0]})" in whole.stdout)

    if "single" in cases:
        text = without_stages(prm)
        with open("no_stages.prm", "w") as f:
            f.write(text)
        with open("one_stage.prm", "w") as f:
            f.write(text + "subsection Stages\n  set Number of stages = 1\n"
                    "  subsection Stage 0\n    set End time = 13\n  end\nend\n")
        run(ausroll, "no_stages.prm", [], "no_stages")
        run(ausroll, "one_stage.prm", [], "one_stage")
        a, b = history("no_stages"), history("one_stage")
        same = len(a) == len(b) and all(ra[c] == rb[c] for ra, rb in zip(a, b) for c in ra
                                        if c != "wall_seconds")
        checks("single: one stage over the run equals no stages in every column", same)
        checks("single: no stage column without stages", "stage" not in a[0])
        checks("single: stage column 0 with one stage", all(r["stage"] == "0" for r in b))

    if "resume" in cases:
        base = ["Checkpoint/Interval=4"]
        run(ausroll, prm, base, "whole_checkpointed")
        for ranks in (0, 2):
            directory = f"resumed_np{ranks or 1}"
            shutil.rmtree(directory, ignore_errors=True)
            first = run(ausroll, prm, base + ["Checkpoint/Abort after step=30"], directory, mpi=ranks)
            checks(f"resume np={ranks or 1}: the first run stopped as asked (exit 99)",
                   first.returncode == 99)
            second = run(ausroll, prm, base, directory, extra=["--resume"], mpi=ranks)
            checks(f"resume np={ranks or 1}: resumed in the cooling stage",
                   "stage 2 (cooling)" in second.stdout)
            a, b = history("whole_checkpointed"), history(directory)
            if ranks == 0:
                ok = len(a) == len(b) and all(ra[c] == rb[c] for ra, rb in zip(a, b) for c in ra
                                              if c != "wall_seconds")
                checks("resume np=1: history identical to the uninterrupted run", ok)
            else:
                worst = 0.0
                for c in a[0]:
                    if c == "wall_seconds":
                        continue
                    scale = max(abs(float(r[c])) for r in a) or 1.0
                    worst = max([worst] + [abs(float(ra[c]) - float(rb[c])) / scale
                                           for ra, rb in zip(a, b)])
                print(f"resume np=2: largest relative difference {worst:.2e}")
                checks("resume np=2: same rows, every column within 1e-8",
                       len(a) == len(b) and worst < 1e-8)

    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
