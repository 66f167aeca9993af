#!/usr/bin/env python3
"""granularSlope's stream, the figures of issue 55 at each written time: the mean speed along
the slope of the sand between the gate and the toe, the first time sand is on the floor, the
sand left in the reservoir, and the bed's load and friction under the stream against the
stream's weight normal to the bed (as slopeBed.py: 1 and tan 25 = 0.466 for a Coulomb layer).

Usage: slopeStream.py CASE DX [TIME ...]

The stream: material particles left of the toe (x < -0.02 m) and below the gate's foot
(y < 1.35 m). On the floor: x > 0. In the reservoir: y > 1.414 m (above the gate's foot).
Masses in the flume's 0.32 m width (as the tutorial's results.txt). Needs ascii fields (the tutorial writes them).
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 3:
    sys.exit(__doc__)
case, dx = sys.argv[1], float(sys.argv[2])
rho, g, slope, width = 1500.0, 9.81, math.radians(50), 0.32
down = (math.cos(slope), -math.sin(slope))  # along the bed, towards the toe
first_on_floor = None
print("# t [s] | stream mass [kg] | stream speed along the slope [m/s] | on the floor [kg] | "
      "in the reservoir [kg] | bed load / weight | bed friction / weight")
for t in sys.argv[3:] or times(case):
    try:
        f = fields(case, t, ['positions', 'U', 'kind', 'mass', 'p', 'wallFriction'])
    except FileNotFoundError:  # the initial time has no wallFriction (nothing has acted yet)
        continue
    stream = momentum = floor = reservoir = load = friction = 0.0
    for x, u, kind, m, p, w in zip(f['positions'], f['U'], f['kind'], f['mass'], f['p'], f['wallFriction']):
        if kind == 0:
            if x[0] > 0:
                floor += m
            if x[1] > 1.414:
                reservoir += m
            if x[0] < -0.02 and x[1] < 1.35:
                stream += m
                momentum += m * (u[0] * down[0] + u[1] * down[1])
        elif x[0] < -0.02 and x[1] < 1.35 and (w[0] != 0 or w[1] != 0):
            load += (p + 0.5 * rho * g * math.cos(slope) * dx) * dx
            friction += (w[0] * down[0] + w[1] * down[1]) * dx
    if floor > 0 and first_on_floor is None:
        first_on_floor = t
    weight = stream * g * math.cos(slope)
    speed = momentum / stream if stream > 0 else float('nan')
    ratio = (lambda v: v / weight if weight > 0 else float('nan'))
    print(f"{float(t):6.3f} {stream * width:8.3f} {speed:7.3f} {floor * width:8.3f} {reservoir * width:8.3f} "
          f"{ratio(load):6.2f} {ratio(friction):6.3f}")
print(f"# first written time with sand on the floor: {first_on_floor}")
