#!/usr/bin/env python3
"""The pressure of a plane wall's wall particles row by row (rows of equal y), against the
hydrostatic pressure rho g (YS - y) of still water whose surface particles' centres are at YS
(p = 0 there): what a wall of a 3D tank carries, and so its force (doc/notes/threeD.md: the
side walls of hydrostaticTank3D).

usage: wallRows.py CASE TIME AXIS VALUE RHO G YS
    the wall particles (kind 1) whose coordinate AXIS (x, y or z) equals VALUE (to 1e-9 m);
    RHO [kg/m^3], G = |g| [m/s^2]; writeFormat ascii
"""
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fields import read_field  # noqa: E402


def main():
    if len(sys.argv) != 8:
        raise SystemExit(__doc__)
    case, t, axis = sys.argv[1], sys.argv[2], 'xyz'.index(sys.argv[3])
    value, rho, g, ys = (float(v) for v in sys.argv[4:8])
    d = os.path.join(case, t, 'lagrangian', 'particles')
    x, p, kind = (read_field(os.path.join(d, f)) for f in ('positions', 'p', 'kind'))
    rows = defaultdict(list)
    for xi, pi, k in zip(x, p, kind):
        if k == 1 and abs(xi[axis] - value) < 1e-9:
            rows[round(xi[1], 9)].append(pi)
    print("y [m], wall particles, mean p [Pa], mean p - rho g (YS - y) [Pa]")
    for y in sorted(rows):
        mean = sum(rows[y]) / len(rows[y])
        print(f"{y:10.6g} {len(rows[y]):5d} {mean:12.6g} {mean - rho * g * (ys - y):12.4g}")


if __name__ == '__main__':
    main()
