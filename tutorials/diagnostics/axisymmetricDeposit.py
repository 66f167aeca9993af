#!/usr/bin/env python3
"""The deposit of a quarter of an axisymmetric column (a `type cylinder` region whose axis is the
line x = z = 0, the planes x = 0 and z = 0 symmetry walls): at each time, the front along x
(the largest x of the material within 2 dx of z = 0), along z (within 2 dx of x = 0) and along
the diagonal (the largest radius within 2 dx of x = z), the run-out ΔR/R0 along x (the front
plus dx/2, less R0), the height at the axis (the highest material particle within 2 dx of it,
plus dx/2) over R0, and how many material particles lie below the floor y = 0
(doc/notes/threeD.md).

usage: axisymmetricDeposit.py CASE R0 DX [TIME ...]   (every written time if none)
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fields import read_field, times  # noqa: E402


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    case, r0, dx = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    band = 2 * dx
    for t in sys.argv[4:] or times(case):
        d = os.path.join(case, t, 'lagrangian', 'particles')
        x, kind = read_field(os.path.join(d, 'positions')), read_field(os.path.join(d, 'kind'))
        pts = [p for p, k in zip(x, kind) if k == 0]
        radius = [math.hypot(p[0], p[2]) for p in pts]
        along_x = max(p[0] for p in pts if abs(p[2]) < band)
        along_z = max(p[2] for p in pts if abs(p[0]) < band)
        diagonal = max(r for p, r in zip(pts, radius) if abs(p[0] - p[2]) < band * math.sqrt(2))
        height = max(p[1] for p, r in zip(pts, radius) if r < band) + dx / 2
        below = sum(1 for p in pts if p[1] < 0)
        print(f"t {t}: {len(pts)} particles; front along x {along_x:.4f}, z {along_z:.4f}, diagonal "
              f"{diagonal:.4f} m; dR/R0 {(along_x + dx / 2 - r0) / r0:.3f}; height at the axis "
              f"{height:.4f} m, H/R0 {height / r0:.3f}; below the floor {below}")


if __name__ == '__main__':
    main()
