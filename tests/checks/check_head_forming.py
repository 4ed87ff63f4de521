#!/usr/bin/env python3
"""Head forming (prm/head_forming.prm, doc/scenes/head_forming.md) with the check for workpiece
boundaries that pass through a die on: the documented answer, and no false alarm.

Usage: check_head_forming.py AUSROLL SOURCE_DIR

Runs the shipped scene (no-slip top, 160 steps to 40 % height reduction, about 3 s) with
`Contact/Penetrating boundaries = add` (the default) and `= warn`. The bore (a polyline that ends
at the die face z = 10 mm) and the shoulder (a polyline that starts at the bore's edge r = 10 mm)
are extended to infinity for the contact only; a node beyond the end of a die is not inside it.
Before that was so, `add` made the free surface above the die face (id 4, bulging out to
r > 10 mm) a candidate of the bore, which then held it at r = 10 mm: the head could not form,
the shoulder was never touched and the punch force at 40 % was 44.9 MN; `warn` warned that the
lateral surface in the bore (id 1) passes through the shoulder at (10, 8), below its end point.

Asserts, for both settings:
  - exit status 0, all 160 steps, and no note or warning that a boundary passes through a die;
  - the punch force at 10, 20, 30 and 40 % within 1 % of the table of doc/scenes/head_forming.md
    (no-slip top: 288.5, 375.2, 564.1, 977.7 kN). The doc states no error bar (no mesh sequence
    exists, the finer Q2 meshes stop at the die corner); the table was measured on 2026-11-23 at
    the former Newton tolerance 1e-9, and the answer of the current solver differs from it by
    0.24 % at 40 % (975.4 kN, doc's results box). 1 % keeps that margin four times and fails on
    any change of the contact problem (the bore holding the free surface: a factor 46);
  - the shoulder force at 40 % within 2 % of the table's 312.9 kN (it rises in steps as further
    nodes land on the shoulder, so it moves more with the tolerance: measured 310.5 kN, -0.8 %),
    and the first shoulder contact between 18.5 % and 19.25 % (table 19.00 %, measured 18.75 %:
    within one step, 0.25 %, of the table);
  - the two settings give the same history (no boundary is added, so the runs are the same).
"""

import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, ausroll_command  # noqa: E402

PUNCH_KN = {10.0: 288.5, 20.0: 375.2, 30.0: 564.1, 40.0: 977.7}  # doc table, no-slip top
SHOULDER_KN_40 = 312.9
FIRST_CONTACT = (18.5, 19.25)


def run(ausroll, prm, directory, setting):
    args = ausroll_command(ausroll, prm, [f"Output/Directory={directory}", "Output/Write VTU=false",
                                          f"Contact/Penetrating boundaries={setting}"])
    r = subprocess.run(args, capture_output=True, text=True)
    print(r.stdout[-2000:])
    rows = []
    if os.path.exists(f"{directory}/history.csv"):
        rows = list(csv.DictReader(open(f"{directory}/history.csv")))
    return r.returncode, r.stdout + r.stderr, rows


def check_run(checks, setting, rc, log, rows):
    last = int(rows[-1]["step"]) if rows else 0  # the history starts with step 0 (t = 0)
    checks(f"{setting}: exit status 0 ({rc}) and 160 steps (last step {last})", rc == 0 and last == 160)
    through = [line for line in log.splitlines() if "passes through die" in line]
    checks(f"{setting}: no boundary passes through a die ({len(through)} notes or warnings)"
           + ("".join("\n     " + line for line in through)), not through)
    by_time = {round(float(r["time"]), 9): r for r in rows}
    for t, reference in PUNCH_KN.items():
        if t not in by_time:
            checks(f"{setting}: the history reaches {t} %", False)
            continue
        force = -float(by_time[t]["die_punch_force_y"]) / 1e3
        checks(f"{setting}: punch force at {t:g} % {force:.1f} kN within 1 % of the documented "
               f"{reference} kN ({force / reference - 1:+.2%})", abs(force / reference - 1) <= 0.01)
    if 40.0 in by_time:
        shoulder = float(by_time[40.0]["die_shoulder_force_y"]) / 1e3
        checks(f"{setting}: shoulder force at 40 % {shoulder:.1f} kN within 2 % of the documented "
               f"{SHOULDER_KN_40} kN ({shoulder / SHOULDER_KN_40 - 1:+.2%})",
               abs(shoulder / SHOULDER_KN_40 - 1) <= 0.02)
    touched = [float(r["time"]) for r in rows
               if float(r["die_shoulder_stick_nodes"]) + float(r["die_shoulder_slip_nodes"]) > 0]
    first = touched[0] if touched else None
    checks(f"{setting}: first shoulder contact at {first} % in [{FIRST_CONTACT[0]}, {FIRST_CONTACT[1]}]",
           first is not None and FIRST_CONTACT[0] <= first <= FIRST_CONTACT[1])


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "prm", "head_forming.prm")
    checks = Checklist()
    runs = {setting: run(ausroll, prm, setting, setting) for setting in ("add", "warn")}
    for setting, (rc, log, rows) in runs.items():
        check_run(checks, setting, rc, log, rows)
    columns = ("die_punch_force_y", "die_shoulder_force_y", "corner_ux", "top_ux")
    same = all(a[c] == b[c] for a, b in zip(runs["add"][2], runs["warn"][2]) for c in columns)
    checks("add and warn give the same history", same and len(runs["add"][2]) == len(runs["warn"][2]))
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
