#!/usr/bin/env python3
"""A 3D slab (a 2D scene extruded along z, `dimension 3;`) layer by layer: for each layer of
material particles along z, at each time, how many are flagged free surface, their mean u_x
and the largest |u_z|. A slab between side walls that runs as its 2D case has the same figures
in every layer; the layers next to the side walls differ where the walls act on them
(doc/notes/threeD.md).

usage: slabLayers.py CASE DX [TIME ...]   (every written time if none; writeFormat ascii)
"""
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fields import read_field, times  # noqa: E402


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    case, dx = sys.argv[1], float(sys.argv[2])
    for t in sys.argv[3:] or times(case)[1:]:
        d = os.path.join(case, t, 'lagrangian', 'particles')
        x, u = read_field(os.path.join(d, 'positions')), read_field(os.path.join(d, 'U'))
        kind, flag = read_field(os.path.join(d, 'kind')), read_field(os.path.join(d, 'freeSurface'))
        layers = defaultdict(lambda: [0, 0, 0.0, 0.0])  # particles, flags, sum u_x, max |u_z|
        for xi, ui, k, f in zip(x, u, kind, flag):
            if k != 0:
                continue
            s = layers[int(xi[2] // dx)]
            s[0] += 1
            s[1] += int(f)
            s[2] += ui[0]
            s[3] = max(s[3], abs(ui[2]))
        print(f"time {t}: layer (z / dx), particles, free-surface flags, mean u_x [m/s], max |u_z| [m/s]")
        for k in sorted(layers):
            n, f, ux, uz = layers[k]
            print(f"    {k:3d} {n:7d} {f:6d} {ux / n:10.4g} {uz:10.3g}")


if __name__ == '__main__':
    main()
