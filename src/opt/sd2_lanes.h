/* opt/sd2_lanes: the symmetric Dirichlet energy of triangles in 2D (the
 * mesh term of every UV map) summed over a range of simplices, eight at a
 * time in vector lanes. The closed forms and the order of every operation
 * are opt/energy's (density, density_grad) and the sums run in simplex
 * order, so the results are those of the one-simplex-at-a-time loops, to
 * the bit; only the Jacobians' inverses and products of eight simplices
 * go through the vector unit together. */
#ifndef SCAF_OPT_SD2_LANES_H
#define SCAF_OPT_SD2_LANES_H

#include <stddef.h>

#include "opt/simplices.h"

/* sum over s in [lo, hi) of weight_s * density(J_s(X)) (+inf where a
 * triangle is not positively oriented), added to 0 in order. S->d == 2. */
double opt_sd2_energy_range(const opt_simplices *S, const double *X, size_t lo, size_t hi);

/* *e += weight_s * density(J_s(X)) and *slope += weight_s * <dE/dJ, J_s(D)>
 * for s in [lo, hi), in order (NaN slope where a triangle is not
 * positively oriented). S->d == 2. */
void opt_sd2_energy_slope_range(const opt_simplices *S, const double *X, const double *D,
                                size_t lo, size_t hi, double *e, double *slope);

#endif /* SCAF_OPT_SD2_LANES_H */
