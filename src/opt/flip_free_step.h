/* opt/flip_free_step: the largest step before a simplex inverts.
 *
 * Along x + t d, a triangle's signed area is a quadratic in t and a
 * tetrahedron's signed volume a cubic. For a positively oriented simplex
 * the first positive root is the largest flip-free step; +INFINITY when the
 * simplex never degenerates along the direction. Computed in floating
 * point (the result is approximate near the root; the line search takes a
 * safety fraction and confirms orientations with exact predicates).
 * Degenerate coefficient cases (vanishing leading terms, double roots,
 * zero direction) are handled. Never fails.
 */
#ifndef SCAF_OPT_FLIP_FREE_STEP_H
#define SCAF_OPT_FLIP_FREE_STEP_H

#include "opt/simplices.h"

/* Smallest t > 0 with c[0] + c[1] t + ... + c[deg] t^deg = 0, for deg <= 3
 * and c[0] > 0; +INFINITY if none. The returned t has p(t') > 0 for every
 * 0 <= t' < t up to rounding. */
double opt_first_positive_root(int deg, const double *c);

/* Triangle corners x0 x1 x2 (2 each), per-corner directions d0 d1 d2. */
double opt_max_step_triangle(const double *x0, const double *x1, const double *x2, const double *d0,
                             const double *d1, const double *d2);

/* Tetrahedron corners x0..x3 (3 each), directions d0..d3. */
double opt_max_step_tet(const double *x0, const double *x1, const double *x2, const double *x3,
                        const double *d0, const double *d1, const double *d2, const double *d3);

/* Minimum over the simplices of S at positions X (#X by d) along D
 * (#X by d). +INFINITY if none can flip. */
double opt_max_step(const opt_simplices *S, const double *X, const double *D);

#endif /* SCAF_OPT_FLIP_FREE_STEP_H */
