/* opt/slim: one SLIM iteration (local proxy, global solve, safe step).
 *
 * Buffers (right-hand side, solution, direction) are kept between calls
 * and grown on demand. Timings are taken with the monotonic clock.
 */
#include "opt/slim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "opt/newton_fill.h"
#include "opt/ordering_reuse.h"

struct opt_slim {
    opt_slim_options o;
    opt_proxy_block blk[OPT_PROXY_MAX_BLOCKS];
    const opt_simplices *blk_of[OPT_PROXY_MAX_BLOCKS];
    opt_proxy_system sys;
    opt_chol *chol;
    double *rhs, *sol, *dir;
    int block_set;   /* solver told the vertex block size */
    int *lead_perm;  /* ordering of term 0's system, reused across patterns */
    int lead_n;
    unsigned lead_version;    /* term 0 block version lead_perm was made for */
    int cap_level;            /* SLIM weight cap level to start from */
    int newton_exact;         /* next Newton step tries the exact Hessian */
    size_t cap_n, cap_x;
};

void opt_slim_options_default(opt_slim_options *o)
{
    o->ordering = OPT_ORDER_AMD;
    opt_ls_options_default(&o->ls);
    o->regularization = 0.0;
    o->block_ordering = 1;
    o->reuse_chart_ordering = 1;
    o->chart_ordering = OPT_ORDER_METIS;
}

opt_slim *opt_slim_create(const opt_slim_options *o, scaf_error *err)
{
    opt_slim *sl = calloc(1, sizeof *sl);
    if (!sl) {
        err_nomem(err, "SLIM context");
        return NULL;
    }
    if (o)
        sl->o = *o;
    else
        opt_slim_options_default(&sl->o);
    sl->chol = opt_chol_create(sl->o.ordering, err);
    if (!sl->chol) {
        free(sl);
        return NULL;
    }
    sl->block_set = 0;
    return sl;
}

void opt_slim_destroy(opt_slim *sl)
{
    if (!sl) return;
    for (int k = 0; k < OPT_PROXY_MAX_BLOCKS; k++) opt_proxy_block_free(&sl->blk[k]);
    opt_proxy_system_free(&sl->sys);
    opt_chol_destroy(sl->chol);
    free(sl->rhs);
    free(sl->sol);
    free(sl->dir);
    free(sl->lead_perm);
    free(sl);
}

const opt_chol *opt_slim_solver(const opt_slim *sl) { return sl->chol; }

int opt_dof_numbering(int nv, const unsigned char *fixed, int *dof)
{
    int k = 0;
    for (int v = 0; v < nv; v++) dof[v] = (fixed && fixed[v]) ? -1 : k++;
    return k;
}

static scaf_status grow(double **p, size_t n, scaf_error *err)
{
    double *q = realloc(*p, (n ? n : 1) * sizeof *q);
    if (!q) return err_nomem(err, "SLIM buffers");
    *p = q;
    return SCAF_OK;
}

/* New summed pattern with several terms: extend term 0's ordering (made
 * once per term-0 pattern) to the whole system and analyse with it. */
static scaf_status analyze_with_chart_ordering(opt_slim *sl, int d, scaf_error *err)
{
    const opt_proxy_block *b0 = &sl->blk[0];
    scaf_status s;
    if (b0->A.n < 1) return SCAF_OK; /* nothing to order: let the solver do it */
    if (!sl->lead_perm || sl->lead_n != b0->A.n || sl->lead_version != b0->version) {
        int *p = realloc(sl->lead_perm, (size_t)b0->A.n * sizeof *p);
        if (!p) return err_nomem(err, "chart ordering");
        sl->lead_perm = p;
        opt_chol *oc = opt_chol_create(sl->o.chart_ordering, err);
        if (!oc) return err ? err->code : SCAF_ERR_NOMEM;
        opt_chol_set_block(oc, sl->o.block_ordering ? d : 1);
        s = opt_chol_compute_ordering(oc, &b0->A, sl->lead_perm, err);
        opt_chol_destroy(oc);
        if (s != SCAF_OK) return s;
        sl->lead_n = b0->A.n;
        sl->lead_version = b0->version;
    }
    int *perm = malloc((size_t)sl->sys.A.n * sizeof *perm);
    if (!perm) return err_nomem(err, "system ordering");
    s = opt_ordering_extend(&sl->sys.A, d, b0->nfree, sl->lead_perm, perm, err);
    if (s == SCAF_OK) s = opt_chol_analyze_given(sl->chol, &sl->sys.A, perm, err);
    free(perm);
    return s;
}

/* Values of the system, summed: SLIM's proxy with squared weights capped
 * at cap, or the Newton Hessian, projected or not (rhs = -gradient). */
