"""scaf_uv.charts: which mesh corners share a UV point (numpy only, no bpy).

scaf takes a triangle mesh with a UV index per triangle corner; corners
with one index are one point of one chart. Blender stores one UV per face
corner (loop). Two ways to number them:
  - from seams (unwrap): the corners around a vertex are joined across
    every edge that is not marked as a seam and has exactly two faces,
    so the marked seams (and the mesh's borders) cut the charts;
  - from the current UVs (pack, check): corners of one vertex with the
    same UV coordinates, bit for bit, are one point (as an OBJ export
    writes them).
Why numpy: meshes of 10^5-10^6 corners, where per-corner Python loops
take seconds.
"""

import numpy as np


def _roots(parent):
    """Path-compressed roots of a union-find forest (vectorized halving)."""
    while True:
        grand = parent[parent]
        if np.array_equal(grand, parent):
            return parent
        parent = grand


def ids_from_seams(loop_vert, loop_edge, loop_next, edge_seam):
    """One id per corner, joined across unmarked two-face edges.

    loop_vert, loop_edge, loop_next: per corner its vertex, the edge to the
    next corner of its face, and the index of that next corner;
    edge_seam: per edge True when marked as a seam. Returns ids 0..n-1."""
    nl = len(loop_vert)
    parent = np.arange(nl)
    order = np.argsort(loop_edge, kind="stable")
    e = loop_edge[order]
    # edges used by exactly two corners: a manifold edge between two faces
    first = np.ones(nl, bool)
    first[1:] = e[1:] != e[:-1]
    starts = np.flatnonzero(first)
    counts = np.diff(np.append(starts, nl))
    pair = starts[counts == 2]
    a, b = order[pair], order[pair + 1]
    keep = ~edge_seam[loop_edge[a]]
    a, b = a[keep], b[keep]
    an, bn = loop_next[a], loop_next[b]
    pairs = []
    for x, y in ((a, b), (a, bn), (an, b), (an, bn)):  # the corners at one vertex
        same = loop_vert[x] == loop_vert[y]
        pairs.append((x[same], y[same]))
    x = np.concatenate([p[0] for p in pairs])
    y = np.concatenate([p[1] for p in pairs])
    # union by repeated min-label propagation until stable (iterative, no recursion)
    while len(x):
        rx, ry = _roots(parent)[x], _roots(parent)[y]
        differ = rx != ry
        if not differ.any():
            break
        lo, hi = np.minimum(rx, ry)[differ], np.maximum(rx, ry)[differ]
        np.minimum.at(parent, hi, lo)
        parent = _roots(parent)
    _, ids = np.unique(_roots(parent), return_inverse=True)
    return ids.astype(np.int32)


def ids_from_uvs(loop_vert, loop_uv):
    """One id per distinct (vertex, u, v) triple, exact bits (float32 UVs
    compared as stored). Returns (ids, uv per id as float64)."""
    uv32 = np.ascontiguousarray(loop_uv, dtype=np.float32)
    bits = uv32.view(np.uint32).reshape(-1, 2).astype(np.int64)
    key = np.column_stack([loop_vert.astype(np.int64), bits])
    _, first, ids = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return ids.reshape(-1).astype(np.int32), uv32[first].astype(np.float64)


def compact_vertices(V, F):
    """V restricted to the vertices the triangles use (scaf maps every
    vertex it is given); F renumbered. Returns (V', F')."""
    used, F2 = np.unique(F, return_inverse=True)
    return V[used], F2.reshape(F.shape).astype(np.int32)
