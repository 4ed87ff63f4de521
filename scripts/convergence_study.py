#!/usr/bin/env python3
"""How accurate is my result, and what would more accuracy cost?

Runs a scene (.prm) on a sequence of resolution levels and/or step sizes, extracts the quantities
you name (reductions of history.csv columns, or a profile CSV compared in the max-norm on a common
grid), and prints for every run the value, CPU and wall time; for every sequence the observed order
of convergence, the Richardson-extrapolated value, the estimated error of each run and the
uncertainty of the finest one (grid convergence index, GCI); and draws a work-precision PNG
(estimated error against CPU time).

Usage (from the repository root, after building; doc/manual.md "How accurate is my result"):

    /usr/bin/python3 scripts/convergence_study.py prm/gear_rolling.prm \\
        --levels 2 3 4 5 \\
        --level-set "Adaptivity/Maximum level = {level}" \\
        --level-set "Adaptivity/Initial refinement cycles = {level}" \\
        --steps 60 120 240 --step-level 4 \\
        --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)" \\
        --history "F_0.6=at(0.6):hypot(die_die_force_x, die_die_force_y)" \\
        --work /tmp/conv --plot /tmp/conv/work_precision.png

The flagship gear scene is adaptive: its levels are the maximum refinement level and the initial
refinement cycles (the line above, as in doc/manual.md); refining it globally instead ("Geometry/
Global refinements", the default template, meant for uniform scenes) costs far more for the same
accuracy at the contact.

Levels: each level L is the base file with the overrides of --level-set (default
"Geometry/Global refinements = {level}"; give it several times for several entries, e.g. an
adaptive "Adaptivity/Maximum level = {level}"), cell size h ~ ratio^-L (--level-ratio, default 2).
Steps: each n is the base file (at --step-level, if given) with --step-set (default
"Loading/Number of steps = {n}"), h ~ 1/n. In a template "{expr}" is evaluated in Python with
`level` and `n` (e.g. "Loading/End time = {n + 8}"). --set adds overrides to every run (applied
first: the sequence overrides win). Every run gets its own output directory WORK/<name> (fresh, so
no run ever writes into another's).

Quantities:
  --history NAME=REDUCTION:EXPR   EXPR: a history column or a Python expression of columns
        (math functions allowed: hypot(die_die_force_x, die_die_force_y)); REDUCTION: last, max,
        min, maxabs, at(T) (linear interpolation in time), mean(T0,T1) (time average over the
        window, trapezoidal, interpolated at the window ends); --time-column names another
        column for T (e.g. die_roll_revolution: the same angle for every step count).
  --profile NAME=FILE:X:Y[:REDUCTION]   a CSV written by the run (FILE relative to its output
        directory; a glob takes the last match in sorted order, e.g. "profile_*.csv"). Without
        REDUCTION the profile Y(X) is compared in the max-norm on the common X range (the finest
        run's X points inside the range of every run, linear interpolation); with REDUCTION (max,
        min, maxabs, at(X0)) it is a scalar. --where COL=max keeps the rows whose COL has its
        largest value (e.g. the last output step of a file with all steps).
  --after "COMMAND {out}"   run after each run (e.g. a post-processing script that writes the
        profile CSV); {out} is the run's output directory; key=value words it prints become
        quantities with --value NAME=KEY.

Richardson arithmetic (values f_1 ... f_k from coarse to fine, sizes h_1 > ... > h_k): with the
last three runs, the observed order p solves e_23 / e_12 = r_23^-p (r_12^p - s) / (r_23^p - s)
(fixed point iteration, s the sign of e_23 / e_12; for a constant ratio r: p = ln(e_12 / e_23) /
ln r), the extrapolated value is f_ext = f_k + (f_k - f_{k-1}) / (r^p - 1), the estimated error of
run i is |f_i - f_ext|, and the uncertainty of the finest run is GCI = F_s |f_k - f_{k-1}| /
(r^p - 1) with Roache's safety factor F_s = 1.25 when the convergence is asymptotic (monotone, and
with four or more runs the orders of the last two triples agree within 25 %) and F_s = 3 when it is
not (the order outside [0.5, 4], or [p_f / 2, 2 p_f] with --formal-order p_f; or two runs and an
assumed --formal-order). Oscillatory convergence (the differences change sign) gives no order:
the estimate is the finest value and the uncertainty the range of the last three values. Profiles use the max-norms of the differences (s = +1) and extrapolate
pointwise. Pure arithmetic: tests/scripts/test_convergence_study.py checks it on synthetic data.

Output: a Markdown table per sequence on stdout, WORK/convergence.json (all numbers), and with
--plot a PNG (log-log error vs CPU time: the estimated error of each run against the extrapolated
value, relative to its size; the finest run with its uncertainty bar).
"""

