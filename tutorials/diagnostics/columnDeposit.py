#!/usr/bin/env python3
"""The column collapse's deposit at its last written time (tutorials/validation/columnCollapse).

Usage: columnDeposit.py CASE [DX]   (DX: the spacing, default 0.0025 m)

Prints the toe (the farthest rod with two rods within 1.5 DX, plus DX/2), the RMS distance of
the final surface to the measured one (highest rod centre plus DX/2 per DX-wide bin, linear
between bin centres, as the ctest ColumnCollapse measures it), the height at the wall (the
first bin), the mean and largest motion of the rods that start within 0.02 m of the top-left
corner, and the mean speed of the rods within 0.05 m of the wall. Needs ascii fields.
"""
import csv
import math
import os
import sys

from fields import fields, times

if len(sys.argv) < 2:
    sys.exit(__doc__)
case = sys.argv[1]
dx = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0025
H, measuredToe = 0.1, 0.4423
here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, '..', 'validation', 'columnCollapse', 'validation',
                    'granular_collapse_bui2008_final_surface.csv')
measured = [(float(r[0]), float(r[1])) for r in csv.reader(open(data)) if r and r[0][:1].isdigit()]

ts = times(case)
first = fields(case, ts[0], ['positions', 'origId', 'kind'])
last = fields(case, ts[-1], ['positions', 'origId', 'kind', 'U'])
start = {int(first['origId'][i]): first['positions'][i] for i in range(len(first['kind'])) if first['kind'][i] == 0}
rods = [i for i in range(len(last['kind'])) if last['kind'][i] == 0]
x = [last['positions'][i] for i in rods]

nb = int(round(0.6 / dx))
top = [0.0] * nb
for p in x:
    b = int(p[0] / dx)
    if 0 <= b < nb:
        top[b] = max(top[b], p[1] + dx / 2)


def surface(xq):
    c = (xq / dx) - 0.5
    if c <= 0:
        return top[0]
    b = min(int(c), nb - 2)
    w = min(c - b, 1.0)
    return top[b] * (1 - w) + top[b + 1] * w


rms = math.sqrt(sum((surface(a) - h) ** 2 for a, h in measured) / len(measured))
toe = 0.0
for p in x:
    near = sum(1 for q in x if q is not p and math.hypot(q[0] - p[0], q[1] - p[1]) < 1.5 * dx)
    if near >= 2:
        toe = max(toe, p[0] + dx / 2)
moves, speeds = [], []
for i in rods:
    p, x0 = last['positions'][i], start[int(last['origId'][i])]
    if x0[0] < 0.02 and x0[1] > H - 0.02:
        moves.append(math.hypot(p[0] - x0[0], p[1] - x0[1]))
    if p[0] < 0.05:
        speeds.append(math.hypot(last['U'][i][0], last['U'][i][1]))
print(f"time {ts[-1]} s: toe {toe:.4f} m ({100 * (toe / measuredToe - 1):+.1f} %), surface RMS {1e3 * rms:.2f} mm, "
      f"height at the wall {top[0]:.4f} m")
print(f"corner rods ({len(moves)}) moved {1e3 * sum(moves) / len(moves):.2f} mm on average, "
      f"{1e3 * max(moves):.2f} mm at most; rods within 0.05 m of the wall: mean speed "
      f"{1e3 * sum(speeds) / len(speeds):.2f} mm/s")
