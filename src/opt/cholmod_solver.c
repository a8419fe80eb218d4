/* opt/cholmod_solver: sparse Cholesky (CHOLMOD, supernodal) with reuse.
 *
 * The analyzed pattern is copied so a later matrix can be compared
 * exactly, by vertices when the caller gives it so (a quarter of the
 * reads in 2D: by scalars, the copy and the compares of each iteration
 * took 1.5 ms of aphrodite's 3 ms analysis). CHOLMOD's own printing is
 * switched off: failures come back as scaf_error messages.
 *
 * With a given permutation the symbolic analysis runs CHOLMOD's own steps
 * (etree, column counts, weighted postorder, supernodes) on matrices built
 * here with three passes instead of cholmod_analyze_p's four transposes;
 * the factor it produces is the same (opt/given_symbolic). With unknowns
 * in vertex blocks the analysis runs on the vertex graph and is expanded
 * (opt/block_symbolic); a declared fixed leading part keeps its analysis
 * across patterns (opt/split_symbolic).
 *
 * The numerical factorization is opt/supernodal_numeric's (subtrees in
 * parallel threads, no transpose of A per factorization) on CHOLMOD's
 * symbolic factor, written into CHOLMOD's L so cholmod_solve2 solves with
 * it; opt_chol_set_numeric switches back to cholmod_factorize (bench,
 * tests: the two factors agree to rounding).
 *
 * OpenMP: the Debian CHOLMOD runs small loops of its supernodal
 * factorization (zeroing and scattering each supernode) in OpenMP regions
 * with a compiled-in team of 4 threads, whatever OMP_NUM_THREADS says. On a
 * 2-core machine that oversubscription costs more than the loops (measured:
 * 30-40% of the process CPU time of an iteration went to spinning and
 * futex calls, aphrodite.obj). The loops only move data (no sums), so the
 * factor is bit-identical with any team size: the CHOLMOD calls run with
 * OpenMP's max-active-levels at 0 (every region gets one thread) and the
 * previous value is restored afterwards. In libgomp (OpenMP 5) that value
 * belongs to the calling thread's data environment, so threads factoring
 * at once, or the user's own OpenMP code in other threads, are not
 * affected (tests/opt/test_cholmod_solver.c: concurrent_factorizations). The dense work stays in BLAS,
 * whose threads OpenBLAS controls. libgomp is reached through weak
 * references (it is loaded by CHOLMOD), so nothing changes when it is
 * absent. scaf's own threads (base/parallel) are POSIX threads, outside
 * libgomp, and never run while CHOLMOD does (the loops that use them
 * return before a factorization starts).
 */
#include "opt/cholmod_solver.h"

#include "opt/block_symbolic.h"
#include "opt/blas_threads.h"
#include "opt/cholmod_view.h"
#include "opt/given_symbolic.h"
#include "opt/split_symbolic.h"
#include "opt/supernodal_numeric.h"
#include "opt/supernodal_solve.h"

#include <assert.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include <cholmod.h>

#include "base/interrupt.h"
#include "base/parallel.h"
#include "base/timer.h"

/* libgomp, if loaded (see the banner). */
extern int omp_get_max_active_levels(void) __attribute__((weak));
extern void omp_set_max_active_levels(int) __attribute__((weak));

/* Serialize CHOLMOD's OpenMP regions; returns the level to restore. */
static int omp_serial_begin(void)
{
    if (!omp_get_max_active_levels || !omp_set_max_active_levels) return -1;
    int old = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
    return old;
}

static void omp_serial_end(int old)
{
    if (old >= 0 && omp_set_max_active_levels) omp_set_max_active_levels(old);
}

