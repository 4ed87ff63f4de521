#!/usr/bin/env python3
"""Compare two runs: align two history.csv files on time, report per-column differences, plot.

Usage:
    scripts/compare_histories.py A/history.csv B/history.csv [--columns C1 C2 ...]
                                 [--time-column time] [--plot out.png]

Alignment: where both files have the same times (to 1e-12 of the time range) the rows are compared
one to one. Otherwise (other step sizes, cutbacks, a run that stopped early) every column of B is
interpolated linearly onto A's times, and this is said in the output; A's rows outside B's time
range are left out (also said). Columns that only one file has are listed and not compared.

Table, per compared column: the largest |A - B| and the time where it occurs, that difference
relative to the column's scale max(|A|, |B|) over all compared rows (the scale that
tests/checks/compare_histories.py uses), and the column's value in A there. Columns that are
not physical results (step, wall_seconds) are left out unless named with --columns.

--plot out.png draws the chosen columns (--columns; without it the up to four columns with the
largest relative difference) of both runs against time, one panel each (matplotlib, Agg).

Exit status: 0 when the comparison was made (whatever the differences), 2 on a usage or data
error (a file that cannot be read, a column that is missing or not a number).
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from history_csv import column, columns_of, read_rows  # noqa: E402

PROGRAM = "compare_histories.py"
NOT_RESULTS = ("step", "wall_seconds")  # left out unless asked for: counters and timings


def fail(message):
    print(f"{PROGRAM}: error: {message}", file=sys.stderr)
    sys.exit(2)


def strictly_increasing(times):
    """@p times sorted and without repeats: indices of the last row of every distinct time (a
    resumed history cannot repeat a time, but a hand-edited one might)."""
    keep = {}
    for k, t in enumerate(times):
        keep[t] = k
    return [keep[t] for t in sorted(keep)]


def interpolate(xs, ys, x):
    """Linear interpolation of (xs strictly increasing, ys) at x inside [xs[0], xs[-1]]."""
    lo, hi = 0, len(xs) - 1
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    w = (x - xs[lo]) / (xs[hi] - xs[lo])
    return (1.0 - w) * ys[lo] + w * ys[hi]


def align(times_a, times_b, tol=1e-12):
    """How B's rows map onto A's times. Returns (rows of A to compare, B's value for each as a
    function of a B column, notes): same times -> row to row; otherwise B interpolated onto A's
    times inside B's range."""
    span = max(max(times_a) - min(times_a), max(times_b) - min(times_b), 1e-300)
    same = len(times_a) == len(times_b) and all(
        abs(x - y) <= tol * span for x, y in zip(times_a, times_b))
    if same:
        return list(range(len(times_a))), (lambda values: list(values)), []
    notes = []
    order = strictly_increasing(times_b)
    if len(order) < len(times_b):
        notes.append(f"B repeats or reorders times: its {len(times_b)} rows give "
                     f"{len(order)} distinct times (the last row of each is used)")
    tb = [times_b[k] for k in order]
    rows_a = [k for k, t in enumerate(times_a) if tb[0] - tol * span <= t <= tb[-1] + tol * span]
    left_out = len(times_a) - len(rows_a)
    notes.append(f"the times differ ({len(times_a)} rows in A, {len(times_b)} in B): B is "
                 f"interpolated linearly onto A's times")
    if left_out:
        notes.append(f"{left_out} of A's rows lie outside B's time range [{tb[0]:.7g}, "
                     f"{tb[-1]:.7g}] and are not compared")
    if len(tb) == 1:
        rows_a = [k for k in rows_a if abs(times_a[k] - tb[0]) <= tol * span]

    def on_a(values):
        vb = [values[k] for k in order]
        return [interpolate(tb, vb, times_a[k]) for k in rows_a]

    return rows_a, on_a, notes


