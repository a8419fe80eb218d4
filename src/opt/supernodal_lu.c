/* opt/supernodal_lu: see supernodal_lu.h.
 *
 * B = P A P^T (P: CHOLMOD's order) is factored as L U, L unit lower. Both
 * live in the supernodes of the symbolic Cholesky factor: supernode s
 * (columns f .. l - 1, rows s[pi[s] ..], its own columns first) holds an
 * nsrow x nscol column-major block in Lx at px[s], whose top square is the
 * factored diagonal block (L11 below its diagonal, U11 on and above it, as
 * LAPACK stores an LU) and whose rows below hold L21; U12^T, the rows
 * below only ((nsrow - nscol) x nscol), is in Ux at pu[s]. Left-looking, as
 * opt/supernodal_numeric: before supernode s is factored, each
 * descendant d (a supernode with rows in s's columns) subtracts
 * L_d(rows >= f) U_d^T(rows in s) from s's columns of L and
 * U_d^T(rows >= l) L_d(rows in s)^T from those of U^T.
 */
#include "opt/supernodal_lu.h"

#include <assert.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cholmod.h>

#include "base/zeroed_pages.h"
#include "opt/cholmod_view.h"
#include "opt/dense_blas.h"
#include "opt/supernodal_check.h"

static const double one = 1.0, zero = 0.0, minus_one = -1.0;

/* Columns of a diagonal block's panels (blocked right-looking LU). */
#define PANEL 32

/* A pivot below this share of its row's original diagonal: singular. */
#define PIVOT_MIN 1e-14

struct opt_lu {
    int n, nsuper;
    int *super, *pi, *s, *perm; /* the symbolic factor's, copied */
    size_t *px, *pu;            /* a supernode's values in Lx, in Ux */
    double *Lx, *Ux;
    double *y; /* n: a solve's vector in the factor's order */
    int maxbelow;
    size_t maxcsize; /* the largest update */
    double *tmp;     /* maxbelow */
};

void opt_lu_free(opt_lu *F)
{
    if (!F) return;
    free(F->super);
    free(F->pi);
    free(F->s);
    free(F->perm);
    free(F->px);
    free(F->pu);
    free(F->Lx);
    free(F->Ux);
    free(F->y);
    free(F->tmp);
    free(F);
}

double opt_lu_entries(const opt_lu *F)
{
    return F ? (double)F->px[F->nsuper] + (double)F->pu[F->nsuper] : 0.0;
}

/* The transpose's pattern (rows sorted) equals A's, and every column
 * holds its diagonal. */
static int symmetric_pattern(int n, const int *Ap, const int *Ai, int **Tp_out, int **Ti_out,
                             int **Tv_out)
{
    size_t nnz = (size_t)Ap[n];
    int *Tp = calloc((size_t)n + 1, sizeof *Tp), *Ti = malloc((nnz + 1) * sizeof *Ti);
    int *Tv = malloc((nnz + 1) * sizeof *Tv), *fill = malloc(((size_t)n + 1) * sizeof *fill);
    if (!Tp || !Ti || !Tv || !fill) {
        free(Tp);
        free(Ti);
        free(Tv);
        free(fill);
        return -1;
    }
    for (size_t q = 0; q < nnz; q++) Tp[Ai[q] + 1]++;
    for (int c = 0; c < n; c++) Tp[c + 1] += Tp[c];
    memcpy(fill, Tp, (size_t)n * sizeof *fill);
    for (int c = 0; c < n; c++)
        for (int q = Ap[c]; q < Ap[c + 1]; q++) {
            int at = fill[Ai[q]]++;
            Ti[at] = c;
            Tv[at] = q; /* the value's index in A */
        }
    free(fill);
    int ok =
        memcmp(Tp, Ap, ((size_t)n + 1) * sizeof *Ap) == 0 && memcmp(Ti, Ai, nnz * sizeof *Ai) == 0;
    for (int c = 0; c < n && ok; c++) {
        int has = 0;
        for (int q = Ap[c]; q < Ap[c + 1]; q++) has |= Ai[q] == c;
        ok = has;
    }
    *Tp_out = Tp;
    *Ti_out = Ti;
    *Tv_out = Tv;
    return ok;
}

/* The supernodal symbolic factor of A's pattern (its upper triangle) in
 * CHOLMOD's fill-reducing order, copied into F. */
