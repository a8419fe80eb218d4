/* opt/supernodal_numeric: see supernodal_numeric.h.
 *
 * Supernode s holds columns [super[s], super[s+1]) of the factor as a
 * dense column-major block of nsrow x nscol values at x + px[s]; its row
 * indices are s[pi[s] .. pi[s+1]), its own columns first, then the rows
 * below, ascending. Left-looking: before s is factored, every supernode d
 * with rows in s's columns (a descendant) subtracts its contribution
 * C = L_d(rows >= s's first, :) L_d(rows in s, :)^T, then s is factored
 * (dpotrf on its diagonal block, dtrsm below it). Each descendant waits
 * in a linked list on the next supernode it updates (head / next), with
 * lpos its first row not yet used. */
#define _GNU_SOURCE /* qsort_r */
#include "opt/supernodal_numeric.h"

#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

void dsyrk_(const char *uplo, const char *trans, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *beta, double *c, const int *ldc);
void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k,
            const double *alpha, const double *a, const int *lda, const double *b, const int *ldb,
            const double *beta, double *c, const int *ldc);
void dtrsm_(const char *side, const char *uplo, const char *transa, const char *diag, const int *m,
            const int *n, const double *alpha, const double *a, const int *lda, double *b,
            const int *ldb);
void dtrsv_(const char *uplo, const char *trans, const char *diag, const int *n, const double *a,
            const int *lda, double *x, const int *incx);
void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
            const int *lda, const double *x, const int *incx, const double *beta, double *y,
            const int *incy);
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);

/* OpenBLAS, if it is the BLAS (weak: another BLAS simply keeps its setting) */
extern void openblas_set_num_threads(int) __attribute__((weak));
extern int openblas_get_num_threads(void) __attribute__((weak));

typedef struct worker {
    int *map;    /* row -> its place in the supernode being factored */
    int *rel;    /* a descendant's rows -> places in that supernode */
    double *C;   /* a descendant's update */
    int *head;   /* descendants waiting on each supernode */
    int minor;   /* first column found not positive definite, or -1 */
    double *tmp; /* solve: a supernode's rows below its diagonal block */
    double *acc; /* solve: this bin's updates of the rows above the cut */
} worker;

struct opt_snum {
    int n, nsuper, threads;
    const int *super, *pi, *px, *s; /* L's structure (not owned) */
    int *col2super;                 /* n */
    int *next, *lpos;               /* nsuper */
    int *aptr, *asrc, *adst;        /* A's entries by supernode: value index, place in the block */
    int *order, *bptr; /* bin k: order[bptr[k] .. bptr[k+1]); the rest: above the cut */
    int *toprow;       /* n: a row's index among the rows above the cut, or -1 */
    int ntop;          /* rows above the cut */
    double *y;         /* n: the solve's vector, in the factor's order */
    worker *w;         /* threads */
};

static const double one = 1.0, zero = 0.0, minus_one = -1.0;
static const int inc1 = 1;

/* Supernodes above the cut with at least this many stored entries get the
 * threads (a par_run costs tens of microseconds). */
#define TOP_PARALLEL_MIN 16384.0

void opt_snum_destroy(opt_snum *P)
{
    if (!P) return;
    if (P->w)
        for (int k = 0; k < P->threads; k++) {
            free(P->w[k].map);
            free(P->w[k].rel);
            free(P->w[k].C);
            free(P->w[k].head);
            free(P->w[k].tmp);
            free(P->w[k].acc);
        }
    free(P->w);
    free(P->col2super);
    free(P->toprow);
    free(P->y);
    free(P->next);
    free(P->lpos);
    free(P->aptr);
    free(P->asrc);
    free(P->adst);
    free(P->order);
    free(P->bptr);
    free(P);
}

/* A's entries grouped by the supernode whose block holds them (aptr,
 * asrc, adst): counted and bucketed by column chunks (chunk k's entries
 * of a supernode after chunk k-1's: the serial order), with the entry's
 * column within the supernode and its row, then placed supernode by
 * supernode through a row -> place map. */
typedef struct scatter_job {
    opt_snum *P;
    const opt_csc *A;
    const int *pinv;
    int nc;     /* chunks */
    int *cnt;   /* nc x nsuper: entries per chunk and supernode, then fill positions */
    int *colin; /* per entry: its column within the supernode */
    int **map;  /* per chunk: row -> place */
    int *bad;   /* per chunk: an entry outside L's structure */
} scatter_job;

