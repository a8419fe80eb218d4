"""scaf.obj: a minimal Wavefront OBJ reader for examples and tests.

The C library does not export its mesh readers (it works on arrays), so
this small reader exists only to get arrays out of a simple OBJ file. It
reads `v x y z`, `vt u v` and `f` lines with 1-based or negative indices
in the forms v, v/vt, v/vt/vn and v//vn; polygons are split into a fan of
triangles; every other line is ignored. No .gz, OFF or PLY: for those,
use the `scaf` program or a mesh library (trimesh, meshio, ...) and pass
the arrays. Errors raise scaf.InputError naming FILE:LINE.
"""

from . import _arrays
from ._errors import InputError


def _index(tok, count, path, lineno, what):
    try:
        i = int(tok)
    except ValueError:
        raise InputError("%s:%d: %r is not a %s index" % (path, lineno, tok, what), 3, "parse error") from None
    if i < 0:
        i += count  # -1 is the last one read so far
    else:
        i -= 1
    if not 0 <= i < count:
        raise InputError("%s:%d: %s index %s out of range (%d read so far)" % (path, lineno, what, tok, count),
                         3, "parse error")
    return i


def read_obj(path):
    """(V, F, UV, FT) from a triangle OBJ: V #V x 3, F #F x 3 (0-based),
    UV #UV x 2 and FT #F x 3 when every face has vt indices, else None and
    None. numpy arrays with numpy, lists of lists without."""
    V, UV, F, FT = [], [], [], []
    all_vt = True
    try:
        fp = open(path, "r", encoding="utf-8", errors="replace")
    except OSError as e:
        raise InputError("%s: cannot open: %s" % (path, e.strerror), 2, "I/O error") from None
    with fp:
        for lineno, line in enumerate(fp, 1):
            t = line.split()
            if not t or t[0].startswith("#"):
                continue
            try:
                if t[0] == "v":
                    V.append([float(t[1]), float(t[2]), float(t[3])])
                elif t[0] == "vt":
                    UV.append([float(t[1]), float(t[2]) if len(t) > 2 else 0.0])
            except (ValueError, IndexError):
                raise InputError("%s:%d: malformed %s line" % (path, lineno, t[0]), 3, "parse error") from None
            if t[0] != "f":
                continue
            if len(t) < 4:
                raise InputError("%s:%d: a face needs 3 corners" % (path, lineno), 3, "parse error")
            vs, ts = [], []
            for c in t[1:]:
                parts = c.split("/")
                vs.append(_index(parts[0], len(V), path, lineno, "vertex"))
                if len(parts) > 1 and parts[1]:
                    ts.append(_index(parts[1], len(UV), path, lineno, "texture"))
            if len(ts) != len(vs):
                all_vt = False
            for k in range(1, len(vs) - 1):  # fan
                F.append([vs[0], vs[k], vs[k + 1]])
                if all_vt:
                    FT.append([ts[0], ts[k], ts[k + 1]])
    if not V or not F:
        raise InputError("%s: no vertices or no faces" % path, 3, "parse error")
    if _arrays.np is not None:
        np = _arrays.np
        V, F = np.array(V, dtype=np.float64), np.array(F, dtype=np.int32)
        if all_vt and UV:
            UV, FT = np.array(UV, dtype=np.float64), np.array(FT, dtype=np.int32)
    if not (all_vt and len(UV)):
        UV = FT = None
    return V, F, UV, FT
