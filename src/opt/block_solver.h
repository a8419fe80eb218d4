/* opt/block_solver: the one owner of a SCAF step's linear solve.
 *
 * A SCAF system (opt/proxy_system) has `block` unknowns per free vertex
 * (interleaved) and a leading part of `nfixed` unknowns whose pattern
 * never changes (the mesh), followed by unknowns whose pattern changes
 * every iteration (the scaffold). Three calls per system:
 *   opt_block_solver_update   the system's pattern is (maybe) new: choose
 *                             the fill-reducing order (policy below);
 *   opt_block_solver_factor   factor (analysing only when the pattern
 *                             differs from the last analysis), with the
 *                             regularization retries when asked, and run
 *                             the forward sweep of the right-hand side
 *                             while the factor is in cache;
 *   opt_block_solver_solve    the solution for that right-hand side.
 * All reuse policy lives here:
 *   - ordering: the fixed part's nested-dissection (METIS, by vertices)
 *     order is computed once, on the first system, and reused; the
 *     changing unknowns go last in natural order while they are few
 *     (at most 256, or at most 1/50 of the system); a larger changing part
 *     would make a nearly dense trailing block (hilbert.obj: 40% scaffold
 *     unknowns), so AMD orders that whole system afresh;
 *   - analysis: kept while the pattern stays (compared by vertices); in
 *     2D (block 2) the fixed part's analysis is kept across patterns
 *     (opt/split_symbolic) and its entries' places in the factor
 *     (opt/supernodal_plan);
 *   - supernode relaxation: 2 in 2D, 4 in 3D (bench/bench_factor: 2D
 *     factorization + solve fastest at 2);
 *   - numerics: scaf's own supernodal factorization and sweeps
 *     (opt/supernodal_numeric, opt/supernodal_solve) on CHOLMOD's
 *     symbolic factor; CHOLMOD's cholmod_factorize / cholmod_solve2 when
 *     that plan cannot be made (opt/cholmod_solver decides).
 * Regularization (a factorization that finds the matrix not positive
 * definite): A + mu diag(A) for mu = 1e-10, 1e-7, ... < 10; when the
 * unknowns are positions (SLIM), the right-hand side gains mu diag(A) x
 * with x the current positions, so the step shrinks towards zero.
 * Errors: SCAF_ERR_NUMERIC (not positive definite after every retry),
 * SCAF_ERR_NOMEM, SCAF_ERR_USAGE (solve before a factorization), and
 * opt/cholmod_solver's (size limit, interrupt).
 */
#ifndef SCAF_OPT_BLOCK_SOLVER_H
#define SCAF_OPT_BLOCK_SOLVER_H

#include "opt/proxy_system.h"

typedef struct opt_block_solver opt_block_solver;

/* New solver for systems of `block` (2 or 3) unknowns per vertex whose
 * first nfixed unknowns (a multiple of block) keep their pattern. NULL on
 * failure with err set. */
opt_block_solver *opt_block_solver_create(int block, int nfixed, scaf_error *err);

/* Free; safe on NULL. */
void opt_block_solver_destroy(opt_block_solver *s);

/* (a) sys (summed: opt_proxy_system_sum) is the next system; choose its
 * ordering (see the banner). Call it whenever sys's pattern may have
 * changed; refilling the values of the same pattern needs no new call. */
scaf_status opt_block_solver_update(opt_block_solver *s, const opt_proxy_system *sys,
                                    scaf_error *err);

/* What a failed factorization does. */
typedef struct opt_block_retry {
    int regularize; /* 0: return SCAF_ERR_NUMERIC at once (the caller
                       refills, e.g. a projected Hessian); 1: the retries
                       of the banner */
    /* the unknowns are positions: the current ones are X (nall vertices
     * of block coordinates), vertex v being unknown vertex dof[v] when
     * dof[v] >= 0. X NULL: the unknowns are steps (rhs left alone). */
    int nall;
    const int *dof;
    const double *X;
} opt_block_retry;

/* (b) Factor sys->A (the pattern given to the last update; its diagonal
 * is changed by the retries) and sweep rhs forward. rhs (n values) is
 * the one the next opt_block_solver_solve solves for: it must stay
 * allocated and unchanged in between (a retry rewrites it). */
scaf_status opt_block_solver_factor(opt_block_solver *s, opt_proxy_system *sys, double *rhs,
                                    const opt_block_retry *retry, scaf_error *err);

/* (c) x (n values) = the solution for the last factorization's rhs. */
scaf_status opt_block_solver_solve(opt_block_solver *s, double *x, scaf_error *err);

/* Cumulative seconds (orderings count as analysis). */
typedef struct opt_block_solver_times {
    double analysis, factor, solve;
} opt_block_solver_times;
opt_block_solver_times opt_block_solver_get_times(const opt_block_solver *s);

/* For measurements (bench/bench_factor): the fixed part's order (nfixed
 * entries), NULL before the first update. */
const int *opt_block_solver_fixed_ordering(const opt_block_solver *s);

#endif /* SCAF_OPT_BLOCK_SOLVER_H */