static void scatter_count(void *ctx, int k)
{
    scatter_job *J = ctx;
    const opt_snum *P = J->P;
    const opt_csc *A = J->A;
    int *cnt = J->cnt + (size_t)k * (size_t)P->nsuper;
    int c0 = (int)par_chunk_begin((size_t)P->n, J->nc, k);
    int c1 = (int)par_chunk_begin((size_t)P->n, J->nc, k + 1);
    for (int c = c0; c < c1; c++) {
        int b = J->pinv[c];
        for (int e = A->colptr[c]; e < A->colptr[c + 1]; e++) {
            int a = J->pinv[A->rowidx[e]];
            cnt[P->col2super[a < b ? a : b]]++;
        }
    }
}

static void scatter_bucket(void *ctx, int k)
{
    scatter_job *J = ctx;
    opt_snum *P = J->P;
    const opt_csc *A = J->A;
    int *fill = J->cnt + (size_t)k * (size_t)P->nsuper;
    int c0 = (int)par_chunk_begin((size_t)P->n, J->nc, k);
    int c1 = (int)par_chunk_begin((size_t)P->n, J->nc, k + 1);
    for (int c = c0; c < c1; c++) {
        int b = J->pinv[c];
        for (int e = A->colptr[c]; e < A->colptr[c + 1]; e++) {
            int a = J->pinv[A->rowidx[e]];
            int lo = a < b ? a : b, hi = a < b ? b : a, sn = P->col2super[lo];
            int t = fill[sn]++;
            P->asrc[t] = e;
            P->adst[t] = hi; /* the row for now */
            J->colin[t] = lo - P->super[sn];
        }
    }
}

static void scatter_place(void *ctx, int k)
{
    scatter_job *J = ctx;
    opt_snum *P = J->P;
    int *map = J->map[k];
    int s0 = (int)par_chunk_begin((size_t)P->nsuper, J->nc, k);
    int s1 = (int)par_chunk_begin((size_t)P->nsuper, J->nc, k + 1);
    for (int sn = s0; sn < s1; sn++) {
        const int *rows = P->s + P->pi[sn];
        int nsrow = P->pi[sn + 1] - P->pi[sn];
        for (int i = 0; i < nsrow; i++) map[rows[i]] = i;
        for (int t = P->aptr[sn]; t < P->aptr[sn + 1]; t++) {
            int r = P->adst[t], place = map[r];
            if (place < 0 || place >= nsrow || rows[place] != r) J->bad[k] = 1; /* not in L */
            P->adst[t] = J->colin[t] * nsrow + place;
        }
    }
}

/* 0 when A has an entry outside L's structure or memory runs out. */
static int build_scatter(opt_snum *P, const opt_csc *A, const int *perm, int threads)
{
    int n = P->n, ns = P->nsuper, nc = par_chunks((size_t)A->nnz);
    if (nc > threads) nc = threads;
    size_t nz = (size_t)A->nnz + 1;
    int *pinv = malloc((size_t)n * sizeof *pinv);
    int *cnt = calloc((size_t)nc * (size_t)ns + 1, sizeof *cnt);
    int *colin = malloc(nz * sizeof *colin), *bad = calloc((size_t)nc, sizeof *bad);
    int **map = calloc((size_t)nc, sizeof *map);
    P->aptr = calloc((size_t)ns + 1, sizeof *P->aptr);
    P->asrc = malloc(nz * sizeof *P->asrc);
    P->adst = malloc(nz * sizeof *P->adst);
    int ok = pinv && cnt && colin && bad && map && P->aptr && P->asrc && P->adst;
    for (int k = 0; ok && k < nc; k++) {
        map[k] = malloc((size_t)n * sizeof *map[k]);
        ok = map[k] != NULL;
        if (ok)
            for (int i = 0; i < n; i++) map[k][i] = -1;
    }
    for (int k = 0; ok && k < n; k++) pinv[perm[k]] = k;
    scatter_job J = {P, A, pinv, nc, cnt, colin, map, bad};
    if (ok) par_run(nc, scatter_count, &J);
    /* fill positions: supernode by supernode, chunk by chunk */
    for (int sn = 0, t = 0; ok && sn < ns; sn++) {
        P->aptr[sn] = t;
        for (int k = 0; k < nc; k++) {
            int c = cnt[(size_t)k * (size_t)ns + (size_t)sn];
            cnt[(size_t)k * (size_t)ns + (size_t)sn] = t;
            t += c;
        }
        P->aptr[sn + 1] = t;
    }
    if (ok) par_run(nc, scatter_bucket, &J);
    if (ok) par_run(nc, scatter_place, &J);
    for (int k = 0; ok && k < nc; k++) ok = !bad[k];
    for (int k = 0; map && k < nc; k++) free(map[k]);
    free(map);
    free(bad);
    free(colin);
    free(cnt);
    free(pinv);
    return ok;
}

