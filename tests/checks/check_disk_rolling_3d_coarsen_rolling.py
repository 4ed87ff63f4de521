#!/usr/bin/env python3
"""Coarsening behind the die while rolling in 3D (issue 15, item 4).

Usage: check_disk_rolling_3d_coarsen_rolling.py AUSROLL SOURCE_DIR

Runs tests/checks/scenes/disk_rolling_3d_round_coarsen_rolling.prm: the coarse 24 x 2 x 2 Q2 thick
ring refined to level 1 in a 2 mm contact band, fed 0.762 mm at 90 degrees (t = 0 ... 4), then
rolled in 2.5 degree steps (t = 5 ... 11) with Coarsening distance = 2 mm, re-adapted after every
step. Checks:
  - coarsening while rolling: an adaptation after a rolling step (t >= 5; the log line
    `mesh adapted: N cells, M DoFs (R cells refined, C coarsened)` follows its step line) reports
    C > 0, and the history's cell count drops from one rolling step to the next;
  - behind the die: the output sub-cells of consecutive VTUs while rolling (a step's VTU is written
    after the adaptation that follows it), grouped by
    the coarse cell they lie in (15 degrees around, two rings, two layers; as
    check_disk_rolling_3d_coarsen.py), show at least one coarse cell going from level 1 back to
    level 0, and every such cell lies behind the die (its centre angle at least BEHIND = 15 degrees,
    one coarse cell, short of the contact angle 90 + revolution);
  - the band follows the die: the coarse cells of the outer ring and lower layer (the groove)
    within NEAR = 10 degrees of the die at the last step are at level 1;
  - force: force_radial < 0 at every loaded step; at the last step (after the coarsening) within
    STEADY = 2 % of the step three steps before (the same position in the 7.5 degree pattern of
    the level-1 cells: the force has this period while rolling; measured 0.7 %), so the coarsening
    behind the die does not disturb the contact;
  - Coulomb per node (contact CSVs of every rolling step): |R_T| <= mu R_n (1 + 1e-8) at every
    closed node, slipping nodes on the cone to 1e-8.
The np = 2 twin (check/disk_rolling_3d_round_coarsen_rolling_np2) compares the histories.
"""

import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, run_scene, CoulombCone  # noqa: E402
from check_disk_rolling_3d_coarsen import coarse_cells  # noqa: E402

MU = 0.3
BEHIND = 15.0
NEAR = 10.0
STEADY = 0.02
FEED_END = 4


def adaptations(log):
    """[(time of the step before, cells coarsened)] of the `mesh adapted` lines after a step."""
    out, t = [], None
    for line in log.splitlines():
        m = re.match(r"step\s+\d+\s+t =\s+(\S+)", line)
        if m:
            t = float(m.group(1))
        m = re.search(r"mesh adapted: .*, (\d+) coarsened\)", line)
        if m and t is not None:
            out.append((t, int(m.group(1))))
    return out


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "tests", "checks", "scenes", "disk_rolling_3d_round_coarsen_rolling.prm")
    stdout = run_scene(ausroll, prm)
    if stdout is None:
        return 1
    checks = Checklist()
    rows = {round(float(r["time"])): r for r in csv.DictReader(open("out/history.csv"))}
    last = max(rows)
    revolution = {t: float(r["die_roll_revolution"]) for t, r in rows.items()}
    rolled = [(t, c) for t, c in adaptations(stdout) if t > FEED_END and t < last]
    checks(f"coarsened cells per adaptation after a rolling step {rolled}: some > 0",
           any(c > 0 for _, c in rolled))
    cells = {t: int(r["cells"]) for t, r in rows.items()}
    drops = [t for t in cells if t > FEED_END + 1 and t - 1 in cells and cells[t] < cells[t - 1]]
    checks(f"cell count drops between rolling steps at t = {drops} "
           f"(cells {[cells[t] for t in sorted(cells)]})", len(drops) > 0)
    # the history's cell count is that of the mesh a step was solved on, so a drop at t means the
    # rolling step t - 1 -> t ran on the coarsened mesh
    checks(f"rolling steps solved on the coarsened mesh (revolution at t = {drops}: "
           f"{[revolution[t] for t in drops]} deg, one step before: {[revolution[t - 1] for t in drops]})",
           len(drops) > 0 and all(revolution[t] > revolution[t - 1] > 0 for t in drops))

    # the VTU of a step is written after the adaptation that follows it: compare consecutive VTUs
    back = []
    for t in range(FEED_END + 1, last + 1):
        before, after = coarse_cells(f"out/solution_{t - 1:04d}.0.vtu"), coarse_cells(f"out/solution_{t:04d}.0.vtu")
        die = 90.0 + revolution[t]
        for k in after:
            if before.get(k, (0, 0, 0))[1] == 1 and after[k][1] == 0:
                back.append((t, 15.0 * k[0] + 7.5, die))
    checks(f"{len(back)} coarse cells back from level 1 to level 0 while rolling (t, centre, die angle: {back})",
           len(back) >= 1)
    checks(f"all of them behind the die by >= {BEHIND} deg", all(die - a >= BEHIND for _, a, die in back))
    final = coarse_cells(f"out/solution_{last:04d}.0.vtu")
    die = 90.0 + revolution[last]
    groove = [k for k in final if abs(15.0 * k[0] + 7.5 - die) < NEAR and k[1] == 1 and k[2] == 0]
    checks(f"{len(groove)} groove cells within {NEAR} deg of the die at level 1 at t = {last}",
           len(groove) > 0 and all(final[k][0] == 1 for k in groove))

    radial = {t: float(r["die_roll_force_radial"]) for t, r in rows.items()}
    loaded = [t for t in rows if t >= 1]
    checks(f"force_radial < 0 at every loaded step (largest {max(radial[t] for t in loaded):.4g} N)",
           all(radial[t] < 0 for t in loaded))
    change = abs(radial[last] / radial[last - 3] - 1.0)
    checks(f"force_radial after the coarsening {radial[last]:.5g} N within {STEADY:.0%} of t = {last - 3} "
           f"({radial[last - 3]:.5g} N): {change:.2%}", change < STEADY)
    cone = CoulombCone([f"out/contact_{t:04d}.csv" for t in rows if t > FEED_END], MU)
    cone.check(checks)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
