#!/usr/bin/env python3
"""Each wall patch's sum of p dx (2D: the normal force per metre a flat patch carries), as the
force sampler counts it (every wall particle a whole spacing) and with each corner particle's
spacing split half and half between its two faces (a wall particle that also lies on the plane
of a neighbouring wall particle with another normal: the corner of a box): what the corner share
alone would change (doc/notes/wallTraction.md).

usage: wallCorners.py CASE TIME DX
    the cloud's wall particles (kind 1) at TIME; DX the spacing [m]
"""
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fields import fields  # noqa: E402


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    case, t, dx = sys.argv[1], sys.argv[2], float(sys.argv[3])
    f = fields(case, t, ('positions', 'normal', 'p', 'kind', 'patch'))
    walls = [i for i, k in enumerate(f['kind']) if k == 1]
    x, n, p, patch = f['positions'], f['normal'], f['p'], f['patch']
    dot = lambda a, b: sum(u * v for u, v in zip(a, b))  # noqa: E731
    whole, halved = defaultdict(float), defaultdict(float)
    for w in walls:
        corner = None
        for v in walls:  # the other face: a neighbour one spacing away, whose plane w lies on
            d = [a - b for a, b in zip(x[w], x[v])]
            if v != w and dot(d, d) < (1.01 * dx) ** 2 and dot(n[v], n[w]) < 0.5 and abs(dot(d, n[v])) < 0.05 * dx:
                corner = v
                break
        whole[int(patch[w])] += p[w] * dx
        if corner is None:
            halved[int(patch[w])] += p[w] * dx
        else:  # half on its own face, half on the neighbour's (the bed below a side wall's corner)
            halved[int(patch[w])] += 0.5 * p[w] * dx
            halved[int(patch[corner])] += 0.5 * p[w] * dx
    print("patch, sum p dx as sampled [N/m], with the corners halved between their faces [N/m]")
    for k in sorted(whole):
        print(f"{k} {whole[k]:.2f} {halved[k]:.2f}")


if __name__ == '__main__':
    main()
