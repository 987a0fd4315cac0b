#!/usr/bin/python3
"""Converter for scripts/test_meshes.sh (numpy only).

  test_meshes_convert.py SRC OUT.ply [--op none|subdivide2] [--comment TEXT]   convert one source file
  test_meshes_convert.py --stats FILE.ply                          print one tab-separated stats line

Output convention as in shared/meshes/MANIFEST.md: binary little-endian PLY, vertex float x y z
(+ float scalar point fields, original names), faces list uchar int, triangles only (fan-triangulated),
unreferenced vertices removed, STL corners with bit-identical coordinates merged.
"""
import argparse
import base64
import re
import struct
import sys
import zlib

import numpy as np

SKIP_FIELDS = {"nx", "ny", "nz", "red", "green", "blue", "alpha", "s", "t", "u", "v",
               "normals", "normals_", "stlsolidlabeling"}


def fan(counts, flat):
    """Fan-triangulate polygons given as corner counts and a flat corner list, keeping their order."""
    counts = np.asarray(counts, np.int64)
    flat = np.asarray(flat, np.int64)
    starts = np.cumsum(counts) - counts
    nt = np.maximum(counts - 2, 0)
    poly = np.repeat(np.arange(len(counts)), nt)
    k = np.arange(nt.sum()) - np.repeat(np.cumsum(nt) - nt, nt) + 1
    s = starts[poly]
    return np.stack([flat[s], flat[s + k], flat[s + k + 1]], axis=1)


def read_stl(data):
    """STL (binary or ASCII) -> points, triangles; corners merged by exact coordinates."""
    n = struct.unpack("<I", data[80:84])[0] if len(data) >= 84 else 0
    if len(data) == 84 + 50 * n:
        rec = np.frombuffer(data, np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]), n, 84)
        corners = rec["v"].reshape(-1, 3)
    else:
        nums = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        corners = np.array(nums, dtype=np.float64).astype(np.float32)
    pts, inv = np.unique(corners, axis=0, return_inverse=True)
    return pts, inv.reshape(-1, 3), {}


def read_obj(data):
    """OBJ -> points, triangles (v and f lines only; negative indices allowed)."""
    pts, counts, flat = [], [], []
    for line in data.decode("latin-1").splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            pts.append([float(x) for x in w[1:4]])
        elif w[0] == "f":
            idx = [int(c.split("/")[0]) for c in w[1:]]
            flat += [i - 1 if i > 0 else len(pts) + i for i in idx]
            counts.append(len(idx))
    return np.array(pts), fan(counts, flat), {}


def read_off(data):
    """OFF -> points, triangles."""
    words = re.sub(rb"#[^\n]*", b"", data).split()
    if words[0].endswith(b"OFF"):
        words = words[1:]
    nv, nf = int(words[0]), int(words[1])
    pts = np.array(words[3:3 + 3 * nv], dtype=np.float64).reshape(-1, 3)
    rest, i, counts, flat = words[3 + 3 * nv:], 0, [], []
    for _ in range(nf):
        n = int(rest[i])
        flat += [int(x) for x in rest[i + 1:i + 1 + n]]
        counts.append(n)
        i += 1 + n
    return pts, fan(counts, flat), {}


PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
             "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
             "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def read_ply(data):
    """PLY (ascii or binary) with a vertex element and a face list -> points, triangles, scalar fields."""
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("latin-1").split("\n")
    fmt = header[1].split()[1]
    bo = "<" if fmt == "binary_little_endian" else ">"
    elements = []
    for line in header:
        w = line.split()
        if w[:1] == ["element"]:
            elements.append((w[1], int(w[2]), []))
        elif w[:1] == ["property"]:
            elements[-1][2].append(w[1:])
    body, pos, out = data[end:], 0, {}
    if fmt == "ascii":
        body, pos = body.split(), 0
    for name, count, props in elements:
        if fmt == "ascii":
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    n = int(body[pos]) if p[0] == "list" else 1
                    row.append([float(x) for x in body[pos + (p[0] == "list"):pos + (p[0] == "list") + n]])
                    pos += n + (p[0] == "list")
                rows.append(row)
            out[name] = (props, rows)
        elif all(p[0] != "list" for p in props):
            dt = np.dtype([(p[1], bo + PLY_TYPES[p[0]]) for p in props])
            out[name] = (props, np.frombuffer(body, dt, count, pos))
            pos += dt.itemsize * count
        else:  # one list property (faces), fast path when every polygon has the same corner count
            ct, it = bo + PLY_TYPES[props[0][1]], bo + PLY_TYPES[props[0][2]]
            n0 = int(np.frombuffer(body, ct, 1, pos)[0])
            dt = np.dtype([("n", ct), ("i", it, n0)])
            rec = np.frombuffer(body, dt, count, pos)
            if (rec["n"] == n0).all():
                out[name] = (props, (rec["n"], rec["i"].ravel()))
                pos += dt.itemsize * count
            else:
                counts, flat, isz, csz = [], [], np.dtype(it).itemsize, np.dtype(ct).itemsize
                for _ in range(count):
                    n = int(np.frombuffer(body, ct, 1, pos)[0])
                    flat.append(np.frombuffer(body, it, n, pos + csz))
                    counts.append(n)
                    pos += csz + n * isz
                out[name] = (props, (counts, np.concatenate(flat)))
    vprops, v = out["vertex"]
    names = [p[1] for p in vprops]
    if fmt == "ascii":
        v = np.array([[r[0] for r in row] for row in v])
        cols = {n: v[:, i] for i, n in enumerate(names)}
        fprops, frows = out["face"]
        counts = [len(r[0]) for r in frows]
        faces = (counts, [int(x) for r in frows for x in r[0]])
    else:
        cols = {n: v[n] for n in names}
        faces = out["face"][1]
    pts = np.stack([cols["x"], cols["y"], cols["z"]], axis=1)
    fields = {n: c for n, c in cols.items() if n not in ("x", "y", "z") and n.lower() not in SKIP_FIELDS}
    return pts, fan(*faces), fields


VTK_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
             "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


def vtk_block(raw, isz, compressed):
    """Decode one VTK XML binary block (header + payload) from raw bytes; returns payload bytes and length used."""
    ut = "<u%d" % isz
    if not compressed:
        n = int(np.frombuffer(raw, ut, 1)[0])
        return raw[isz:isz + n], isz + n
    nb = int(np.frombuffer(raw, ut, 1)[0])
    sizes = np.frombuffer(raw, ut, 3 + nb)[3:].astype(np.int64)
    pos, out = isz * (3 + nb), []
    for s in sizes:
        out.append(zlib.decompress(raw[pos:pos + s]))
        pos += s
    return b"".join(out), pos