static scaf_status fill_values(opt_slim *sl, int newton, int project, const opt_term *terms,
                               int nterms, const int *dof, const double *X, double cap,
                               double *w2max, int *clamped, scaf_error *err)
{
    for (int k = 0; k < nterms; k++) {
        if (newton) {
            opt_newton_fill_stats ns;
            scaf_status s = opt_newton_block_fill(&sl->blk[k], &terms[k], dof, X, project,
                                                  sl->rhs, &ns, err);
            if (s != SCAF_OK) return s;
            *clamped += ns.clamped;
        } else {
            double w = opt_proxy_block_fill_capped(&sl->blk[k], &terms[k], dof, X, sl->rhs, cap);
            if (w > *w2max) *w2max = w;
        }
    }
    return SCAF_OK;
}

static void add_to_diagonal(opt_csc *A, double shift)
{
    for (int c = 0; c < A->n; c++) {
        int e = A->colptr[c + 1] - 1;
        if (e >= A->colptr[c] && A->rowidx[e] == c) A->val[e] += shift;
    }
}

static double max_diagonal(const opt_csc *A)
{
    double m = 0;
    for (int c = 0; c < A->n; c++) {
        int e = A->colptr[c + 1] - 1;
        if (e >= A->colptr[c] && A->rowidx[e] == c && A->val[e] > m) m = A->val[e];
    }
    return m;
}

