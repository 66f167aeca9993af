#!/usr/bin/env python3
"""The kernel sum θ of each material particle of a 2D case with its wall and dummy particles
moved half a spacing back along their wall's normal (a dummy takes its nearest wall particle's),
against the full lattice's θ0: what the PPE's relaxation source compares with 1.01 θ0
(src/isph/pressure/PressurePoissonEquation.hpp; WendlandC2, h = 1.3 dx, volumes dx²). On the
lattice at a flat wall or a tank's corner θ/θ0 = 1; the largest values name where the wall
layout reads as compression (doc/notes/threeD.md: 1.13 by a block's convex corners).

usage: thetaLattice.py CASE DX [TIME]   (the first written time if none; prints the 10
largest θ/θ0 and how many exceed 1.01)
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fields import read_field, times  # noqa: E402


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    case, dx = sys.argv[1], float(sys.argv[2])
    t = sys.argv[3] if len(sys.argv) > 3 else times(case)[0]
    d = os.path.join(case, t, 'lagrangian', 'particles')
    x = [p[:2] for p in read_field(os.path.join(d, 'positions'))]
    kind = read_field(os.path.join(d, 'kind'))
    normal = [p[:2] for p in read_field(os.path.join(d, 'normal'))]
    h = 1.3 * dx
    alpha = 7 / (4 * math.pi * h * h)

    def w(r):
        q = r / h
        return alpha * (1 - q / 2) ** 4 * (2 * q + 1) if q < 2 else 0.0

    theta0 = sum(dx * dx * w(math.hypot(i * dx, j * dx)) for i in range(-4, 5) for j in range(-4, 5))
    walls = [i for i in range(len(x)) if kind[i] == 1]
    n = list(normal)
    for i in range(len(x)):
        if kind[i] == 2:
            nearest = min(walls, key=lambda b: (x[b][0] - x[i][0]) ** 2 + (x[b][1] - x[i][1]) ** 2)
            n[i] = normal[nearest]
    moved = [(x[i][0] - 0.5 * dx * n[i][0], x[i][1] - 0.5 * dx * n[i][1]) if kind[i] != 0 else x[i]
             for i in range(len(x))]
    rows = []
    for a in range(len(x)):
        if kind[a] != 0:
            continue
        theta = sum(dx * dx * w(math.hypot(m[0] - x[a][0], m[1] - x[a][1])) for m in moved
                    if abs(m[0] - x[a][0]) < 2 * h and abs(m[1] - x[a][1]) < 2 * h)
        rows.append((theta / theta0, x[a]))
    rows.sort(reverse=True)
    for ratio, p in rows[:10]:
        print(f"{ratio:.4f}  at ({p[0]:.4f} {p[1]:.4f})")
    print(f"above 1.01 theta0: {sum(1 for r, _ in rows if r > 1.01)} of {len(rows)}")


if __name__ == '__main__':
    main()
