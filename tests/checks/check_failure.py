#!/usr/bin/env python3
"""Check how a run that must fail ended (see run_failure_check.cmake).

  check_failure.py RUN_LOG EXIT_STATUS OUTPUT_DIR --expect-status 3 --expect-message TEXT
                   --max-column COLUMN LIMIT
The exit status must match, stderr/stdout must contain TEXT, history.csv must be complete (every
row has all columns, numbers only) with COLUMN below LIMIT in every row (only converged states),
and solution.pvd must list only existing .pvtu files whose .vtu pieces exist.
"""
import argparse
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET


def main():
    p = argparse.ArgumentParser()
    p.add_argument("log")
    p.add_argument("status", type=int)
    p.add_argument("directory")
    p.add_argument("--expect-status", type=int, required=True)
    p.add_argument("--expect-message", required=True)
    p.add_argument("--max-column", nargs=2, default=None)
    a = p.parse_args()
    failures = []
    log = open(a.log).read()
    if a.status != a.expect_status:
        failures.append(f"exit status {a.status}, expected {a.expect_status}")
    if a.expect_message not in log:
        failures.append(f"message '{a.expect_message}' missing")
    rows = list(csv.reader(open(os.path.join(a.directory, "history.csv"))))
    header, data = rows[0], rows[1:]
    for r in data:
        if len(r) != len(header) or not all(math.isfinite(float(x)) for x in r):
            failures.append(f"damaged history row {r}")
    if a.max_column:
        c, limit = header.index(a.max_column[0]), float(a.max_column[1])
        worst = max(float(r[c]) for r in data)
        if worst >= limit:
            failures.append(f"history has {a.max_column[0]} = {worst} >= {limit}")
    root = ET.parse(os.path.join(a.directory, "solution.pvd")).getroot()
    for d in root.findall(".//DataSet"):
        pvtu = os.path.join(a.directory, d.get("file"))
        if not os.path.exists(pvtu):
            failures.append(f"{pvtu} missing")
            continue
        for piece in ET.parse(pvtu).getroot().findall(".//Piece"):
            if not os.path.exists(os.path.join(os.path.dirname(pvtu), piece.get("Source"))):
                failures.append(f"piece {piece.get('Source')} of {pvtu} missing")
    print(f"{len(data)} converged history rows, {len(root.findall('.//DataSet'))} outputs")
    for f in failures:
        print("FAIL:", f)
    print("passed" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
