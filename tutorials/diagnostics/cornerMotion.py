#!/usr/bin/env python3
"""How the rods near the top-left corner of the column move (tutorials/validation/columnCollapse).

Usage: cornerMotion.py CASE [H]   (H: the column height, default 0.1 m)

For every written time: the mean and largest settlement, the mean move away from the wall and
the mean distance moved (as tests/isph/ColumnCollapseTest.cpp measures it) of the rods that
start within 0.02 m of the top-left corner (x < 0.02, y > H - 0.02), their mean speed, and the mean speed of the rods between x = 0.05 and 0.1 m. Needs ascii fields.
"""
import math
import sys

from fields import fields, times

if len(sys.argv) < 2:
    sys.exit(__doc__)
case = sys.argv[1]
H = float(sys.argv[2]) if len(sys.argv) > 2 else 0.1
ts = times(case)


def material(time):
    f = fields(case, time, ['positions', 'origId', 'kind', 'U'])
    return {int(f['origId'][i]): (f['positions'][i], f['U'][i]) for i in range(len(f['kind'])) if f['kind'][i] == 0}


start = material(ts[0])
corner = [o for o, (x, _) in start.items() if x[0] < 0.02 and x[1] > H - 0.02]
print(f"{len(corner)} corner rods; mm and mm/s")
print("time   dy mean  dy min  dx mean  moved mean  corner speed  speed at x 0.05-0.1 m")
for t in ts:
    now = material(t)
    dy = [now[o][0][1] - start[o][0][1] for o in corner]
    dxw = [now[o][0][0] - start[o][0][0] for o in corner]
    moved = [math.hypot(a, b) for a, b in zip(dxw, dy)]
    speed = [math.hypot(*now[o][1][:2]) for o in corner]
    middle = [math.hypot(*u[:2]) for x, u in now.values() if 0.05 < x[0] < 0.1]
    print(f"{t:>6} {1e3 * sum(dy) / len(dy):7.2f} {1e3 * min(dy):7.2f} {1e3 * sum(dxw) / len(dxw):8.2f} "
          f"{1e3 * sum(moved) / len(moved):11.2f} {1e3 * sum(speed) / len(speed):13.2f} {1e3 * sum(middle) / max(len(middle), 1):22.2f}")