static scaf_status analyze(opt_lu *F, int n, const int *Ap, const int *Ai, scaf_error *err)
{
    size_t nnz = (size_t)Ap[n];
    int *up = malloc(((size_t)n + 1) * sizeof *up), *ui = malloc((nnz + 1) * sizeof *ui);
    if (!up || !ui) {
        free(up);
        free(ui);
        return err_nomem(err, "LU analysis");
    }
    up[0] = 0;
    for (int c = 0; c < n; c++) {
        up[c + 1] = up[c];
        for (int q = Ap[c]; q < Ap[c + 1] && Ai[q] <= c; q++) ui[up[c + 1]++] = Ai[q];
    }
    cholmod_common cm;
    if (!cholmod_start(&cm)) {
        free(up);
        free(ui);
        return err_set(err, SCAF_ERR_NUMERIC, "CHOLMOD could not start");
    }
    cm.print = 0;
    cm.error_handler = NULL;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    /* AMD: METIS's nested dissection leaves less fill but costs more than
     * it saves here (the mean-value system, one thread: 443k faces 0.66-1.03
     * s in all against 1.66-1.74, 1.77M faces 6.1 against 8.1 s) */
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_AMD;
    cm.postorder = 1;
    cholmod_sparse S = opt_cholmod_pattern_view(n, up, ui, 1);
    cholmod_factor *L = cholmod_analyze(&S, &cm);
    free(up);
    free(ui);
    scaf_status st = SCAF_OK;
    if (!L || !L->is_super) {
        st = cm.status == CHOLMOD_OUT_OF_MEMORY
            ? err_nomem(err, "LU analysis")
            : err_set(err, SCAF_ERR_NUMERIC, "LU analysis failed (CHOLMOD status %d)", cm.status);
        goto done;
    }
    int ns = (int)L->nsuper;
    const int *lsuper = L->super, *lpi = L->pi, *ls = L->s, *lperm = L->Perm;
    F->nsuper = ns;
    F->super = malloc(((size_t)ns + 1) * sizeof *F->super);
    F->pi = malloc(((size_t)ns + 1) * sizeof *F->pi);
    F->px = malloc(((size_t)ns + 1) * sizeof *F->px);
    F->pu = malloc(((size_t)ns + 1) * sizeof *F->pu);
    F->s = malloc(((size_t)lpi[ns] + 1) * sizeof *F->s);
    F->perm = malloc(((size_t)n + 1) * sizeof *F->perm);
    if (!F->super || !F->pi || !F->px || !F->pu || !F->s || !F->perm) {
        st = err_nomem(err, "LU analysis");
        goto done;
    }
    memcpy(F->super, lsuper, ((size_t)ns + 1) * sizeof *F->super);
    memcpy(F->pi, lpi, ((size_t)ns + 1) * sizeof *F->pi);
    memcpy(F->s, ls, (size_t)lpi[ns] * sizeof *F->s);
    memcpy(F->perm, lperm, (size_t)n * sizeof *F->perm);
    /* offsets recomputed in size_t: CHOLMOD's int px would overflow on
     * the largest meshes before the values do */
    F->px[0] = F->pu[0] = 0;
    for (int k = 0; k < ns; k++) {
        size_t nscol = (size_t)(lsuper[k + 1] - lsuper[k]), nsrow = (size_t)(lpi[k + 1] - lpi[k]);
        F->px[k + 1] = F->px[k] + nscol * nsrow;
        F->pu[k + 1] = F->pu[k] + nscol * (nsrow - nscol);
    }
    F->maxcsize = L->maxcsize;
done:
    if (L) cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
    return st;
}

/* A's columns of supernode sn into its blocks X (L, and the diagonal
 * block whole) and Y (U^T below the diagonal block), zero before; map:
 * factor row -> place in the supernode's rows; iperm: A's index ->
 * factor's. */
static void assemble(const opt_lu *F, int sn, const int *Ap, const int *Ai, const double *Ax,
                     const int *Tp, const int *Ti, const int *Tv, const int *iperm, const int *map,
                     double *X, double *Y)
{
    int f = F->super[sn], l = F->super[sn + 1], nsrow = F->pi[sn + 1] - F->pi[sn];
    for (int j = f; j < l; j++) {
        int c = F->perm[j];
        double *xc = X + (size_t)(j - f) * (size_t)nsrow;
        double *yc = Y + (size_t)(j - f) * (size_t)(nsrow - (l - f));
        for (int q = Ap[c]; q < Ap[c + 1]; q++) { /* B(i, j): L, or U inside the block */
            int i = iperm[Ai[q]];
            if (i >= f) xc[map[i]] = Ax[q];
        }
        for (int q = Tp[c]; q < Tp[c + 1]; q++) { /* B(j, i), i below the block: U^T */
            int i = iperm[Ti[q]];
            if (i >= l) yc[map[i] - (l - f)] = Ax[Tv[q]];
        }
    }
}

