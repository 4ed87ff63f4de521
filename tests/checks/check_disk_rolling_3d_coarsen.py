#!/usr/bin/env python3
"""Coarsening behind the die in 3D (issue 15, item 4).

Usage: check_disk_rolling_3d_coarsen.py AUSROLL SOURCE_DIR

Runs tests/checks/scenes/disk_rolling_3d_round_coarsen_short.prm: the coarse 24 x 2 x 2 Q2 thick
ring refined to level 1 in a 2 mm contact band, fed 0.762 mm at 90 degrees, lifted, moved 90
degrees along the rim while lifted and fed again at 180 degrees (Keep plastic strain above = 0.05).
The output sub-cells of the last VTU before the move (t = 3) and of the last one (t = 5) are
grouped by the coarse cell they lie in (15 degrees around, the two radial rings split at
r = 30.675 mm, the two layers split at z = 6.35 mm; VTU points are the undeformed ones). Checks:
  - coarsening happened: the log reports coarsened cells and the history's cell count drops at the
    adaptation after the move (n_active_cells at t = 5 below t = 4);
  - behind the die: every coarse cell farther than FAR = 60 degrees from the die at t = 5 (the
    coarsening distance 2 (band + cell size) = 2 (2 + 9.1) = 22 mm is about 53 degrees on the rim)
    is either back at level 0 in all its sub-cells or kept at level 1 with plastic strain (VTU
    maximum of its sub-cells above KEPT = 0.02: the output is a cell average, below the point
    maximum > 0.05 that the rule looks at); at least one coarse cell went from level 1 (t = 3) to
    level 0 (t = 5) and at least one plastic groove cell stayed at level 1;
  - the band follows the die: every coarse cell of the outer ring and lower layer within 10 degrees
    of the new die position (the groove there) is at level 1 at t = 5;
  - force: force_radial < 0 at the loaded steps (t = 1, 2, 5); zero force (|F| < 1e-9 N, no
    closed node) while lifted (t = 3, 4);
  - Coulomb per node (contact CSVs of t = 1, 2, 5): |R_T| <= mu R_n (1 + 1e-8) at every closed node,
    slipping nodes on the cone to 1e-8.
The np = 2 twin (check/disk_rolling_3d_round_coarsen_short_np2) compares the histories to 1e-8.
"""

import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, run_scene, CoulombCone  # noqa: E402
from check_disk_rolling_3d_adaptive import arrays  # noqa: E402

MU = 0.3
DIE_ANGLE = 180.0  # 90 degrees (initial line) + 90 degrees moved
FAR = 60.0
NEAR = 10.0
KEPT = 0.02


def coarse_cells(path):
    """{(angle index, ring, layer): (min level, max level, max plastic strain)} of a VTU."""
    a = arrays(path)
    pts, conn, offs = a["points"], a["connectivity"], a["offsets"]
    level, eps = a["level"], a["equivalent_plastic_strain"]
    out, start = {}, 0
    for end in offs:
        ids = conn[start:end]
        start = end
        x, y, z = (sum(pts[3 * i + k] for i in ids) / len(ids) for k in range(3))
        angle = math.degrees(math.atan2(y, x)) % 360.0
        key = (int(angle // 15.0), int(math.hypot(x, y) > 30.675), int(z > 6.35))
        lev = round(level[ids[0]])
        e = max(eps[i] for i in ids)
        lo, hi, em = out.get(key, (lev, lev, e))
        out[key] = (min(lo, lev), max(hi, lev), max(em, e))
    return out


def angle_from_die(key):
    centre = 15.0 * key[0] + 7.5
    return abs((centre - DIE_ANGLE + 180.0) % 360.0 - 180.0)


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "tests", "checks", "scenes", "disk_rolling_3d_round_coarsen_short.prm")
    stdout = run_scene(ausroll, prm)
    if stdout is None:
        return 1
    checks = Checklist()
    coarsened = [int(m.group(1)) for m in re.finditer(r"mesh adapted: .*, (\d+) coarsened\)", stdout)]
    checks(f"coarsened cells per adaptation {coarsened}: some > 0", any(c > 0 for c in coarsened))
    rows = {round(float(r["time"]), 9): r for r in csv.DictReader(open("out/history.csv"))}
    cells = {t: int(r["cells"]) for t, r in rows.items()}
    checks(f"n_active_cells drops after the move ({cells[4]} at t = 4 -> {cells[5]} at t = 5)",
           cells[5] < cells[4])

    before, after = coarse_cells("out/solution_0003.0.vtu"), coarse_cells("out/solution_0005.0.vtu")
    far = [k for k in after if angle_from_die(k) > FAR]
    mixed = [k for k in far if after[k][0] != after[k][1]]
    unexplained = [k for k in far if after[k][1] == 1 and after[k][2] <= KEPT]
    back = [k for k in far if before.get(k, (0, 0, 0))[1] == 1 and after[k][1] == 0]
    kept = [k for k in far if after[k][1] == 1 and after[k][2] > KEPT]
    checks(f"{len(far)} coarse cells > {FAR} deg behind: none partly refined ({len(mixed)}), none at level 1 "
           f"without plastic strain ({len(unexplained)})", len(far) > 0 and not mixed and not unexplained)
    checks(f"{len(back)} coarse cells from level 1 (t = 3) back to level 0 (t = 5)", len(back) >= 1)
    checks(f"{len(kept)} plastic groove cells kept at level 1 (max eps "
           f"{max((after[k][2] for k in kept), default=0):.3g})", len(kept) >= 1)
    groove = [k for k in after if angle_from_die(k) < NEAR and k[1] == 1 and k[2] == 0]
    checks(f"{len(groove)} groove cells within {NEAR} deg of the die at level 1",
           len(groove) > 0 and all(after[k][0] == 1 for k in groove))

    radial = {t: float(r["die_roll_force_radial"]) for t, r in rows.items()}
    mag = {t: float(r["die_roll_force_magnitude"]) for t, r in rows.items()}
    checks(f"force_radial < 0 loaded ({radial[1]:.4g}, {radial[2]:.4g}, {radial[5]:.4g} N)",
           all(radial[t] < 0 for t in (1, 2, 5)))
    checks(f"no force while lifted ({mag[3]:.3g}, {mag[4]:.3g} N)", all(abs(mag[t]) < 1e-9 for t in (3, 4)))
    cone = CoulombCone([f"out/contact_000{i}.csv" for i in (1, 2, 5)], MU)
    cone.check(checks)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
