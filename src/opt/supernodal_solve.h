/* opt/supernodal_solve: solves with the factor of opt/supernodal_numeric,
 * on the same plan (opt/supernodal_plan): the forward sweep runs each
 * bin's supernodes in its own thread (updates of the rows above the cut
 * kept per thread and subtracted after, in thread order), then the
 * supernodes above the cut; the backward sweep the other way round. One
 * thread sweeps in CHOLMOD's order. BLAS runs one-threaded throughout. */
#ifndef SCAF_OPT_SUPERNODAL_SOLVE_H
#define SCAF_OPT_SUPERNODAL_SOLVE_H

#include "opt/supernodal_plan.h"

/* Solve A X = B with the factor in L (made by opt_snum_factor with this
 * plan): nrhs columns of n, column-major; X may be B. */
void opt_snum_solve(opt_snum *P, const cholmod_factor *L, int nrhs, const double *B, double *X);

#endif /* SCAF_OPT_SUPERNODAL_SOLVE_H */
