#!/usr/bin/env python3
"""Compare two history.csv files column by column (e.g. an np=1 and an np=2 run of one scene).

For every column present in both files (except those given with --ignore) and every row, the
difference |a - b| is measured relative to the column's scale max_k max(|a_k|, |b_k|); the check
fails if any relative difference exceeds --rel-tol, or if the files differ in rows or columns.

Exit status: 0 agree, 1 differ, 2 usage/data error.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from history_csv import read_rows  # noqa: E402


def read(path):
    return read_rows(path, "compare_histories.py")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("first")
    parser.add_argument("second")
    parser.add_argument("--rel-tol", type=float, default=1e-8)
    parser.add_argument("--ignore", nargs="*", default=["wall_seconds"])
    parser.add_argument("--noise-floor", type=float, default=1e-9,
                        help="columns whose values all stay below this fraction of the largest "
                             "force-like value in the file are round-off and not compared")
    args = parser.parse_args()

    a, b = read(args.first), read(args.second)
    if len(a) != len(b):
        print(f"different number of rows: {len(a)} vs {len(b)} (scripts/compare_histories.py "
              f"aligns the two on time and shows where they differ)")
        return 1
    columns = [c for c in a[0].keys() if c not in args.ignore]
    missing = [c for c in columns if c not in b[0]]
    if missing:
        print(f"columns missing in {args.second}: {missing}")
        return 1

    largest = 0.0
    for c in columns:
        if c in ("step", "time", "load_factor", "dofs", "cells", "newton_iterations", "cutbacks"):
            continue
        for r in a + b:
            largest = max(largest, abs(float(r[c])))
    worst = (0.0, None, None)
    for c in columns:
        va = [float(r[c]) for r in a]
        vb = [float(r[c]) for r in b]
        scale = max(max(abs(x) for x in va), max(abs(x) for x in vb))
        if scale == 0.0 or scale < args.noise_floor * largest:
            continue
        for k, (x, y) in enumerate(zip(va, vb)):
            d = abs(x - y) / scale
            if d > worst[0]:
                worst = (d, c, k)
    d, c, k = worst
    where = f" (column {c}, row {k})" if c else ""
    print(f"{len(columns)} columns x {len(a)} rows compared; max relative difference {d:.3e}{where}; "
          f"tolerance {args.rel_tol:g}")
    if d > args.rel_tol:
        print("FAILED")
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
