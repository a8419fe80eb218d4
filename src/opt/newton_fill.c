/* opt/newton_fill: one term's share of the projected Newton system.
 *
 * Per simplex: corner gradient and (projected) corner Hessian
 * (opt_isotropic_simplex_hessian), the gradient's free entries subtracted from
 * rhs, the Hessian scattered into the cached pattern
 * (opt_proxy_block_add_local).
 */
#include "opt/newton_fill.h"

#include <string.h>

#include "opt/isotropic_hessian.h"

scaf_status opt_newton_block_fill(opt_proxy_block *b, const opt_term *t, const int *dof,
                                  const double *X, int project, double *rhs,
                                  opt_newton_fill_stats *st, scaf_error *err)
{
    const opt_simplices *S = t->s;
    int d = S->d, nc = d + 1;
    memset(b->A.val, 0, (size_t)b->A.nnz * sizeof *b->A.val);
    double energy = 0, e, g[12], H[144];
    int clamped = 0;
    for (int s = 0; s < S->n; s++) {
        int neg = opt_isotropic_simplex_hessian(t->energy, S, s, X, project, &e, g, H);
        if (neg < 0)
            return err_set(err, SCAF_ERR_NUMERIC,
                           "Newton: simplex %d is inverted or degenerate (signed volume %g)", s,
                           opt_signed_volume(S, s, X));
        clamped += neg > 0;
        energy += e;
        const int *ix = S->idx + (size_t)s * nc;
        for (int i = 0; i < nc; i++) {
            int di = dof[ix[i]];
            if (di >= 0)
                for (int a = 0; a < d; a++) rhs[(size_t)di * d + a] -= g[i * d + a];
        }
        opt_proxy_block_add_local(b, S, s, dof, H);
    }
    if (st) {
        st->energy = energy;
        st->clamped = clamped;
    }
    return SCAF_OK;
}
