"""tests/formats/gltf_tool: writing and reading small glTF 2.0 files with the
standard library only (json + struct), for the glTF tests.

make_scene() builds the test document: two meshes (three primitives), a
skin with joints, weights and inverse bind matrices, an animation, two
materials (one with an extension), a morph target, extras everywhere; the
first primitive splits its vertices along a normal crease and carries a
3-byte COLOR_0 (padded to a 4-byte stride) and a TEXCOORD_1. save() writes
it as .glb or as .gltf with its buffer embedded; load() reads either back;
values() reads an accessor as tuples of numbers.
"""
import base64
import json
import math
import struct

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
FMT = {FLOAT: "f", UBYTE: "B", USHORT: "H", UINT: "I", 5120: "b", 5122: "h"}
NCOMP = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors = [], []

    def add(self, rows, ctype, atype, target=None, normalized=False, minmax=False):
        """One accessor over a new buffer view of rows (tuples)."""
        n = NCOMP[atype]
        elem = struct.calcsize("<" + FMT[ctype] * n)
        stride = (elem + 3) // 4 * 4 if target == 34962 else elem
        while len(self.bin) % 4:
            self.bin.append(0)
        start = len(self.bin)
        for r in rows:
            self.bin += struct.pack("<" + FMT[ctype] * n, *r)
            self.bin += b"\0" * (stride - elem)
        view = {"buffer": 0, "byteOffset": start, "byteLength": len(self.bin) - start}
        if stride != elem:
            view["byteStride"] = stride
        if target:
            view["target"] = target
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": len(rows),
               "type": atype}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"] = [min(r[c] for r in rows) for c in range(n)]
            acc["max"] = [max(r[c] for r in rows) for c in range(n)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def grid_primitive(b, cells=6):
    """A bumpy grid whose vertices are split along the column x = 1/2 (two
    normals there, as a flat-shaded crease exports)."""
    P, N, T, J, W, C, U1 = [], [], [], [], [], [], []
    index = {}
    for j in range(cells + 1):
        for i in range(cells + 1):
            x, y = i / cells, j / cells
            z = 0.1 * math.sin(3 * x) * math.cos(2 * y)
            sides = (0, 1) if i == cells // 2 else ((0,) if i < cells // 2 else (1,))
            for s in sides:
                index[(i, j, s)] = len(P)
                P.append((x, y, z))
                N.append((0.0, 0.0, 1.0) if s == 0 else (0.0, 0.6, 0.8))
                T.append((1.0, 0.0, 0.0, 1.0 if s == 0 else -1.0))
                J.append((0, 1, 0, 0))
                W.append((1.0 - x, x, 0.0, 0.0))
                C.append((int(255 * x), int(255 * y), 7 * s))
                U1.append((x * 0.5, y * 0.5))
    F = []
    for j in range(cells):
        for i in range(cells):
            s = 0 if i < cells // 2 else 1
            a, bb = index[(i, j, s)], index[(i + 1, j, s)]
            c, d = index[(i + 1, j + 1, s)], index[(i, j + 1, s)]
            F += [a, bb, c, a, c, d]
    attrs = {
        "POSITION": b.add(P, FLOAT, "VEC3", 34962, minmax=True),
        "NORMAL": b.add(N, FLOAT, "VEC3", 34962),
        "TANGENT": b.add(T, FLOAT, "VEC4", 34962),
        "JOINTS_0": b.add(J, UBYTE, "VEC4", 34962),
        "WEIGHTS_0": b.add(W, FLOAT, "VEC4", 34962),
        "COLOR_0": b.add(C, UBYTE, "VEC3", 34962, normalized=True),
        "TEXCOORD_1": b.add(U1, FLOAT, "VEC2", 34962),
    }
    ind = b.add([(f,) for f in F], USHORT, "SCALAR", 34963)
    return {"attributes": attrs, "indices": ind, "material": 0, "mode": 4,
            "extras": {"part": "grid", "weight": 0.25}}


def fan_unindexed(b):
    """A hexagon fan as 6 unindexed triangles (every corner its own vertex)."""
    ring = [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3), 0.2) for k in range(6)]
    P = []
    for k in range(6):
        P += [(0.0, 0.0, 0.5), ring[k], ring[(k + 1) % 6]]
    N = [(0.0, 0.0, 1.0)] * len(P)
    return {"attributes": {"POSITION": b.add(P, FLOAT, "VEC3", 34962, minmax=True),
                           "NORMAL": b.add(N, FLOAT, "VEC3", 34962)}, "material": 1}


def quad_with_target(b):
    P = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.1), (0.0, 1.0, 0.0), (0.5, 0.5, 0.3)]
    D = [(0.0, 0.0, 0.1 * k) for k in range(len(P))]
    F = [0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4]
    return {"attributes": {"POSITION": b.add(P, FLOAT, "VEC3", 34962, minmax=True)},
            "indices": b.add([(f,) for f in F], UBYTE, "SCALAR", 34963),
            "targets": [{"POSITION": b.add(D, FLOAT, "VEC3", 34962, minmax=True)}]}