/* X (the n x n diagonal square, leading dimension ld) = L U in place, without
 * pivots, right-looking by panels of PANEL columns; 0, or 1 + the first
 * column whose pivot is not positive or falls below PIVOT_MIN of diag. */
static int factor_square(double *X, int ld, int n, const double *diag)
{
    for (int k0 = 0; k0 < n; k0 += PANEL) {
        int kb = n - k0 < PANEL ? n - k0 : PANEL, rest = n - k0 - kb;
        for (int k = k0; k < k0 + kb; k++) {
            double *ck = X + (size_t)k * (size_t)ld;
            double piv = ck[k];
            if (!(piv > PIVOT_MIN * diag[k]) || !isfinite(piv)) return k + 1;
            double r = 1.0 / piv;
            for (int i = k + 1; i < n; i++) ck[i] *= r;
            for (int j = k + 1; j < k0 + kb; j++) {
                double *cj = X + (size_t)j * (size_t)ld;
                double u = cj[k];
                for (int i = k + 1; i < n; i++) cj[i] -= ck[i] * u;
            }
        }
        if (rest > 0) {
            double *A11 = X + (size_t)k0 * (size_t)ld + k0;
            double *A12 = X + (size_t)(k0 + kb) * (size_t)ld + k0;
            double *A21 = A11 + kb, *A22 = A12 + kb;
            dtrsm_("L", "L", "N", "U", &kb, &rest, &one, A11, &ld, A12, &ld);
            dgemm_("N", "N", &rest, &rest, &kb, &minus_one, A21, &ld, A12, &ld, &one, A22, &ld);
        }
    }
    return 0;
}

