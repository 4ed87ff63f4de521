#!/usr/bin/env python3
"""Unit test of the Richardson arithmetic and the reductions of scripts/convergence_study.py on
synthetic data with a known order (no simulation). Exit 0 if all pass.

References (exact by construction): f(h) = f* + C h^p gives the observed order p and the
extrapolated value f* to round-off, for constant and for varying refinement ratios (Celik's fixed
point); a profile f(x, h) = sin x + h^2 cos x gives order 2 and sin x pointwise; f = 1 + h + 50 h^3
(order 1 only asymptotically) must be flagged "not asymptotic" on four runs whose orders differ,
and its GCI with F_s = 3 must still cover the true error of the finest run; alternating
differences are "oscillatory"; two runs need an assumed order (F_s = 3).
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
import convergence_study as cs  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}")
    if not ok:
        failures.append(name)


def close(a, b, tol):
    return abs(a - b) <= tol * max(1.0, abs(b))


# 1. constant ratio 2, order 1.5
h = [1.0, 0.5, 0.25, 0.125]
f = [2.0 + 0.3 * x ** 1.5 for x in h]
a = cs.analyse_sequence(f, h)
check("order 1.5, ratio 2", close(a["order"], 1.5, 1e-10), f"p = {a['order']}")
check("extrapolated 2", close(a["extrapolated"], 2.0, 1e-12), f"f_ext = {a['extrapolated']}")
check("both triples give 1.5", all(close(p, 1.5, 1e-10) for p in a["orders"]))
check("asymptotic, F_s = 1.25", a["asymptotic"] and a["safety"] == 1.25)
true_err = [abs(x - 2.0) for x in f]
check("estimated errors exact", all(close(e, t, 1e-10) for e, t in zip(a["errors"], true_err)))
check("GCI = 1.25 x true error of the finest", close(a["uncertainty"], 1.25 * true_err[-1], 1e-9))

# 2. varying ratios, order 2 (Celik fixed point)
h = [1.0, 0.6, 0.3, 0.2]
f = [5.0 - 0.7 * x ** 2 for x in h]
a = cs.analyse_sequence(f, h)
check("order 2, varying ratios", close(a["order"], 2.0, 1e-8), f"p = {a['order']}")
check("extrapolated 5, varying ratios", close(a["extrapolated"], 5.0, 1e-8))

# 3. the step-size form h = 1/n
n = [30, 60, 120]
f = [10.0 + 4.0 / k for k in n]
a = cs.analyse_sequence(f, [1.0 / k for k in n])
check("order 1 in 1/n", close(a["order"], 1.0, 1e-10))
check("three runs: F_s 1.25, note", a["safety"] == 1.25 and "three runs" in a["note"])

# 4. profile: sin x + h^2 cos x on a common grid
grid = [0.1 * i for i in range(40)]
h = [0.4, 0.2, 0.1]
profiles = [[math.sin(x) + hh ** 2 * math.cos(x) for x in grid] for hh in h]
a = cs.analyse_sequence(profiles, h)
check("profile order 2", close(a["order"], 2.0, 1e-9), f"p = {a['order']}")
check("profile extrapolated to sin x",
      max(abs(e - math.sin(x)) for e, x in zip(a["extrapolated"], grid)) < 1e-12)
check("profile errors = h^2 max|cos|",
      all(close(e, hh ** 2 * max(abs(math.cos(x)) for x in grid), 1e-9)
          for e, hh in zip(a["errors"], h)))

# 5. not asymptotic: 1 + h + 50 h^3 on coarse grids (orders of the two triples 2.26 and 1.62)
h = [0.2, 0.1, 0.05, 0.025]
f = [1.0 + x + 50 * x ** 3 for x in h]
a = cs.analyse_sequence(f, h)
check("pre-asymptotic flagged", not a["asymptotic"] and a["safety"] == 3.0,
      f"orders {a['orders']}")
check("GCI (F_s = 3) covers the true error", a["uncertainty"] >= abs(f[-1] - 1.0),
      f"{a['uncertainty']} vs {abs(f[-1] - 1.0)}")

# 6. oscillatory
a = cs.analyse_sequence([1.0, 1.2, 1.1], [1.0, 0.5, 0.25])
check("oscillatory", a["convergence"] == "oscillatory" and a["order"] is None
      and close(a["uncertainty"], 0.2, 1e-12))

# 7. two runs with an assumed order
a = cs.analyse_sequence([1.0 + 0.5, 1.0 + 0.125], [1.0, 0.5], formal_order=2.0)
check("two runs, assumed order 2", close(a["extrapolated"], 1.0, 1e-12) and a["safety"] == 3.0)
a = cs.analyse_sequence([1.5, 1.125], [1.0, 0.5])
check("two runs without order: no estimate", a["extrapolated"] is None)

# 8. formal order bounds the asymptotic range
h = [1.0, 0.5, 0.25]
a = cs.analyse_sequence([1 + x ** 5 for x in h], h, formal_order=1.0)
check("order 5 against formal 1: not asymptotic", not a["asymptotic"])

a = cs.analyse_sequence([1 + x ** 0.2 for x in h], h)
check("order 0.2 without formal order: not asymptotic, F_s = 3",
      not a["asymptotic"] and a["safety"] == 3.0 and close(a["order"], 0.2, 1e-10))

# 9. reductions of a history
ts = [0.0, 0.5, 1.0, 1.5, 2.0]
ys = [0.0, 1.0, 4.0, 1.0, -5.0]
check("max", cs.reduce_series("max", ts, ys) == 4.0)
check("maxabs", cs.reduce_series("maxabs", ts, ys) == -5.0)
check("at(0.75)", close(cs.reduce_series("at(0.75)", ts, ys), 2.5, 1e-14))
# mean of the piecewise linear y over [0.25, 1.25]: exact integral / 1
exact = (0.5 * (0.5 + 1.0) * 0.25 + 0.5 * (1.0 + 4.0) * 0.5 + 0.5 * (4.0 + 2.5) * 0.25)
check("mean(0.25,1.25)", close(cs.reduce_series("mean(0.25,1.25)", ts, ys), exact, 1e-14))
rows = [{"time": str(t), "fx": str(3 * y), "fy": str(4 * y)} for t, y in zip(ts, ys)]
check("expression hypot", close(cs.history_value(rows, "max", "hypot(fx, fy)"), 25.0, 1e-14))

# 10. common grid and templates
coarse = [(0.0, 0.0), (2.0, 2.0)]
fine = [(-1.0, 0.0), (0.5, 0.5), (1.0, 1.0), (2.5, 0.0)]
grid = cs.common_grid([coarse, fine])
check("common grid", grid == [0.5, 1.0])
check("on grid", cs.on_grid(coarse, grid) == [0.5, 1.0])
check("template", cs.expand("Loading/End time = {n + 8}", n=288, level=None)
      == "Loading/End time = 296")

# 11. the report prints at least 7 significant digits of values and errors: three forces that
# agree to 4 digits (as -1.7e+06 in the 4-digit report) must differ in what is printed
check("7 digits", cs.fmt(-1712345.6) == "-1712346" and cs.fmt(1.2345678e-3) == "0.001234568",
      f"{cs.fmt(-1712345.6)}, {cs.fmt(1.2345678e-3)}")

# 12. the figure names the quantities it cannot draw instead of dropping them
h = [1.0, 0.5, 0.25]
good = cs.analyse_sequence([2.0 + 0.3 * x ** 2 for x in h], h)
diverging = cs.analyse_sequence([1.0, 1.1, 1.4], h)  # differences grow: order < 0, no estimate
for a, scale in ((good, 2.0), (diverging, 1.4)):  # what study() adds: runs and scale
    a["runs"] = ["level1", "level2", "level3"]
    a["scale"] = scale
oscillating = cs.analyse_sequence([1.0, 1.2, 1.1], h)
oscillating["runs"], oscillating["scale"] = diverging["runs"], 1.1
record = {"label": "levels 1, 2, 3", "runs": [],
          "analyses": {"F_good": good, "F_bad": diverging, "F_failed": None,
                       "F_osc": oscillating}}
missing = cs.plot_omissions([record])
names = [n for n, _, _ in missing]
check("omissions: the diverging and the failed quantity, not the converged one",
      names == ["F_bad", "F_failed", "F_osc"], f"{missing}")
check("omission reasons say why", "did not converge" in missing[0][2]
      and "two successful runs" in missing[1][2]
      and "oscillatory" in missing[2][2] and "1.1 ± 0.2" in missing[2][2], f"{missing}")
try:
    import matplotlib  # noqa: F401
    have_matplotlib = True
except ImportError:
    have_matplotlib = False
if have_matplotlib:
    import contextlib
    import io
    import tempfile
    record["runs"] = [{"name": n, "cpu": c} for n, c in zip(good["runs"], [1.0, 4.0, 16.0])]
    oscillating["runs"] = good["runs"]
    with tempfile.TemporaryDirectory() as tmp:
        out = io.StringIO()
        png = os.path.join(tmp, "wp.png")
        with contextlib.redirect_stdout(out):
            cs.plot([record], png)
        printed = out.getvalue()
        check("figure written, omissions printed", os.path.getsize(png) > 0
              and "F_bad (levels 1, 2, 3) not drawn" in printed
              and "F_failed (levels 1, 2, 3) not drawn" in printed, printed)

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
