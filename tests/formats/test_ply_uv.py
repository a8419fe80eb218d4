"""PLY with texture coordinates: read in every flavour, written with seams.

Generated here: a 3 x 3 grid (two triangles per cell, UV = xy) as PLY with
per-vertex s,t / u,v / texture_u,texture_v / texture_s,texture_t, and with
per-face `texcoord` lists, in ASCII, binary little and big endian, with
float and double values. `scaf info --json` must report the UVs (count,
source, charts, seams) and `scaf check` must prove them bijective; a seam
made by giving one face its own texcoords must show as a second chart.
Then `scaf atlas` / `scaf param` write PLY (-o .ply): the file is parsed
here (binary little endian, its per-face texcoord lists), its positions
and faces must equal the input's and its UVs those of the same run written
as OBJ, and `scaf check` must prove the PLY bijective.
"""
import json
import os
import struct

from scaf_run import expect, run, workdir

N = 3  # grid cells per side


def grid():
    V = [(i / N, j / N, 0.0) for j in range(N + 1) for i in range(N + 1)]
    F = []
    for j in range(N):
        for i in range(N):
            a = j * (N + 1) + i
            F += [(a, a + 1, a + N + 2), (a, a + N + 2, a + N + 1)]
    return V, F


def write_ply(path, fmt, V, F, vertex_uv=None, face_tc=None, ftype="float"):
    """vertex_uv: (name_u, name_v) with UV = xy; face_tc: per face a list of
    (u, v) per corner."""
    head = ["ply", "format %s 1.0" % fmt, "comment scaf test", "element vertex %d" % len(V),
            "property %s x" % ftype, "property %s y" % ftype, "property %s z" % ftype]
    if vertex_uv:
        head += ["property %s %s" % (ftype, vertex_uv[0]), "property %s %s" % (ftype, vertex_uv[1])]
    head += ["element face %d" % len(F)]
    # texcoord first when given: the reader must not depend on the order
    if face_tc:
        head += ["property list uchar %s texcoord" % ftype]
    head += ["property list uchar int vertex_indices", "end_header"]
    out = ("\n".join(head) + "\n").encode()
    end = "<" if fmt == "binary_little_endian" else ">"
    fc = "f" if ftype == "float" else "d"
    for v in V:
        vals = list(v) + ([v[0], v[1]] if vertex_uv else [])
        if fmt == "ascii":
            out += (" ".join(repr(x) for x in vals) + "\n").encode()
        else:
            out += struct.pack(end + fc * len(vals), *vals)
    for k, f in enumerate(F):
        tc = [c for uv in face_tc[k] for c in uv] if face_tc else None
        if fmt == "ascii":
            line = ("%d %s " % (len(tc), " ".join(repr(c) for c in tc))) if tc else ""
            out += (line + "3 %d %d %d\n" % f).encode()
        else:
            if tc:
                out += struct.pack(end + "B" + fc * len(tc), len(tc), *tc)
            out += struct.pack(end + "Biii", 3, *f)
    open(path, "wb").write(out)