import argparse
import csv
import glob
import json
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SAFETY_ASYMPTOTIC = 1.25  # Roache: three or more grids, asymptotic range
SAFETY_NOT_ASYMPTOTIC = 3.0  # Roache: two grids, or the order is not (yet) asymptotic


# ----------------------------------------------------------------------------- Richardson
def observed_order(e_coarse, e_fine, r_coarse, r_fine, tol=1e-12, max_iter=200):
    """Observed order p from the differences e_coarse = f_2 - f_1 and e_fine = f_3 - f_2 of three
    runs with size ratios r_coarse = h_1 / h_2 and r_fine = h_2 / h_3 (Celik et al. 2008, J.
    Fluids Eng. 130: fixed point of p = |ln|e_c/e_f| + q(p)| / ln r_f,
    q(p) = ln((r_f^p - s) / (r_c^p - s)), s = sign(e_f / e_c)). None if not defined."""
    if e_coarse == 0.0 or e_fine == 0.0:
        return None
    s = 1.0 if e_fine / e_coarse > 0 else -1.0
    ratio = abs(e_coarse / e_fine)
    p = abs(math.log(ratio)) / math.log(r_fine)
    if abs(r_coarse - r_fine) < 1e-14 * r_fine and s > 0:
        return math.log(ratio) / math.log(r_fine)
    for _ in range(max_iter):
        num, den = r_fine ** p - s, r_coarse ** p - s
        if num <= 0 or den <= 0:
            return None
        new = abs(math.log(ratio) + math.log(num / den)) / math.log(r_fine)
        if abs(new - p) < tol * max(1.0, p):
            return new
        p = new
    return p


def extrapolate(f_medium, f_fine, r, p):
    """Richardson extrapolation from the two finest values (ratio r = h_medium / h_fine)."""
    return f_fine + (f_fine - f_medium) / (r ** p - 1.0)


