#!/usr/bin/env python3
"""The along-bed balance of the material upstream of a barrier, from the wall force routine's inputs.

Usage: wedgeBalance.py CASE DX GX XB [WIDTH] [-t TIME ...]

In the bed's frame (x along the bed, y normal to it, the bed's wall particles at y = 0, the
barrier's upstream face at x = XB): for each written time, the material with x < XB (its
mass, weight along the bed M GX and mean speed along the bed) against the forces that the
wall force routine (src/postProcessing/forces/PatchForces.hpp) finds holding it: the bed's
Coulomb friction (the field wallFriction of the bed's wall particles upstream of XB, times
their area dx) and the pressure and friction on the barrier's upstream face (its wall
particles within dx of XB, above the bed, with a normal facing upstream: n_x < -1/2, as
the tutorial's `facing (-1 0 0)`). For material at rest the two must balance; their difference is the
routine's error on that structure (the function object momentumBalance gives the exact
total over all walls only). WIDTH (default 0.3 m, the barrier tutorial's flume) scales the
per-metre forces of 2D. Needs ascii fields.
"""
import sys

from fields import fields, times

args = sys.argv[1:]
selected = args[args.index('-t') + 1:] if '-t' in args else []
if '-t' in args:
    args = args[:args.index('-t')]
if len(args) < 4:
    sys.exit(__doc__)
case, dx, gx, xb = args[0], float(args[1]), float(args[2]), float(args[3])
width = float(args[4]) if len(args) > 4 else 0.3
names = ['positions', 'kind', 'p', 'normal', 'wallFriction', 'mass', 'U']
for t in selected or times(case)[1:]:
    f = fields(case, t, names)
    X, K, P, N, T, M, U = (f[k] for k in names)
    mass = momentum = bedFriction = barrierPressure = barrierFriction = 0.0
    for i, x in enumerate(X):
        if K[i] == 0 and x[0] < xb:
            mass += M[i]
            momentum += M[i] * U[i][0]
        elif K[i] == 1 and abs(x[1]) < 1e-9 * dx and x[0] < xb - 1e-9:
            bedFriction += T[i][0] * dx
        elif K[i] == 1 and x[1] > 1e-9 * dx and abs(x[0] - xb) < dx and N[i][0] < -0.5:
            barrierPressure -= P[i] * dx * N[i][0]
            barrierFriction += T[i][0] * dx
    if mass == 0:
        print(f"t {t}: no material upstream of x = {xb}")
        continue
    weight = width * mass * gx
    held = width * (bedFriction + barrierPressure + barrierFriction)
    print(f"t {t}: upstream {width * mass:.1f} kg, mean speed along the bed {momentum / mass:.3f} m/s, "
          f"along-bed weight {weight:.1f} N; held by bed friction {width * bedFriction:.1f} N + barrier pressure "
          f"{width * barrierPressure:.1f} N + barrier friction {width * barrierFriction:.1f} N = {held:.1f} N "
          f"({held / weight:.3f} of the weight)")