def make_scene():
    b = Builder()
    meshes = [
        {"name": "grid", "primitives": [grid_primitive(b)], "extras": {"lod": 0}},
        {"name": "cap", "primitives": [fan_unindexed(b), quad_with_target(b)], "weights": [0.5]},
    ]
    ibm = [tuple(1.0 if r == c else 0.0 for r in range(4) for c in range(4)),
           tuple([1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, -0.5, 0, 0, 1.0])]
    ibm_acc = b.add(ibm, FLOAT, "MAT4")
    times = b.add([(0.0,), (1.0,)], FLOAT, "SCALAR", minmax=True)
    rots = b.add([(0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.3826834, 0.9238795)], FLOAT, "VEC4")
    doc = {
        "asset": {"version": "2.0", "generator": "scaf test", "extras": {"source": "test_gltf"}},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "main", "nodes": [0]}],
        "nodes": [
            {"name": "root", "children": [1, 2, 3], "extras": {"tag": [1, 2, 3]}},
            {"name": "skinned", "mesh": 0, "skin": 0},
            {"name": "cap", "mesh": 1, "translation": [2.0, 0.0, 0.0], "scale": [0.5, 0.5, 0.5]},
            {"name": "j0", "children": [4]},
            {"name": "j1", "translation": [0.5, 0.0, 0.0]},
        ],
        "skins": [{"name": "rig", "joints": [3, 4], "inverseBindMatrices": ibm_acc,
                   "skeleton": 3}],
        "animations": [{"name": "bend",
                        "samplers": [{"input": times, "output": rots, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 4, "path": "rotation"}}]}],
        "materials": [
            {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.1, 0.1, 1.0],
                                                     "metallicFactor": 0.25},
             "extras": {"note": "keep me"}},
            {"name": "glow", "emissiveFactor": [1.0, 1.0, 0.5],
             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}}},
        ],
        "meshes": meshes,
        "extras": {"pipeline": "scaf", "version": 3},
    }
    doc["accessors"], doc["bufferViews"] = b.accessors, b.views
    doc["buffers"] = [{"byteLength": len(b.bin)}]
    return doc, bytes(b.bin)


def save(path, doc, binbuf):
    doc = json.loads(json.dumps(doc))
    if path.endswith(".glb"):
        js = json.dumps(doc).encode()
        js += b" " * (-len(js) % 4)
        bb = binbuf + b"\0" * (-len(binbuf) % 4)
        out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(bb))
        out += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bb), b"BIN\0") + bb
        open(path, "wb").write(out)
    else:
        doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                    base64.b64encode(binbuf).decode())
        open(path, "w").write(json.dumps(doc, indent=1))


def load(path):
    """(document, [buffer bytes]) of a .glb or .gltf (data URIs only)."""
    data = open(path, "rb").read()
    if data[:4] == b"glTF":
        _, version, length = struct.unpack_from("<4sII", data)
        assert version == 2 and length == len(data), "GLB header"
        p, doc, binchunk = 12, None, None
        while p < len(data):
            n, kind = struct.unpack_from("<I4s", data, p)
            chunk = data[p + 8:p + 8 + n]
            if kind == b"JSON":
                doc = json.loads(chunk)
            elif kind == b"BIN\0":
                binchunk = chunk
            p += 8 + n
    else:
        doc, binchunk = json.loads(data), None
    bufs = []
    for k, bdesc in enumerate(doc.get("buffers", [])):
        if "uri" in bdesc:
            uri = bdesc["uri"]
            assert uri.startswith("data:"), "external buffer in test output"
            raw = base64.b64decode(uri.split(",", 1)[1])
        else:
            assert k == 0 and binchunk is not None
            raw = binchunk
        assert len(raw) >= bdesc["byteLength"], "buffer %d shorter than its byteLength" % k
        bufs.append(raw[:bdesc["byteLength"]])
    return doc, bufs


def values(doc, bufs, index):
    """Accessor `index` as a list of tuples (raw component values)."""
    a = doc["accessors"][index]
    n = NCOMP[a["type"]]
    f = "<" + FMT[a["componentType"]] * n
    elem = struct.calcsize(f)
    if "bufferView" not in a:
        return [tuple([0] * n)] * a["count"]
    v = doc["bufferViews"][a["bufferView"]]
    stride = v.get("byteStride", elem)
    buf = bufs[v["buffer"]]
    assert v.get("byteOffset", 0) + v["byteLength"] <= len(buf), "buffer view outside its buffer"
    base = v.get("byteOffset", 0) + a.get("byteOffset", 0)
    if a["count"]:
        end = a.get("byteOffset", 0) + (a["count"] - 1) * stride + elem
        assert end <= v["byteLength"], "accessor %d outside its buffer view" % index
    return [struct.unpack_from(f, buf, base + i * stride) for i in range(a["count"])]


def corners(doc, bufs, prim):
    """The vertex index of every triangle corner of a TRIANGLES primitive."""
    if "indices" in prim:
        return [r[0] for r in values(doc, bufs, prim["indices"])]
    return list(range(doc["accessors"][prim["attributes"]["POSITION"]]["count"]))