/* Largest update buffer: a descendant's rows from one supernode's range
 * times its rows from there down. */
static size_t max_update(const opt_snum *P)
{
    size_t most = 1;
    for (int d = 0; d < P->nsuper; d++) {
        int nscol = P->super[d + 1] - P->super[d];
        const int *rows = P->s + P->pi[d];
        int nsrow = P->pi[d + 1] - P->pi[d];
        for (int p = nscol; p < nsrow;) {
            int sn = P->col2super[rows[p]], q = p;
            while (q < nsrow && P->col2super[rows[q]] == sn) q++;
            size_t c = (size_t)(q - p) * (size_t)(nsrow - p);
            if (c > most) most = c;
            p = q;
        }
    }
    return most;
}

static int cmp_work_desc(const void *a, const void *b, void *wv)
{
    const double *W = wv;
    double x = W[*(const int *)a], y = W[*(const int *)b];
    if (x != y) return x < y ? 1 : -1;
    return *(const int *)a - *(const int *)b;
}

/* Longest-first assignment of the candidate subtrees to T bins; returns the
 * heaviest bin's work, bin[i] the bin of cand[i] (cand sorted by work). */
static double assign_bins(int *cand, int nc, const double *W, int T, int *bin)
{
    qsort_r(cand, (size_t)nc, sizeof *cand, cmp_work_desc, (void *)W);
    double load[PAR_MAX_CHUNKS] = {0};
    for (int i = 0; i < nc; i++) {
        int best = 0;
        for (int k = 1; k < T; k++)
            if (load[k] < load[best]) best = k;
        load[best] += W[cand[i]];
        bin[i] = best;
    }
    double most = 0;
    for (int k = 0; k < T; k++)
        if (load[k] > most) most = load[k];
    return most;
}

/* Cut the supernodal tree into subtrees for T bins (order, bptr); the
 * supernodes above the cut follow in ascending order. Returns the bins
 * used (1: no cut, everything runs above it). */
static int plan_bins(opt_snum *P, int T)
{
    int ns = P->nsuper;
    P->order = malloc(((size_t)ns + 1) * sizeof *P->order);
    P->bptr = calloc((size_t)T + 2, sizeof *P->bptr);
    if (!P->order || !P->bptr) return 0;
    for (int k = 0; k < ns; k++) P->order[k] = k;
    if (T < 2 || ns < 2 * T) return 1;
    int *parent = malloc((size_t)ns * sizeof *parent), *chead = malloc((size_t)ns * sizeof *chead);
    int *cnext = malloc((size_t)ns * sizeof *cnext), *cand = malloc((size_t)ns * sizeof *cand);
    int *bin = malloc((size_t)ns * sizeof *bin), *owner = malloc((size_t)ns * sizeof *owner);
    double *W = malloc((size_t)ns * sizeof *W);
    int used = 1;
    if (!parent || !chead || !cnext || !cand || !bin || !owner || !W) goto done;
    for (int sn = 0; sn < ns; sn++) {
        int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
        double w = 0;
        for (int c = 0; c < nscol; c++) w += (double)(nsrow - c) * (double)(nsrow - c);
        W[sn] = w;
        chead[sn] = -1;
        parent[sn] = nsrow > nscol ? P->col2super[P->s[P->pi[sn] + nscol]] : -1;
    }
    double total = 0;
    for (int sn = 0; sn < ns; sn++) total += W[sn];
    for (int sn = 0; sn < ns; sn++) {
        int p = parent[sn];
        if (p < 0) continue;
        if (p <= sn) goto done; /* a parent before its child: no cut */
        W[p] += W[sn];
    }
    for (int sn = ns - 1; sn >= 0; sn--)
        if (parent[sn] >= 0) {
            cnext[sn] = chead[parent[sn]];
            chead[parent[sn]] = sn;
        }
    int nc = 0;
    for (int sn = 0; sn < ns; sn++)
        if (parent[sn] < 0) cand[nc++] = sn;
    /* split the heaviest subtree until the bins are within 3% of even, or
     * the work above the cut would pass a quarter of the whole */
    double above = 0;
    for (int iter = 0; iter < ns; iter++) {
        double most = assign_bins(cand, nc, W, T, bin), sum = 0;
        for (int i = 0; i < nc; i++) sum += W[cand[i]];
        if (most <= 1.03 * sum / T) break;
        int i = 0;
        while (i < nc && chead[cand[i]] < 0) i++;
        if (i == nc) break;
        int c = cand[i];
        double own = W[c];
        for (int ch = chead[c]; ch >= 0; ch = cnext[ch]) own -= W[ch];
        if (above + own > 0.5 * total) break;
        above += own;
        cand[i] = cand[--nc];
        for (int ch = chead[c]; ch >= 0; ch = cnext[ch]) cand[nc++] = ch;
    }
    assign_bins(cand, nc, W, T, bin);
    /* a supernode belongs to the bin of its candidate ancestor; parents
     * come after their children, so a descending sweep sees them first */
    for (int sn = 0; sn < ns; sn++) owner[sn] = -2;
    for (int i = 0; i < nc; i++) owner[cand[i]] = bin[i];
    for (int sn = ns - 1; sn >= 0; sn--)
        if (owner[sn] == -2) owner[sn] = parent[sn] >= 0 ? owner[parent[sn]] : -1;
    int pos = 0;
    for (int k = 0; k < T; k++) {
        P->bptr[k] = pos;
        for (int sn = 0; sn < ns; sn++)
            if (owner[sn] == k) P->order[pos++] = sn;
    }
    P->bptr[T] = pos;
    for (int sn = 0; sn < ns; sn++)
        if (owner[sn] < 0) P->order[pos++] = sn;
    used = T;
done:
    if (used == 1) memset(P->bptr, 0, ((size_t)T + 2) * sizeof *P->bptr);
    free(parent);
    free(chead);
    free(cnext);
    free(cand);
    free(bin);
    free(owner);
    free(W);
    return used;
}