struct opt_chol {
    cholmod_common cm;
    cholmod_factor *L;
    opt_ordering ordering;
    int n, nnz; /* analyzed pattern: A's size and entries */
    /* the analyzed pattern: A's (pblock 1) or its pattern by vertices of
     * pblock unknowns (opt_chol_factor_vertices); arrays of cap_* ints */
    int pblock;
    int *colptr, *rowidx;
    size_t cap_colptr, cap_rowidx;
    int factored;              /* L holds a valid numerical factor */
    cholmod_dense *X, *Y, *E;  /* cholmod_solve2's result and workspaces, kept */
    int block;                 /* unknowns per vertex for compressed ordering */
    int last_n;                /* unknowns of the last analysis asked for (messages) */
    int nfixed;                /* leading unknowns of a fixed pattern and order */
    opt_split_symbolic *split; /* their analysis, kept (opt/split_symbolic) */
    long split_made_at;        /* fixed_pattern when split was made */
    opt_snum *snum;            /* numerical factorization plan for L (opt/supernodal_numeric) */
    opt_snum_kept *kept;       /* its fixed part's scatter of A, kept across plans */
    long fixed_pattern;        /* changes of the fixed part's pattern between analyses */
    int own_numeric;           /* factor with opt/supernodal_numeric, not cholmod_factorize */
    double *xbuf;              /* its factor's values, kept across analyses (see free_factor) */
    size_t xcap;               /* doubles in xbuf */
    const double *fwd_b;       /* the right-hand side whose forward sweep the plan holds */
    int fwd_valid;             /* fwd_b's forward sweep is done (opt_chol_factor_rhs) */
    opt_chol_stats st;
};

static void set_ordering(opt_chol *c, opt_ordering ord)
{
    cholmod_common *cm = &c->cm;
    if (ord == OPT_ORDER_CHOLMOD_DEFAULT) {
        cm->nmethods = 0;
        return;
    }
    cm->nmethods = 1;
    cm->method[0].ordering = ord == OPT_ORDER_METIS ? CHOLMOD_METIS : CHOLMOD_AMD;
    cm->postorder = 1;
}

opt_chol *opt_chol_create(opt_ordering ordering, scaf_error *err)
{
    opt_chol *c = calloc(1, sizeof *c);
    if (!c) {
        err_nomem(err, "CHOLMOD solver");
        return NULL;
    }
    if (!cholmod_start(&c->cm)) {
        free(c);
        err_set(err, SCAF_ERR_NUMERIC, "CHOLMOD could not start");
        return NULL;
    }
    c->cm.print = 0;
    c->cm.error_handler = NULL;
    c->cm.supernodal = CHOLMOD_SUPERNODAL;
    c->cm.final_ll = 1; /* keep L L^T (not LDL^T) after a supernodal factorization */
    c->ordering = ordering;
    c->block = 1;
    c->own_numeric = 1;
    set_ordering(c, ordering);
    return c;
}

void opt_chol_set_block(opt_chol *c, int block) { c->block = block > 1 ? block : 1; }

void opt_chol_set_numeric(opt_chol *c, opt_numeric numeric)
{
    c->own_numeric = numeric == OPT_NUMERIC_SUPERNODAL;
    opt_snum_destroy(c->snum);
    c->snum = NULL;
    c->fwd_valid = 0;
}

void opt_chol_set_fixed_part(opt_chol *c, int nfixed) { c->nfixed = nfixed > 0 ? nfixed : 0; }

void opt_chol_set_relax(opt_chol *c, int scale)
{
    static const size_t base[3] = {4, 16, 48}; /* CHOLMOD's defaults */
    if (scale < 1) scale = 1;
    for (int k = 0; k < 3; k++) c->cm.nrelax[k] = base[k] * (size_t)scale;
}

/* Fill-reducing permutation of the vertex graph G (nb vertices): pv. */
static int graph_ordering(opt_chol *c, int nb, int *cp, int *ri, int *pv)
{
    cholmod_sparse G = opt_cholmod_pattern_view(nb, cp, ri, 1);
    return c->ordering == OPT_ORDER_METIS ? cholmod_metis(&G, NULL, 0, 1, pv, &c->cm)
                                          : cholmod_amd(&G, NULL, 0, pv, &c->cm);
}

/* Fill-reducing permutation of A computed on its vertex graph
 * (opt/block_symbolic) and expanded. perm: n. */
static int block_ordering(opt_chol *c, const opt_csc *A, int *perm)
{
    int b = c->block, nb = A->n / b;
    int *cp = NULL, *ri = NULL;
    int *pv = malloc(((size_t)nb + 1) * sizeof *pv);
    int ok = pv && opt_block_graph(A, b, &cp, &ri) && graph_ordering(c, nb, cp, ri, pv);
    if (ok)
        for (int k = 0; k < nb; k++)
            for (int a = 0; a < b; a++) perm[k * b + a] = pv[k] * b + a;
    free(cp);
    free(ri);
    free(pv);
    return ok;
}

/* Free L; values lent from xbuf are taken back first, so that the next
 * analysis's factor reuses memory already mapped: a new array of the
 * factor's size (hundreds of MB at a million faces) comes fresh from mmap
 * and page-faults on first touch, which cost a quarter of an iteration's
 * CPU time on 1.77M faces (bench/RESULTS-param.md). */
