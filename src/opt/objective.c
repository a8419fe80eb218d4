/* opt/objective: the term interface and its simplex implementation (see
 * objective.h). The simplex term's energy sums and slope follow the loops
 * the line search had when it knew only simplices, in the same order, so
 * results are bit for bit those of before.
 */
#include "opt/objective.h"

#include <math.h>
#include <string.h>

#include "base/parallel.h"
#include "geom/predicates.h"
#include "opt/flip_free_step.h"
#include "opt/newton_fill.h"
#include "opt/sd2_lanes.h"

void opt_obj_term_free(opt_obj_term *t)
{
    if (t) opt_proxy_block_free(&t->blk);
}

double opt_obj_energy(const opt_obj_term *terms, int nterms, const double *X)
{
    double e = 0;
    for (int k = 0; k < nterms; k++) e += terms[k].ops->energy(&terms[k], X);
    return e;
}

int opt_obj_valid(const opt_obj_term *terms, int nterms, const double *X)
{
    for (int k = 0; k < nterms; k++)
        if (terms[k].ops->valid && !terms[k].ops->valid(&terms[k], X)) return 0;
    return 1;
}

/* ---- simplices with a distortion energy ----------------------------------- */

static double simplex_energy(const opt_obj_term *t, const double *X)
{
    const opt_simplex_term *st = t->self;
    opt_term term = {st->S, st->energy};
    return opt_term_energy(&term, X);
}

/* sum weight * density and sum weight * <dE/dJ, J(D)> (J is linear in
 * positions) over simplices [lo, hi), added to the running sums e, slope. */
static void energy_slope_range(const opt_simplex_term *st, const double *X, const double *D,
                               size_t lo, size_t hi, double *energy, double *slope)
{
    const opt_simplices *S = st->S;
    int d = S->d;
    if (d == 2 && st->energy == OPT_ENERGY_SYMMETRIC_DIRICHLET) {
        opt_sd2_energy_slope_range(S, X, D, lo, hi, energy, slope); /* the same, in lanes */
        return;
    }
    double acc = *slope, e = *energy, J[9], G[9], JD[9];
    for (size_t s = lo; s < hi; s++) {
        opt_jacobian(S, (int)s, X, J);
        opt_jacobian(S, (int)s, D, JD);
        double v = opt_density_grad(st->energy, d, J, G);
        double dot = 0;
        for (int q = 0; q < d * d; q++) dot += G[q] * JD[q];
        acc += S->weight[s] * dot;
        e += S->weight[s] * v;
    }
    *energy = e;
    *slope = acc;
}

/* One chunk: the serial loop, continuing the running sums. More: each
 * chunk sums from 0 and the partials are added in chunk order; the chunks
 * are par_sum_chunks', so any thread count gives the same bits
 * (base/parallel). */
typedef struct slope_job {
    const opt_simplex_term *st;
    const double *X, *D;
    size_t n;
    int nc;
    double pe[PAR_MAX_CHUNKS], ps[PAR_MAX_CHUNKS];
} slope_job;

static void slope_chunk(void *ctx, int k)
{
    slope_job *j = ctx;
    j->pe[k] = j->ps[k] = 0;
    energy_slope_range(j->st, j->X, j->D, par_chunk_begin(j->n, j->nc, k),
                       par_chunk_begin(j->n, j->nc, k + 1), &j->pe[k], &j->ps[k]);
}

static void simplex_energy_slope(const opt_obj_term *t, const double *X, const double *D,
                                 double *energy, double *slope)
{
    const opt_simplex_term *st = t->self;
    size_t n = (size_t)st->S->n;
    int nc = par_sum_chunks(n);
    if (nc == 1) {
        energy_slope_range(st, X, D, 0, n, energy, slope);
        return;
    }
    slope_job j = {.st = st, .X = X, .D = D, .n = n, .nc = nc};
    par_run(nc, slope_chunk, &j);
    for (int k = 0; k < nc; k++) {
        *energy += j.pe[k];
        *slope += j.ps[k];
    }
}

static scaf_status simplex_pattern(opt_obj_term *t, const int *dof, int nfree, scaf_error *err)
{
    const opt_simplex_term *st = t->self;
    if (st->keep_pattern && t->blk.A.colptr && t->blk.nfree <= nfree) return SCAF_OK;
    return opt_proxy_block_pattern(&t->blk, st->S, dof, nfree, err);
}

static void simplex_fill(opt_obj_term *t, const int *dof, const double *X, double *rhs)
{
    const opt_simplex_term *st = t->self;
    opt_simplices proxy = *st->S;
    if (st->proxy_weight) proxy.weight = (double *)st->proxy_weight; /* read only */
    opt_term term = {&proxy, st->energy};
    opt_proxy_block_fill(&t->blk, &term, dof, X, rhs);
}

static double simplex_max_step(const opt_obj_term *t, const double *X, const double *D)
{
    const opt_simplex_term *st = t->self;
    return opt_max_step(st->S, X, D);
}

/* Whether simplices [lo, hi) are all strictly positively oriented at X
 * (exact predicates). */
static int valid_range(const opt_simplices *S, const double *X, size_t lo, size_t hi)
{
    int d = S->d;
    for (size_t s = lo; s < hi; s++) {
        const int *ix = S->idx + s * (d + 1);
        int ok;
        if (d == 2)
            ok = orient2d(X + 2 * (size_t)ix[0], X + 2 * (size_t)ix[1], X + 2 * (size_t)ix[2]) > 0;
        else /* Shewchuk's orient3d is positive for a negatively oriented tet. */
            ok = orient3d(X + 3 * (size_t)ix[0], X + 3 * (size_t)ix[1], X + 3 * (size_t)ix[2],
                          X + 3 * (size_t)ix[3]) < 0;
        if (!ok) return 0;
    }
    return 1;
}

/* Every simplex strictly positively oriented at X, decided exactly; the
 * chunks in parallel (each says 1 or 0: their minimum). */
typedef struct valid_ctx {
    const opt_simplices *S;
    const double *X;
} valid_ctx;

static double valid_chunk(const void *ctx, size_t lo, size_t hi)
{
    const valid_ctx *c = ctx;
    return valid_range(c->S, c->X, lo, hi);
}

static int simplex_valid(const opt_obj_term *t, const double *X)
{
    const opt_simplex_term *st = t->self;
    valid_ctx c = {st->S, X};
    return par_min((size_t)st->S->n, valid_chunk, &c) > 0.0;
}

/* Newton uses the true weights: a softer proxy weight would change the
 * minimizer's model, not just the step length. */
static scaf_status simplex_hessian_fill(opt_obj_term *t, const int *dof, const double *X,
                                        int project, double *rhs, scaf_error *err)
{
    const opt_simplex_term *st = t->self;
    opt_term term = {st->S, st->energy};
    return opt_newton_block_fill(&t->blk, &term, dof, X, project, rhs, NULL, err);
}

static const opt_obj_term_ops simplex_ops = {
    simplex_energy,   simplex_energy_slope, simplex_pattern,      simplex_fill,
    simplex_max_step, simplex_valid,        simplex_hessian_fill,
};

opt_obj_term opt_simplex_term_make(opt_simplex_term *st)
{
    opt_obj_term t;
    memset(&t, 0, sizeof t);
    t.ops = &simplex_ops;
    t.self = st;
    return t;
}