def compare(path_a, path_b, columns=None, time_column="time"):
    """Compare two histories. Returns a dict: rows (compared), notes, only_a, only_b,
    results [(column, max |A - B|, time of it, relative to the scale, A there)], series
    {column: (times, A values, B values on A's times)}."""
    rows_a = read_rows(path_a, PROGRAM)
    rows_b = read_rows(path_b, PROGRAM)
    cols_a, cols_b = columns_of(rows_a), columns_of(rows_b)
    for path, cols in ((path_a, cols_a), (path_b, cols_b)):
        if time_column not in cols:
            fail(f"'{path}' has no column '{time_column}' (--time-column)")
    only_a = [c for c in cols_a if c not in cols_b]
    only_b = [c for c in cols_b if c not in cols_a]
    if columns:
        for c in columns:
            for path, cols in ((path_a, cols_a), (path_b, cols_b)):
                if c not in cols:
                    fail(f"--columns: '{path}' has no column '{c}'")
        chosen = list(columns)
    else:
        chosen = [c for c in cols_a if c in cols_b and c != time_column and c not in NOT_RESULTS]
    times_a = column(rows_a, time_column, path_a, PROGRAM)
    times_b = column(rows_b, time_column, path_b, PROGRAM)
    compared, b_on_a, notes = align(times_a, times_b)
    if not compared:
        fail(f"no time of '{path_a}' lies inside the time range of '{path_b}'")
    t = [times_a[k] for k in compared]
    results, series = [], {}
    for c in chosen:
        va_all = column(rows_a, c, path_a, PROGRAM)
        va = [va_all[k] for k in compared]
        vb = b_on_a(column(rows_b, c, path_b, PROGRAM))
        diffs = [abs(x - y) for x, y in zip(va, vb)]
        k = max(range(len(diffs)), key=lambda i: diffs[i])
        scale = max(max(abs(x) for x in va), max(abs(y) for y in vb))
        rel = diffs[k] / scale if scale > 0 else 0.0
        results.append((c, diffs[k], t[k], rel, va[k]))
        series[c] = (t, va, vb)
    return {"rows": len(compared), "notes": notes, "only_a": only_a, "only_b": only_b,
            "results": results, "series": series}


def report(result, path_a, path_b):
    print(f"A: {path_a}\nB: {path_b}")
    for note in result["notes"]:
        print(f"note: {note}")
    if not result["notes"]:
        print("note: same times in both files: rows compared one to one")
    if result["only_a"]:
        print(f"only in A (not compared): {', '.join(result['only_a'])}")
    if result["only_b"]:
        print(f"only in B (not compared): {', '.join(result['only_b'])}")
    print(f"{len(result['results'])} columns x {result['rows']} rows compared\n")
    width = max([len("column")] + [len(r[0]) for r in result["results"]])
    print(f"| {'column':<{width}} | max abs. difference | at time | relative to scale | A there |")
    print(f"|{'-' * (width + 2)}|---:|---:|---:|---:|")
    for c, d, t, rel, a in result["results"]:
        print(f"| {c:<{width}} | {d:.7g} | {t:.7g} | {rel:.7g} | {a:.7g} |")


def plot(result, columns, filename, label_a, label_b):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        fail("--plot needs matplotlib (Debian: /usr/bin/python3 with python3-matplotlib)")
    n = len(columns)
    fig, axes = plt.subplots(n, 1, figsize=(7.0, 2.4 * n + 0.6), sharex=True, squeeze=False)
    for ax, c in zip(axes[:, 0], columns):
        t, va, vb = result["series"][c]
        ax.plot(t, va, "-", label=f"A: {label_a}")
        ax.plot(t, vb, "--", label=f"B: {label_b}")
        ax.set_ylabel(c, fontsize=8)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    axes[-1, 0].set_xlabel("time" + (" (B interpolated onto A's times)" if result["notes"] else ""))
    fig.tight_layout()
    fig.savefig(filename, dpi=110)
    print(f"\nfigure: {filename} ({', '.join(columns)})")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("first", metavar="A.csv")
    parser.add_argument("second", metavar="B.csv")
    parser.add_argument("--columns", nargs="+", help="columns to compare and plot (default: all "
                        "columns both files have, except step and wall_seconds)")
    parser.add_argument("--time-column", default="time", help="column to align on (default time)")
    parser.add_argument("--plot", metavar="OUT.png", help="draw the chosen columns of both runs")
    args = parser.parse_args(argv)

    result = compare(args.first, args.second, args.columns, args.time_column)
    report(result, args.first, args.second)
    if args.plot:
        if args.columns:
            chosen = args.columns
        else:
            ranked = sorted(result["results"], key=lambda r: -r[3])
            chosen = [r[0] for r in ranked[:4] if not math.isnan(r[3])]
            print(f"\n(no --columns: plotting the {len(chosen)} columns with the largest relative "
                  "difference)")
        if chosen:
            plot(result, chosen, args.plot, os.path.dirname(args.first) or args.first,
                 os.path.dirname(args.second) or args.second)
    return 0


if __name__ == "__main__":
    sys.exit(main())
