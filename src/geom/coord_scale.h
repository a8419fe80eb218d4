/* geom/coord_scale: bringing coordinates to unit scale by a power of two.
 *
 * Results must not depend on the units of the input: a mesh in
 * kilometres, in nanometres or scaled by 1e80 is the same surface, a UV
 * layout at 1e-200 the same layout. Squared lengths and areas (products
 * of up to four coordinates) overflow above about 1e77 and underflow
 * below about 1e-77. Dividing every point used by the faces by 2^e, with
 * e the exponent of the largest coordinate magnitude, puts that one in
 * [1, 2): exact in floating point (only exponents change, barring a
 * coordinate more than 2^1022 below the largest, which rounds into the
 * subnormal range), so exact predicates give the same verdicts on the
 * scaled points, and a result in the scaled units times 2^e is the result
 * in the input's units (bit for bit when the input was itself scaled by a
 * power of two). No translation: it would round.
 */
#ifndef SCAF_GEOM_COORD_SCALE_H
#define SCAF_GEOM_COORD_SCALE_H

#include <stddef.h>

/* The exponent e such that the largest |coordinate| of the points used by
 * the corners, divided by 2^e, is in [1, 2); 0 when there is none or all
 * are 0 (or one is not finite: the caller's own checks report that).
 *   X        points, dim (2 or 3) coordinates each
 *   ncorner  number of corners; idx[i] the point of corner i (in range,
 *            checked by the caller), e.g. a face array with 3 per face */
int coord_scale_exponent(const double *X, int dim, size_t ncorner, const int *idx);

/* Xs = X (n points) with every point used by a corner divided by 2^e
 * (ldexp; the others copied as they are). Xs may not alias X. */
void coord_scale_apply(double *Xs, const double *X, int dim, int n, size_t ncorner, const int *idx,
                       int e);

#endif /* SCAF_GEOM_COORD_SCALE_H */
