#!/usr/bin/env python3
"""Where a layer at rest moves (tutorials/validation/granularAtRest and its two-layer tests).

Usage: layerCreep.py CASE TIME [-p RHO_LOW,RHO_UP,Y_CONTACT,BETA_DEG] [ROW_Y ...]

Prints the particles that moved most between the first written time and TIME (by origId), the
largest displacement of those that started below the top two rows and of those in them (as
tests/isph/GranularAtRestTest.cpp's elastic-plastic test splits them), and for each row that started at height ROW_Y (default: the top row) the displacement along and
normal to the bed of every third particle, as x0:dx/dy in mm. With -p, also the mean of
p minus the layered lithostatic pressure per starting row (0.15 < x < 0.45 m), that pressure
counted as in tests/isph/GranularAtRestTest.cpp from the highest particle at TIME. Needs ascii
fields.
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 3:
    sys.exit(__doc__)
case, time = sys.argv[1], sys.argv[2]
args = sys.argv[3:]
layered = None
if args[:1] == ['-p']:
    layered = [float(v) for v in args[1].split(',')]
    args = args[2:]


def material(t):
    f = fields(case, t, ['positions', 'origId', 'kind', 'material'])
    return {int(f['origId'][i]): (f['positions'][i], int(f['material'][i]))
            for i in range(len(f['kind'])) if f['kind'][i] == 0}


start, end = material(times(case)[0]), material(time)
moved = sorted(((math.dist(end[o][0][:2], start[o][0][:2]), o) for o in start), reverse=True)
for d, o in moved[:5]:
    (x0, m), (x1, _) = start[o], end[o]
    print(f"origId {o} (material {m}) from ({x0[0]:.4f}, {x0[1]:.4f}) to ({x1[0]:.4f}, {x1[1]:.4f}): {1e3 * d:.2f} mm")
top0 = max(x[1] for x, _ in start.values())
spacing = top0 - max(x[1] for x, _ in start.values() if x[1] < top0 - 1e-9)
deep = [d for d, o in moved if start[o][0][1] < top0 - 1.5 * spacing]
upper = [d for d, o in moved if start[o][0][1] >= top0 - 1.5 * spacing]
print(f"largest displacement below the top two rows {1e3 * max(deep, default=0):.2f} mm, "
      f"in them {1e3 * max(upper, default=0):.2f} mm")
rows = [float(y) for y in args] or [max(x[1] for x, _ in start.values())]
for y in rows:
    row = sorted((start[o][0][0], o) for o in start if abs(start[o][0][1] - y) < 1e-6)
    print(f"row y0 = {y}: " + " ".join(f"{x:.2f}:{1e3 * (end[o][0][0] - x):.1f}/{1e3 * (end[o][0][1] - y):.1f}"
                                       for x, o in row[::3]))
if layered:
    rho_low, rho_up, yc, beta = layered
    f = fields(case, time, ['positions', 'origId', 'kind', 'p'])
    top = max(x[1] for x, _ in end.values())
    g = 9.81 * math.cos(math.radians(beta))
    offset = {}
    for i, kind in enumerate(f['kind']):
        x = f['positions'][i]
        if kind != 0 or not 0.15 < x[0] < 0.45:
            continue
        exact = g * (rho_up * (top - max(x[1], yc)) + rho_low * max(yc - x[1], 0.0))
        offset.setdefault(round(start[int(f['origId'][i])][0][1], 6), []).append(f['p'][i] - exact)
    for y in sorted(offset):
        print(f"row y0 = {y}: mean p - layered lithostatic {sum(offset[y]) / len(offset[y]):8.1f} Pa")
