#!/usr/bin/env python3
"""examples/volume_example.py: scaf's 3D functions from Python on numpy arrays.

    python3 volume_example.py [OUT_PREFIX]

Builds its own closed surface (an octahedron refined twice onto the unit
sphere, as numpy arrays), then:
  1. scaf.inflate grows it 1.5 times inside a box of tets, printing a
     progress line per iteration; scaf.check_surface proves the result free
     of self-intersections and scaf.check_tets every tet positive (exact);
  2. pushes one vertex through the opposite side (the surface now
     intersects itself: check_surface counts the pairs) and scaf.untangle
     frees it again;
  3. when meshio (Debian: python3-meshio) is installed, feeds a meshio mesh
     to scaf.inflate -- `scaf.inflate(m.points, m.cells_dict["triangle"])`
     -- and writes the tets with meshio as OUT_PREFIX.mesh (MEDIT, which
     `scaf check` reads); without meshio it says so and skips that part.
     (trimesh is not packaged in Debian 12; with it, the same call is
     `scaf.inflate(t.vertices, t.faces)`.)
Writes OUT_PREFIX.obj (the inflated surface) when given. Exit status 0
when every check holds.

Run from a build:      SCAF_LIBRARY=build/libscaf.so PYTHONPATH=python python3 examples/volume_example.py
"""
import sys

import numpy as np

import scaf


def sphere(levels=2):
    """A closed triangle sphere: an octahedron, each face split in 4 per level."""
    V = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    F = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    for _ in range(levels):
        mid, G = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                mid[key] = len(V)
                V.append([(V[a][k] + V[b][k]) / 2 for k in range(3)])
            return mid[key]

        for a, b, c in F:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            G += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        F = G
    V = np.array(V, dtype=float)
    return V / np.linalg.norm(V, axis=1)[:, None], np.array(F, dtype=np.int32)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else None
    V, F = sphere()
    ok = True

    # 1. inflate, with a progress line per iteration
    def progress(info):
        print("  iteration %d: energy %.4g, %d tets, min quality %.3f"
              % (info.step, info.energy, info.tets, info.quality_min))
    r = scaf.inflate(V, F, scale=1.5, iterations=5, tets=True, progress=progress)
    P, T, label = r.tets
    s, t = scaf.check_surface(r.positions, F), scaf.check_tets(P, T)
    print("inflate: diagonal x%.3f, %d tets (%d inside), surface free: %s, tets positive: %s"
          % (r.diagonal_after / r.diagonal_before, len(T), int((label == 1).sum()),
             s.intersection_free, t.valid))
    ok &= s.intersection_free and t.valid and r.diagonal_after > r.diagonal_before
    if out:
        with open(out + ".obj", "w") as f:
            f.writelines("v %.17g %.17g %.17g\n" % tuple(p) for p in r.positions)
            f.writelines("f %d %d %d\n" % tuple(i + 1 for i in tri) for tri in F)

    # 2. a dent through the other side, then untangle
    W = V.copy()
    top = int(np.argmax(W[:, 2]))
    W[top] = [0.0, 0.0, -1.05]  # just through the bottom: freed in about 17 flow steps
    before = scaf.check_surface(W, F)
    u = scaf.untangle(W, F, iterations=10)
    after = scaf.check_surface(u.positions, F)
    print("untangle: %d intersecting pairs -> %d after %d flow steps and %d iterations (%s)"
          % (before.pairs, after.pairs, u.flow_steps, u.iterations, u.stop_reason))
    ok &= before.pairs > 0 and after.intersection_free

    # 3. a meshio mesh in, the tets out through meshio
    try:
        import meshio
    except ImportError:
        print("meshio: not installed (Debian: python3-meshio): skipped")
    else:
        m = meshio.Mesh(V, [("triangle", F)])  # or meshio.read("surface.obj")
        r = scaf.inflate(m.points, m.cells_dict["triangle"], scale=1.2, iterations=3, tets=True)
        P, T, label = r.tets
        ok &= scaf.check_tets(P, T).valid
        print("meshio: inflated %d points, %d tets" % (len(r.positions), len(T)))
        if out:
            meshio.write(out + ".mesh", meshio.Mesh(P, [("tetra", T)], cell_data={"medit:ref": [label]}))
    print("all checks hold" if ok else "A CHECK FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
