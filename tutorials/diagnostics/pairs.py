#!/usr/bin/env python3
"""How close the material particles sit to each other: the distance to the nearest material
neighbour, in spacings, at the written times of a case.

Usage: pairs.py CASE DX [TIME ...]

Prints, per time (default: every written time), the quartiles of that distance over the
material particles and how many sit closer than 0.6 dx (on the lattice every particle has 1.0;
the collision safeguard, `collision { distance 0.5; }` in system/isphSchemes, holds pairs at
0.5). A flow whose particles pair up shows a median falling towards 0.5. Needs ascii fields.
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 3:
    sys.exit(__doc__)
case, dx = sys.argv[1], float(sys.argv[2])
for t in sys.argv[3:] or times(case):
    f = fields(case, t, ['positions', 'kind'])
    points = [(x[0], x[1]) for x, kind in zip(f['positions'], f['kind']) if kind == 0]
    cells = {}
    for i, (x, y) in enumerate(points):
        cells.setdefault((math.floor(x / dx), math.floor(y / dx)), []).append(i)
    nearest = []
    for i, (x, y) in enumerate(points):
        cx, cy = math.floor(x / dx), math.floor(y / dx)
        d = min((math.hypot(points[j][0] - x, points[j][1] - y)
                 for ix in range(cx - 2, cx + 3) for iy in range(cy - 2, cy + 3)
                 for j in cells.get((ix, iy), []) if j != i), default=math.inf)
        nearest.append(d / dx)
    nearest.sort()
    n = len(nearest)
    print(f"t {t}: {n} material particles, nearest neighbour / dx: quartiles "
          f"{nearest[n // 4]:.2f} {nearest[n // 2]:.2f} {nearest[3 * n // 4]:.2f}, "
          f"closer than 0.6 dx: {sum(1 for d in nearest if d < 0.6)}")
