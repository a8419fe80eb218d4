/* geom/tri_intersect: exact intersection tests of segments and triangles
 * in 3D, built on orient3d / orient2d (geom/predicates) only.
 *
 * All tests are on CLOSED sets (a touch at one point counts) and decided
 * exactly for any finite coordinates: no tolerance, no constructed points.
 * Coplanar configurations are decided in 2D after dropping the coordinate
 * axis along which the triangle's projection is not degenerate (decided by
 * orient2d, so the projection is exactly a bijection of the plane).
 *
 * The triangle arguments must be non-degenerate (tri3_degenerate() == 0);
 * the segment must have two distinct endpoints. Pure functions.
 */
#ifndef SCAF_GEOM_TRI_INTERSECT_H
#define SCAF_GEOM_TRI_INTERSECT_H

/* 1 when a, b, c are collinear (or coincide): the triangle has zero area,
 * exactly. */
int tri3_degenerate(const double a[3], const double b[3], const double c[3]);

/* The coordinate axis (0, 1 or 2) to drop so that the projection of the
 * non-degenerate triangle abc onto the other two axes is not degenerate. */
int tri3_projection_axis(const double a[3], const double b[3], const double c[3]);

/* Orientation of the projections of a, b, c with coordinate `axis` dropped
 * (the other two kept in cyclic order: axis 2 keeps x, y). */
double orient2d_dropping(int axis, const double a[3], const double b[3], const double c[3]);

/* 1 when the closed segment pq and the closed triangle abc share a point. */
int seg_tri_intersect(const double p[3], const double q[3], const double a[3], const double b[3],
                      const double c[3]);

/* 1 when the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point. */
int tri_tri_intersect(const double *const a[3], const double *const b[3]);

#endif /* SCAF_GEOM_TRI_INTERSECT_H */