static void free_factor(opt_chol *c)
{
    if (!c->L) return;
    if (c->xbuf && c->L->x == c->xbuf) {
        c->L->x = NULL;
        c->L->xtype = CHOLMOD_PATTERN;
    }
    cholmod_free_factor(&c->L, &c->cm);
}

/* Make the symbolic supernodal L numeric (real, L L^T) with xbuf's
 * memory, grown when too small; 0 when out of memory. */
static int lend_values(opt_chol *c)
{
    cholmod_factor *L = c->L;
    size_t need = L->xsize > 0 ? L->xsize : 1;
    if (need > c->xcap) {
        /* With slack: the scaffold's share varies, and SCAF's first factor
         * (the whole system in one METIS order) is smaller than the next
         * ones (mesh first, scaffold last): 1.77M faces, 201.9M -> 213.2M
         * values. A new buffer page-faults on every page it touches, so
         * the first one gets 1/8 more (untouched pages cost no memory):
         * that run, 4 iterations, 30.2 -> 26.5 s wall, 6.8 -> 2.9 s of
         * system time, peak RSS 4.24 -> 3.03 GB. */
        free(c->xbuf);
        size_t cap = need + need / (c->xcap ? 32 : 8);
        c->xbuf = malloc(cap * sizeof *c->xbuf);
        c->xcap = c->xbuf ? cap : 0;
        if (!c->xbuf) return 0;
    }
    L->x = c->xbuf;
    L->xtype = CHOLMOD_REAL;
    L->is_ll = 1;
    L->minor = L->n;
    return 1;
}

void opt_chol_destroy(opt_chol *c)
{
    if (!c) return;
    free_factor(c);
    free(c->xbuf);
    opt_snum_destroy(c->snum);
    opt_snum_kept_destroy(c->kept);
    opt_split_destroy(c->split);
    cholmod_free_dense(&c->X, &c->cm);
    cholmod_free_dense(&c->Y, &c->cm);
    cholmod_free_dense(&c->E, &c->cm);
    cholmod_finish(&c->cm);
    free(c->colptr);
    free(c->rowidx);
    free(c);
}

static const char *status_text(int status)
{
    switch (status) {
    case CHOLMOD_OK: return "ok";
    case CHOLMOD_NOT_INSTALLED: return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY: return "out of memory";
    case CHOLMOD_TOO_LARGE: return "problem too large";
    case CHOLMOD_INVALID: return "invalid input";
    case CHOLMOD_GPU_PROBLEM: return "GPU problem";
    case CHOLMOD_NOT_POSDEF: return "matrix not positive definite";
    case CHOLMOD_DSMALL: return "diagonal of the factor very small";
    }
    return "unknown CHOLMOD status";
}

scaf_status opt_chol_size_check(double n, double entries, scaf_error *err)
{
    if (n <= OPT_CHOL_INDEX_MAX && entries <= OPT_CHOL_INDEX_MAX) return SCAF_OK;
    return err_set(err, SCAF_ERR_MESH,
                   "the problem is too large for the solver: %.0f unknowns and %.0f matrix "
                   "entries, more than its 32-bit indices hold (%d); split the input",
                   n, entries, OPT_CHOL_INDEX_MAX);
}

static scaf_status fail(opt_chol *c, const char *what, scaf_error *err)
{
    int s = c->cm.status;
    if (s == CHOLMOD_OUT_OF_MEMORY) return err_nomem(err, what);
    if (s == CHOLMOD_TOO_LARGE) /* a limit of the solver, not a numerical failure */
        return err_set(err, SCAF_ERR_MESH,
                       "the problem is too large for the solver: the factor of %d unknowns "
                       "needs more entries than its 32-bit indices hold (%d); split the input "
                       "(CHOLMOD %s)",
                       c->last_n, OPT_CHOL_INDEX_MAX, what);
    return err_set(err, SCAF_ERR_NUMERIC, "CHOLMOD %s failed: %s (status %d)", what, status_text(s),
                   s);
}

