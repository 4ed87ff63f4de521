#!/usr/bin/env python3
"""Unit test of the face-trace maximum of benchmarks/convergence/disk_lobe_phase.py on synthetic
rim profiles (no simulation). Exit 0 if all pass.

References (exact by construction): a profile sampled at the vertices and midpoints of faces of
length 2 h, piecewise quadratic on each face, has its maximum where the quadratic of the face has
its vertex; the function must return that value and angle to round-off, both when the largest
sample is a midpoint and when it is a vertex (then the two faces next to it are tried), and
return the sample itself where the quadratic has no interior maximum (a kink at a vertex).
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "benchmarks", "convergence"))
import disk_lobe_phase as lp  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}")
    if not ok:
        failures.append(name)


def sampled(trace, h=0.9375, n=384):
    """Support points of n / 2 faces of length 2 h around the ring; trace(a) per face."""
    return [(k * h % 360.0, trace(k * h % 360.0)) for k in range(n)]


def parabola(a0, peak, width):
    return lambda a: peak - ((a - a0) / width) ** 2


# 1. the maximum inside a face whose midpoint is the largest sample: face [101.25, 103.125]
a0 = 102.3
points = sorted(sampled(parabola(a0, 0.7, 3.0)))
i = max(range(len(points)), key=lambda k: points[k][1])
value, angle, vertex = lp.face_maximum(points, i)
check("midpoint: vertex flag", not vertex, f"largest sample at {points[i][0]}")
check("midpoint: value", abs(value - 0.7) < 1e-12, f"{value}")
check("midpoint: angle", abs(angle - a0) < 1e-9, f"{angle}")

# 2. the maximum inside the face right of a vertex that is the largest sample
a0 = 101.5
points = sorted(sampled(parabola(a0, 0.65, 3.0)))
i = max(range(len(points)), key=lambda k: points[k][1])
value, angle, vertex = lp.face_maximum(points, i)
check("vertex: vertex flag", vertex and abs(points[i][0] - 101.25) < 1e-12, f"{points[i][0]}")
check("vertex: value", abs(value - 0.65) < 1e-12, f"{value}")
check("vertex: angle", abs(angle - a0) < 1e-9, f"{angle}")

# 3. a kink at a vertex (linear rise, linear fall): the sample is the maximum
points = sorted(sampled(lambda a: 0.6 - 0.18 * max(101.25 - a, 0.0) - 0.05 * max(a - 101.25, 0.0)))
i = max(range(len(points)), key=lambda k: points[k][1])
value, angle, vertex = lp.face_maximum(points, i)
check("kink: value is the sample", abs(value - 0.6) < 1e-12 and abs(angle - 101.25) < 1e-12,
      f"{value} at {angle}")

# 4. across 0 degrees: the faces wrap around the ring
a0 = 0.3
points = sorted(sampled(lambda a: 0.5 - (((a - a0 + 180.0) % 360.0 - 180.0) / 3.0) ** 2))
i = max(range(len(points)), key=lambda k: points[k][1])
value, angle, vertex = lp.face_maximum(points, i)
check("wrap: value", abs(value - 0.5) < 1e-12, f"{value} at {angle}")

print("FAILED: " + ", ".join(failures) if failures else "all passed")
sys.exit(1 if failures else 0)