def read_binary_ply(path):
    """The vertices and per-face (indices, texcoords) of a PLY scaf wrote."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().splitlines()
    expect(head[1] == "format binary_little_endian 1.0", "PLY output format: " + head[1])
    nv = int(next(l for l in head if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in head if l.startswith("element face")).split()[2])
    expect("property list uchar double texcoord" in head, "no texcoord list in the PLY header")
    p = end
    V = [struct.unpack_from("<3d", data, p + 24 * i) for i in range(nv)]
    p += 24 * nv
    F, T = [], []
    for _ in range(nf):
        n = data[p]
        F.append(struct.unpack_from("<%di" % n, data, p + 1))
        p += 1 + 4 * n
        m = data[p]
        tc = struct.unpack_from("<%dd" % m, data, p + 1)
        T.append([(tc[2 * k], tc[2 * k + 1]) for k in range(m // 2)])
        p += 1 + 8 * m
    expect(p == len(data), "PLY output: %d bytes after the faces" % (len(data) - p))
    return V, F, T


def read_obj(path):
    V, VT, F, FT = [], [], [], []
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            V.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "vt":
            VT.append((float(w[1]), float(w[2])))
        elif w[0] == "f":
            F.append(tuple(int(c.split("/")[0]) - 1 for c in w[1:]))
            FT.append(tuple(int(c.split("/")[1]) - 1 for c in w[1:]))
    return V, F, [[VT[t] for t in ft] for ft in FT]


def info(path):
    rc, out, err = run(["info", "--json", path])
    expect(rc == 0, "info %s: exit %d %s" % (path, rc, err))
    return json.loads(out)


def main():
    V, F = grid()
    uv_of = [[(V[c][0], V[c][1]) for c in f] for f in F]
    with workdir("ply_uv") as d:
        # every flavour of per-vertex and per-face UVs
        cases = []
        for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
            for names in (("s", "t"), ("u", "v"), ("texture_u", "texture_v"),
                          ("texture_s", "texture_t")):
                cases.append((fmt, names, None, "float"))
            cases.append((fmt, None, uv_of, "float"))
            cases.append((fmt, None, uv_of, "double"))
        for k, (fmt, names, tc, ftype) in enumerate(cases):
            p = os.path.join(d, "case%d.ply" % k)
            write_ply(p, fmt, V, F, names, tc, ftype)
            what = "%s %s %s" % (fmt, names or "texcoord", ftype)
            j = info(p)
            expect(j["has_uv"] is True, what + ": no UVs found")
            expect(j["uv_coordinates"] == len(V), what + ": %d UVs" % j["uv_coordinates"])
            expect(j["uv_charts"] == 1 and j["seam_edges"] == 0, what + ": charts/seams")
            expect(j["uv_source"] == ("PLY face texcoord" if tc else "PLY vertex u, v"),
                   what + ": uv_source " + str(j["uv_source"]))
            rc, _, err = run(["check", p])
            expect(rc == 0, what + ": check exit %d %s" % (rc, err))

        # a seam: the last face gets texcoords of its own (moved right): 2 charts
        seam = [list(t) for t in uv_of]
        seam[-1] = [(u + 2.0, v) for u, v in seam[-1]]
        p = os.path.join(d, "seam.ply")
        write_ply(p, "binary_little_endian", V, F, None, seam)
        j = info(p)
        expect(j["uv_charts"] == 2 and j["uv_coordinates"] == len(V) + 3,
               "seam: %d charts %d UVs" % (j["uv_charts"], j["uv_coordinates"]))
        rc, _, err = run(["check", p])
        expect(rc == 0, "seam: check exit %d" % rc)

        # a texcoord list of the wrong length: exit 3 naming the face
        bad = os.path.join(d, "bad.ply")
        short = [list(t) for t in uv_of]
        short[4] = short[4][:2]
        write_ply(bad, "ascii", V, F, None, short)
        rc, _, err = run(["info", bad])
        expect(rc == 3 and "face 4" in err and "texcoord" in err, "bad texcoord: %d %s" % (rc, err))

        # atlas / param written as PLY; the same run as OBJ for comparison
        src = os.path.join(d, "hemi.obj")
        rc, _, err = run(["gen", "hemisphere", "-s", "8", "-o", src])
        expect(rc == 0, err)
        common = ["-q", "--threads", "1", "--iterations", "8"]
        outs = {}
        for ext in ("obj", "ply"):
            o = os.path.join(d, "atlas." + ext)
            rc, _, err = run(["atlas", src, "-o", o, "--compact-iterations", "3"] + common)
            expect(rc == 0, "atlas -o .%s: exit %d %s" % (ext, rc, err))
            outs[ext] = o
        Vo, Fo, To = read_obj(outs["obj"])
        Vp, Fp, Tp = read_binary_ply(outs["ply"])
        expect(Vp == Vo and [tuple(f) for f in Fp] == Fo, "atlas PLY: positions or faces differ")
        expect(Tp == To, "atlas PLY: UVs differ from the OBJ of the same run")
        rc, _, err = run(["check", outs["ply"]])
        expect(rc == 0, "check of the atlas PLY: exit %d %s" % (rc, err))
        j = info(outs["ply"])
        expect(j["uv_source"] == "PLY face texcoord" and j["uv_charts"] >= 1, "info atlas.ply")
        # the PLY read back has the UVs the OBJ has (one per distinct corner point)
        jo = info(outs["obj"])
        expect(j["uv_coordinates"] == jo["uv_coordinates"] and j["uv_charts"] == jo["uv_charts"],
               "atlas PLY read back: %d UVs / %d charts, OBJ %d / %d" % (
                   j["uv_coordinates"], j["uv_charts"], jo["uv_coordinates"], jo["uv_charts"]))
        # PLY in (with its UVs: --init input keeps them) and PLY out, also gzip-compressed
        o2 = os.path.join(d, "again.ply.gz")
        rc, _, err = run(["atlas", outs["ply"], "-o", o2, "--init", "input"] + common)
        expect(rc == 0, "atlas PLY -> PLY.gz: exit %d %s" % (rc, err))
        rc, _, err = run(["check", o2])
        expect(rc == 0, "check of the .ply.gz: exit %d %s" % (rc, err))
        o3 = os.path.join(d, "param.ply")
        rc, _, err = run(["param", p, "-o", o3, "-q", "--iterations", "5"])
        expect(rc == 0, "param seam.ply -o .ply: exit %d %s" % (rc, err))
        rc, _, err = run(["check", o3])
        expect(rc == 0, "check of param's PLY: exit %d" % rc)
        # a command that writes OBJ only still refuses .ply
        rc, _, err = run(["gen", "grid", "-o", os.path.join(d, "g.ply")])
        expect(rc == 2 and "OBJ only" in err, "gen -o .ply: exit %d %s" % (rc, err))
    print("test_ply_uv: ok")


if __name__ == "__main__":
    main()
