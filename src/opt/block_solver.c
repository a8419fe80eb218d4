/* opt/block_solver: the SCAF step's linear solve (see block_solver.h).
 *
 * Built on opt/cholmod_solver, which does the work (CHOLMOD's orderings and
 * analysis, scaf's own symbolic shortcuts and numeric factorization); this
 * file holds the policy that decides what it is asked to do. */
#include "opt/block_solver.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "opt/cholmod_solver.h"

struct opt_block_solver {
    int block;
    size_t nfixed;
    opt_chol *chol;  /* analysis reused while the pattern stays */
    int *fixed_perm; /* nfixed: the fixed part's order, from the first
                            (METIS) ordering; reused */
    int *perm;       /* the permutation given to the next analysis */
    size_t cap_perm;
    const int *given; /* perm, or NULL: the solver's own (AMD) ordering */
    double *rhs;      /* the last factorization's right-hand side */
    int factored;     /* rhs's factorization succeeded */
    double t_order;   /* seconds in the fixed part's ordering */
};

opt_block_solver *opt_block_solver_create(int block, int nfixed, scaf_error *err)
{
    assert(block >= 2 && nfixed >= 0 && nfixed % block == 0);
    opt_block_solver *s = calloc(1, sizeof *s);
    if (!s) {
        err_nomem(err, "block solver");
        return NULL;
    }
    s->block = block;
    s->nfixed = (size_t)nfixed;
    s->chol = opt_chol_create(OPT_ORDER_AMD, err);
    if (!s->chol) {
        free(s);
        return NULL;
    }
    opt_chol_set_block(s->chol, block);
    if (block == 2) {
        /* the mesh's analysis and scatter kept across scaffolds */
        opt_chol_set_fixed_part(s->chol, nfixed);
        opt_chol_set_relax(s->chol, 2); /* factorization + solve fastest (bench_factor) */
    } else {
        opt_chol_set_relax(s->chol, 4);
    }
    return s;
}

void opt_block_solver_destroy(opt_block_solver *s)
{
    if (!s) return;
    opt_chol_destroy(s->chol);
    free(s->fixed_perm);
    free(s->perm);
    free(s);
}

static scaf_status perm_room(opt_block_solver *s, size_t n, scaf_error *err)
{
    if (n <= s->cap_perm) return SCAF_OK;
    int *q = realloc(s->perm, n * sizeof *q);
    if (!q) return err_nomem(err, "ordering");
    s->perm = q;
    s->cap_perm = n;
    return SCAF_OK;
}

/* The first system: METIS on the whole (by vertices); its fixed unknowns'
 * relative order is kept for every later system. */
static scaf_status first_ordering(opt_block_solver *s, const opt_csc *A, scaf_error *err)
{
    size_t n = (size_t)A->n, nm = s->nfixed;
    double t0 = timer_now();
    opt_chol *m = opt_chol_create(OPT_ORDER_METIS, err);
    if (!m) return err && err->code ? err->code : SCAF_ERR_NOMEM;
    opt_chol_set_block(m, s->block); /* order vertices, not scalars */
    scaf_status st = opt_chol_analyze_given(m, A, NULL, err);
    const int *p = opt_chol_permutation(m);
    s->fixed_perm = malloc((nm ? nm : 1) * sizeof *s->fixed_perm);
    scaf_status room = perm_room(s, n, err);
    if (st == SCAF_OK && (!p || !s->fixed_perm || room != SCAF_OK)) st = err_nomem(err, "ordering");
    if (st == SCAF_OK) {
        size_t k = 0;
        for (size_t i = 0; i < n; i++)
            if ((size_t)p[i] < nm) s->fixed_perm[k++] = p[i];
        assert(k == nm);
        memcpy(s->perm, p, n * sizeof *s->perm);
        s->given = s->perm;
    } else {
        free(s->fixed_perm);
        s->fixed_perm = NULL;
    }
    opt_chol_destroy(m);
    s->t_order += timer_now() - t0;
    return st;
}

