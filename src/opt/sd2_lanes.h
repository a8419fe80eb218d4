/* opt/sd2_lanes: the symmetric Dirichlet energy of triangles in 2D (the
 * mesh term of every UV map) summed over a range of simplices, and its
 * SLIM proxies, a batch of simplices at a time in vector lanes. The
 * closed forms and the order of every operation are those of the
 * energy's row (opt/energy_symmetric_dirichlet.c: density, density_grad)
 * and of opt/energy's 2D proxy, and the sums run in simplex
 * order, so the results are those of the one-simplex-at-a-time loops, to
 * the bit; only the arithmetic of a batch's Jacobians goes through the
 * vector unit together. Used by opt/energy, opt/objective and
 * opt/proxy_block; it needs only the shared weight (opt/sd_weight), not
 * opt/energy, so the two do not depend on each other. */
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
void opt_sd2_energy_slope_range(const opt_simplices *S, const double *X, const double *D, size_t lo,
                                size_t hi, double *e, double *slope);

/* The SLIM proxies of triangles s in [lo, hi) at X (opt/proxy_block's
 * per-simplex proxy with opt/energy's 2D rotation target, squared
 * weights capped at w2_cap): loc[10 (s - lo) ..] gets M = W^T W (2 x 2),
 * then lin = M T G_s^T per corner (3 x 2). Returns the largest squared
 * weight before the cap (0 for an empty range). S->d == 2. */
double opt_sd2_proxy_range(const opt_simplices *S, const double *X, size_t lo, size_t hi,
                           double w2_cap, double *loc);

#endif /* SCAF_OPT_SD2_LANES_H */