def analyse_sequence(values, sizes, formal_order=None, norm=None):
    """Richardson analysis of a sequence, coarse to fine. @p values: numbers, or lists (profiles
    on a common grid, compared with @p norm, default max-norm). Returns a dict:
    order (observed, or None), orders (of every triple), used_order, extrapolated, errors (estimate
    per run: |f_i - f_ext| or ||f_i - f_ext||), uncertainty (GCI of the finest run), safety
    (F_s, or None), asymptotic, convergence ('monotone', 'oscillatory', 'two runs', ...), note."""
    k = len(values)
    if k != len(sizes) or k < 2:
        raise ValueError("need at least two runs with a size each")
    if any(sizes[i] <= sizes[i + 1] for i in range(k - 1)):
        raise ValueError("sizes must decrease from coarse to fine")
    vector = isinstance(values[0], (list, tuple))
    if norm is None:
        norm = lambda v: max(abs(x) for x in v)  # noqa: E731
    sub = (lambda a, b: [x - y for x, y in zip(a, b)]) if vector else (lambda a, b: a - b)
    size = norm if vector else abs

    def add_scaled(a, b, c):  # a + c b
        return [x + c * y for x, y in zip(a, b)] if vector else a + c * b

    def diff(i):  # f_{i+1} - f_i (signed for scalars, norm for profiles)
        d = sub(values[i + 1], values[i])
        return norm(d) if vector else d

    out = {"order": None, "orders": [], "used_order": None, "extrapolated": None,
           "errors": [None] * k, "uncertainty": None, "safety": None, "asymptotic": False,
           "convergence": "", "note": ""}
    for i in range(k - 2):
        out["orders"].append(observed_order(diff(i), diff(i + 1), sizes[i] / sizes[i + 1],
                                            sizes[i + 1] / sizes[i + 2]))
    r = sizes[-2] / sizes[-1]
    last_diff = diff(k - 2)
    if (size(last_diff) if not vector else last_diff) == 0.0:
        out.update(order=None, used_order=None, extrapolated=values[-1], uncertainty=0.0,
                   convergence="converged", asymptotic=True, safety=SAFETY_ASYMPTOTIC,
                   note="the two finest runs agree exactly")
        out["errors"] = [size(sub(v, values[-1])) for v in values]
        return out
    if k == 2:
        if formal_order is None:
            out.update(convergence="two runs", note="two runs: give --formal-order for an estimate")
            return out
        p, fs = formal_order, SAFETY_NOT_ASYMPTOTIC
        out.update(convergence="two runs", note=f"two runs: assumed order {p:g}, F_s = 3")
    else:
        monotone = vector or diff(k - 3) * diff(k - 2) > 0
        if not monotone:
            last3 = values[-3:]
            out.update(convergence="oscillatory", extrapolated=values[-1],
                       uncertainty=max(last3) - min(last3),
                       note="oscillatory: no order; uncertainty = range of the last three values")
            out["errors"] = [abs(v - values[-1]) for v in values]
            return out
        p = out["orders"][-1]
        out["order"] = p
        out["convergence"] = "monotone"
        if p is None or p <= 0:
            out.update(note="diverging or undefined order: no estimate")
            return out
        consistent = True
        if k >= 4 and out["orders"][-2] is not None:
            q = out["orders"][-2]
            consistent = abs(p - q) <= 0.25 * max(p, q)
        elif k >= 4:
            consistent = False
        # without a formal order: orders outside [0.5, 4] are not taken as asymptotic
        lo, hi = (0.5 * formal_order, 2.0 * formal_order) if formal_order else (0.5, 4.0)
        in_range = lo <= p <= hi
        asymptotic = consistent and in_range and k >= 3
        fs = SAFETY_ASYMPTOTIC if asymptotic else SAFETY_NOT_ASYMPTOTIC
        out["asymptotic"] = asymptotic
        if not asymptotic:
            reasons = []
            if not consistent:
                reasons.append("orders of the last two triples differ by more than 25 %")
            if not in_range:
                reasons.append(f"order outside [{lo:g}, {hi:g}]")
            out["note"] = "not asymptotic (" + "; ".join(reasons) + "): F_s = 3"
        elif k == 3:
            out["note"] = "three runs: order not cross-checked, F_s = 1.25 (Roache)"
    delta = sub(values[-1], values[-2])
    factor = 1.0 / (r ** p - 1.0)
    f_ext = add_scaled(values[-1], delta, factor)
    out["used_order"] = p
    out["extrapolated"] = f_ext
    out["safety"] = fs
    out["uncertainty"] = fs * size(delta) * factor
    out["errors"] = [size(sub(v, f_ext)) for v in values]
    return out


# ----------------------------------------------------------------------------- reductions
def interpolate(xs, ys, x):
    """Linear interpolation of (xs ascending, ys) at x (clamped to the ends)."""
    if x <= xs[0]:
        return ys[0]
    for i in range(1, len(xs)):
        if xs[i] >= x:
            if xs[i] == xs[i - 1]:
                return ys[i]
            w = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return (1 - w) * ys[i - 1] + w * ys[i]
    return ys[-1]


def window_mean(ts, ys, t0, t1):
    """Time average of y over [t0, t1]: trapezoidal rule on the samples inside plus the
    interpolated values at the window ends."""
    pts = [(t0, interpolate(ts, ys, t0))] + [(t, y) for t, y in zip(ts, ys) if t0 < t < t1] + [
        (t1, interpolate(ts, ys, t1))]
    area = sum(0.5 * (a[1] + b[1]) * (b[0] - a[0]) for a, b in zip(pts[:-1], pts[1:]))
    return area / (t1 - t0)


REDUCTION = re.compile(r"^(last|max|min|maxabs|at\(([^)]*)\)|mean\(([^,]*),([^)]*)\))$")


