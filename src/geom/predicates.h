/* geom/predicates: exact geometric predicates on doubles.
 *
 * Each returns a double whose SIGN is exactly the sign of the determinant
 * computed with real numbers from the given doubles (any finite inputs);
 * the magnitude is only an approximation. A fast floating-point filter
 * decides most calls; only when it cannot, exact expansion arithmetic does.
 * Pure functions: no global state, thread-safe. Sign conventions follow
 * Shewchuk's predicates. Exact for every finite input, huge/tiny mixes and
 * subnormals included (predicates.c says how); a NaN or infinite
 * coordinate gives NaN.
 */
#ifndef SCAF_GEOM_PREDICATES_H
#define SCAF_GEOM_PREDICATES_H

/* > 0 if a, b, c are in counter-clockwise order, < 0 if clockwise,
 * 0 if collinear. Points are {x, y}. */
double orient2d(const double a[2], const double b[2], const double c[2]);

/* > 0 if d lies inside the circle through a, b, c (which must be in
 * counter-clockwise order; the sign flips otherwise), < 0 outside,
 * 0 on it. */
double incircle(const double a[2], const double b[2], const double c[2], const double d[2]);

/* > 0 if d lies below the plane through a, b, c, where "below" means a, b, c
 * appear counter-clockwise seen from above; < 0 above; 0 coplanar.
 * (Equivalently: positive when the tetrahedron a, b, c, d is negatively
 * oriented in the right-handed sense; Shewchuk's convention.) */
double orient3d(const double a[3], const double b[3], const double c[3], const double d[3]);

/* > 0 if e lies inside the sphere through a, b, c, d (which must be
 * positively oriented: orient3d(a, b, c, d) > 0; the sign flips
 * otherwise), < 0 outside, 0 on it. */
double insphere(const double a[3], const double b[3], const double c[3], const double d[3],
                const double e[3]);

#endif /* SCAF_GEOM_PREDICATES_H */
