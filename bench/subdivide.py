#!/usr/bin/env python3
"""Upsample a triangle mesh for scale benchmarks: 1-to-4 midpoint subdivision.

Every triangle (a, b, c) becomes (a, ab, ca), (ab, b, bc), (ca, bc, c) and
(ab, bc, ca), with ab the midpoint of edge a-b (one new vertex per edge,
shared by both faces of the edge). The surface, the topology (a disk stays a
disk) and the orientation are unchanged; the face count is multiplied by 4
per level. Reads OBJ (v and f lines; f entries may be v/vt/vn, only v is
kept; polygons are fan-triangulated), plain or .gz; writes OBJ, gzip-
compressed when OUT ends in .gz.

    bench/subdivide.py IN.obj[.gz] OUT.obj[.gz] [LEVELS]   (default 1 level)

Example (7.1M faces from the 1.77M-face mesh of ../shared/data):

    bench/subdivide.py ../shared/data/large/aphrodite_subdiv16x.obj.gz \\
        /tmp/aphrodite_subdiv64x.obj

Exit status: 0 ok, 1 unreadable input or no triangle, 2 usage.
"""
import gzip
import os
import sys


def open_text(path, mode):
    if path.endswith(".gz"):
        return gzip.open(path, mode + "t", compresslevel=1) if "w" in mode else gzip.open(path, "rt")
    return open(path, mode)


def read_obj(path):
    xyz, tris = [], []
    with open_text(path, "r") as f:
        for line in f:
            if line.startswith("v "):
                p = line.split()
                xyz.append((float(p[1]), float(p[2]), float(p[3])))
            elif line.startswith("f "):
                idx = []
                for tok in line.split()[1:]:
                    k = int(tok.split("/")[0])
                    idx.append(k - 1 if k > 0 else len(xyz) + k)
                for j in range(1, len(idx) - 1):
                    tris.append((idx[0], idx[j], idx[j + 1]))
    return xyz, tris


def subdivide(xyz, tris):
    n = len(xyz)
    mid = {}

    def midpoint(a, b):
        key = a * n + b if a < b else b * n + a
        m = mid.get(key)
        if m is None:
            m = len(xyz)
            pa, pb = xyz[a], xyz[b]
            xyz.append(((pa[0] + pb[0]) * 0.5, (pa[1] + pb[1]) * 0.5, (pa[2] + pb[2]) * 0.5))
            mid[key] = m
        return m

    out = []
    for a, b, c in tris:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return xyz, out


def main(argv):
    if len(argv) not in (3, 4) or argv[1] in ("-h", "--help"):
        print(__doc__.strip().split("\n\n")[2].strip(), file=sys.stderr)
        return 2
    levels = int(argv[3]) if len(argv) == 4 else 1
    if levels < 0:
        print("subdivide: LEVELS must be >= 0", file=sys.stderr)
        return 2
    try:
        xyz, tris = read_obj(argv[1])
    except (OSError, ValueError, IndexError) as e:
        print("subdivide: %s: %s" % (argv[1], e), file=sys.stderr)
        return 1
    if not tris:
        print("subdivide: %s: no triangle" % argv[1], file=sys.stderr)
        return 1
    for _ in range(levels):
        xyz, tris = subdivide(xyz, tris)
    tmp = argv[2] + ".part"
    with open_text(tmp, "w") as f:
        f.write("# DERIVED from %s: %d level(s) of 1-to-4 midpoint subdivision "
                "(bench/subdivide.py)\n" % (argv[1], levels))
        f.writelines("v %.9g %.9g %.9g\n" % p for p in xyz)
        f.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in tris)
    os.replace(tmp, argv[2])
    print("%s: %d vertices, %d faces" % (argv[2], len(xyz), len(tris)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