opt_snum *opt_snum_create(const cholmod_factor *L, const opt_csc *A, int threads)
{
    if (!L->is_super || L->itype != CHOLMOD_INT || (int)L->n != A->n) return NULL;
    if (threads < 1) threads = 1;
    if (threads > PAR_MAX_CHUNKS) threads = PAR_MAX_CHUNKS;
    opt_snum *P = calloc(1, sizeof *P);
    if (!P) return NULL;
    P->n = A->n;
    P->nsuper = (int)L->nsuper;
    P->super = L->super;
    P->pi = L->pi;
    P->px = L->px;
    P->s = L->s;
    int n = P->n, ns = P->nsuper;
    P->col2super = malloc(((size_t)n + 1) * sizeof *P->col2super);
    P->next = malloc(((size_t)ns + 1) * sizeof *P->next);
    P->lpos = malloc(((size_t)ns + 1) * sizeof *P->lpos);
    if (!P->col2super || !P->next || !P->lpos) goto fail;
    for (int sn = 0; sn < ns; sn++)
        for (int k = P->super[sn]; k < P->super[sn + 1]; k++) P->col2super[k] = sn;
    if (!build_scatter(P, A, L->Perm, threads)) goto fail;
    int T = plan_bins(P, threads);
    if (T < 1) goto fail;
    P->threads = T;
    P->toprow = malloc(((size_t)n + 1) * sizeof *P->toprow);
    P->y = malloc(((size_t)n + 1) * sizeof *P->y);
    if (!P->toprow || !P->y) goto fail;
    for (int k = 0; k < n; k++) P->toprow[k] = -1;
    for (int i = P->bptr[T > 1 ? T : 0]; i < ns && T > 1; i++)
        for (int k = P->super[P->order[i]]; k < P->super[P->order[i] + 1]; k++)
            P->toprow[k] = P->ntop++;
    size_t csize = max_update(P);
    int maxrow = 1;
    for (int sn = 0; sn < ns; sn++)
        if (P->pi[sn + 1] - P->pi[sn] > maxrow) maxrow = P->pi[sn + 1] - P->pi[sn];
    P->w = calloc((size_t)T, sizeof *P->w);
    if (!P->w) goto fail;
    for (int k = 0; k < T; k++) {
        worker *wk = &P->w[k];
        wk->map = malloc(((size_t)n + 1) * sizeof *wk->map);
        wk->rel = malloc((size_t)maxrow * sizeof *wk->rel);
        wk->C = malloc(csize * sizeof *wk->C);
        wk->head = malloc(((size_t)ns + 1) * sizeof *wk->head);
        wk->tmp = malloc((size_t)maxrow * sizeof *wk->tmp);
        wk->acc = malloc(((size_t)P->ntop + 1) * sizeof *wk->acc);
        if (!wk->map || !wk->rel || !wk->C || !wk->head || !wk->tmp || !wk->acc) goto fail;
    }
    return P;
fail:
    opt_snum_destroy(P);
    return NULL;
}

