#!/usr/bin/env python3
"""How far a material rides above a flat bed: the lowest material particle per dx-wide column.

Usage: bedGap.py CASE DX X0 X1 [TIME ...]

In the bed's frame (x along the bed, y normal to it, the bed's wall particles at y = 0): for
each written time (or the given ones), the columns dx wide between X0 and X1 that hold
material, and the height of their lowest material particle centre over the bed, in dx:
smallest, median, 90th percentile and largest. Material resting on the bed on its initial
lattice sits at 0.5 dx; more is a gap between the material and the bed. Needs ascii fields.
"""
import sys

from fields import fields, times

if len(sys.argv) < 5:
    sys.exit(__doc__)
case, dx, x0, x1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
for t in sys.argv[5:] or times(case):
    f = fields(case, t, ['positions', 'kind'])
    low = {}
    for x, k in zip(f['positions'], f['kind']):
        if k != 0 or not (x0 <= x[0] < x1):
            continue
        column = int((x[0] - x0) / dx)
        low[column] = min(low.get(column, float('inf')), x[1])
    if not low:
        print(f"t {t}: no material between x = {x0} and {x1}")
        continue
    v = sorted(h / dx for h in low.values())
    print(f"t {t}: {len(v)} columns, lowest particle over the bed [dx]: min {v[0]:.2f} median {v[len(v) // 2]:.2f} "
          f"p90 {v[int(0.9 * len(v))]:.2f} max {v[-1]:.2f}")
