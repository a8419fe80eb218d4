/* opt/supernodal_numeric: the numerical supernodal Cholesky factorization
 * A = L L^T on the symbolic factor of a CHOLMOD analysis, in place of
 * cholmod_factorize, with the plan of opt/supernodal_plan.
 *
 * Why not cholmod_factorize: CHOLMOD 3 (Debian 12) factors the supernodes
 * one after another, parallel only inside BLAS calls, which are small on
 * the narrow supernodes of a 2D mesh (1.09x at two threads, bench/
 * RESULTS-param.md); it also forms the permuted transpose of A and enters
 * an OpenMP region per supernode at every factorization. Here the
 * supernodes are left-looking as in CHOLMOD (the same symbolic factor, the
 * same factor to rounding; small updates are one dgemm where CHOLMOD makes
 * two calls), A is scattered through the plan's map, and each bin of the
 * plan is factored whole by one of the threads; above the cut, each large
 * supernode's updates are split by columns and its rows below the
 * diagonal block by rows into the plan's shares. BLAS runs one-threaded
 * throughout (the threads are scaf's). The bins and shares are the
 * plan's, not the thread count: the factor is the same bits for any. The factor is written into L
 * (CHOLMOD's supernodal layout, L L^T), so cholmod_solve2 can use it too.
 */
#ifndef SCAF_OPT_SUPERNODAL_NUMERIC_H
#define SCAF_OPT_SUPERNODAL_NUMERIC_H

#include "opt/supernodal_plan.h"

/* Factor A (the pattern of the plan) into L, whose values must already be
 * allocated (a real supernodal L L^T factor). Returns -1 when A is
 * positive definite (L->minor = n), otherwise the first column (in the
 * factor's order) where it is not (L->minor set to it; the factor's values
 * are then not usable). */
int opt_snum_factor(opt_snum *P, const opt_csc *A, cholmod_factor *L);

/* opt_snum_factor that also runs the forward sweep of the solve with b (n
 * values, natural order) while each supernode is still in cache: when A is
 * positive definite, opt_snum_backward (opt/supernodal_solve) then gives
 * A^-1 b, the same bits as opt_snum_solve after opt_snum_factor, and only
 * the backward sweep is left (aphrodite: solve 18 -> 10 ms, factorization
 * +2 ms). */
int opt_snum_factor_forward(opt_snum *P, const opt_csc *A, cholmod_factor *L, const double *b);

#endif /* SCAF_OPT_SUPERNODAL_NUMERIC_H */