/* Subtract descendant d's update from supernode sn (block X, nsrow rows). */
static void apply_descendant(const opt_snum *P, worker *wk, int d, int sn, const double *Lx,
                             double *X, int nsrow)
{
    int k2 = P->super[sn + 1];
    int ndcol = P->super[d + 1] - P->super[d];
    int pdi = P->pi[d], ndrow = P->pi[d + 1] - pdi;
    const int *rows = P->s + pdi;
    int p1 = P->lpos[d], p2 = p1;
    while (p2 < ndrow && rows[p2] < k2) p2++;
    int ndrow1 = p2 - p1, ndrow2 = ndrow - p1, ndrow3 = ndrow2 - ndrow1;
    const double *Xd = Lx + P->px[d] + p1;
    double *C = wk->C;
    dsyrk_("L", "N", &ndrow1, &ndcol, &one, Xd, &ndrow, &zero, C, &ndrow2);
    if (ndrow3 > 0)
        dgemm_("N", "T", &ndrow3, &ndrow1, &ndcol, &one, Xd + ndrow1, &ndrow, Xd, &ndrow, &zero,
               C + ndrow1, &ndrow2);
    int *rel = wk->rel;
    for (int i = 0; i < ndrow2; i++) rel[i] = wk->map[rows[p1 + i]];
    for (int j = 0; j < ndrow1; j++) {
        double *col = X + (size_t)rel[j] * (size_t)nsrow;
        const double *cj = C + (size_t)j * (size_t)ndrow2;
        for (int i = j; i < ndrow2; i++) col[rel[i]] -= cj[i];
    }
    P->lpos[d] = p2;
}

/* Link d to wait on the supernode of its row at place p (if any). */
static void link_next(const opt_snum *P, int *head, int d, int p)
{
    int ndrow = P->pi[d + 1] - P->pi[d];
    if (p >= ndrow) return;
    int q = P->col2super[P->s[P->pi[d] + p]];
    P->next[d] = head[q];
    head[q] = d;
}

/* Supernode sn's block X: zeroed, then A's entries. */
static void assemble(const opt_snum *P, int sn, const double *Ax, double *X)
{
    int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
    memset(X, 0, (size_t)nsrow * (size_t)nscol * sizeof *X);
    for (int t = P->aptr[sn]; t < P->aptr[sn + 1]; t++) X[P->adst[t]] = Ax[P->asrc[t]];
}

/* Subtract the updates of the descendants waiting on sn in head (into X,
 * sn's block or a block-sized buffer); each is relinked into head. */
static void apply_list(const opt_snum *P, worker *wk, int sn, int *head, const double *Lx,
                       double *X)
{
    int psi = P->pi[sn], nsrow = P->pi[sn + 1] - psi;
    for (int i = 0; i < nsrow; i++) wk->map[P->s[psi + i]] = i;
    int d = head[sn];
    head[sn] = -1;
    while (d >= 0) {
        int dnext = P->next[d];
        apply_descendant(P, wk, d, sn, Lx, X, nsrow);
        link_next(P, head, d, P->lpos[d]);
        d = dnext;
    }
}

/* Factor the diagonal block of sn (dpotrf); -1, or the first column where
 * the matrix is not positive definite. */
static int factor_diagonal(const opt_snum *P, int sn, double *X)
{
    int k1 = P->super[sn], nscol = P->super[sn + 1] - k1, nsrow = P->pi[sn + 1] - P->pi[sn];
    int info = 0;
    dpotrf_("L", &nscol, X, &nsrow, &info);
    return info == 0 ? -1 : k1 + (info > 0 ? info - 1 : 0);
}

/* Rows [r0, r1) of sn's part below its diagonal block: L21 = A21 L11^-T. */
static void solve_below(const opt_snum *P, int sn, double *X, int r0, int r1)
{
    int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
    int m = r1 - r0;
    if (m > 0) dtrsm_("R", "L", "T", "N", &m, &nscol, &one, X, &nsrow, X + nscol + r0, &nsrow);
}

