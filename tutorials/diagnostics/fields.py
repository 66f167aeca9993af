"""Reading the ascii particle fields of a time directory (writeFormat ascii in system/controlDict).

<case>/<time>/lagrangian/<cloud>/<field>: an OpenFOAM-style header, then N ( ... ) of scalars
or of (x y z) vectors or (xx xy xz yy yz zz) symmetric tensors.
"""
import os
import re


def read_field(path):
    text = open(path).read()
    body = text[text.index('}', text.index('FoamFile')) + 1:]
    body = re.sub(r'//.*', '', body)
    m = re.search(r'(\d+)\s*\(', body)
    if not m:
        raise SystemExit(f"{path}: no list found (is writeFormat ascii?)")
    n = int(m.group(1))
    inner = body[m.end():body.rindex(')')]
    if '(' in inner:
        values = [tuple(map(float, v.split())) for v in re.findall(r'\(([^()]*)\)', inner)]
    else:
        values = [float(v) for v in inner.split()]
    if len(values) != n:
        raise SystemExit(f"{path}: {len(values)} values, the header says {n}")
    return values


def times(case):
    return sorted((t for t in os.listdir(case) if re.fullmatch(r'[0-9.eE+-]+', t) and
                   os.path.isdir(os.path.join(case, t, 'lagrangian'))), key=float)


def fields(case, time, names, cloud='particles'):
    d = os.path.join(case, time, 'lagrangian', cloud)
    return {name: read_field(os.path.join(d, name)) for name in names}
