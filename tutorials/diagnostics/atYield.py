#!/usr/bin/env python3
"""How many material particles are at yield: |tau| against the rigid-plastic strength.

Usage: atYield.py CASE TIME DX PHI1,PHI2,... RHO1,RHO2,...   (per material, in the order of
constant/materialProperties; DX the spacing)

|tau| = sqrt(tau:tau / 2) of the written deviatoric stress, against the strength of
DruckerPragerRigidPlastic, sin(phi) (p + rho |g| dx / 2) with |g| = 9.81. A particle below
0.999 of it has its viscosity at the cap etaMax (rigid); at 0.999 or more it is at yield.
Needs ascii fields.
"""
import math
import sys

from fields import fields

if len(sys.argv) < 6:
    sys.exit(__doc__)
case, time, dx = sys.argv[1], sys.argv[2], float(sys.argv[3])
phis = [float(v) for v in sys.argv[4].split(',')]
rhos = [float(v) for v in sys.argv[5].split(',')]
f = fields(case, time, ['kind', 'material', 'p', 'tau'])
count = {}
for i, kind in enumerate(f['kind']):
    if kind != 0:
        continue
    m = int(f['material'][i])
    strength = math.sin(math.radians(phis[m])) * (max(f['p'][i], 0.0) + 0.5 * rhos[m] * 9.81 * dx)
    xx, xy, xz, yy, yz, zz = f['tau'][i]
    norm = math.sqrt(0.5 * (xx * xx + yy * yy + zz * zz) + xy * xy + xz * xz + yz * yz)
    state = 'at yield' if strength > 0 and norm >= 0.999 * strength else 'below yield'
    count[(m, state)] = count.get((m, state), 0) + 1
for (m, state), n in sorted(count.items()):
    print(f"material {m}: {n} {state}")