def parse_reduction(text):
    m = REDUCTION.match(text.strip())
    if not m:
        raise SystemExit(f"convergence_study.py: unknown reduction '{text}' "
                         "(last, max, min, maxabs, at(T), mean(T0,T1))")
    return text.strip()


def reduce_series(reduction, ts, ys):
    """Apply a reduction (see parse_reduction) to the series ys(ts)."""
    m = REDUCTION.match(reduction)
    if reduction == "last":
        return ys[-1]
    if reduction == "max":
        return max(ys)
    if reduction == "min":
        return min(ys)
    if reduction == "maxabs":
        return max(ys, key=abs)
    if m.group(2) is not None:
        return interpolate(ts, ys, float(m.group(2)))
    return window_mean(ts, ys, float(m.group(3)), float(m.group(4)))


def evaluate_expression(expr, row):
    names = {k: v for k, v in vars(math).items() if not k.startswith("_")}
    names.update(abs=abs, min=min, max=max)
    for key, value in row.items():
        try:
            names[key] = float(value)
        except (TypeError, ValueError):
            pass
    return float(eval(expr, {"__builtins__": {}}, names))


def history_value(rows, reduction, expr, time_column="time"):
    ts = [float(r[time_column]) for r in rows]
    ys = [evaluate_expression(expr, r) for r in rows]
    return reduce_series(reduction, ts, ys)


def common_grid(profiles):
    """The finest profile's x points inside the x range of every profile (profiles: lists of
    (x, y) sorted by x, coarse to fine)."""
    lo = max(p[0][0] for p in profiles)
    hi = min(p[-1][0] for p in profiles)
    return [x for x, _ in profiles[-1] if lo <= x <= hi]


def on_grid(profile, grid):
    xs = [x for x, _ in profile]
    ys = [y for _, y in profile]
    return [interpolate(xs, ys, x) for x in grid]


# ----------------------------------------------------------------------------- runs
def expand(template, **names):
    """Replace every {expr} in @p template by the value of the Python expression with @p names."""

    def value(m):
        v = eval(m.group(1), {"__builtins__": {}}, names)
        return v if isinstance(v, str) else str(v)

    return re.sub(r"\{([^{}]*)\}", value, template)


def run_case(args, name, overrides):
    """Run one variant (fresh output directory WORK/name) and return the Run of
    benchmarks/ausroll_run.py (history rows, wall, CPU = user + system of the process)."""
    sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
    from ausroll_run import run_variant  # noqa: E402

    out = os.path.join(args.work, name)
    if not args.reuse and os.path.isdir(out):
        for f in glob.glob(os.path.join(out, "*")):
            if os.path.isfile(f):
                os.remove(f)
    run = run_variant(args.ausroll, args.prm, args.work, name, args.set + overrides, np=args.np,
                      reuse=args.reuse, timeout=args.timeout)
    status = "ok" if run.ok else f"FAILED (exit {run.returncode})"
    print(f"  {name}: {status}, {len(run.rows) - 1} steps, CPU {run.cpu:.1f} s, "
          f"wall {run.wall:.1f} s", flush=True)
    if not run.ok:
        print("    " + run.log.strip()[-400:].replace("\n", "\n    "), file=sys.stderr)
    return run, out


def read_profile(out, spec, where):
    files = sorted(glob.glob(os.path.join(out, spec["file"])))
    if not files:
        raise FileNotFoundError(f"{spec['file']} not in {out}")
    rows = list(csv.DictReader(open(files[-1])))
    for key, what in where:
        values = [float(r[key]) for r in rows]
        target = max(values) if what == "max" else min(values)
        rows = [r for r, v in zip(rows, values) if v == target]
    return sorted((float(r[spec["x"]]), float(r[spec["y"]])) for r in rows)


def collect(args, run, out):
    """Quantities of one run: {name: float or [(x, y)]} (None where the run failed)."""
    q = {}
    if args.after and run.ok:
        result = subprocess.run(args.after.replace("{out}", out), shell=True, capture_output=True,
                                text=True)
        words = dict(w.split("=", 1) for w in result.stdout.split() if "=" in w)
        for name, key in args.value:
            q[name] = float(words[key]) if key in words else None
    for name, reduction, expr in args.history:
        q[name] = history_value(run.rows, reduction, expr, args.time_column) if run.ok else None
    for name, spec in args.profile:
        try:
            prof = read_profile(out, spec, args.where) if run.ok else None
        except (FileNotFoundError, KeyError) as e:
            print(f"    {name}: {e}", file=sys.stderr)
            prof = None
        if prof is not None and spec.get("reduction"):
            prof = reduce_series(spec["reduction"], [x for x, _ in prof], [y for _, y in prof])
        q[name] = prof
    return q