scaf_status opt_block_solver_update(opt_block_solver *s, const opt_proxy_system *sys,
                                    scaf_error *err)
{
    const opt_csc *A = &sys->A;
    size_t n = (size_t)A->n, nm = s->nfixed;
    assert(n >= nm && n % (size_t)s->block == 0);
    s->factored = 0;
    s->given = NULL;
    if (!s->fixed_perm) return first_ordering(s, A, err);
    size_t nsc = n - nm;
    if (nsc <= 256 || nsc * 50 <= n) { /* few changing unknowns: after the fixed ones */
        scaf_status st = perm_room(s, n, err);
        if (st != SCAF_OK) return st;
        memcpy(s->perm, s->fixed_perm, nm * sizeof *s->perm);
        for (size_t k = nm; k < n; k++) s->perm[k] = (int)k;
        s->given = s->perm;
    }
    return SCAF_OK;
}

/* One factorization of sys->A with the chosen order; an unchanged
 * pattern (late iterations, the boundary barely moving) keeps the
 * analysis. */
static scaf_status factor_once(opt_block_solver *s, opt_proxy_system *sys, scaf_error *err)
{
    if (sys->owns)
        return opt_chol_factor_vertices(s->chol, &sys->A, sys->vcolptr, sys->vrowidx, s->given,
                                        s->rhs, err);
    if (!opt_chol_pattern_matches(s->chol, &sys->A)) {
        scaf_status st =
            opt_chol_analyze_vertices(s->chol, &sys->A, NULL, sys->vrowidx, s->given, err);
        if (st != SCAF_OK) return st;
    }
    return opt_chol_factor_rhs(s->chol, &sys->A, s->rhs, err);
}

/* A + mu diag(A), rhs + mu diag(A) x (positions) for growing mu, after a
 * plain factorization failed. */
static scaf_status regularized(opt_block_solver *s, opt_csc *A, const opt_block_retry *r,
                               scaf_error *err)
{
    size_t n = (size_t)A->n;
    int d = s->block;
    double *d0 = malloc(n * sizeof *d0), *r0 = malloc(n * sizeof *r0);
    int *pos = malloc(n * sizeof *pos);
    if (!d0 || !r0 || !pos) {
        free(d0);
        free(r0);
        free(pos);
        return err_nomem(err, "regularized system");
    }
    for (size_t c = 0; c < n; c++) {
        int e = A->colptr[c + 1] - 1;
        pos[c] = (e >= A->colptr[c] && A->rowidx[e] == (int)c) ? e : -1;
        d0[c] = pos[c] >= 0 ? A->val[e] : 0.0;
    }
    memcpy(r0, s->rhs, n * sizeof *r0);
    scaf_status st = SCAF_ERR_NUMERIC;
    for (double mu = 1e-10; st == SCAF_ERR_NUMERIC && mu < 10.0; mu *= 1000.0) {
        for (size_t c = 0; c < n; c++)
            if (pos[c] >= 0) A->val[pos[c]] = d0[c] * (1.0 + mu);
        for (int v = 0; r->X && v < r->nall; v++)
            if (r->dof[v] >= 0)
                for (int a = 0; a < d; a++) {
                    size_t c = (size_t)d * (size_t)r->dof[v] + a;
                    s->rhs[c] = r0[c] + mu * d0[c] * r->X[(size_t)d * (size_t)v + a];
                }
        err_clear(err);
        st = opt_chol_factor_rhs(s->chol, A, s->rhs, err);
    }
    free(d0);
    free(r0);
    free(pos);
    return st;
}

scaf_status opt_block_solver_factor(opt_block_solver *s, opt_proxy_system *sys, double *rhs,
                                    const opt_block_retry *retry, scaf_error *err)
{
    s->rhs = rhs;
    s->factored = 0;
    scaf_status st = factor_once(s, sys, err);
    if (st == SCAF_ERR_NUMERIC && retry && retry->regularize)
        st = regularized(s, &sys->A, retry, err);
    s->factored = st == SCAF_OK;
    return st;
}

scaf_status opt_block_solver_solve(opt_block_solver *s, double *x, scaf_error *err)
{
    if (!s->factored)
        return err_set(err, SCAF_ERR_USAGE,
                       "block solver: solve without a successful factorization");
    /* the same rhs address as the factorization: only the backward sweep */
    return opt_chol_solve(s->chol, 1, s->rhs, x, err);
}

opt_block_solver_times opt_block_solver_get_times(const opt_block_solver *s)
{
    opt_chol_stats c = opt_chol_get_stats(s->chol);
    return (opt_block_solver_times){c.t_analyze + s->t_order, c.t_factor, c.t_solve};
}

const int *opt_block_solver_fixed_ordering(const opt_block_solver *s) { return s->fixed_perm; }