/* sn done: wait on the supernode of its first row below the diagonal. */
static void link_done(const opt_snum *P, int sn, int *head)
{
    int nscol = P->super[sn + 1] - P->super[sn];
    P->lpos[sn] = nscol;
    link_next(P, head, sn, nscol);
}

/* Supernode sn entirely in one thread (descendants from head). */
static int factor_super(const opt_snum *P, worker *wk, int sn, const double *Ax, double *Lx,
                        int *head)
{
    double *X = Lx + P->px[sn];
    assemble(P, sn, Ax, X);
    apply_list(P, wk, sn, head, Lx, X);
    int minor = factor_diagonal(P, sn, X);
    if (minor >= 0) return minor;
    solve_below(P, sn, X, 0, P->pi[sn + 1] - P->pi[sn] - (P->super[sn + 1] - P->super[sn]));
    link_done(P, sn, head);
    return -1;
}

typedef struct factor_job {
    opt_snum *P;
    const double *Ax;
    double *Lx;
    int sn; /* top phase: the supernode */
} factor_job;

static void run_bin(void *ctx, int k)
{
    factor_job *J = ctx;
    opt_snum *P = J->P;
    worker *wk = &P->w[k];
    wk->minor = -1;
    for (int i = P->bptr[k]; i < P->bptr[k + 1] && wk->minor < 0; i++)
        wk->minor = factor_super(P, wk, P->order[i], J->Ax, J->Lx, wk->head);
}

/* The part of descendant d's update that falls in columns [c0, c1) of
 * supernode sn (a top-phase thread's share); d's lists are not touched. */
static void apply_descendant_cols(const opt_snum *P, worker *wk, int d, int sn, const double *Lx,
                                  double *X, int c0, int c1)
{
    int k2 = P->super[sn + 1], nsrow = P->pi[sn + 1] - P->pi[sn];
    int ndcol = P->super[d + 1] - P->super[d];
    int pdi = P->pi[d], ndrow = P->pi[d + 1] - pdi;
    const int *rows = P->s + pdi;
    int p1 = P->lpos[d], p2 = p1;
    while (p2 < ndrow && rows[p2] < k2) p2++;
    int ndrow1 = p2 - p1, ndrow2 = ndrow - p1;
    int *rel = wk->rel;
    for (int i = 0; i < ndrow2; i++) rel[i] = wk->map[rows[p1 + i]];
    int ja = 0, jb;
    while (ja < ndrow1 && rel[ja] < c0) ja++;
    for (jb = ja; jb < ndrow1 && rel[jb] < c1;) jb++;
    int m1 = jb - ja, m3 = ndrow2 - jb, ldc = ndrow2 - ja;
    if (m1 == 0) return;
    const double *Xd = Lx + P->px[d] + p1;
    double *C = wk->C;
    dsyrk_("L", "N", &m1, &ndcol, &one, Xd + ja, &ndrow, &zero, C, &ldc);
    if (m3 > 0)
        dgemm_("N", "T", &m3, &m1, &ndcol, &one, Xd + jb, &ndrow, Xd + ja, &ndrow, &zero, C + m1,
               &ldc);
    for (int jj = 0; jj < m1; jj++) {
        int j = ja + jj;
        double *col = X + (size_t)rel[j] * (size_t)nsrow;
        const double *cj = C + (size_t)jj * (size_t)ldc - ja;
        for (int i = j; i < ndrow2; i++) col[rel[i]] -= cj[i];
    }
}

/* Top phase, thread k: every waiting descendant's update to its share of
 * sn's columns (shares of about equal work: column c gets nsrow - c rows). */
static void run_top_updates(void *ctx, int k)
{
    factor_job *J = ctx;
    opt_snum *P = J->P;
    worker *wk = &P->w[k];
    int sn = J->sn, T = P->threads;
    int psi = P->pi[sn], nsrow = P->pi[sn + 1] - psi, nscol = P->super[sn + 1] - P->super[sn];
    double total = 0, acc = 0;
    for (int c = 0; c < nscol; c++) total += nsrow - c;
    int c0 = k == 0 ? 0 : nscol, c1 = nscol;
    for (int c = 0; c < nscol; c++) {
        if (k > 0 && c0 == nscol && acc >= total * k / T) c0 = c;
        acc += nsrow - c;
        if (k < T - 1 && acc >= total * (k + 1) / T) {
            c1 = c + 1;
            break;
        }
    }
    for (int i = 0; i < nsrow; i++) wk->map[P->s[psi + i]] = i;
    double *X = J->Lx + P->px[sn];
    for (int h = 0; h < T; h++)
        for (int d = P->w[h].head[sn]; d >= 0; d = P->next[d])
            apply_descendant_cols(P, wk, d, sn, J->Lx, X, c0, c1);
}

