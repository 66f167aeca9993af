#!/usr/bin/env python3
"""The pressure on a flat bed against the weight of the material above it, in the bed's frame
(x along the bed, y normal to it, the bed's wall particles at y = 0), at written times.

Usage: bedPressure.py CASE DX RHO GN X0:X1 [X0:X1 ...] [-t TIME ...]

GN is the component of gravity normal to the bed [m/s^2] (9.81 cos θ). For each range of x
it prints the bed's Σ p A (A = dx per metre of width) against the lithostatic one,
Σ ρ GN (h + dx/2) A, h the highest material particle centre over the wall particle (within
its dx-wide column), and the material particles' mean pressure there against their mean
lithostatic pressure ρ GN (depth + dx/2). A ratio near 1 is a layer whose pressure is its
weight; far above 1, a pressure the weight does not explain. Needs ascii fields.
"""
import math
import sys

from fields import fields, times

args = sys.argv[1:]
if len(args) < 5:
    sys.exit(__doc__)
selected = args[args.index('-t') + 1:] if '-t' in args else []
if '-t' in args:
    args = args[:args.index('-t')]
case, dx, rho, gn = args[0], float(args[1]), float(args[2]), float(args[3])
ranges = [tuple(float(v) for v in r.split(':')) for r in args[4:]]
for t in selected or times(case):
    f = fields(case, t, ['positions', 'kind', 'p'])
    x, kind, p = f['positions'], f['kind'], f['p']
    top = {}
    for i, k in enumerate(kind):
        if k == 0:
            column = math.floor(x[i][0] / dx)
            top[column] = max(top.get(column, -math.inf), x[i][1])
    print(f"t {t}:")
    for x0, x1 in ranges:
        bed = lithostatic = 0.0
        walls = 0
        for w, k in enumerate(kind):
            if k != 1 or abs(x[w][1]) > 1e-9 or not x0 < x[w][0] < x1:
                continue
            h = top.get(math.floor(x[w][0] / dx))
            bed += p[w] * dx
            lithostatic += rho * gn * (h + 0.5 * dx) * dx if h is not None else 0.0
            walls += 1
        inside = [(p[i], rho * gn * (top[math.floor(x[i][0] / dx)] - x[i][1] + 0.5 * dx))
                  for i, k in enumerate(kind) if k == 0 and x0 < x[i][0] < x1]
        ratio = bed / lithostatic if lithostatic > 0 else math.nan
        print(f"  x {x0:g} to {x1:g}: bed ({walls} wall particles) {bed:.4g} N/m against lithostatic "
              f"{lithostatic:.4g} N/m, ratio {ratio:.3f}", end='')
        if inside:
            n = len(inside)
            print(f"; material ({n}): mean p {sum(v[0] for v in inside) / n:.0f} Pa against "
                  f"{sum(v[1] for v in inside) / n:.0f} Pa lithostatic, max {max(v[0] for v in inside):.0f} Pa")
        else:
            print()
