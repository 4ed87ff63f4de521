#!/usr/bin/env python3
"""Unit test of the ISO 1328-1 profile quantities of scripts/gear_flank_analysis.py
(profile_deviations(): total profile deviation F_alpha, form f_f_alpha, slope f_H_alpha) on
synthetic traces d(xi) with closed forms (no simulation). Exit 0 if all pass.

Closed forms over an evaluation range of roll length L starting at xi0 (u = xi - xi0):
  slope     d = d0 + s u:         F = |s| L, f_f = 0, f_H = s L (the trace is its mean line);
  parabola  d = d0 + s u + c u^2: the least-squares line of c u^2 on [0, L] is c (L u - L^2 / 6),
            so f_H = (s + c L) L, f_f = c L^2 / 4 (residual c (u^2 - L u + L^2 / 6): L^2 / 6 at
            the ends, -L^2 / 12 at the middle), F = |s L + c L^2| when d is monotonic.
The trace is linear between its points, so a sampled parabola differs from the parabola by at most
c h^2 / 8 (h the spacing): with 2000 points over L = 1.2 the quantities are within 1e-6 of c L^2.
A straight trace is exact to round-off (1e-12) whatever the spacing and wherever the range ends
cut a segment; uneven spacing must not tilt the mean line (length weighting).
scripts/gear_flank_3d.py (iso_of_layer()) takes a layer's nodes by reference radius R: a trace
linear in the roll length xi = sqrt(R^2 - r_b^2), sampled at radii and given the range as radii,
must give the slope closed form above (1e-12).
"""

import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import gear_flank_3d  # noqa: E402
import gear_flank_analysis as gfa  # noqa: E402

failures = []


def check(name, got, expected, tolerance):
    ok = all(abs(g - e) <= tolerance for g, e in zip(got, expected))
    print(f"{'ok  ' if ok else 'FAIL'} {name}: got {tuple(f'{g:.9g}' for g in got)}, "
          f"expected {tuple(f'{e:.9g}' for e in expected)} (tolerance {tolerance:g})")
    if not ok:
        failures.append(name)


def trace(f, xs):
    return [(x, f(x)) for x in sorted(xs)]


XI0, L = 3.0, 1.2  # the evaluation range [3, 4.2] (mm of roll length)
uniform = [2.5 + 2.2 * k / 1999 for k in range(2000)]  # the trace extends beyond both ends
random.seed(1)
uneven = [2.5 + 2.2 * random.random() ** 2 for _ in range(300)] + [2.5, 4.7]

# 1. pure slope, 4 um over the range, on uneven points (range ends cut segments)
s = 4e-3 / L
check("slope, uneven points", gfa.profile_deviations(trace(lambda x: 1e-3 + s * (x - XI0), uneven), XI0, XI0 + L),
      (4e-3, 0.0, 4e-3), 1e-12)
# 2. falling slope: f_H negative, F positive
check("falling slope", gfa.profile_deviations(trace(lambda x: -s * (x - XI0), uniform), XI0, XI0 + L),
      (4e-3, 0.0, -4e-3), 1e-12)
# 3. parabola c u^2 (monotonic on the range)
c = 5e-3
check("parabola", gfa.profile_deviations(trace(lambda x: c * (x - XI0) ** 2, uniform), XI0, XI0 + L),
      (c * L * L, c * L * L / 4, c * L * L), 1e-6 * c * L * L)
# 4. parabola with a slope against it and an offset: not monotonic, F from the extremes
s2 = -1.5 * c * L


def p4(x):
    return 2e-3 + s2 * (x - XI0) + c * (x - XI0) ** 2


u_min = -s2 / (2 * c)  # the vertex inside the range
F4 = max(p4(XI0), p4(XI0 + L)) - p4(XI0 + u_min)
check("parabola with slope", gfa.profile_deviations(trace(p4, uniform), XI0, XI0 + L),
      (F4, c * L * L / 4, (s2 + c * L) * L), 1e-6 * c * L * L)
# 5. uneven spacing: the parabola's mean line must not lean towards the dense end
dense = [XI0 + L * (k / 3000) ** 3 for k in range(3001)]
check("parabola, points dense at the SAP end",
      gfa.profile_deviations(trace(lambda x: c * (x - XI0) ** 2, dense), XI0, XI0 + L),
      (c * L * L, c * L * L / 4, c * L * L), 1e-5 * c * L * L)
# 6. a range the trace does not reach is an error
try:
    gfa.profile_deviations(trace(lambda x: x, [0.0, 1.0]), 2.0, 3.0)
    failures.append("range outside the trace")
    print("FAIL range outside the trace: no error")
except ValueError as e:
    print(f"ok   range outside the trace: {e}")

# 7. the 3D script's layer rows (Z, R, d_n): radii of the thesis gear (r_b 42.94 mm), a slope in xi
rb = 42.9449
radii = [math.hypot(rb, 2.5 + 2.2 * random.random()) for _ in range(40)] + [math.hypot(rb, 2.5)]
layer = [(12.7, R, 1e-3 + s * (math.sqrt(R * R - rb * rb) - XI0)) for R in radii]
R0, R1 = math.hypot(rb, XI0), math.hypot(rb, XI0 + L)
check("3D layer rows by radius", gear_flank_3d.iso_of_layer(layer, rb, R0, R1), (4e-3, 0.0, 4e-3), 1e-12)

print(f"{len(failures)} failure(s)" if failures else "all passed")
sys.exit(1 if failures else 0)
