#!/usr/bin/env python3
"""A 2D case against the same case run as a 3D slab (dimension 3, width, sideWalls): per layer
of the slab along z, the L2 difference of p and of the in-plane velocity from the 2D case's at
the same (x, y) lattice sites. Use after the first step (or a few), while the particles still
sit on their lattice sites.

Usage: slabAgainst2D.py CASE2D SLAB TIME

Needs ascii or binary fields of both cases at TIME and the 2D case's log.particleMesh (the
spacing); the sites are matched on a half-spacing grid.
"""
import math
import os
import re
import sys

from fields import fields

if len(sys.argv) != 4:
    sys.exit(__doc__)
flat, slab, time = sys.argv[1], sys.argv[2], sys.argv[3]
try:
    with open(os.path.join(flat, 'log.particleMesh')) as log:
        dx = float(re.search(r'spacing\s+([-+0-9.eE]+)\s+m', log.read()).group(1))
except (OSError, AttributeError):
    sys.exit(f"slabAgainst2D.py: no spacing in {flat}/log.particleMesh (run particleMesh there first)")
f2 = fields(flat, time, ['kind', 'positions', 'p', 'U'])
f3 = fields(slab, time, ['kind', 'positions', 'p', 'U'])


def site(x):
    return round(x / dx * 2)


sites2 = {(site(x[0]), site(x[1])): i for i, (x, k) in enumerate(zip(f2['positions'], f2['kind'])) if k == 0}
layers = {}
for i, (x, k) in enumerate(zip(f3['positions'], f3['kind'])):
    j = sites2.get((site(x[0]), site(x[1])))
    if k == 0 and j is not None:
        layers.setdefault(site(x[2]), []).append((i, j))
for z in sorted(layers):
    pairs = layers[z]
    dp = sum((f3['p'][i] - f2['p'][j]) ** 2 for i, j in pairs)
    p2 = sum(f2['p'][j] ** 2 for _, j in pairs)
    du = sum((f3['U'][i][c] - f2['U'][j][c]) ** 2 for i, j in pairs for c in range(2))
    u2 = sum(f2['U'][j][c] ** 2 for _, j in pairs for c in range(2))
    print(f"layer z = {z * dx / 2:.5f} m: {len(pairs)} sites, p {100 * math.sqrt(dp / p2):.3f} %, "
          f"U {100 * math.sqrt(du / u2):.3f} % (L2 against the 2D case)")
