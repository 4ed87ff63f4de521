#!/usr/bin/env python3
"""Contact/Penetrating boundaries in 3D: the quarter-cylinder upsetting with the platen on the top
face only (issue 17's second case, in 3D).

Usage: check_penetrating_boundaries_3d.py AUSROLL SOURCE_DIR

Runs prm/upsetting_3d.prm on its coarse mesh (one global refinement, as check/upsetting_3d),
sticking platen, predictor and adaptive steps, to 20 % height reduction:
  (a) as shipped: Candidate boundaries = 4 (top face), 2 (curved side);
  (b) Candidate boundaries = 4 only, Penetrating boundaries = add (the default);
  (c) Candidate boundaries = 4 only, Penetrating boundaries = warn.
The free side bulges and rolls onto the platen near 19-20 % (the side node at the top corner
reaches it). Asserts:
  - (b) says once that boundary 2 passes through die 0 and is now a candidate, naming the entry
    to add; the run finishes (exit 0);
  - (b) the platen force at 20 % within 0.5 % of (a): once added, the side is in contact as in the
    shipped scene; the remaining difference is the part of a step in which the side was not yet
    a candidate (measured 0.09 %); at 15 %, before any side node reaches the platen, the two are
    equal to 1e-9 (the same problem);
  - (c) warns once that boundary 2 passes through the platen, naming the entry to change; no note.
"""

import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, ausroll_command  # noqa: E402

COMMON = ["Geometry/Global refinements=1", "Loading/End time=20", "Loading/Number of steps=20",
          "Output/Write VTU=false", "Loading/Predictor=linear extrapolation",
          "Loading/Step control=adaptive"]


def run(ausroll, prm, directory, extra):
    args = ausroll_command(ausroll, prm, COMMON + [f"Output/Directory={directory}"] + extra)
    r = subprocess.run(args, capture_output=True, text=True)
    print(r.stdout[-3000:])
    forces = {}
    if os.path.exists(f"{directory}/history.csv"):
        for row in csv.DictReader(open(f"{directory}/history.csv")):
            forces[round(float(row["time"]), 9)] = float(row["die_platen_force_z"])
    return r.returncode, r.stdout + r.stderr, forces


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "prm", "upsetting_3d.prm")
    checks = Checklist()
    rc_a, _, f_a = run(ausroll, prm, "shipped", [])
    rc_b, log_b, f_b = run(ausroll, prm, "add", ["Contact/Die 0/Candidate boundaries=4"])
    rc_c, log_c, _ = run(ausroll, prm, "warn", ["Contact/Die 0/Candidate boundaries=4",
                                                "Contact/Penetrating boundaries=warn"])
    checks(f"exit status 0 of the three runs ({rc_a}, {rc_b}, {rc_c})", rc_a == rc_b == rc_c == 0)
    notes = [line for line in log_b.splitlines() if "note: boundary 2 of the workpiece passes through die 0" in line]
    checks(f"add: said once that boundary 2 is now a candidate ({len(notes)} notes)",
           len(notes) == 1 and "it is now a candidate of that die" in notes[0]
           and "Add 2 to Contact/Die 0/Candidate boundaries" in notes[0])
    ok = 20.0 in f_a and 20.0 in f_b and 15.0 in f_a and 15.0 in f_b
    checks("both histories reach 15 % and 20 %", ok)
    if ok:
        d20 = abs(f_b[20.0] / f_a[20.0] - 1.0)
        d15 = abs(f_b[15.0] / f_a[15.0] - 1.0)
        checks(f"add: platen force at 20 % {f_b[20.0]:.6g} N within 0.5 % of the shipped candidates' "
               f"{f_a[20.0]:.6g} N ({d20:.2%})", d20 <= 5e-3)
        checks(f"at 15 % (no side node at the platen yet) equal to 1e-9 ({d15:.1e})", d15 <= 1e-9)
    warnings = [line for line in log_c.splitlines() if "warning: boundary 2 of the workpiece passes through die 0" in line]
    checks(f"warn: warned once, naming the entry ({len(warnings)} warnings)",
           len(warnings) == 1 and "Add 2 to Contact/Die 0/Candidate boundaries" in warnings[0]
           and "now a candidate" not in log_c)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