def study(args, label, cases):
    """Run @p cases [(name, h, overrides, tag)] and analyse every quantity; returns a record."""
    runs = []
    for name, h, overrides, tag in cases:
        run, out = run_case(args, name, overrides)
        runs.append({"name": name, "h": h, "tag": tag, "cpu": run.cpu, "wall": run.wall,
                     "ok": run.ok, "steps": len(run.rows) - 1,
                     "dofs": int(float(run.rows[-1]["dofs"])) if run.rows else 0,
                     "values": collect(args, run, out)})
    names = [n for n, _ in args.value] + [n for n, _, _ in args.history] + [
        n for n, _ in args.profile]
    analyses = {}
    for name in names:
        good = [r for r in runs if r["ok"] and r["values"].get(name) is not None]
        if len(good) < 2:
            analyses[name] = None
            continue
        values = [r["values"][name] for r in good]
        if isinstance(values[0], list):
            grid = common_grid(values)
            values = [on_grid(v, grid) for v in values]
        a = analyse_sequence(values, [r["h"] for r in good], args.formal_order)
        a["runs"] = [r["name"] for r in good]
        a["profile"] = isinstance(values[0], list)
        if a["profile"]:
            a["grid"] = grid
            a["scale"] = max(abs(x) for x in (a["extrapolated"] or values[-1]))
        else:
            a["scale"] = abs(a["extrapolated"]) if a["extrapolated"] is not None else abs(
                values[-1])
        analyses[name] = a
    return {"label": label, "runs": runs, "analyses": analyses}


DIGITS = 7  # significant digits of values, errors and uncertainties in the report


def fmt(x, digits=DIGITS):
    if x is None:
        return "–"
    if isinstance(x, list):
        return f"max {max(y for _, y in x):.{digits}g}, min {min(y for _, y in x):.{digits}g}" \
            if x and isinstance(x[0], tuple) else "profile"
    return f"{x:.{digits}g}"


def report(record):
    print(f"\n### {record['label']}\n")
    names = list(record["analyses"])
    head = ["run", "h", "DoFs", "steps", "CPU (s)", "wall (s)"]
    for n in names:
        head += [n, f"est. error {n}"]
    print("| " + " | ".join(head) + " |")
    print("|" + "|".join("---:" for _ in head) + "|")
    for i, r in enumerate(record["runs"]):
        cells = [r["name"], f"{r['h']:.4g}", str(r["dofs"]), str(r["steps"]), f"{r['cpu']:.1f}",
                 f"{r['wall']:.1f}"]
        for n in names:
            a = record["analyses"][n]
            v = r["values"].get(n)
            cells.append(fmt(v))
            err = None
            if a is not None and r["name"] in a["runs"]:
                err = a["errors"][a["runs"].index(r["name"])]
            if err is None:
                cells.append("–")
            else:
                rel = err / a["scale"] if a["scale"] else float("nan")
                cells.append(f"{fmt(err)} ({100 * rel:.3g} %)")
        print("| " + " | ".join(cells) + " |")
    print()
    for n in names:
        a = record["analyses"][n]
        if a is None:
            print(f"- {n}: fewer than two successful runs")
            continue
        orders = ", ".join("–" if p is None else f"{p:.2f}" for p in a["orders"])
        ext = a["extrapolated"]
        if a["profile"]:
            ext_s = "pointwise profile" if ext is not None else "–"
            if ext is not None:
                ext_s += f" (max {fmt(max(ext))}, min {fmt(min(ext))})"
        else:
            ext_s = fmt(ext)
        unc = a["uncertainty"]
        unc_s = fmt(unc)
        if unc is not None and a["scale"]:
            unc_s += f" ({100 * unc / a['scale']:.3g} %)"
        print(f"- {n}: {a['convergence']}, observed orders {orders or '–'}; "
              f"extrapolated {ext_s}; uncertainty of the finest run {unc_s}"
              + (f", F_s = {a['safety']:g}" if a["safety"] else "")
              + (f"; {a['note']}" if a["note"] else ""))