/* The numeric factorization on F's structure. */
static scaf_status factor(opt_lu *F, const int *Ap, const int *Ai, const double *Ax, const int *Tp,
                          const int *Ti, const int *Tv, scaf_error *err)
{
    int n = F->n, ns = F->nsuper;
    int maxrow = 1;
    for (int k = 0; k < ns; k++) {
        int nsrow = F->pi[k + 1] - F->pi[k];
        if (nsrow > maxrow) maxrow = nsrow;
        if (nsrow - (F->super[k + 1] - F->super[k]) > F->maxbelow)
            F->maxbelow = nsrow - (F->super[k + 1] - F->super[k]);
    }
    int *iperm = malloc(((size_t)n + 1) * sizeof *iperm);
    int *map = malloc(((size_t)n + 1) * sizeof *map);
    int *col2super = malloc(((size_t)n + 1) * sizeof *col2super);
    int *head = malloc(((size_t)ns + 1) * sizeof *head),
        *next = malloc(((size_t)ns + 1) * sizeof *next);
    int *lpos = malloc(((size_t)ns + 1) * sizeof *lpos),
        *rel = malloc(((size_t)maxrow + 1) * sizeof *rel);
    /* the largest update (a descendant's rows from its place by its rows
     * inside the target): the symbolic factor's maxcsize */
    double *C = malloc((F->maxcsize ? F->maxcsize : 1) * sizeof *C);
    double *diag = malloc(((size_t)n + 1) * sizeof *diag);
    size_t xs = F->px[ns] ? F->px[ns] : 1;
    F->Lx = zeroed_pages(xs, sizeof *F->Lx); /* zero: assemble writes only A's entries */
    F->Ux = zeroed_pages(F->pu[ns] ? F->pu[ns] : 1, sizeof *F->Ux);
    F->y = malloc(((size_t)n + 1) * sizeof *F->y);
    F->tmp = malloc(((size_t)F->maxbelow + 1) * sizeof *F->tmp);
    scaf_status st = SCAF_OK;
    if (!iperm || !map || !col2super || !head || !next || !lpos || !rel || !C || !diag || !F->Lx ||
        !F->Ux || !F->y || !F->tmp) {
        st = err_nomem(err, "LU factor");
        goto done;
    }
    for (int k = 0; k < n; k++) iperm[F->perm[k]] = k;
    for (int c = 0; c < n; c++) {
        diag[iperm[c]] = 0.0;
        for (int q = Ap[c]; q < Ap[c + 1]; q++)
            if (Ai[q] == c) diag[iperm[c]] = fabs(Ax[q]);
    }
    for (int k = 0; k < ns; k++) {
        head[k] = -1;
        for (int j = F->super[k]; j < F->super[k + 1]; j++) col2super[j] = k;
    }
    for (int sn = 0; sn < ns; sn++) {
        int f = F->super[sn], l = F->super[sn + 1], nscol = l - f;
        int psi = F->pi[sn], nsrow = F->pi[sn + 1] - psi;
        double *X = F->Lx + F->px[sn], *Y = F->Ux + F->pu[sn];
        int below = nsrow - nscol;
        for (int i = 0; i < nsrow; i++) map[F->s[psi + i]] = i;
        assemble(F, sn, Ap, Ai, Ax, Tp, Ti, Tv, iperm, map, X, Y);
        for (int d = head[sn]; d >= 0;) {
            int dnext = next[d];
            int ndcol = F->super[d + 1] - F->super[d], pdi = F->pi[d];
            int ndrow = F->pi[d + 1] - pdi, p1 = lpos[d], p2 = p1, ldu = ndrow - ndcol;
            const int *rows = F->s + pdi;
            while (p2 < ndrow && rows[p2] < l) p2++;
            int m1 = p2 - p1, m2 = ndrow - p1, m3 = m2 - m1;
            /* p1 >= ndcol: a descendant's rows below its diagonal block */
            const double *Ld = F->Lx + F->px[d] + p1, *Ud = F->Ux + F->pu[d] + (p1 - ndcol);
            for (int i = 0; i < m2; i++) rel[i] = map[rows[p1 + i]];
            /* L (and the diagonal block whole): L_d(rows >= f) U_d(rows in s)^T */
            dgemm_("N", "T", &m2, &m1, &ndcol, &one, Ld, &ndrow, Ud, &ldu, &zero, C, &m2);
            for (int j = 0; j < m1; j++) {
                double *col = X + (size_t)rel[j] * (size_t)nsrow;
                const double *cj = C + (size_t)j * (size_t)m2;
                for (int i = 0; i < m2; i++) col[rel[i]] -= cj[i];
            }
            /* U^T below the block: U_d(rows >= l) L_d(rows in s)^T */
            if (m3 > 0) {
                dgemm_("N", "T", &m3, &m1, &ndcol, &one, Ud + m1, &ldu, Ld, &ndrow, &zero, C, &m3);
                for (int j = 0; j < m1; j++) {
                    double *col = Y + (size_t)rel[j] * (size_t)below;
                    const double *cj = C + (size_t)j * (size_t)m3;
                    for (int i = 0; i < m3; i++) col[rel[m1 + i] - nscol] -= cj[i];
                }
            }
            lpos[d] = p2;
            if (p2 < ndrow) { /* wait on the next supernode d updates */
                int q = col2super[rows[p2]];
                next[d] = head[q];
                head[q] = d;
            }
            d = dnext;
        }
        int bad = factor_square(X, nsrow, nscol, diag + f);
        if (bad) {
            int col = f + bad - 1;
            st = err_set(err, SCAF_ERR_NUMERIC,
                         "LU without pivoting: pivot %d (row %d of the matrix) is not positive "
                         "(%g): the matrix is not an M-matrix, or singular",
                         col, F->perm[col],
                         X[(size_t)(bad - 1) * (size_t)nsrow + (size_t)(bad - 1)]);
            goto done;
        }
        if (below > 0) {
            dtrsm_("R", "U", "N", "N", &below, &nscol, &one, X, &nsrow, X + nscol, &nsrow);
            dtrsm_("R", "L", "T", "U", &below, &nscol, &one, X, &nsrow, Y, &below);
            lpos[sn] = nscol;
            int q = col2super[F->s[psi + nscol]];
            next[sn] = head[q];
            head[q] = sn;
        }
    }
done:
    free(iperm);
    free(map);
    free(col2super);
    free(head);
    free(next);
    free(lpos);
    free(rel);
    free(C);
    free(diag);
    return st;
}