static int same_pattern(const opt_chol *c, const opt_csc *A)
{
    if (!c->L || c->n != A->n || c->nnz != A->nnz) return 0;
    if (c->pblock > 1)
        return opt_csc_is_vertex_expansion(A, c->pblock, A->n / c->pblock, c->colptr, c->rowidx);
    return memcmp(c->colptr, A->colptr, ((size_t)A->n + 1) * sizeof *A->colptr) == 0 &&
        memcmp(c->rowidx, A->rowidx, (size_t)A->nnz * sizeof *A->rowidx) == 0;
}

/* same_pattern for A given by vertices (vcp, vri): a quarter of the
 * reads when the kept pattern is by vertices too (2D). */
static int same_vertex_pattern(const opt_chol *c, const opt_csc *A, const int *vcp, const int *vri)
{
    if (c->pblock != c->block) return same_pattern(c, A);
    int nb = A->n / c->block;
    return c->L && c->n == A->n && c->nnz == A->nnz &&
        memcmp(c->colptr, vcp, ((size_t)nb + 1) * sizeof *vcp) == 0 &&
        memcmp(c->rowidx, vri, (size_t)vcp[nb] * sizeof *vri) == 0;
}

/* Whether the first nf columns of A (given by vertices when vcp is not
 * NULL) are those of the kept pattern. */
static int same_fixed_part(const opt_chol *c, const opt_csc *A, const int *vcp, const int *vri,
                           int nf)
{
    if (!(nf > 0 && c->n >= nf && A->n >= nf)) return 0;
    if (c->pblock == 1)
        return memcmp(c->colptr, A->colptr, ((size_t)nf + 1) * sizeof *A->colptr) == 0 &&
            memcmp(c->rowidx, A->rowidx, (size_t)A->colptr[nf] * sizeof *A->rowidx) == 0;
    if (nf % c->pblock) return 0;
    int nfv = nf / c->pblock; /* column J's expansion is made of vertex column J alone */
    if (!vcp || c->pblock != c->block)
        return opt_csc_starts_with_vertex_expansion(A, c->pblock, nfv, c->colptr, c->rowidx);
    return memcmp(c->colptr, vcp, ((size_t)nfv + 1) * sizeof *vcp) == 0 &&
        memcmp(c->rowidx, vri, (size_t)vcp[nfv] * sizeof *vri) == 0;
}

/* Keep cp (n + 1) and ri (cp[n]) as the analyzed pattern, by vertices of
 * pblock unknowns. The arrays grow with slack, so that a scaffold's
 * pattern (a little larger or smaller each iteration) reuses them. */
static int keep_pattern(opt_chol *c, int pblock, int n, const int *cp, const int *ri)
{
    size_t ncp = (size_t)n + 1, nri = (size_t)cp[n] + 1;
    if (ncp > c->cap_colptr) {
        size_t cap = ncp + ncp / 16;
        int *p = realloc(c->colptr, cap * sizeof *p);
        if (!p) return 0;
        c->colptr = p;
        c->cap_colptr = cap;
    }
    if (nri > c->cap_rowidx) {
        size_t cap = nri + nri / 16;
        int *p = realloc(c->rowidx, cap * sizeof *p);
        if (!p) return 0;
        c->rowidx = p;
        c->cap_rowidx = cap;
    }
    memcpy(c->colptr, cp, ncp * sizeof *cp);
    memcpy(c->rowidx, ri, (size_t)cp[n] * sizeof *ri);
    c->pblock = pblock;
    return 1;
}

int opt_chol_pattern_matches(const opt_chol *c, const opt_csc *A) { return same_pattern(c, A); }

/* The symbolic factor from the vertex graph (opt/block_symbolic), for
 * unknowns in blocks of c->block, with the vertex order behind perm or,
 * without perm, the solver's ordering of the vertex graph. The relaxation
 * thresholds count vertex columns there, hence divided by the block size.
 * When the fixed part (opt_chol_set_fixed_part) comes first in perm and
 * the rest in natural order, the fixed part's analysis is kept and reused
 * (opt/split_symbolic; *by_split set). NULL with status OK when perm
 * splits a block (the caller then analyses the scalar pattern), NULL with
 * an error status on failure. */
