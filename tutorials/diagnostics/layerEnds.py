#!/usr/bin/env python3
"""A layer sliding on a plane (a copy of slidingBlock: x down the bed, the bed's wall
particles at y = 0): at each written time, its extent against its length at the start, the
wall particles carrying friction (and those beyond the layer's ends), the bed friction against
tan(delta) times the layer's weight normal to the bed, and the particles left behind at rest.

Usage: layerEnds.py CASE ANGLE_DEG DELTA_DEG [DX]

ANGLE_DEG is the plane's slope (from constant/g), DELTA_DEG the bed's friction angle, DX the
spacing (default 0.005 m). Needs the wallFriction field (written by the solver with a Coulomb
bed) and ascii or binary fields.
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 4:
    sys.exit(__doc__)
case, angle, delta = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
dx = float(sys.argv[4]) if len(sys.argv) > 4 else 0.005
allTimes = times(case)
first = fields(case, allTimes[0], ['kind', 'positions'])
x0 = sorted(p[0] for p, k in zip(first['positions'], first['kind']) if k == 0)
length0 = x0[-1] - x0[0]
for t in allTimes[1:]:
    f = fields(case, t, ['kind', 'positions', 'wallFriction', 'U', 'mass'])
    kind, pos, wf = f['kind'], f['positions'], f['wallFriction']
    mat = [i for i, k in enumerate(kind) if k == 0]
    walls = [i for i, k in enumerate(kind) if k == 1]
    xs = sorted(pos[i][0] for i in mat)
    weightNormal = sum(f['mass'][i] for i in mat) * 9.81 * math.cos(math.radians(angle))
    capacity = math.tan(math.radians(delta)) * weightNormal
    carrying = [i for i in walls if wf[i][0] != 0]
    beyond = [i for i in carrying if pos[i][0] < xs[0] - 1e-9 or pos[i][0] > xs[-1] + 1e-9]
    atRest = sum(1 for i in mat if abs(f['U'][i][0]) < 1e-3)
    print(f"t {t}: extent {(xs[-1] - xs[0]) / length0:.3f} of its length, {len(carrying)} wall particles "
          f"with friction ({len(beyond)} beyond the ends), bed friction "
          f"{sum(wf[i][0] for i in walls) * dx / capacity:.4f} tan(delta) W_n, {atRest} particles at rest")
