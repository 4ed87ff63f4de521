#!/usr/bin/env python3
"""Compare a result curve y(x) from a CSV file with a reference curve from another CSV file.

The reference is interpolated linearly at the result's x values (only those inside the
reference's x range, and >= --x-min if given). For each point the relative error

    |y_result * scale - y_reference| / max(|y_reference|, abs_floor)

is computed; a short table and the maximum error are printed.

Exit status: 0 if the maximum error is <= --rel-tol, 1 if it is larger, 2 on usage errors
(missing file or column, no comparable points, non-numeric data).

Example (thick cylinder, u(b) against pressure):
    compare_curves.py --result history.csv --reference thick_cylinder_load.csv \\
        --x-result pressure --y-result u_outer --x-reference pressure --y-reference u_outer \\
        --rel-tol 0.005 --x-min 1
"""

import argparse
import csv
import math
import sys


def fail(message):
    """Usage/data error: message on stderr, exit status 2."""
    print(f"compare_curves.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_columns(path, x_name, y_name):
    """Returns the (x, y) pairs of columns x_name and y_name of the CSV file at path."""
    try:
        with open(path, newline="") as f:
            # skip comment lines (starting with '#') and blank lines
            lines = [l for l in f if l.strip() and not l.lstrip().startswith("#")]
    except OSError as e:
        fail(f"cannot read '{path}': {e.strerror}")
    reader = csv.DictReader(lines, skipinitialspace=True)
    if reader.fieldnames is None:
        fail(f"'{path}' is empty")
    columns = [c.strip() for c in reader.fieldnames]
    reader.fieldnames = columns
    for name in (x_name, y_name):
        if name not in columns:
            fail(f"column '{name}' not found in '{path}' (columns: {', '.join(columns)})")
    points = []
    for line_no, row in enumerate(reader, start=2):
        try:
            x = float(row[x_name])
            y = float(row[y_name])
        except (TypeError, ValueError):
            fail(f"'{path}' row {line_no}: non-numeric value in '{x_name}' or '{y_name}'")
        if not (math.isfinite(x) and math.isfinite(y)):
            fail(f"'{path}' row {line_no}: non-finite value in '{x_name}' or '{y_name}'")
        points.append((x, y))
    if not points:
        fail(f"'{path}' has no data rows")
    return points


def prepare_reference(points, path):
    """Sorts the reference by x; equal x values are merged (their y values must agree)."""
    points = sorted(points)
    merged = [points[0]]
    for x, y in points[1:]:
        if x == merged[-1][0]:
            if y != merged[-1][1]:
                fail(f"reference '{path}' has two different y values at x = {x:g}")
            continue
        merged.append((x, y))
    return merged


def interpolate(ref, x):
    """Linear interpolation in the sorted reference; None outside its x range."""
    if x < ref[0][0] or x > ref[-1][0]:
        return None
    lo, hi = 0, len(ref) - 1
    while hi - lo > 1:  # bisection for the interval ref[lo][0] <= x <= ref[hi][0]
        mid = (lo + hi) // 2
        if ref[mid][0] <= x:
            lo = mid
        else:
            hi = mid
    (x0, y0), (x1, y1) = ref[lo], ref[hi]
    if x1 == x0:
        return y0
    t = (x - x0) / (x1 - x0)
    return y0 + t * (y1 - y0)


def main():
    parser = argparse.ArgumentParser(
        description="Compare a result curve with a reference curve (relative error).")
    parser.add_argument("--result", required=True, help="result CSV file")
    parser.add_argument("--reference", required=True, help="reference CSV file")
    parser.add_argument("--x-result", required=True, help="x column in the result file")
    parser.add_argument("--y-result", required=True, help="y column in the result file")
    parser.add_argument("--x-reference", required=True, help="x column in the reference file")
    parser.add_argument("--y-reference", required=True, help="y column in the reference file")
    parser.add_argument("--scale-y-result", type=float, default=1.0,
                        help="factor applied to the result's y before comparing (default 1)")
    parser.add_argument("--rel-tol", type=float, default=0.005,
                        help="maximum allowed relative error (default 0.005)")
    parser.add_argument("--abs-floor", type=float, default=0.0,
                        help="lower bound of the error denominator max(|y_ref|, floor) (default 0)")
    parser.add_argument("--x-min", type=float, default=None,
                        help="compare only result points with x >= X-MIN")
    args = parser.parse_args()

    if not (args.rel_tol >= 0 and args.abs_floor >= 0):
        fail("--rel-tol and --abs-floor must be >= 0")

    result = read_columns(args.result, args.x_result, args.y_result)
    ref = prepare_reference(read_columns(args.reference, args.x_reference, args.y_reference),
                            args.reference)

    rows = []  # (x, y_result scaled, y_reference, relative error)
    skipped = 0
    for x, y in result:
        if args.x_min is not None and x < args.x_min:
            continue
        y_ref = interpolate(ref, x)
        if y_ref is None:
            skipped += 1
            continue
        y_res = y * args.scale_y_result
        denom = max(abs(y_ref), args.abs_floor)
        if denom == 0.0:
            err = 0.0 if y_res == 0.0 else math.inf
        else:
            err = abs(y_res - y_ref) / denom
        rows.append((x, y_res, y_ref, err))

    if not rows:
        fail(f"no result point with '{args.x_result}' inside the reference range "
             f"[{ref[0][0]:g}, {ref[-1][0]:g}]"
             + (f" and >= {args.x_min:g}" if args.x_min is not None else ""))

    print(f"compare_curves: {args.result} [{args.x_result}, {args.y_result}"
          + (f" * {args.scale_y_result:g}" if args.scale_y_result != 1.0 else "")
          + f"] vs {args.reference} [{args.x_reference}, {args.y_reference}]")
    print(f"{'x':>14} {'result':>14} {'reference':>14} {'rel.error':>10}")
    # print at most ~20 rows (evenly spaced) plus the worst one, to keep logs short
    worst = max(range(len(rows)), key=lambda i: rows[i][3])
    stride = max(1, math.ceil(len(rows) / 20))
    for i, (x, y_res, y_ref, err) in enumerate(rows):
        if i % stride == 0 or i == worst or i == len(rows) - 1:
            mark = "  <- max" if i == worst else ""
            print(f"{x:14.6g} {y_res:14.6g} {y_ref:14.6g} {err:10.2e}{mark}")
    max_err = rows[worst][3]
    print(f"compared {len(rows)} points ({skipped} outside the reference range skipped); "
          f"max relative error {max_err:.3e} at x = {rows[worst][0]:g}; tolerance {args.rel_tol:g}")
    if max_err > args.rel_tol:
        print("FAILED")
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
