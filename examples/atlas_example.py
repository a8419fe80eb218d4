#!/usr/bin/env python3
"""examples/atlas_example.py: a texture atlas from Python (package scaf).

    python3 atlas_example.py [IN.obj [OUT.obj]]

Without arguments it builds its own mesh (five bumpy grid patches, five
charts); with IN.obj it reads a triangle OBJ (its vt seams define the
charts when every face has vt). It runs scaf.atlas with a progress line per
iteration, checks what the library promises (UVs in the unit square, no
flipped triangle, the padding between charts), prints the packing
efficiency, the smallest chart gap and the per-chart distortion, and writes
OUT.obj (v, vt, f v/vt) when given. Works with or without numpy.

Run from a build:      SCAF_LIBRARY=build/libscaf.so PYTHONPATH=python python3 examples/atlas_example.py
Run after an install:  PYTHONPATH=<prefix>/lib/python3/dist-packages python3 atlas_example.py
"""
import math
import sys

import scaf


def patches(r=8):
    """Five curved r x r patches of different sizes, far apart in 3D."""
    V, F = [], []
    for p in range(5):
        s, base = 0.6 + 0.35 * p, len(V)
        for j in range(r + 1):
            for i in range(r + 1):
                x, y = s * i / r, s * j / r
                V.append([x + 10.0 * p, y, 0.3 * s * math.sin(1.7 * x / s + p) * math.cos(1.1 * y / s)])
        for j in range(r):
            for i in range(r):
                a = base + j * (r + 1) + i
                F += [[a, a + 1, a + r + 2], [a, a + r + 2, a + r + 1]]
    return V, F, None, None


def aslist(a):
    """Rows as lists, whether scaf returned numpy arrays or lists."""
    return a.tolist() if hasattr(a, "tolist") else a


def progress(info):
    if not sys.stderr.isatty():
        return None
    print("\r%-7s iteration %3d  E %.5f  efficiency %.3f" % (info.phase, info.iteration, info.energy,
                                                            info.efficiency), end="", file=sys.stderr)


def main(argv):
    V, F, UV, FT = scaf.read_obj(argv[1]) if len(argv) > 1 else patches()
    r = scaf.atlas(V, F, UV, FT, resolution=1024, padding_texels=4, progress=progress)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    uv, ft = aslist(r.uv), aslist(r.ft)
    # what the library promises, checked here (in floating point)
    assert all(0.0 <= x <= 1.0 for p in uv for x in p), "UV outside the unit square"
    for a, b, c in ft:
        assert (uv[b][0] - uv[a][0]) * (uv[c][1] - uv[a][1]) - (uv[c][0] - uv[a][0]) * (uv[b][1] - uv[a][1]) > 0
    assert r.min_gap >= r.padding
    print("scaf %s: %d charts, %d UVs, iterations %s" % (scaf.__version__, r.chart_count, len(uv), r.iterations))
    for c, e in enumerate(r.chart_distortion):
        print("  chart %d: distortion %.5f" % (c, e))
    print("packing efficiency %.4f, smallest chart gap %.6f (padding %.6f)" % (r.efficiency, r.min_gap, r.padding))
    if len(argv) > 2:
        Vl, Fl = aslist(V), aslist(F)
        with open(argv[2], "w") as out:
            out.writelines("v %.17g %.17g %.17g\n" % tuple(v) for v in Vl)
            out.writelines("vt %.17g %.17g\n" % tuple(t) for t in uv)
            out.writelines("f %d/%d %d/%d %d/%d\n" % (f[0] + 1, t[0] + 1, f[1] + 1, t[1] + 1, f[2] + 1, t[2] + 1)
                           for f, t in zip(Fl, ft))
        print("wrote", argv[2])
    return 0  # a failed run raised scaf.Error (MeshError, ...) with the C message


if __name__ == "__main__":
    sys.exit(main(sys.argv))
