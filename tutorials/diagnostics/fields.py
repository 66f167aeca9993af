"""Reading the particle fields of a time directory, ascii or binary (writeFormat in
system/controlDict).

<case>/<time>/lagrangian/<cloud>/<field>: an OpenFOAM-style header, then N ( ... ) of scalars
or of (x y z) vectors or (xx xy xz yy yz zz) symmetric tensors; binary: N, then ( and the
values as raw little-endian numbers (the header's arch: label=32, scalar=64), then ).
"""
import os
import re
import struct

COMPONENTS = {'labelField': 1, 'scalarField': 1, 'vectorField': 3, 'symmTensorField': 6}


def read_binary(path, data):
    head_end = data.index(b'}', data.index(b'FoamFile')) + 1
    header = data[:head_end].decode('latin-1')
    cls = re.search(r'class\s+(\w+)', header).group(1)
    if cls not in COMPONENTS:
        raise SystemExit(f"{path}: class {cls} is not a field this reader knows")
    m = re.compile(rb'(?:\s|//[^\n]*\n)*(\d+)\s*\(').match(data, head_end)
    if not m:
        raise SystemExit(f"{path}: no list found after the header")
    n, comps = int(m.group(1)), COMPONENTS[cls]
    code = 'i' if cls == 'labelField' else 'd'
    fmt = '<%d%s' % (n * comps, code)
    flat = struct.unpack_from(fmt, data, m.end())
    if comps == 1:
        return [float(v) for v in flat]
    return [tuple(flat[k * comps:(k + 1) * comps]) for k in range(n)]


def read_field(path):
    data = open(path, 'rb').read()
    head = data[:data.index(b'}', data.index(b'FoamFile')) + 1]
    if re.search(rb'format\s+binary', head):
        return read_binary(path, data)
    text = data.decode('latin-1')
    body = text[text.index('}', text.index('FoamFile')) + 1:]
    body = re.sub(r'//.*', '', body)
    m = re.search(r'(\d+)\s*\(', body)
    if not m:
        raise SystemExit(f"{path}: no list found")
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
