"""scaf_uv.overlaps: which triangles' UV boundaries cross or touch.

The faces Check selects besides the flipped ones: for every pair of UV
boundary segments (edges of one triangle only) that share no UV index
and meet, crossing or touching, decided exactly (scaf_uv.orientation:
segments p and q meet iff their boxes meet and each one's endpoints are
not strictly on one side of the other's line), the triangles owning them.
These are the pairs `scaf check` counts as boundary_crossings and
boundary_touchings; its other defects (fold-backs, folds, nesting) are
counted by the program, not selected. Candidate pairs come from a uniform
grid (numpy), so the cost is about linear in the boundary's size.
"""

import numpy as np

from .orientation import orient


def boundary_segments(ft):
    """(segments #B x 2 UV indices, owner triangle #B) of a map's boundary."""
    e = np.concatenate([ft[:, [0, 1]], ft[:, [1, 2]], ft[:, [2, 0]]])
    tri = np.tile(np.arange(len(ft)), 3)
    key = np.sort(e, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    once = counts[inverse.reshape(-1)] == 1
    return e[once], tri[once]


def _candidate_pairs(lo, hi):
    """Pairs (i < j) of boxes sharing a grid cell (a superset of the pairs
    of boxes that meet)."""
    n = len(lo)
    span = np.max(hi.max(axis=0) - lo.min(axis=0))
    cell = max(span / max(np.sqrt(n), 1.0), np.median(np.max(hi - lo, axis=1)), 1e-300)
    origin = lo.min(axis=0)
    c0 = np.floor((lo - origin) / cell).astype(np.int64)
    c1 = np.floor((hi - origin) / cell).astype(np.int64)
    side = int(c1.max()) + 2
    ids, cells = [], []
    for i in range(n):  # boxes cover few cells: median-size cells
        xs, ys = np.meshgrid(np.arange(c0[i, 0], c1[i, 0] + 1), np.arange(c0[i, 1], c1[i, 1] + 1))
        k = (xs * side + ys).reshape(-1)
        cells.append(k)
        ids.append(np.full(len(k), i))
    cells, ids = np.concatenate(cells), np.concatenate(ids)
    order = np.argsort(cells, kind="stable")
    cells, ids = cells[order], ids[order]
    starts = np.flatnonzero(np.r_[True, cells[1:] != cells[:-1]])
    ends = np.r_[starts[1:], len(cells)]
    a, b = [], []
    for s, e in zip(starts, ends):
        if e - s > 1:
            i, j = np.triu_indices(e - s, 1)
            a.append(ids[s + i])
            b.append(ids[s + j])
    if not a:
        return np.empty((0, 2), np.int64)
    pairs = np.column_stack([np.concatenate(a), np.concatenate(b)])
    return np.unique(np.sort(pairs, axis=1), axis=0)


def overlapping_triangles(uv, ft):
    """Indices of the triangles owning a boundary segment that crosses or
    touches another one (sharing no UV index), and the number of such
    segment pairs."""
    seg, owner = boundary_segments(np.asarray(ft))
    if len(seg) < 2:
        return np.empty(0, np.int64), 0
    p, q = uv[seg[:, 0]], uv[seg[:, 1]]
    lo, hi = np.minimum(p, q), np.maximum(p, q)
    pairs = _candidate_pairs(lo, hi)
    i, j = pairs[:, 0], pairs[:, 1]
    shared = (seg[i, 0, None] == seg[j]).any(axis=1) | (seg[i, 1, None] == seg[j]).any(axis=1)
    boxes = np.all(lo[i] <= hi[j], axis=1) & np.all(lo[j] <= hi[i], axis=1)
    keep = ~shared & boxes
    i, j = i[keep], j[keep]
    o1 = orient(uv, np.column_stack([seg[i, 0], seg[i, 1], seg[j, 0]]))
    o2 = orient(uv, np.column_stack([seg[i, 0], seg[i, 1], seg[j, 1]]))
    o3 = orient(uv, np.column_stack([seg[j, 0], seg[j, 1], seg[i, 0]]))
    o4 = orient(uv, np.column_stack([seg[j, 0], seg[j, 1], seg[i, 1]]))
    meet = (o1.astype(int) * o2 <= 0) & (o3.astype(int) * o4 <= 0)
    i, j = i[meet], j[meet]
    return np.unique(np.concatenate([owner[i], owner[j]])), int(len(i))