def vtk_inline(text, isz, compressed):
    """Decode an inline base64 DataArray (header and payload are separate base64 runs when compressed)."""
    text = "".join(text.split())
    if not compressed:
        return vtk_block(base64.b64decode(text), isz, False)[0]
    nb = int(np.frombuffer(base64.b64decode(text[:4 * -(-isz // 3)]), "<u%d" % isz, 1)[0])
    hlen = 4 * -(-(isz * (3 + nb)) // 3)
    return vtk_block(base64.b64decode(text[:hlen]) + base64.b64decode(text[hlen:]), isz, True)[0]


def read_vtp(data):
    """VTK XML PolyData (ascii, inline binary or raw appended; optional zlib) -> points, triangles, scalar fields."""
    head = data.split(b"<AppendedData", 1)
    xml = head[0].decode("latin-1")
    appended = None
    if len(head) > 1:
        appended = head[1][head[1].index(b"_") + 1:]
    isz = 8 if 'header_type="UInt64"' in xml else 4
    compressed = "vtkZLibDataCompressor" in xml

    def arrays(section):
        """Name -> numpy array for every DataArray in one XML section."""
        m = re.search(r"<%s[^>]*>(.*?)</%s>" % (section, section), xml, re.S)
        res = {}
        for a in re.finditer(r"<DataArray([^>]*?)(/>|>(.*?)</DataArray>)", m.group(1) if m else "", re.S):
            attr = dict(re.findall(r'(\w+)="([^"]*)"', a.group(1)))
            dt = np.dtype("<" + VTK_TYPES[attr["type"]])
            if attr.get("format") == "ascii":
                arr = np.array(re.sub(r"<[^>]*>.*?</[^>]*>", " ", a.group(3), flags=re.S).split(), dt)
            elif attr.get("format") == "appended":
                arr = np.frombuffer(vtk_block(appended[int(attr["offset"]):], isz, compressed)[0], dt)
            else:
                arr = np.frombuffer(vtk_inline(a.group(3), isz, compressed), dt)
            res[attr.get("Name", "")] = arr.reshape(-1, int(attr.get("NumberOfComponents", "1")))
        return res

    pts = next(iter(arrays("Points").values())).reshape(-1, 3)
    polys = arrays("Polys")
    offs = polys["offsets"].ravel().astype(np.int64)
    counts = np.diff(np.concatenate([[0], offs]))
    tris = fan(counts, polys["connectivity"].ravel())
    fields = {n: a.ravel() for n, a in arrays("PointData").items()
              if a.shape[1] == 1 and n.lower() not in SKIP_FIELDS and a.dtype.kind == "f"}
    return pts, tris, fields


def read_swc_tubes(data, sides=16):
    """SWC centre-line tree -> one capped tube per branch (bifurcation to bifurcation/tip), wound outward."""
    a = np.loadtxt(data.decode().splitlines(), comments="#", ndmin=2)
    ids, xyz, rad, par = a[:, 0].astype(int), a[:, 2:5], a[:, 5], a[:, 6].astype(int)
    row = {i: k for k, i in enumerate(ids)}
    kids = {i: [] for i in ids}
    for i, p in zip(ids, par):
        if p in kids:
            kids[p].append(i)
    starts = [(None, i) for i, p in zip(ids, par) if p not in kids] + \
             [(i, c) for i in ids if len(kids[i]) > 1 for c in kids[i]]
    ang = 2 * np.pi * np.arange(sides) / sides
    pts, tris = [], []
    for first, node in starts:
        path = ([first] if first is not None else []) + [node]
        while len(kids[path[-1]]) == 1:
            path.append(kids[path[-1]][0])
        if len(path) < 2:
            continue
        p = xyz[[row[i] for i in path]]
        r = rad[[row[i] for i in path]]
        if first is not None:
            r[0] = min(r[0], r[1])
        d = np.diff(p, axis=0)
        t = np.concatenate([d[:1], d[:-1] + d[1:], d[-1:]])
        t /= np.linalg.norm(t, axis=1, keepdims=True)
        n = np.cross(t[0], [1, 0, 0] if abs(t[0][0]) < 0.9 else [0, 1, 0])
        rings = []
        for k in range(len(p)):
            n = n - np.dot(n, t[k]) * t[k]
            n /= np.linalg.norm(n)
            b = np.cross(t[k], n)
            rings.append(p[k] + r[k] * (np.cos(ang)[:, None] * n + np.sin(ang)[:, None] * b))
        base = sum(len(x) for x in pts)
        m = len(p)
        pts += [np.concatenate(rings), p[:1], p[-1:]]
        j = np.arange(sides)
        for k in range(m - 1):
            a0, a1, b0, b1 = base + k * sides + j, base + k * sides + (j + 1) % sides, \
                base + (k + 1) * sides + j, base + (k + 1) * sides + (j + 1) % sides
            tris += [np.stack([a0, a1, b1], 1), np.stack([a0, b1, b0], 1)]
        c0, c1 = base + m * sides, base + m * sides + 1
        tris += [np.stack([np.full(sides, c0), base + (j + 1) % sides, base + j], 1),
                 np.stack([np.full(sides, c1), base + (m - 1) * sides + j, base + (m - 1) * sides + (j + 1) % sides], 1)]
    return np.concatenate(pts), np.concatenate(tris).astype(np.int64), {}


def subdivide(pts, tris, fields):
    """One 1-to-4 midpoint subdivision (flat: the surface is unchanged, triangles x4)."""
    e = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    uniq, inv = np.unique(e, axis=0, return_inverse=True)
    mid = len(pts) + inv.reshape(3, -1)
    new = 0.5 * (pts[uniq[:, 0]].astype(np.float64) + pts[uniq[:, 1]])
    f = {k: np.concatenate([v, 0.5 * (v[uniq[:, 0]] + v[uniq[:, 1]])]) for k, v in fields.items()}
    a, b, c = tris.T
    ab, bc, ca = mid
    out = np.concatenate([np.stack(x, 1) for x in ([a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca])])
    return np.concatenate([pts, new]), out, f


def clean(pts, tris, fields):
    """Drop vertices no triangle references (and renumber)."""
    used = np.zeros(len(pts), bool)
    used[tris.ravel()] = True
    remap = np.cumsum(used) - 1
    return pts[used], remap[tris], {k: v[used] for k, v in fields.items()}


def write_ply(path, pts, tris, fields, comment=""):
    """Binary little-endian PLY: float x y z + non-constant float fields, faces list uchar int."""
    names = sorted(k for k, v in fields.items() if np.ptp(v) > 0)
    head = ["ply", "format binary_little_endian 1.0"] + (["comment " + comment] if comment else [])
    head += ["element vertex %d" % len(pts),
            "property float x", "property float y", "property float z"]
    head += ["property float %s" % n for n in names]
    head += ["element face %d" % len(tris), "property list uchar int vertex_indices", "end_header"]
    vert = np.concatenate([np.asarray(pts, "<f4")] + [np.asarray(fields[n], "<f4")[:, None] for n in names], axis=1)
    face = np.zeros(len(tris), np.dtype([("n", "u1"), ("i", "<i4", 3)]))
    face["n"], face["i"] = 3, tris
    with open(path, "wb") as f:
        f.write(("\n".join(head) + "\n").encode())
        f.write(np.ascontiguousarray(vert).tobytes())
        f.write(face.tobytes())


def components(n, a, b):
    """Number of connected components among the nodes that edges a-b touch (union-find)."""
    parent = list(range(n))

    def root(x):
        """Root of x's set, halving the path on the way."""
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for x, y in zip(a.tolist(), b.tolist()):
        rx, ry = root(x), root(y)
        if rx != ry:
            parent[max(rx, ry)] = min(rx, ry)
    return len({root(x) for x in np.unique(np.concatenate([a, b])).tolist()})


def stats(path):
    """Tab-separated: V T bnd loops nm inc cc genus vol bbox scalars (genus: total, closed manifold meshes only)."""
    pts, tris, fields = read_ply(open(path, "rb").read())
    e = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    lo_hi = np.sort(e, axis=1)
    keys, inv, cnt = np.unique(lo_hi[:, 0] * len(pts) + lo_hi[:, 1], return_inverse=True, return_counts=True)
    ea, eb = keys // len(pts), keys % len(pts)
    fwd = np.bincount(inv.ravel(), weights=e[:, 0] < e[:, 1], minlength=len(keys))
    inc = int(((cnt == 2) & (fwd != 1)).sum())
    bnd = cnt == 1
    loops = components(len(pts), ea[bnd], eb[bnd]) if bnd.any() else 0
    cc = components(len(pts), ea, eb)
    chi = len(pts) - len(keys) + len(tris)
    genus = str((2 * cc - chi) // 2) if not bnd.any() and (cnt > 2).sum() == 0 else "-"
    p = pts.astype(np.float64)[tris]
    vol = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6
    lo, hi = pts.min(0), pts.max(0)
    bbox = "[%s] .. [%s]" % (", ".join("%.4g" % x for x in lo), ", ".join("%.4g" % x for x in hi))
    sc = "; ".join("%s (%.4g..%.4g)" % (k, v.min(), v.max()) for k, v in sorted(fields.items())) or "-"
    return "\t".join(map(str, [len(pts), len(tris), int(bnd.sum()), loops, int((cnt > 2).sum()), inc, cc, genus,
                                "%.4g" % vol, bbox, sc]))


READERS = {"stl": read_stl, "obj": read_obj, "off": read_off, "ply": read_ply, "vtp": read_vtp, "swc": read_swc_tubes}


def main(argv):
    """Command line: convert SRC to OUT (optionally subdivided, with a source comment), or --stats FILE."""
    if argv[0] == "--stats":
        print(stats(argv[1]))
        return
    ap = argparse.ArgumentParser()
    ap.add_argument("src")
    ap.add_argument("out")
    ap.add_argument("--op", choices=["none", "subdivide2"], default="none")
    ap.add_argument("--comment", default="")
    args = ap.parse_args(argv)
    pts, tris, fields = READERS[args.src.rsplit(".", 1)[-1].lower()](open(args.src, "rb").read())
    pts, tris, fields = clean(np.asarray(pts), tris, fields)
    for _ in range(2 if args.op == "subdivide2" else 0):
        pts, tris, fields = subdivide(pts, tris, fields)
    write_ply(args.out, pts, tris, fields, args.comment)


if __name__ == "__main__":
    main(sys.argv[1:])
