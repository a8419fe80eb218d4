/* opt/supernodal_solve: solves with the factor of opt/supernodal_numeric,
 * on the same plan (opt/supernodal_plan): the forward sweep runs each
 * bin's supernodes whole in one of the threads (updates of the rows above
 * the cut kept per bin and subtracted after, in bin order: the same bits
 * for any thread count), then the supernodes above the cut; the backward
 * sweep the other way round. A plan of one bin sweeps in CHOLMOD's order.
 * BLAS runs one-threaded throughout. */
#ifndef SCAF_OPT_SUPERNODAL_SOLVE_H
#define SCAF_OPT_SUPERNODAL_SOLVE_H

#include "opt/supernodal_plan.h"

/* Solve A X = B with the factor in L (made by opt_snum_factor with this
 * plan): nrhs columns of n, column-major; X may be B. */
void opt_snum_solve(opt_snum *P, const cholmod_factor *L, int nrhs, const double *B, double *X);

/* The sweeps one at a time, so that the forward one can run inside the
 * factorization (opt/supernodal_numeric) while each supernode is still in
 * cache. forward_begin: y = b in the factor's order, the bins' updates
 * of the rows above the cut zeroed; forward_super: supernode sn's forward
 * step (acc: the calling bin's updates of the rows above the cut, NULL
 * above the cut and with one bin); forward_gather: after the bins,
 * subtract their updates (in bin order); backward: the backward sweep
 * after the whole forward one, x = the solution in the natural order. */
void opt_snum_forward_begin(opt_snum *P, const cholmod_factor *L, const double *b);
void opt_snum_forward_super(const opt_snum *P, opt_snum_worker *wk, int sn, const double *Lx,
                            double *acc);
void opt_snum_forward_gather(opt_snum *P);
void opt_snum_backward(opt_snum *P, const cholmod_factor *L, double *x);

#endif /* SCAF_OPT_SUPERNODAL_SOLVE_H */
