/* mesh/degenerate: zero-area triangles in 3D, decided exactly.
 *
 * A triangle abc has zero area iff a, b, c are collinear, i.e. iff its
 * projections onto the three coordinate planes are all collinear. Each
 * projection is tested with the exact orient2d sign (geom/predicates.h), so
 * the verdict holds for every finite double input: no tolerance.
 */
#ifndef SCAF_MESH_DEGENERATE_H
#define SCAF_MESH_DEGENERATE_H

/* 1 if the points a, b, c ({x, y, z} each) are collinear (zero area,
 * including coincident points), else 0. */
int tri3_is_degenerate(const double a[3], const double b[3], const double c[3]);

#endif /* SCAF_MESH_DEGENERATE_H */
