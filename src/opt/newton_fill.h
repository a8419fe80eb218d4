/* opt/newton_fill: one term's share of the projected Newton system.
 *
 * The Newton system of a term's energy sum_s weight_s * Psi(J_s(x))
 * (symmetric Dirichlet, ARAP or conformal) over the free vertices is
 * H p = -g, H the sum of the simplices' PSD-projected Hessians
 * (opt/isotropic_hessian) and g the gradient,
 * restricted to free unknowns (dof numbering as in opt/proxy_block:
 * interleaved, fixed vertices -1; a fixed vertex does not move, so its
 * couplings simply drop out). The values go into the SAME pattern that
 * opt_proxy_block_pattern builds for SLIM's proxy, so a solver can switch
 * between SLIM and Newton iterations without a new symbolic analysis; the
 * blocks of several terms are summed by opt/proxy_system as for SLIM.
 * Unlike SLIM's system, whose solution is the proxy's minimizer (new
 * positions), this one's solution is the step p itself.
 * H is only semidefinite (clamped twists give zero modes); with every
 * boundary vertex fixed it is definite in practice, otherwise regularize.
 */
#ifndef SCAF_OPT_NEWTON_FILL_H
#define SCAF_OPT_NEWTON_FILL_H

#include "opt/proxy_block.h"

typedef struct opt_newton_fill_stats {
    double energy; /* sum_s weight_s * Psi(J_s) of the term at X */
    int clamped;   /* simplices with at least one negative eigenvalue
                        (clamped when projecting) */
} opt_newton_fill_stats;

/* Fill b's values (zeroed first) with the Hessian of term t at positions
 * X (#X by d), each simplex's projected PSD when project != 0 (the exact,
 * possibly indefinite one otherwise: near a minimum the sum is positive
 * definite even where single simplices are not); rhs (nfree*d) ACCUMULATES -gradient (zero it
 * first). b's pattern must have been built for t->s under dof. st may be
 * NULL. Fails with SCAF_ERR_NUMERIC naming
 * the first simplex that is inverted or degenerate at X (values are then
 * partial: do not factor them). Big sets run in base/parallel's threads;
 * values, rhs and stats are the serial fill's, bit for bit, for any count. */
scaf_status opt_newton_block_fill(opt_proxy_block *b, const opt_term *t, const int *dof,
                                  const double *X, int project, double *rhs,
                                  opt_newton_fill_stats *st, scaf_error *err);

#endif /* SCAF_OPT_NEWTON_FILL_H */
