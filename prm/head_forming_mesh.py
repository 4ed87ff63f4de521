#!/usr/bin/env python3
"""Write the mesh of prm/head_forming.prm (Gmsh 2.2 ASCII): the rectangle 0 <= r <= R,
0 <= z <= H in NR x NZ uniform cells, with the lateral surface split at the die face z = Z_S.

Boundary ids (physical tags): 0 axis r = 0, 1 lateral surface in the bore (z <= Z_S),
2 bottom z = 0, 3 top z = H, 4 free lateral surface above the die face (z >= Z_S).

Usage: head_forming_mesh.py OUT.msh [--radius 10] [--height 30] [--shoulder 10] [--cells 4,12]
"""

import argparse
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--radius", type=float, default=10.0)
    ap.add_argument("--height", type=float, default=30.0)
    ap.add_argument("--shoulder", type=float, default=10.0)
    ap.add_argument("--cells", default="4,12")
    a = ap.parse_args()
    nr, nz = (int(v) for v in a.cells.split(","))
    xs = [a.radius * i / nr for i in range(nr + 1)]
    ys = [a.height * j / nz for j in range(nz + 1)]
    if min(abs(y - a.shoulder) for y in ys) > 1e-9:
        raise SystemExit("head_forming_mesh.py: the die face z = shoulder must be a row of nodes")
    nx = nr + 1

    def node(i, j):
        return j * nx + i + 1

    lines = []
    for j in range(nz):
        lines.append((0, node(0, j + 1), node(0, j)))
        tag = 1 if ys[j + 1] <= a.shoulder + 1e-9 else 4
        lines.append((tag, node(nr, j), node(nr, j + 1)))
    for i in range(nr):
        lines.append((2, node(i, 0), node(i + 1, 0)))
        lines.append((3, node(i + 1, nz), node(i, nz)))
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(nz) for i in range(nr)]
    with open(a.out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n")
        f.write(f"{nx * (nz + 1)}\n")
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
    print(f"{a.out}: {nr} x {nz} cells")
    return 0


if __name__ == "__main__":
    sys.exit(main())
