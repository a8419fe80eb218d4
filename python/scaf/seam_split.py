"""scaf.seam_split: a per-corner UV map turned into one vertex per UV.

Formats such as glTF, and libraries such as trimesh, keep one UV per
vertex: a vertex on a seam (two UVs, one per side) must become two
vertices. split_seams does that split the way xatlas's binding hands out
its result: `vmapping` (the original vertex of each new vertex), `indices`
(the faces over the new vertices) and `uvs` (one UV per new vertex), so
any other per-vertex attribute follows with `attr[vmapping]`.
"""

from . import _arrays


def split_seams(F, FT, UV):
    """One output vertex per distinct (vertex, UV index) pair of the corners.

    F   #F by 3 vertex indices of the triangles
    FT  #F by 3 UV indices of the same corners (e.g. atlas(...).ft)
    UV  #UV by 2 texture coordinates (e.g. atlas(...).uv)
    Returns (vmapping, indices, uvs):
      vmapping  #N original vertex index of each new vertex
      indices   #F by 3 new vertex index of each corner
      uvs       #N by 2 the UV of each new vertex
    New vertices are numbered in the order their first corner appears
    (face by face), so the result does not depend on the input's UV
    numbering beyond which corners share a UV. numpy arrays with numpy,
    lists without. ValueError names the argument on a bad shape or an
    index outside UV's rows (or a negative vertex index)."""
    f = _arrays.matrix(F, "F", 3, True)
    ft = _arrays.matrix(FT, "FT", 3, True)
    uv = _arrays.matrix(UV, "UV", 2, False)
    if f.rows != ft.rows:
        raise ValueError("FT: %d rows, F has %d (one UV index per corner)" % (ft.rows, f.rows))
    n = 3 * f.rows
    fv = [f.ptr[i] for i in range(n)] if _arrays.np is None else f._owner.reshape(-1)
    tv = [ft.ptr[i] for i in range(n)] if _arrays.np is None else ft._owner.reshape(-1)
    np = _arrays.np
    if np is not None:
        if fv.min() < 0:
            raise ValueError("F: negative vertex index %d" % fv.min())
        if tv.min() < 0 or tv.max() >= uv.rows:
            bad = int(tv.min()) if tv.min() < 0 else int(tv.max())
            raise ValueError("FT: UV index %d outside 0..%d" % (bad, uv.rows - 1))
        pairs = fv.astype(np.int64) * (int(tv.max()) + 1) + tv
        _, first, inverse = np.unique(pairs, return_index=True, return_inverse=True)
        order = np.argsort(first, kind="stable")  # unique pairs by first corner
        rank = np.empty_like(order)
        rank[order] = np.arange(order.size)
        corners = first[order]
        indices = rank[inverse].reshape(-1, 3).astype(np.int32)
        vmapping = fv[corners].astype(np.int32)
        uvs = uv._owner[tv[corners]].copy()
        return vmapping, indices, uvs
    seen = {}
    vmapping, uvs, flat = [], [], []
    uvrows = [[uv.ptr[2 * i], uv.ptr[2 * i + 1]] for i in range(uv.rows)]
    for c in range(n):
        v, t = fv[c], tv[c]
        if v < 0:
            raise ValueError("F: negative vertex index %d" % v)
        if not 0 <= t < uv.rows:
            raise ValueError("FT: UV index %d outside 0..%d" % (t, uv.rows - 1))
        k = seen.get((v, t))
        if k is None:
            k = seen[(v, t)] = len(vmapping)
            vmapping.append(v)
            uvs.append(list(uvrows[t]))
        flat.append(k)
    return vmapping, [flat[i:i + 3] for i in range(0, n, 3)], uvs
