#!/usr/bin/env python3
"""A layer sliding on a plane (a copy of slidingBlock: x down the bed, the plane's frame, the
bed a wall patch named `bed`): at each written time, its extent against its length at the
start, the wall particles carrying friction (and those beyond the layer's ends), the bed
friction against tan(delta) times the layer's weight normal to the bed, and the particles left
behind at rest.

Usage: layerEnds.py CASE

Reads the case's own figures: gravity from constant/g (its y component is the weight normal
to the bed), the bed's friction angle from system/particleMeshDict (walls/bed), the spacing
from log.particleMesh. Needs the wallFriction field (written by the solver with a Coulomb bed).
"""
import math
import os
import re
import sys

from fields import fields, times


def entry(path, pattern, what):
    try:
        with open(path) as f:
            m = re.search(pattern, re.sub(r'//[^\n]*', '', f.read()))
    except OSError as e:
        sys.exit(f"layerEnds.py: {e}")
    if not m:
        sys.exit(f"layerEnds.py: no {what} in {path}")
    return m.group(1)


if len(sys.argv) != 2:
    sys.exit(__doc__)
case = sys.argv[1]
number = r'([-+0-9.eE]+)'
gy = float(entry(os.path.join(case, 'constant', 'g'), r'value\s*\(\s*\S+\s+' + number, 'value'))
delta = float(entry(os.path.join(case, 'system', 'particleMeshDict'),
                    r'\bbed\s*\{[^}]*frictionAngle\s+' + number, 'walls/bed frictionAngle'))
dx = float(entry(os.path.join(case, 'log.particleMesh'), r'spacing\s+' + number + r'\s+m', 'spacing'))
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
    weightNormal = sum(f['mass'][i] for i in mat) * abs(gy)
    capacity = math.tan(math.radians(delta)) * weightNormal
    carrying = [i for i in walls if wf[i][0] != 0]
    beyond = [i for i in carrying if pos[i][0] < xs[0] - 1e-9 or pos[i][0] > xs[-1] + 1e-9]
    atRest = sum(1 for i in mat if abs(f['U'][i][0]) < 1e-3)
    print(f"t {t}: extent {(xs[-1] - xs[0]) / length0:.3f} of its length, {len(carrying)} wall particles "
          f"with friction ({len(beyond)} beyond the ends), bed friction "
          f"{sum(wf[i][0] for i in walls) * dx / capacity:.4f} tan(delta) W_n, {atRest} particles at rest")
