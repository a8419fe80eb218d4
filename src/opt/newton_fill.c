/* opt/newton_fill: one term's share of the projected Newton system.
 *
 * Per simplex: corner gradient and (projected) corner Hessian
 * (opt_isotropic_simplex_hessian), the gradient's free entries subtracted from
 * rhs, the Hessian scattered into the cached pattern
 * (opt_proxy_block_add_local).
 */
#include "opt/newton_fill.h"

#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

#include "opt/isotropic_hessian.h"

static scaf_status inverted(const opt_simplices *S, int s, const double *X, scaf_error *err)
{
    return err_set(err, SCAF_ERR_NUMERIC,
                   "Newton: simplex %d is inverted or degenerate (signed volume %g)", s,
                   opt_signed_volume(S, s, X));
}

typedef struct newton_job {
    opt_proxy_block *b;
    const opt_term *t;
    const int *dof;
    const double *X;
    double *rhs;
    int project;
    double *energy; /* per simplex of the batch, written by its owner */
    int *neg;       /* per simplex of the batch: opt_isotropic_simplex_hessian's value */
    size_t b0, m;
    const int *cb; /* the batch's column ranges (opt/fill_split) */
} newton_job;

/* The range holding simplex s's largest dof (0 when it has no free
 * corner): the one thread that records its energy and sign. */
static int owner(const newton_job *j, int s)
{
    const opt_simplices *S = j->t->s;
    const int *ix = S->idx + (size_t)s * (S->d + 1);
    int top = -1, k = 0;
    for (int i = 0; i <= S->d; i++)
        if (j->dof[ix[i]] > top) top = j->dof[ix[i]];
    while (top >= 0 && top >= j->cb[k + 1]) k++;
    return k;
}

/* Range k of columns over the batch, as the serial fill runs: each
 * simplex that touches the range gets its gradient and Hessian computed
 * and scattered at once (a simplex across ranges is computed by each of
 * their threads, the same bits); its owner records its energy and sign. A
 * simplex found inverted is not scattered (the fill fails). */
static void newton_range(void *ctx, int k)
{
    newton_job *j = ctx;
    const opt_simplices *S = j->t->s;
    int d = S->d, lo = j->cb[k], hi = j->cb[k + 1];
    double e, g[12], H[144];
    for (size_t s = j->b0; s < j->b0 + j->m; s++) {
        int mine = opt_fill_split_touches(S, (int)s, j->dof, lo, hi);
        int own = owner(j, (int)s) == k;
        if (!mine && !own) continue;
        int neg =
            opt_isotropic_simplex_hessian(j->t->energy, S, (int)s, j->X, j->project, &e, g, H);
        if (own) {
            j->energy[s - j->b0] = e;
            j->neg[s - j->b0] = neg;
        }
        if (!mine || neg < 0) continue;
        const int *ix = S->idx + s * (d + 1);
        for (int i = 0; i <= d; i++) {
            int di = j->dof[ix[i]];
            if (di >= lo && di < hi)
                for (int a = 0; a < d; a++) j->rhs[(size_t)di * d + a] -= g[i * d + a];
        }
        opt_proxy_block_add_local_range(j->b, S, (int)s, j->dof, H, lo, hi);
    }
}

/* The fill with nc > 1 chunks (base/parallel), simplices in batches:
 * each thread fills its own columns and rhs entries of the batch
 * (opt/fill_split, the batch's own cut), computing what it needs and
 * scattering it at once, as the serial fill does; the energy, the clamped
 * count and the first failure are then taken in simplex order. Every
 * value receives its terms in simplex order: the serial fill's numbers,
 * bit for bit. Returns SCAF_ERR_NOMEM without touching anything when the
 * scratch cannot be had (the caller fills serially). */
static scaf_status fill_parallel(opt_proxy_block *b, const opt_term *t, const int *dof,
                                 const double *X, int project, double *rhs,
                                 opt_newton_fill_stats *st, int nc, scaf_error *err)
{
    const opt_simplices *S = t->s;
    size_t n = (size_t)S->n;
    newton_job j = {.b = b, .t = t, .dof = dof, .X = X, .rhs = rhs, .project = project};
    if (opt_fill_split_prepare(&b->split, S, dof, nc, OPT_FILL_BATCH) != 0) return SCAF_ERR_NOMEM;
    j.energy = malloc((size_t)OPT_FILL_BATCH * sizeof *j.energy);
    j.neg = malloc((size_t)OPT_FILL_BATCH * sizeof *j.neg);
    if (!j.energy || !j.neg) {
        free(j.energy);
        free(j.neg);
        return SCAF_ERR_NOMEM;
    }
    opt_proxy_block_zero(b);
    double energy = 0;
    int clamped = 0;
    scaf_status status = SCAF_OK;
    for (j.b0 = 0; j.b0 < n && status == SCAF_OK; j.b0 += OPT_FILL_BATCH) {
        j.m = n - j.b0 < OPT_FILL_BATCH ? n - j.b0 : OPT_FILL_BATCH;
        j.cb = opt_fill_split_ranges(&b->split, j.b0);
        par_run(nc, newton_range, &j);
        for (size_t s = j.b0; s < j.b0 + j.m; s++) {
            if (j.neg[s - j.b0] < 0) {
                status = inverted(S, (int)s, X, err);
                break;
            }
            clamped += j.neg[s - j.b0] > 0;
            energy += j.energy[s - j.b0];
        }
    }
    free(j.energy);
    free(j.neg);
    if (status == SCAF_OK && st) {
        st->energy = energy;
        st->clamped = clamped;
    }
    return status;
}

scaf_status opt_newton_block_fill(opt_proxy_block *b, const opt_term *t, const int *dof,
                                  const double *X, int project, double *rhs,
                                  opt_newton_fill_stats *st, scaf_error *err)
{
    const opt_simplices *S = t->s;
    int d = S->d, nc = d + 1, nchunks = par_chunks((size_t)S->n);
    if (nchunks > 1) {
        scaf_status r = fill_parallel(b, t, dof, X, project, rhs, st, nchunks, err);
        if (r != SCAF_ERR_NOMEM) return r;
    }
    memset(b->A.val, 0, (size_t)b->A.nnz * sizeof *b->A.val);
    double energy = 0, e, g[12], H[144];
    int clamped = 0;
    for (int s = 0; s < S->n; s++) {
        int neg = opt_isotropic_simplex_hessian(t->energy, S, s, X, project, &e, g, H);
        if (neg < 0) return inverted(S, s, X, err);
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