static cholmod_factor *analyze_blocks(opt_chol *c, const opt_csc *A, const int *vcp, const int *vri,
                                      const int *perm, int *by_split)
{
    cholmod_common *cm = &c->cm;
    int b = c->block, nb = A->n / b;
    int *cp = NULL, *ri = NULL, *pv = malloc(((size_t)nb + 1) * sizeof *pv);
    cholmod_factor *Lv = NULL, *L = NULL;
    if (vcp) { /* the caller's vertex pattern: read only */
        cp = (int *)vcp;
        ri = (int *)vri;
    }
    if (!pv || (!vcp && !opt_block_graph(A, b, &cp, &ri))) {
        cm->status = CHOLMOD_OUT_OF_MEMORY;
        goto done;
    }
    if (perm ? !opt_block_perm_compress(A->n, b, perm, pv) : !graph_ordering(c, nb, cp, ri, pv))
        goto done;
    size_t relax[3];
    for (int k = 0; k < 3; k++) {
        relax[k] = cm->nrelax[k];
        cm->nrelax[k] = (relax[k] + (size_t)b - 1) / (size_t)b;
    }
    /* a fixed leading part in its own order, the rest in natural order:
     * the fixed part's analysis is kept (opt/split_symbolic) */
    int nfv = c->nfixed / b, split = perm && c->nfixed % b == 0 && nfv > 0 && nfv < nb;
    for (int k = nfv; k < nb && split; k++) split = pv[k] == k;
    /* the fixed part's pattern unchanged since split was made (each
     * analysis compares it with the last one's) */
    int known = c->split && c->fixed_pattern == c->split_made_at;
    if (split && !opt_split_matches(c->split, nfv, cp, ri, pv, known)) {
        opt_split_destroy(c->split);
        c->split = opt_split_create(cm, nfv, cp, ri, pv);
        c->split_made_at = c->fixed_pattern;
        split = c->split != NULL;
    }
    if (split) {
        Lv = opt_split_factor(c->split, cm, nb, cp, ri);
        *by_split = Lv != NULL;
    } else if (cm->status == CHOLMOD_OK) {
        Lv = opt_given_symbolic(cm, nb, cp, ri, pv);
    }
    for (int k = 0; k < 3; k++) cm->nrelax[k] = relax[k];
    if (Lv) L = opt_block_expand_symbolic(Lv, b, cm);
done:
    if (Lv) cholmod_free_factor(&Lv, cm);
    if (!vcp) {
        free(cp);
        free(ri);
    }
    free(pv);
    return L;
}

scaf_status opt_chol_analyze_given(opt_chol *c, const opt_csc *A, const int *perm, scaf_error *err)
{
    return opt_chol_analyze_vertices(c, A, NULL, NULL, perm, err);
}

scaf_status opt_chol_analyze_vertices(opt_chol *c, const opt_csc *A, const int *vcolptr,
                                      const int *vrowidx, const int *perm, scaf_error *err)
{
    if (A->n < 1) return err_set(err, SCAF_ERR_USAGE, "CHOLMOD: empty system (no free unknowns)");
    /* CHOLMOD is told the columns are sorted upper ones (no copy, no check) */
    assert(opt_csc_is_upper_sorted(A));
    /* the analysis of a large system takes seconds (METIS, etree, counts):
     * a pending SIGINT / SIGTERM stops it before and after */
    scaf_status sig = interrupt_check("analysis", "analysing the system", err);
    if (sig != SCAF_OK) return sig;
    c->last_n = A->n;
    if ((sig = opt_chol_size_check(A->n, (double)A->nnz, err)) != SCAF_OK) return sig;
    double t0 = timer_now();
    /* the fixed part's pattern (its columns) against the last analysis's */
    int bv = vcolptr && c->block > 1 && A->n % c->block == 0; /* keep it by vertices */
    if (!same_fixed_part(c, A, bv ? vcolptr : NULL, vrowidx, c->nfixed)) c->fixed_pattern++;
    free_factor(c);
    opt_snum_destroy(c->snum);
    c->snum = NULL;
    c->factored = 0;
    c->fwd_valid = 0;
    c->n = c->nnz = 0;
    cholmod_sparse S = opt_csc_cholmod_view(A);
    int lv = omp_serial_begin();
    c->cm.status = CHOLMOD_OK;
    /* the solver is supernodal (opt_chol_create) */
    int by_split = 0;
    if (c->block > 1 && A->n % c->block == 0 && (perm || c->ordering != OPT_ORDER_CHOLMOD_DEFAULT))
        c->L = analyze_blocks(c, A, vcolptr, vrowidx, perm, &by_split);
    int by_blocks = c->L != NULL;
    if (c->L || c->cm.status != CHOLMOD_OK) {
        /* done by blocks, or failed */
    } else if (perm) {
        /* A given permutation: use it as the only method. */
        int save_n = c->cm.nmethods, save_ord = c->cm.method[0].ordering;
        c->cm.nmethods = 1;
        c->cm.method[0].ordering = CHOLMOD_GIVEN;
        c->cm.status = CHOLMOD_OK;
        c->L = opt_given_symbolic(&c->cm, A->n, A->colptr, A->rowidx, perm);
        if (!c->L && c->cm.status == CHOLMOD_OK)
            c->L = cholmod_analyze_p(&S, (int *)perm, NULL, 0, &c->cm);
        c->cm.nmethods = save_n;
        c->cm.method[0].ordering = save_ord;
    } else {
        c->L = cholmod_analyze(&S, &c->cm);
    }
    omp_serial_end(lv);
    if (!c->L) return fail(c, "analysis", err);
    if ((sig = interrupt_check(NULL, "analysing the system", err)) != SCAF_OK) {
        free_factor(c);
        return sig;
    }
    if (!(bv ? keep_pattern(c, c->block, A->n / c->block, vcolptr, vrowidx)
             : keep_pattern(c, 1, A->n, A->colptr, A->rowidx))) {
        free_factor(c); /* no pattern to compare a later A with */
        return err_nomem(err, "CHOLMOD pattern copy");
    }
    c->n = A->n;
    c->nnz = A->nnz;
    c->st.analyses++;
    c->st.block_analyses += by_blocks;
    c->st.split_analyses += by_split;
    c->st.t_analyze += timer_now() - t0;
    return SCAF_OK;
}

