#!/usr/bin/env python3
"""What granularSlope's 50-degree bed does to the sand on it: the bed's normal load and its
friction against the weight of the sand on the slope, at written times.

Usage: slopeBed.py CASE DX [TIME ...]

Takes the material particles left of the toe (x < -0.02 m) and below the gate (y < 1.35 m)
and the wall particles of the slope there that carry friction (the `wallFriction` field, a
traction per dx of bed). Prints the sand's weight normal to the bed, M g cos 50, and against
it: the sum over those wall particles of (p_w + the half layer of WallFriction.hpp) dx, the
load the wall-pressure capacity takes (1 for a layer pressing with its weight), and the
friction they take along the slope, which a Coulomb layer sliding on the 25-degree bed keeps
at tan 25 = 0.466 of the weight (more: the stream is braked beyond its bed's friction).
The half layer takes the tutorial's 1500 kg/m3. Needs ascii fields.
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 3:
    sys.exit(__doc__)
case, dx = sys.argv[1], float(sys.argv[2])
rho, g, slope = 1500.0, 9.81, math.radians(50)
down = (math.cos(slope), -math.sin(slope))  # along the bed, towards the toe
for t in sys.argv[3:] or times(case):
    f = fields(case, t, ['positions', 'kind', 'mass', 'p', 'wallFriction'])
    mass = load = friction = 0.0
    walls = 0
    for x, kind, m, p, w in zip(f['positions'], f['kind'], f['mass'], f['p'], f['wallFriction']):
        if x[0] >= -0.02 or x[1] > 1.35:
            continue
        if kind == 0:
            mass += m
        elif w[0] != 0 or w[1] != 0:
            walls += 1
            load += (p + 0.5 * rho * g * math.cos(slope) * dx) * dx
            friction += (w[0] * down[0] + w[1] * down[1]) * dx
    weight = mass * g * math.cos(slope)
    if weight <= 0:
        print(f"t {t}: no sand on the slope")
        continue
    print(f"t {t}: sand on the slope {mass:.1f} kg/m, its weight normal to the bed {weight:.0f} N/m; "
          f"{walls} bed particles with friction: load {load:.0f} N/m = {load / weight:.2f} x the weight, "
          f"friction {friction:.0f} N/m = {friction / weight:.3f} x the weight (tan 25 = 0.466)")