#ifndef NDEBUG
/* The factor's structure (for the assert below): perm a permutation;
 * supernodes covering the columns in order, each one's rows its own
 * columns first, then strictly ascending below them; L's and U's values
 * in place order; every pivot finite and not zero. */
static int lu_valid(const opt_lu *F)
{
    int n = F->n, ns = F->nsuper;
    if (!opt_is_permutation(n, F->perm) || ns < 1 || F->super[0] != 0 || F->super[ns] != n)
        return 0;
    for (int sn = 0; sn < ns; sn++) {
        int f = F->super[sn], nscol = F->super[sn + 1] - f, nsrow = F->pi[sn + 1] - F->pi[sn];
        if (nscol < 1 || nsrow < nscol) return 0;
        const int *rows = F->s + F->pi[sn];
        for (int i = 0; i < nsrow; i++)
            if (i < nscol ? rows[i] != f + i : (rows[i] <= rows[i - 1] || rows[i] >= n)) return 0;
        if (F->px[sn + 1] - F->px[sn] < (size_t)nsrow * (size_t)nscol) return 0;
        const double *X = F->Lx + F->px[sn];
        for (int j = 0; j < nscol; j++) {
            double p = X[(size_t)j * (size_t)nsrow + (size_t)j];
            if (!(p != 0.0) || !isfinite(p)) return 0;
        }
    }
    return 1;
}
#endif

opt_lu *opt_lu_factor(int n, const int *Ap, const int *Ai, const double *Ax, scaf_error *err)
{
    if (n < 1) {
        err_set(err, SCAF_ERR_USAGE, "LU: empty matrix");
        return NULL;
    }
    int *Tp = NULL, *Ti = NULL, *Tv = NULL;
    int sym = symmetric_pattern(n, Ap, Ai, &Tp, &Ti, &Tv);
    opt_lu *F = NULL;
    if (sym < 0) {
        err_nomem(err, "LU pattern");
        goto done;
    }
    if (!sym) {
        err_set(err, SCAF_ERR_USAGE,
                "LU without pivoting: the pattern is not symmetric or lacks a diagonal entry");
        goto done;
    }
    F = calloc(1, sizeof *F);
    if (!F) {
        err_nomem(err, "LU");
        goto done;
    }
    F->n = n;
    if (analyze(F, n, Ap, Ai, err) != SCAF_OK ||
        factor(F, Ap, Ai, Ax, Tp, Ti, Tv, err) != SCAF_OK) {
        opt_lu_free(F);
        F = NULL;
    }
    assert(!F || lu_valid(F));
done:
    free(Tp);
    free(Ti);
    free(Tv);
    return F;
}

void opt_lu_solve(opt_lu *F, const double *b, double *x)
{
    int n = F->n, ns = F->nsuper, inc = 1;
    double *y = F->y, *tmp = F->tmp;
    for (int k = 0; k < n; k++) y[k] = b[F->perm[k]];
    for (int sn = 0; sn < ns; sn++) { /* L y = P b, L unit lower */
        int f = F->super[sn], nscol = F->super[sn + 1] - f;
        int psi = F->pi[sn], nsrow = F->pi[sn + 1] - psi, below = nsrow - nscol;
        const double *X = F->Lx + F->px[sn];
        dtrsv_("L", "N", "U", &nscol, X, &nsrow, y + f, &inc);
        if (below > 0) {
            dgemv_("N", &below, &nscol, &one, X + nscol, &nsrow, y + f, &inc, &zero, tmp, &inc);
            const int *rows = F->s + psi + nscol;
            for (int i = 0; i < below; i++) y[rows[i]] -= tmp[i];
        }
    }
    for (int sn = ns - 1; sn >= 0; sn--) { /* U z = y */
        int f = F->super[sn], nscol = F->super[sn + 1] - f;
        int psi = F->pi[sn], nsrow = F->pi[sn + 1] - psi, below = nsrow - nscol;
        const double *X = F->Lx + F->px[sn], *Y = F->Ux + F->pu[sn];
        if (below > 0) {
            const int *rows = F->s + psi + nscol;
            for (int i = 0; i < below; i++) tmp[i] = y[rows[i]];
            dgemv_("T", &below, &nscol, &minus_one, Y, &below, tmp, &inc, &one, y + f, &inc);
        }
        dtrsv_("U", "N", "N", &nscol, X, &nsrow, y + f, &inc);
    }
    for (int k = 0; k < n; k++) x[F->perm[k]] = y[k];
}