/* After the top phase's updates of sn: move each descendant on (into
 * thread 0's lists), as apply_list does. */
static void relink_top(const opt_snum *P, int sn)
{
    int T = P->threads, k2 = P->super[sn + 1];
    for (int h = 0; h < T; h++) {
        int d = P->w[h].head[sn];
        P->w[h].head[sn] = -1;
        while (d >= 0) {
            int dnext = P->next[d], ndrow = P->pi[d + 1] - P->pi[d], p = P->lpos[d];
            const int *rows = P->s + P->pi[d];
            while (p < ndrow && rows[p] < k2) p++;
            P->lpos[d] = p;
            link_next(P, P->w[0].head, d, p);
            d = dnext;
        }
    }
}

static void run_top_solve(void *ctx, int k)
{
    factor_job *J = ctx;
    opt_snum *P = J->P;
    int sn = J->sn, nrest = P->pi[sn + 1] - P->pi[sn] - (P->super[sn + 1] - P->super[sn]);
    solve_below(P, sn, J->Lx + P->px[sn], (int)par_chunk_begin((size_t)nrest, P->threads, k),
                (int)par_chunk_begin((size_t)nrest, P->threads, k + 1));
}

/* Whether a supernode above the cut is worth its T threads. */
static int top_parallel(const opt_snum *P, int sn)
{
    return P->threads > 1 &&
        (double)(P->pi[sn + 1] - P->pi[sn]) * (double)(P->super[sn + 1] - P->super[sn]) >=
        TOP_PARALLEL_MIN;
}

/* A supernode above the cut: descendants from every thread's list. */
static int factor_top(opt_snum *P, int sn, const double *Ax, double *Lx)
{
    int T = P->threads;
    double *X = Lx + P->px[sn];
    assemble(P, sn, Ax, X);
    factor_job J = {P, Ax, Lx, sn};
    if (top_parallel(P, sn)) {
        par_run(T, run_top_updates, &J);
        relink_top(P, sn);
    } else {
        for (int k = 0; k < T; k++) apply_list(P, &P->w[k], sn, P->w[k].head, Lx, X);
    }
    int minor = factor_diagonal(P, sn, X);
    if (minor >= 0) return minor;
    if (top_parallel(P, sn)) par_run(T, run_top_solve, &J);
    else solve_below(P, sn, X, 0, P->pi[sn + 1] - P->pi[sn] - (P->super[sn + 1] - P->super[sn]));
    link_done(P, sn, P->w[0].head);
    return -1;
}

opt_snum_shape opt_snum_get_shape(const opt_snum *P)
{
    int T = P->threads, first_above = P->bptr[T > 1 ? T : 0];
    opt_snum_shape sh = {T, P->nsuper, first_above, P->nsuper - first_above, 0};
    for (int i = first_above; i < P->nsuper; i++) sh.above_parallel += top_parallel(P, P->order[i]);
    return sh;
}

int opt_snum_factor(opt_snum *P, const opt_csc *A, cholmod_factor *L)
{
    int T = P->threads, ns = P->nsuper;
    for (int k = 0; k < T; k++) {
        for (int sn = 0; sn < ns; sn++) P->w[k].head[sn] = -1;
        P->w[k].minor = -1;
    }
    /* BLAS one-threaded: the threads are scaf's (bins, then the top's
     * updates and rows); OpenBLAS's own would spin beside them */
    int blas = T > 1 && openblas_get_num_threads && openblas_set_num_threads
        ? openblas_get_num_threads()
        : 0;
    if (blas > 1) openblas_set_num_threads(1);
    factor_job J = {P, A->val, L->x, -1};
    int minor = -1;
    if (T > 1) {
        par_run(T, run_bin, &J);
        for (int k = 0; k < T; k++)
            if (P->w[k].minor >= 0 && (minor < 0 || P->w[k].minor < minor)) minor = P->w[k].minor;
    }
    for (int i = P->bptr[T > 1 ? T : 0]; i < ns && minor < 0; i++)
        minor = factor_top(P, P->order[i], A->val, L->x);
    if (blas > 1) openblas_set_num_threads(blas);
    L->minor = minor < 0 ? L->n : (size_t)minor;
    return minor;
}

