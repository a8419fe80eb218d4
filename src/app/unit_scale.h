/* app/unit_scale: the 3D functions work on their input at unit scale.
 *
 * Squared lengths and areas overflow above about 1e77 and underflow below
 * about 1e-77: `scaf tet` on a tetrahedron at 1e300 made TetGen assert,
 * at 1e-300 it saw "facets intersect", and the flow called a face at
 * 1e300 "zero area". As the 2D functions already do (geom/coord_scale),
 * the positions are divided by a power of two so the largest coordinate is
 * in [1, 2) -- exact, so every exact predicate says the same -- and the
 * results are multiplied back. Inputs whose largest coordinate is within
 * 2^+-UNIT_SCALE_SAFE are used as they are (their products of four
 * coordinates stay in range), so their results keep the same bits.
 *
 * Fails with SCAF_ERR_MESH, giving the range, when the input spans more
 * binary orders of magnitude than a double holds at once (a nonzero
 * coordinate would become subnormal at unit scale), or when a result in
 * the input's units is beyond the largest double (the box around a
 * surface near 1e308).
 */
#ifndef SCAF_APP_UNIT_SCALE_H
#define SCAF_APP_UNIT_SCALE_H

#include <stddef.h>

#include "base/error.h"

/* Binary exponents of the largest coordinate left as they are. */
#define UNIT_SCALE_SAFE 60

/* Divide V (nv by 3) by 2^*e in place, *e from geom/coord_scale over the
 * corners of F (nf by 3, indices in range); *e = 0 within the safe range. */
scaf_status unit_scale_down(int nv, double *V, int nf, const int *F, int *e, scaf_error *err);

/* Multiply the n values X by 2^e in place; SCAF_ERR_MESH when one is not
 * finite then (X partly scaled). */
scaf_status unit_scale_up(double *X, size_t n, int e, scaf_error *err);

#endif /* SCAF_APP_UNIT_SCALE_H */