static scaf_status step(opt_slim *sl, int newton, const opt_term *terms, int nterms,
                        const int *term_changed, int nv, const int *dof, int nfree, double *X,
                        opt_slim_stats *st, scaf_error *err)
{
    const char *who = newton ? "Newton" : "SLIM";
    opt_slim_stats local;
    if (!st) st = &local;
    memset(st, 0, sizeof *st);
    if (nterms < 1 || nterms > OPT_PROXY_MAX_BLOCKS)
        return err_set(err, SCAF_ERR_USAGE, "%s: %d terms (1..%d allowed)", who, nterms,
                       OPT_PROXY_MAX_BLOCKS);
    int d = terms[0].s->d;
    for (int k = 0; k < nterms; k++)
        if (terms[k].s->d != d)
            return err_set(err, SCAF_ERR_USAGE, "%s: term %d has dimension %d, term 0 has %d", who, k,
                           terms[k].s->d, d);
    if (nfree < 1) return err_set(err, SCAF_ERR_USAGE, "%s: no free vertex", who);
    size_t n = (size_t)nfree * d, nx = (size_t)nv * d;
    scaf_status s;
    if (n > sl->cap_n) {
        if ((s = grow(&sl->rhs, n, err)) || (s = grow(&sl->sol, n, err)))
            return s;
        sl->cap_n = n;
    }
    if (nx > sl->cap_x) {
        if ((s = grow(&sl->dir, nx, err))) return s;
        sl->cap_x = nx;
    }
    /* Patterns. */
    double t0 = timer_now();
    for (int k = 0; k < nterms; k++) {
        opt_proxy_block *b = &sl->blk[k];
        int stale = !b->A.colptr || sl->blk_of[k] != terms[k].s || b->ns != terms[k].s->n ||
                    b->d != d || (term_changed && term_changed[k]);
        if (stale) {
            s = opt_proxy_block_pattern(b, terms[k].s, dof, nfree, err);
            if (s != SCAF_OK) return s;
            sl->blk_of[k] = terms[k].s;
            st->blocks_rebuilt++;
        }
    }
    st->t_pattern = timer_now() - t0;
    /* Values, factorization, solve. SLIM: on a numerically indefinite
     * system (extreme SLIM weights) retry with the squared weights capped,
     * tighter each time; the level that worked is kept while it is
     * binding. Newton (level -1): the exact Hessian when the last step was
     * a full one (near a minimum, where it is positive definite and gives
     * quadratic convergence; per-simplex projection alone changes the
     * Hessian AT the minimum of a curved surface and converges only
     * linearly); if it is not positive definite or gives no descent, the
     * projected one (level 0), then with a diagonal shift of 1e-10, 1e-8,
     * ... times its largest diagonal entry (levels 1..). */
    static const double caps[] = {INFINITY, 1e12, 1e9, 1e6, 1e4};
    static const double shifts[] = {0, 1e-10, 1e-8, 1e-6, 1e-4};
    const int ncaps = (int)(sizeof caps / sizeof caps[0]);
    const int nshifts = (int)(sizeof shifts / sizeof shifts[0]);
    const opt_proxy_block *bl[OPT_PROXY_MAX_BLOCKS];
    for (int k = 0; k < nterms; k++) bl[k] = &sl->blk[k];
    if (sl->o.block_ordering && !sl->block_set) {
        opt_chol_set_block(sl->chol, d); /* order the vertex graph: d unknowns per vertex */
        sl->block_set = 1;
    }
    opt_chol_stats c0 = opt_chol_get_stats(sl->chol);
    double t_extend = 0, w2max = 0, shift = 0;
    int level = newton ? (sl->newton_exact ? -1 : 0) : sl->cap_level < ncaps ? sl->cap_level : 0;
    int exact_failed = 0;
    for (;;) {
        double ta = timer_now();
        memset(sl->rhs, 0, n * sizeof *sl->rhs);
        w2max = 0;
        st->clamped = 0;
        s = fill_values(sl, newton, level >= 0, terms, nterms, dof, X,
                        caps[level >= 0 ? level : 0], &w2max, &st->clamped, err);
        if (s != SCAF_OK) return s;
        s = opt_proxy_system_sum(&sl->sys, bl, nterms, err);
        if (s != SCAF_OK) return s;
        if (sl->sys.nfree != nfree)
            return err_set(err, SCAF_ERR_USAGE,
                           "%s: %d free vertices but the simplices use only %d (a free vertex is "
                           "in no simplex: fix it or drop it)", who, nfree, sl->sys.nfree);
        shift = newton && level > 0 ? shifts[level] * max_diagonal(&sl->sys.A) : 0.0;
        if (sl->o.regularization + shift > 0)
            add_to_diagonal(&sl->sys.A, sl->o.regularization + shift);
        st->t_assemble += timer_now() - ta;
        if (sl->o.reuse_chart_ordering && !opt_chol_pattern_matches(sl->chol, &sl->sys.A)) {
            double te = timer_now();
            s = analyze_with_chart_ordering(sl, d, err);
            if (s != SCAF_OK) return s;
            t_extend += timer_now() - te;
        }
        s = opt_chol_factor(sl->chol, &sl->sys.A, err);
        if (s == SCAF_OK) {
            s = opt_chol_solve(sl->chol, 1, sl->rhs, sl->sol, err);
            if (s != SCAF_OK) return s;
            /* rhs = -g: descent iff -g . p > 0. */
            double dec = 0;
            for (size_t k = 0; k < n; k++) dec += sl->rhs[k] * sl->sol[k];
            if (level >= 0 || dec > 0) break;
            s = SCAF_ERR_NUMERIC;
        }
        if (s != SCAF_ERR_NUMERIC) return s;
        if (newton && level < 0) { /* exact Hessian indefinite: project */
            exact_failed = 1;
            level = 0;
            continue;
        }
        if (level + 1 >= (newton ? nshifts : ncaps)) return s;
        level++;
        st->cap_retries++;
    }
    if (newton) {
        st->weight_cap = INFINITY;
        st->shift = shift;
        st->exact = level < 0;
        st->exact_rejected = exact_failed;
    } else {
        st->weight_cap = caps[level];
        st->max_weight2 = w2max;
        sl->cap_level = w2max > caps[level] ? level : 0;
    }
    opt_chol_stats c1 = opt_chol_get_stats(sl->chol);
    st->analyzed = c1.analyses > c0.analyses;
    st->t_analyze = t_extend > 0 ? t_extend : c1.t_analyze - c0.t_analyze;
    st->t_factor = c1.t_factor - c0.t_factor;
    st->t_solve = c1.t_solve - c0.t_solve;
    /* Direction and line search. */
    double t4 = timer_now();
    for (int v = 0; v < nv; v++)
        for (int a = 0; a < d; a++)
            sl->dir[(size_t)v * d + a] =
                dof[v] < 0 ? 0.0
                : newton   ? sl->sol[(size_t)dof[v] * d + a]
                           : sl->sol[(size_t)dof[v] * d + a] - X[(size_t)v * d + a];
    s = opt_line_search(terms, nterms, d, nv, X, sl->dir, &sl->o.ls, &st->ls, err);
    st->t_line_search = timer_now() - t4;
    /* Next Newton step: try the exact Hessian after a full step, unless it
     * just failed (then one projected step first). */
    sl->newton_exact = s == SCAF_OK && st->ls.step >= sl->o.ls.max_step && !exact_failed;
    return s;
}

scaf_status opt_slim_step(opt_slim *sl, const opt_term *terms, int nterms,
                          const int *term_changed, int nv, const int *dof, int nfree, double *X,
                          opt_slim_stats *st, scaf_error *err)
{
    return step(sl, 0, terms, nterms, term_changed, nv, dof, nfree, X, st, err);
}

scaf_status opt_newton_step(opt_slim *sl, const opt_term *terms, int nterms,
                            const int *term_changed, int nv, const int *dof, int nfree, double *X,
                            opt_slim_stats *st, scaf_error *err)
{
    return step(sl, 1, terms, nterms, term_changed, nv, dof, nfree, X, st, err);
}