def plot_omissions(records):
    """The quantities the work-precision figure cannot draw, with the reason: [(quantity, sequence
    label, reason)]. A quantity is drawn only where its sequence converges monotonically (or the
    two finest runs agree) to an extrapolated value and at least one run has a positive estimated
    error."""
    missing = []
    for rec in records:
        for n, a in rec["analyses"].items():
            if a is None:
                reason = "fewer than two successful runs"
            elif a["extrapolated"] is None:
                reason = "did not converge: " + (a["note"] or a["convergence"])
            elif a["convergence"] == "oscillatory":
                # the differences to the finest value are no error estimate: say so instead
                reason = (f"oscillatory, no order: finest value {fmt(a['extrapolated'])} ± "
                          f"{fmt(a['uncertainty'])} (range of the last three)")
            elif not a["scale"]:
                reason = "extrapolated value is zero (no relative error)"
            elif not any(e is not None and e > 0 for e in a["errors"]):
                reason = "no error to draw: " + (a["note"] or "every estimated error is zero")
            else:
                continue
            missing.append((n, rec["label"], reason))
    return missing


def plot(records, filename):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib not installed: no figure; Debian: /usr/bin/python3)")
        return
    import textwrap

    missing = plot_omissions(records)
    skipped = {(label, n) for n, label, _ in missing}
    # the quantities that are not drawn are listed under the axes, with the reason
    notes = []
    for n, label, reason in missing:
        notes += textwrap.wrap(f"{n} ({label}): {reason}", 110, subsequent_indent="    ")
    fig, ax = plt.subplots(figsize=(7.5, 4.8 + 0.125 * (len(notes) + 1 if notes else 0)))
    markers = "os^vD<>p*h"
    styles = ["-", "--", ":", "-."]
    for j, rec in enumerate(records):
        for i, (n, a) in enumerate(rec["analyses"].items()):
            if (rec["label"], n) in skipped:
                continue
            runs = {r["name"]: r for r in rec["runs"]}
            pts = [(runs[name]["cpu"], e / a["scale"]) for name, e in zip(a["runs"], a["errors"])
                   if e is not None and e > 0]
            line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts],
                              marker=markers[i % len(markers)], linestyle=styles[j % len(styles)],
                              label=f"{n} ({rec['label']})")
            if a["uncertainty"]:
                fine = runs[a["runs"][-1]]["cpu"]
                ax.errorbar([fine], [a["uncertainty"] / a["scale"]], fmt="none",
                            yerr=[[0.5 * a["uncertainty"] / a["scale"]], [0]],
                            color=line.get_color(), capsize=3)
    for n, label, reason in missing:
        print(f"figure: {n} ({label}) not drawn: {reason}")
    ax.set_xlabel("CPU time of the run (s)")
    ax.set_ylabel("estimated error / |extrapolated value|")
    ax.grid(alpha=0.3, which="both")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
    ax.set_title("work-precision (bar: GCI uncertainty of the finest run)", fontsize=9)
    if notes:
        fig.text(0.01, 0.01, "\n".join(["not drawn (no converged error estimate):"] + notes),
                 fontsize=7, va="bottom", ha="left", color="firebrick", family="monospace")
        fig.tight_layout(rect=(0, 0.125 * (len(notes) + 1) / fig.get_figheight() + 0.01, 1, 1))
    else:
        fig.tight_layout()
    fig.savefig(filename, dpi=110)
    print(f"figure: {filename}")


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("prm")
    p.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    p.add_argument("--work", default="convergence_study")
    p.add_argument("--levels", type=int, nargs="*", default=[])
    p.add_argument("--level-set", action="append", default=[],
                   help="override template per level (default 'Geometry/Global refinements = "
                        "{level}')")
    p.add_argument("--level-ratio", type=float, default=2.0,
                   help="cell size ratio between successive levels (h ~ ratio^-level)")
    p.add_argument("--steps", type=int, nargs="*", default=[])
    p.add_argument("--step-set", action="append", default=[],
                   help="override template per step count (default 'Loading/Number of steps = "
                        "{n}')")
    p.add_argument("--step-level", type=int, help="level of the step-size sequence")
    p.add_argument("--set", action="append", default=[], help="override for every run")
    p.add_argument("--history", action="append", default=[], metavar="NAME=REDUCTION:EXPR")
    p.add_argument("--time-column", default="time",
                   help="history column that at(T) and mean(T0,T1) refer to (e.g. the die "
                        "revolution angle, which maps to different times for different step "
                        "counts)")
    p.add_argument("--profile", action="append", default=[], metavar="NAME=FILE:X:Y[:REDUCTION]")
    p.add_argument("--where", action="append", default=[], metavar="COL=max|min")
    p.add_argument("--after", help="command run after every run ({out}: its output directory)")
    p.add_argument("--value", action="append", default=[], metavar="NAME=KEY",
                   help="quantity from a key=value word printed by --after")
    p.add_argument("--formal-order", type=float,
                   help="expected order: bounds the asymptotic range, used with two runs")
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--timeout", type=float)
    p.add_argument("--reuse", action="store_true", help="reuse the runs of an earlier study")
    p.add_argument("--plot", help="work-precision PNG")
    args = p.parse_args(argv)
    args.prm = os.path.abspath(args.prm)
    args.work = os.path.abspath(args.work)
    args.level_set = args.level_set or ["Geometry/Global refinements = {level}"]
    args.step_set = args.step_set or ["Loading/Number of steps = {n}"]
    hist = []
    for text in args.history:
        name, _, rest = text.partition("=")
        reduction, _, expr = rest.partition(":")
        if not expr:
            raise SystemExit(f"--history '{text}': expected NAME=REDUCTION:EXPR")
        hist.append((name.strip(), parse_reduction(reduction), expr.strip()))
    args.history = hist
    prof = []
    for text in args.profile:
        name, _, rest = text.partition("=")
        parts = rest.split(":")
        if len(parts) not in (3, 4):
            raise SystemExit(f"--profile '{text}': expected NAME=FILE:X:Y[:REDUCTION]")
        spec = {"file": parts[0], "x": parts[1], "y": parts[2]}
        if len(parts) == 4:
            spec["reduction"] = parse_reduction(parts[3])
        prof.append((name.strip(), spec))
    args.profile = prof
    args.where = [tuple(w.split("=", 1)) for w in args.where]
    args.value = [tuple(v.split("=", 1)) for v in args.value]
    if not (args.history or args.profile or args.value):
        raise SystemExit("convergence_study.py: name at least one quantity (--history, "
                         "--profile or --value)")
    if not (args.levels or args.steps):
        raise SystemExit("convergence_study.py: give --levels and/or --steps")
    if not os.path.exists(args.prm):
        raise SystemExit(f"convergence_study.py: no file {args.prm}")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    os.makedirs(args.work, exist_ok=True)
    records = []
    if len(args.levels) >= 1:
        cases = [(f"level{L}", args.level_ratio ** -L,
                  [expand(t, level=L, n=None) for t in args.level_set], "level")
                 for L in sorted(args.levels)]
        records.append(study(args, "resolution levels " + ", ".join(map(str, args.levels)),
                             cases))
    if len(args.steps) >= 1:
        base = [expand(t, level=args.step_level, n=None) for t in args.level_set] \
            if args.step_level is not None else []
        tag = f"_level{args.step_level}" if args.step_level is not None else ""
        cases = [(f"steps{n}{tag}", 1.0 / n, base + [expand(t, level=args.step_level, n=n)
                                                      for t in args.step_set], "steps")
                 for n in sorted(args.steps)]
        records.append(study(args, "step counts " + ", ".join(map(str, args.steps))
                             + (f" (level {args.step_level})" if tag else ""), cases))
    for rec in records:
        report(rec)
    summary = os.path.join(args.work, "convergence.json")
    with open(summary, "w") as f:
        json.dump(records, f, indent=1, default=str)
    print(f"\nall numbers: {summary}")
    if args.plot:
        plot(records, args.plot)
    failed = any(not r["ok"] for rec in records for r in rec["runs"])
    return 3 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
