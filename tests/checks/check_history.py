#!/usr/bin/env python3
"""Assertions on a history.csv at given times, each with its own tolerance.

  --value COLUMN TIME EXPECTED TOL        |h[COLUMN](TIME) - EXPECTED| <= TOL * max(|EXPECTED|, 1)
                                          (TOL is relative for |EXPECTED| >= 1, absolute below)
  --ratio NUM DEN TIME EXPECTED TOL       |h[NUM]/h[DEN] - EXPECTED| <= TOL
  --range COLUMN TIME LOW HIGH            LOW <= h[COLUMN](TIME) <= HIGH
TIME selects the row whose `time` is closest (it must match within 1e-9 relative).
Exit status 0 if all hold, 1 otherwise, 2 on usage/data errors.
"""

import argparse
import csv
import sys


def main():
    p = argparse.ArgumentParser(description="assertions on history.csv")
    p.add_argument("history")
    p.add_argument("--value", nargs=4, action="append", default=[],
                   metavar=("COLUMN", "TIME", "EXPECTED", "TOL"))
    p.add_argument("--ratio", nargs=5, action="append", default=[],
                   metavar=("NUM", "DEN", "TIME", "EXPECTED", "TOL"))
    p.add_argument("--range", nargs=4, action="append", default=[],
                   metavar=("COLUMN", "TIME", "LOW", "HIGH"))
    a = p.parse_args()
    try:
        rows = list(csv.DictReader(open(a.history)))
    except OSError as e:
        print(f"check_history.py: cannot read {a.history}: {e.strerror}", file=sys.stderr)
        return 2

    def row_at(t):
        t = float(t)
        best = min(rows, key=lambda r: abs(float(r["time"]) - t))
        if abs(float(best["time"]) - t) > 1e-9 * max(1.0, abs(t)):
            print(f"check_history.py: no row at time {t}", file=sys.stderr)
            sys.exit(2)
        return best

    def col(r, c):
        if c not in r:
            print(f"check_history.py: no column '{c}' (have: {', '.join(r)})", file=sys.stderr)
            sys.exit(2)
        return float(r[c])

    failed = 0
    for c, t, e, tol in a.value:
        v, e, tol = col(row_at(t), c), float(e), float(tol)
        ok = abs(v - e) <= tol * max(abs(e), 1.0)
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {c}(t={t}) = {v:.10g}, expected {e:.10g} (tol {tol:g})")
    for n, d, t, e, tol in a.ratio:
        r = row_at(t)
        v, e, tol = col(r, n) / col(r, d), float(e), float(tol)
        ok = abs(v - e) <= tol
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {n}/{d}(t={t}) = {v:.10g}, expected {e:.10g} (tol {tol:g})")
    for c, t, lo, hi in a.range:
        v = col(row_at(t), c)
        ok = float(lo) <= v <= float(hi)
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {c}(t={t}) = {v:.10g} in [{lo}, {hi}]")
    print("passed" if not failed else f"{failed} assertion(s) failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
