#!/usr/bin/env python3
"""The sand left on granularSlope's 50-degree slope: per 0.1 m along the slope (from its toe),
the particles there, the layer's thickness, their mean speed, and their pressure against the
lithostatic pressure of that thickness at the bed, rho g H cos(50).

Usage: slopeFilm.py CASE TIME [RHO]

Counts the material particles left of the toe (x < -0.02 m) and below the gate (y < 1.40 m);
RHO defaults to the tutorial's 1500 kg/m3. A jammed layer shows a speed near 0 and a pressure
many times its lithostatic one. Needs ascii fields.
"""
import math
import sys

from fields import fields

if len(sys.argv) < 3:
    sys.exit(__doc__)
case, time = sys.argv[1], sys.argv[2]
rho = float(sys.argv[3]) if len(sys.argv) > 3 else 1500.0
slope = math.radians(50)
f = fields(case, time, ['positions', 'U', 'p', 'kind'])
bins = {}
for x, u, p, kind in zip(f['positions'], f['U'], f['p'], f['kind']):
    if kind != 0 or x[0] >= -0.02 or x[1] > 1.40:
        continue
    along = -x[0] / math.cos(slope)                                 # up the slope from the toe
    normal = x[1] * math.cos(slope) + x[0] * math.sin(slope)      # above the bed
    bins.setdefault(int(along / 0.1), []).append((normal, math.hypot(u[0], u[1]), p))
print(f"t {time}: {sum(len(b) for b in bins.values())} particles on the slope below the gate")
print("along [m]  particles  thickness [mm]  mean speed [m/s]  max p [Pa]  mean p [Pa]  lithostatic at the bed [Pa]")
for k in sorted(bins):
    b = bins[k]
    H = max(q[0] for q in b)
    print(f"{k * 0.1:8.1f} {len(b):10d} {H * 1e3:15.1f} {sum(q[1] for q in b) / len(b):17.3f} "
          f"{max(q[2] for q in b):11.0f} {sum(q[2] for q in b) / len(b):12.0f} {rho * 9.81 * H * math.cos(slope):14.0f}")
