#!/usr/bin/env python3
"""Write the graded quadrilateral mesh of prm/flat_punch.prm as a Gmsh 2.2 ASCII file.

Block 0 <= x <= W, 0 <= y <= D (half model of a plane-strain flat punch problem), punch
0 <= x <= b on the top. The columns are graded geometrically towards the punch edge x = b from
both sides and the rows towards the top surface, with a smallest cell h at the edge.
Boundary ids (physical tags of the boundary lines): 0 symmetry axis x = 0, 1 right side x = W,
2 bottom y = 0, 3 free top surface b < x <= W, 4 punch face 0 <= x <= b.

Usage: flat_punch_mesh.py OUT.msh [--b 1] [--width 6] [--depth 6] [--h 0.05] [--growth 1.15]
"""

import argparse
import sys


def graded(length, h, growth):
    """Points 0 = s_0 < ... < s_n = length with s_1 - s_0 = h and growth factor <= growth."""
    sizes = []
    total = 0.0
    size = h
    while total + size < length:
        sizes.append(size)
        total += size
        size *= growth
    # spread the remainder over all cells proportionally
    scale = length / total if sizes else 1.0
    if not sizes or length - total > 0.5 * sizes[-1]:
        sizes.append(length - total)
        scale = 1.0
    points = [0.0]
    for s in sizes:
        points.append(points[-1] + s * scale)
    points[-1] = length
    return points


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--b", type=float, default=1.0)
    ap.add_argument("--width", type=float, default=6.0)
    ap.add_argument("--depth", type=float, default=6.0)
    ap.add_argument("--h", type=float, default=0.05)
    ap.add_argument("--growth", type=float, default=1.15)
    a = ap.parse_args()

    left = [a.b - s for s in reversed(graded(a.b, a.h, a.growth))]
    right = [a.b + s for s in graded(a.width - a.b, a.h, a.growth)]
    xs = left + right[1:]
    ys = [a.depth - s for s in reversed(graded(a.depth, a.h, a.growth))]
    nx, ny = len(xs), len(ys)

    def node(i, j):
        return j * nx + i + 1

    lines = []
    for j in range(ny - 1):  # left and right sides
        lines.append((0, node(0, j + 1), node(0, j)))
        lines.append((1, node(nx - 1, j), node(nx - 1, j + 1)))
    for i in range(nx - 1):  # bottom and top
        lines.append((2, node(i, 0), node(i + 1, 0)))
        tag = 4 if xs[i + 1] <= a.b + 1e-12 else 3
        lines.append((tag, node(i + 1, ny - 1), node(i, ny - 1)))
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(ny - 1) for i in range(nx - 1)]

    with open(a.out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n")
        f.write(f"{nx * ny}\n")
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                f.write(f"{node(i, j)} {x:.12g} {y:.12g} 0\n")
        f.write("$EndNodes\n$Elements\n")
        f.write(f"{len(lines) + len(quads)}\n")
        n = 0
        for tag, p, q in lines:
            n += 1
            f.write(f"{n} 1 2 {tag} {tag} {p} {q}\n")
        for quad in quads:
            n += 1
            f.write(f"{n} 3 2 0 0 {' '.join(map(str, quad))}\n")
        f.write("$EndElements\n")
    print(f"{a.out}: {nx - 1} x {ny - 1} cells, smallest {a.h}, x nodes at the punch edge: "
          f"{a.b in xs}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