scaf_status opt_chol_compute_ordering(opt_chol *c, const opt_csc *A, int *perm, scaf_error *err)
{
    if (A->n < 1) return err_set(err, SCAF_ERR_USAGE, "CHOLMOD: empty system (no free unknowns)");
    if (c->block > 1 && A->n % c->block == 0 && c->ordering != OPT_ORDER_CHOLMOD_DEFAULT)
        return block_ordering(c, A, perm) ? SCAF_OK : fail(c, "block ordering", err);
    cholmod_sparse S = opt_csc_cholmod_view(A);
    int ok = c->ordering == OPT_ORDER_METIS ? cholmod_metis(&S, NULL, 0, 1, perm, &c->cm)
                                            : cholmod_amd(&S, NULL, 0, perm, &c->cm);
    return ok ? SCAF_OK : fail(c, "ordering", err);
}

static atomic_long not_posdef_total;

long opt_chol_not_posdef_total(void) { return atomic_load(&not_posdef_total); }

scaf_status opt_chol_factor(opt_chol *c, const opt_csc *A, scaf_error *err)
{
    return opt_chol_factor_rhs(c, A, NULL, err);
}

static scaf_status factor_numeric(opt_chol *c, const opt_csc *A, const double *b, scaf_error *err);

scaf_status opt_chol_factor_rhs(opt_chol *c, const opt_csc *A, const double *b, scaf_error *err)
{
    c->fwd_valid = 0;
    if (!same_pattern(c, A)) {
        scaf_status st = opt_chol_analyze_given(c, A, NULL, err);
        if (st != SCAF_OK) return st;
    }
    return factor_numeric(c, A, b, err);
}

scaf_status opt_chol_factor_vertices(opt_chol *c, const opt_csc *A, const int *vcolptr,
                                     const int *vrowidx, const int *perm, const double *b,
                                     scaf_error *err)
{
    c->fwd_valid = 0;
    assert(c->block > 1 && A->n % c->block == 0 &&
           opt_csc_is_vertex_expansion(A, c->block, A->n / c->block, vcolptr, vrowidx));
    if (!same_vertex_pattern(c, A, vcolptr, vrowidx)) {
        scaf_status st = opt_chol_analyze_vertices(c, A, vcolptr, vrowidx, perm, err);
        if (st != SCAF_OK) return st;
    }
    return factor_numeric(c, A, b, err);
}

