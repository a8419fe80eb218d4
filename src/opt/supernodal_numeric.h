/* opt/supernodal_numeric: the numerical supernodal Cholesky factorization
 * A = L L^T on the symbolic factor of a CHOLMOD analysis, in place of
 * cholmod_factorize, with independent subtrees of the supernodal
 * elimination tree factored in parallel threads.
 *
 * Why not cholmod_factorize: CHOLMOD 3 (Debian 12) factors the supernodes
 * one after another, parallel only inside BLAS calls, which are small on
 * the narrow supernodes of a 2D mesh (1.09x at two threads, bench/
 * RESULTS-param.md); it also forms the permuted transpose of A and enters
 * an OpenMP region per supernode at every factorization. Here the
 * supernodes are left-looking as in CHOLMOD (the same symbolic factor,
 * the same BLAS calls per supernode), but:
 *   - A is scattered into the supernodes through a map built once per
 *     pattern (no transpose per factorization);
 *   - with T threads, the elimination tree is cut into subtrees whose
 *     work (sum of squared column counts) is balanced over T bins by
 *     longest-first assignment; each bin runs in its own thread with
 *     one-threaded BLAS, then the supernodes above the cut run in the
 *     calling thread with T-threaded BLAS.
 * The factor is written into L (CHOLMOD's supernodal layout, L L^T), so
 * cholmod_solve2 uses it as its own. Deterministic for a given T: the bins
 * and the order of every update depend on the structure and T only; T = 1
 * runs the supernodes in CHOLMOD's order.
 */
#ifndef SCAF_OPT_SUPERNODAL_NUMERIC_H
#define SCAF_OPT_SUPERNODAL_NUMERIC_H

#include <cholmod.h>

#include "opt/csc.h"

typedef struct opt_snum opt_snum;

/* Plan the factorization of matrices with A's pattern (upper, natural
 * order) on L, a supernodal symbolic (or numeric) factor of that pattern,
 * in `threads` threads. L keeps its structure while the plan lives.
 * NULL when out of memory. */
opt_snum *opt_snum_create(const cholmod_factor *L, const opt_csc *A, int threads);

void opt_snum_destroy(opt_snum *P);

/* How the plan cut the work: threads used (1 when the tree could not be
 * cut), supernodes in the bins, above the cut, and of those the ones whose
 * updates and rows are shared by the threads. */
typedef struct opt_snum_shape {
    int threads, supernodes, in_bins, above, above_parallel;
} opt_snum_shape;
opt_snum_shape opt_snum_get_shape(const opt_snum *P);

/* Factor A (the pattern of the plan) into L, whose values must already be
 * allocated (cholmod_change_factor to a real supernodal L L^T factor).
 * Returns -1 when A is positive definite (L->minor = n), otherwise the
 * first column (in the factor's order) where it is not (L->minor set to
 * it; the factor's values are then not usable). */
int opt_snum_factor(opt_snum *P, const opt_csc *A, cholmod_factor *L);

/* Solve A X = B with the factor in L (made by opt_snum_factor with this
 * plan): nrhs columns of n, column-major; X may be B. The bins' forward
 * and backward sweeps run in their threads, the supernodes above the cut
 * in the calling thread; one thread sweeps in CHOLMOD's order. */
void opt_snum_solve(opt_snum *P, const cholmod_factor *L, int nrhs, const double *B, double *X);

#endif /* SCAF_OPT_SUPERNODAL_NUMERIC_H */
