"""scaf_uv.orientation: exact sign of each UV triangle's area.

The sign of (b - a) x (c - a) for double coordinates, decided exactly: a
floating-point evaluation is trusted when its magnitude exceeds the
static error bound of Shewchuk's orient2d filter (ccwerrboundA); the few
others are recomputed with fractions.Fraction (every double is a
rational, so that is exact). The same verdict the library's checker
(geom/predicates) gives, without a tolerance.
"""

from fractions import Fraction

import numpy as np

_EPS = np.finfo(np.float64).eps / 2  # Shewchuk's epsilon: half an ulp of 1
_BOUND = (3.0 + 16.0 * _EPS) * _EPS


def orient(uv, tris):
    """+1 counter-clockwise, -1 clockwise, 0 zero area, per row of tris
    (#T x 3 indices into uv, #UV x 2 float64)."""
    a, b, c = uv[tris[:, 0]], uv[tris[:, 1]], uv[tris[:, 2]]
    left = (a[:, 0] - c[:, 0]) * (b[:, 1] - c[:, 1])
    right = (a[:, 1] - c[:, 1]) * (b[:, 0] - c[:, 0])
    det = left - right
    sign = np.sign(det).astype(np.int8)
    unsure = np.flatnonzero(~(np.abs(det) > _BOUND * (np.abs(left) + np.abs(right))))
    for t in unsure:
        (ax, ay), (bx, by), (cx, cy) = ([Fraction(float(x)) for x in p] for p in (a[t], b[t], c[t]))
        d = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)
        sign[t] = (d > 0) - (d < 0)
    return sign