/* ---- solve: L L^T x = b, bins in parallel as in the factorization ---- */

/* Forward step of supernode sn: y_s = L_ss^-1 y_s, then the rows below
 * lose L_below y_s (into acc for rows above the cut when acc is given). */
static void forward_super(const opt_snum *P, worker *wk, int sn, const double *Lx, double *acc)
{
    int k1 = P->super[sn], nscol = P->super[sn + 1] - k1;
    int nsrow = P->pi[sn + 1] - P->pi[sn], nrest = nsrow - nscol;
    const double *X = Lx + P->px[sn];
    double *ys = P->y + k1;
    dtrsv_("L", "N", "N", &nscol, X, &nsrow, ys, &inc1);
    if (nrest <= 0) return;
    dgemv_("N", &nrest, &nscol, &one, X + nscol, &nsrow, ys, &inc1, &zero, wk->tmp, &inc1);
    const int *rows = P->s + P->pi[sn] + nscol;
    for (int i = 0; i < nrest; i++) {
        int t = acc ? P->toprow[rows[i]] : -1;
        if (t >= 0) acc[t] += wk->tmp[i];
        else P->y[rows[i]] -= wk->tmp[i];
    }
}

/* Backward step of supernode sn: y_s = L_ss^-T (y_s - L_below^T y_below). */
static void backward_super(const opt_snum *P, worker *wk, int sn, const double *Lx)
{
    int k1 = P->super[sn], nscol = P->super[sn + 1] - k1;
    int nsrow = P->pi[sn + 1] - P->pi[sn], nrest = nsrow - nscol;
    const double *X = Lx + P->px[sn];
    double *ys = P->y + k1;
    if (nrest > 0) {
        const int *rows = P->s + P->pi[sn] + nscol;
        for (int i = 0; i < nrest; i++) wk->tmp[i] = P->y[rows[i]];
        dgemv_("T", &nrest, &nscol, &minus_one, X + nscol, &nsrow, wk->tmp, &inc1, &one, ys, &inc1);
    }
    dtrsv_("L", "T", "N", &nscol, X, &nsrow, ys, &inc1);
}

typedef struct solve_job {
    opt_snum *P;
    const double *Lx;
} solve_job;

static void run_bin_forward(void *ctx, int k)
{
    solve_job *J = ctx;
    worker *wk = &J->P->w[k];
    for (int t = 0; t < J->P->ntop; t++) wk->acc[t] = 0;
    for (int i = J->P->bptr[k]; i < J->P->bptr[k + 1]; i++)
        forward_super(J->P, wk, J->P->order[i], J->Lx, wk->acc);
}

static void run_bin_backward(void *ctx, int k)
{
    solve_job *J = ctx;
    for (int i = J->P->bptr[k + 1] - 1; i >= J->P->bptr[k]; i--)
        backward_super(J->P, &J->P->w[k], J->P->order[i], J->Lx);
}

void opt_snum_solve(opt_snum *P, const cholmod_factor *L, int nrhs, const double *B, double *X)
{
    int n = P->n, T = P->threads, ns = P->nsuper, top = P->bptr[T > 1 ? T : 0];
    const int *perm = L->Perm;
    solve_job J = {P, L->x};
    int blas = T > 1 && openblas_get_num_threads && openblas_set_num_threads
        ? openblas_get_num_threads()
        : 0;
    if (blas > 1) openblas_set_num_threads(1);
    for (int r = 0; r < nrhs; r++) {
        const double *b = B + (size_t)r * (size_t)n;
        double *x = X + (size_t)r * (size_t)n;
        for (int k = 0; k < n; k++) P->y[k] = b[perm[k]];
        if (T > 1) {
            par_run(T, run_bin_forward, &J);
            for (int k = 0; k < n; k++) {
                int t = P->toprow[k];
                if (t < 0) continue;
                for (int h = 0; h < T; h++) P->y[k] -= P->w[h].acc[t];
            }
        }
        for (int i = top; i < ns; i++) forward_super(P, &P->w[0], P->order[i], L->x, NULL);
        for (int i = ns - 1; i >= top; i--) backward_super(P, &P->w[0], P->order[i], L->x);
        if (T > 1) par_run(T, run_bin_backward, &J);
        for (int k = 0; k < n; k++) x[perm[k]] = P->y[k];
    }
    if (blas > 1) openblas_set_num_threads(blas);
}