/* The numerical factorization of A, whose pattern is the analyzed one. */
static scaf_status factor_numeric(opt_chol *c, const opt_csc *A, const double *b, scaf_error *err)
{
    assert(opt_csc_is_upper_sorted(A));
    double t0 = timer_now();
    cholmod_sparse S = opt_csc_cholmod_view(A);
    c->factored = 0;
    int ok;
    if (c->own_numeric && c->L->is_super && !c->snum) {
        /* values for the supernodal L L^T factor, then the plan: one bin
         * per thread of scaf's loops (base/parallel), or, deterministic,
         * OPT_SNUM_BINS whatever the count (the same factor for any; one
         * thread then pays for the cut, bench/RESULTS-param.md session
         * 16); without a plan (out of memory) cholmod_factorize does the
         * work */
        if (c->L->xtype == CHOLMOD_PATTERN) lend_values(c);
        int bins = opt_deterministic() ? OPT_SNUM_BINS : par_threads();
        if (c->L->xtype == CHOLMOD_REAL && c->L->is_ll)
            c->snum = opt_snum_create_kept(c->L, A, bins, c->nfixed, c->fixed_pattern, &c->kept);
        if (c->snum) c->st.kept_scatters += c->snum->kept_reused;
    }
    if (c->snum) {
        c->cm.status = CHOLMOD_OK;
        ok = 1;
        int minor =
            b ? opt_snum_factor_forward(c->snum, A, c->L, b) : opt_snum_factor(c->snum, A, c->L);
        if (minor >= 0) c->cm.status = CHOLMOD_NOT_POSDEF;
        c->fwd_valid = minor < 0 && b;
        c->fwd_b = b;
    } else {
        /* BLAS in one thread: OpenBLAS's dpotrf cuts its blocks by its
         * thread count, which would change the factor with it */
        int lv = omp_serial_begin(), blas = opt_blas_serial_begin();
        ok = cholmod_factorize(&S, c->L, &c->cm);
        opt_blas_serial_end(blas);
        omp_serial_end(lv);
    }
    c->st.t_factor += timer_now() - t0;
    if (!ok) return fail(c, "factorization", err);
    if (c->cm.status == CHOLMOD_NOT_POSDEF || c->L->minor < c->L->n) {
        c->st.not_posdef++;
        atomic_fetch_add(&not_posdef_total, 1);
        return err_set(err, SCAF_ERR_NUMERIC,
                       "CHOLMOD factorization: matrix not positive definite (fails at column %d of "
                       "%d after reordering; a free vertex may be unconstrained or a weight "
                       "negative)",
                       (int)c->L->minor, (int)c->L->n);
    }
    c->factored = 1;
    c->st.factorizations++;
    c->st.nnz_L = c->cm.lnz;
    c->st.flops = c->cm.fl;
    return SCAF_OK;
}

scaf_status opt_chol_solve(opt_chol *c, int nrhs, const double *B, double *X, scaf_error *err)
{
    if (!c->factored)
        return err_set(err, SCAF_ERR_USAGE,
                       "CHOLMOD solve called before a successful factorization");
    if (nrhs < 1) return err_set(err, SCAF_ERR_USAGE, "CHOLMOD solve: %d right-hand sides", nrhs);
    double t0 = timer_now();
    if (c->snum && c->fwd_valid && nrhs == 1 && B == c->fwd_b) {
        opt_snum_backward(c->snum, c->L, X); /* the forward sweep ran in the factorization */
    } else if (c->snum) {
        opt_snum_solve(c->snum, c->L, nrhs, B, X);
    } else {
        cholmod_dense Bd;
        memset(&Bd, 0, sizeof Bd);
        Bd.nrow = (size_t)c->n;
        Bd.ncol = (size_t)nrhs;
        Bd.nzmax = Bd.nrow * Bd.ncol;
        Bd.d = Bd.nrow;
        Bd.x = (void *)B;
        Bd.xtype = CHOLMOD_REAL;
        Bd.dtype = CHOLMOD_DOUBLE;
        int lv = omp_serial_begin(), blas = opt_blas_serial_begin();
        /* cholmod_solve2 (what cholmod_solve calls) with the result and its
         * workspaces kept between solves instead of allocated each time */
        int ok = cholmod_solve2(CHOLMOD_A, c->L, &Bd, NULL, &c->X, NULL, &c->Y, &c->E, &c->cm);
        opt_blas_serial_end(blas);
        omp_serial_end(lv);
        if (!ok) return fail(c, "solve", err);
        memcpy(X, c->X->x, Bd.nzmax * sizeof *X);
    }
    c->fwd_valid = 0; /* the sweeps overwrote the plan's vector */
    c->st.t_solve += timer_now() - t0;
    return SCAF_OK;
}

const int *opt_chol_permutation(const opt_chol *c) { return c->L ? (const int *)c->L->Perm : NULL; }

opt_chol_stats opt_chol_get_stats(const opt_chol *c) { return c->st; }
