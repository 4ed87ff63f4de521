#!/usr/bin/env python3
"""Unit test of scripts/compare_histories.py on small synthetic history.csv files whose
differences are known by construction (no simulation). Exit 0 if all pass.

1. Same times: B = A except one column, offset by 0.5 at t = 0.3 only -> that column's max
   difference 0.5 at t = 0.3, relative 0.5 / scale; every other column 0; "one to one" said.
2. Different times: A on t = 0, 0.1, ..., 1; B on t = 0, 0.25, 0.5, 0.75, 1 (and up to 0.75
   only); a linear column interpolates exactly (difference 0 up to round-off), t^2 differs by
   the chord error (t - t0)(t1 - t) of linear interpolation between B's nodes t0 < t < t1
   (largest on A's grid: 0.015); the interpolation and the rows outside B's range are said.
3. Columns only in one file are listed; a missing --columns entry or a non-number exits 2.
4. --plot writes a PNG with the chosen columns (when matplotlib is available).
"""

import contextlib
import io
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "scripts", "compare_histories.py")
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import compare_histories as ch  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}")
    if not ok:
        failures.append(name)


def write(path, header, rows):
    with open(path, "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(repr(float(x)) for x in r) + "\n")


def run(*args):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = ch.main(list(args))
    return status, out.getvalue()


with tempfile.TemporaryDirectory() as tmp:
    a_csv, b_csv, c_csv = (os.path.join(tmp, n) for n in ("a.csv", "b.csv", "c.csv"))
    header = ["step", "time", "die_force_y", "feed", "wall_seconds"]
    times = [0.1 * k for k in range(11)]
    rows_a = [[k, t, -1000.0 * t, 2.0 * t, 0.01 * k] for k, t in enumerate(times)]
    rows_b = [[k, t, -1000.0 * t + (0.5 if k == 3 else 0.0), 2.0 * t, 0.02 * k]
              for k, t in enumerate(times)]
    write(a_csv, header, rows_a)
    write(b_csv, header, rows_b)

    # 1. same times
    res = ch.compare(a_csv, b_csv)
    by = {r[0]: r for r in res["results"]}
    check("same times: no interpolation note", res["notes"] == [] and res["rows"] == 11)
    check("step and wall_seconds left out by default", set(by) == {"die_force_y", "feed"})
    c, d, t, rel, a = by["die_force_y"]
    check("force: max difference 0.5 at t = 0.3", abs(d - 0.5) < 1e-9 and abs(t - 0.3) < 1e-12,
          f"{d}, {t}")
    check("force: relative to the column scale 1000", abs(rel - 0.5 / 1000.0) < 1e-12, f"{rel}")
    check("feed identical", by["feed"][1] == 0.0 and by["feed"][3] == 0.0)
    status, text = run(a_csv, b_csv)
    check("exit 0 and a table with 7 digits", status == 0 and "| die_force_y" in text
          and "0.0005 |" in text and "one to one" in text, text)

    # 2. different times: B on a coarser grid, and B ending at 0.75
    tb = [0.0, 0.25, 0.5, 0.75, 1.0]
    header_q = ["time", "linear", "square"]
    write(a_csv, header_q, [[t, 3.0 * t + 1.0, t * t] for t in times])
    write(b_csv, header_q, [[t, 3.0 * t + 1.0, t * t] for t in tb])
    res = ch.compare(a_csv, b_csv)
    by = {r[0]: r for r in res["results"]}
    check("interpolation said", any("interpolated linearly onto A's times" in n
                                    for n in res["notes"]), f"{res['notes']}")
    check("linear column: interpolation exact", by["linear"][1] < 1e-12, f"{by['linear'][1]}")
    # chord of t^2 between nodes t0, t1 lies above by (t - t0)(t1 - t): largest on A's grid
    expected = max((t - 0.25 * int(t / 0.25 + 1e-9)) * (0.25 * (int(t / 0.25 + 1e-9) + 1) - t)
                   for t in times if t < 1.0 - 1e-12)
    check("square column: the known interpolation error", abs(by["square"][1] - expected) < 1e-12,
          f"{by['square'][1]} vs {expected}")
    check("at a time between B's nodes", abs(by["square"][2] - 0.1) < 1e-12
          or abs(by["square"][2] - 0.9) < 1e-12 or abs(by["square"][2] - 0.4) < 1e-12
          or abs(by["square"][2] - 0.6) < 1e-12, f"t = {by['square'][2]}")
    write(b_csv, header_q, [[t, 3.0 * t + 1.0, t * t] for t in tb[:4]])
    res = ch.compare(a_csv, b_csv)
    check("rows outside B's range left out and said", res["rows"] == 8 and any(
        "3 of A's rows lie outside" in n for n in res["notes"]), f"{res['rows']}, {res['notes']}")

    # 3. columns in one file only; bad input
    write(c_csv, ["time", "linear", "extra"], [[t, 3.0 * t + 1.0, 0.0] for t in times])
    res = ch.compare(a_csv, c_csv)
    check("only-in lists", res["only_a"] == ["square"] and res["only_b"] == ["extra"],
          f"{res['only_a']}, {res['only_b']}")
    bad = subprocess.run([sys.executable, SCRIPT, a_csv, c_csv, "--columns", "square"],
                         capture_output=True, text=True)
    check("missing --columns entry: exit 2 naming it", bad.returncode == 2
          and "no column 'square'" in bad.stderr, bad.stderr)
    with open(c_csv, "a") as f:
        f.write("1.1,oops,0\n")
    bad = subprocess.run([sys.executable, SCRIPT, a_csv, c_csv], capture_output=True, text=True)
    check("non-number: exit 2 naming file, column, row", bad.returncode == 2
          and "column linear, data row 12" in bad.stderr, bad.stderr)
    bad = subprocess.run([sys.executable, SCRIPT, a_csv, os.path.join(tmp, "none.csv")],
                         capture_output=True, text=True)
    check("missing file: exit 2", bad.returncode == 2 and "cannot read" in bad.stderr, bad.stderr)

    # 4. plot
    try:
        import matplotlib  # noqa: F401
        have_matplotlib = True
    except ImportError:
        have_matplotlib = False
    if have_matplotlib:
        write(b_csv, header_q, [[t, 3.0 * t + 1.0, t * t] for t in tb])
        png = os.path.join(tmp, "cmp.png")
        status, text = run(a_csv, b_csv, "--columns", "square", "linear", "--plot", png)
        check("plot written", status == 0 and os.path.getsize(png) > 0
              and "figure:" in text and "(square, linear)" in text, text[-200:])
    else:
        print("skip plot (no matplotlib)")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
