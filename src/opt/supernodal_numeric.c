/* opt/supernodal_numeric: see supernodal_numeric.h.
 *
 * Left-looking: before supernode s is factored, every supernode d with
 * rows in s's columns (a descendant) subtracts its contribution
 * C = L_d(rows >= s's first, :) L_d(rows in s, :)^T, then s is factored
 * (its diagonal block, then the rows below it, by blocks of TRSM_BLOCK
 * columns: factor_diagonal, solve_below). Each descendant waits
 * in a linked list on the next supernode it updates (head / next), with
 * lpos its first row not yet used; each thread keeps its own lists, and
 * the supernodes above the cut take their descendants from all of them. */
#include "opt/supernodal_numeric.h"

#include <assert.h>
#include <math.h>
#include <string.h>

#include "base/parallel.h"
#include "opt/blas_threads.h"
#include "opt/dense_blas.h"
#include "opt/supernodal_solve.h"
#include "opt/vector_clones.h"

static const double one = 1.0, zero = 0.0, minus_one = -1.0;

/* Updates from at most this many rows of a descendant into a supernode's
 * columns are one dgemm instead of dsyrk + dgemm: 2D meshes make many such
 * small updates, and one small-kernel call beats two packed ones (aphrodite,
 * one thread: factorization -6%). */
#define SMALL_UPDATE 32

/* Rows i0 .. i0 + W - 1 and columns j0 .. j0 + NJ - 1 (W <= 8, NJ <= 4)
 * of C = A B^T, A m x k and B n x k column-major: the W x NJ sums stay in
 * registers over the k products (W and NJ constants in the hot calls, so
 * the row loops are vector operations). */
static inline void gemm_nt_block(double *C, int ldc, const double *A, int lda, const double *B,
                                 int ldb, int k, int i0, int W, int j0, int NJ)
{
    double acc[4][8];
    for (int jj = 0; jj < NJ; jj++)
        for (int t = 0; t < W; t++) acc[jj][t] = 0.0;
    for (int p = 0; p < k; p++) {
        const double *a = A + (size_t)p * (size_t)lda + i0;
        const double *b = B + (size_t)p * (size_t)ldb + j0;
        for (int jj = 0; jj < NJ; jj++)
            for (int t = 0; t < W; t++) acc[jj][t] += a[t] * b[jj];
    }
    for (int jj = 0; jj < NJ; jj++)
        for (int t = 0; t < W; t++) C[(size_t)(j0 + jj) * (size_t)ldc + i0 + t] = acc[jj][t];
}

/* C = A B^T (m x n; A m x k, B n x k, k and n small: a descendant's
 * update) straight from the factor's columns, by blocks of 8 rows and 4
 * columns. OpenBLAS's dgemm (here its Haswell kernels) packs both operands
 * into buffers taken from a locked pool at every call; two threads calling
 * it side by side each ran 1.4-1.5x slower than alone, while this kernel
 * does not (aphrodite, two threads: factorization 56 -> 47.5 ms; alone it
 * is 3-5% slower than OpenBLAS's, which one thread keeps). The full
 * column blocks are a call of their own so that NJ is the constant 4. */
VECTOR_CLONES static void small_gemm_nt(double *C, int ldc, const double *A, int lda,
                                        const double *B, int ldb, int m, int n, int k)
{
    for (int j0 = 0; j0 < n; j0 += 4) {
        int nj = n - j0 < 4 ? n - j0 : 4;
        int i0 = 0;
        if (nj == 4)
            for (; i0 + 8 <= m; i0 += 8) gemm_nt_block(C, ldc, A, lda, B, ldb, k, i0, 8, j0, 4);
        else
            for (; i0 + 8 <= m; i0 += 8) gemm_nt_block(C, ldc, A, lda, B, ldb, k, i0, 8, j0, nj);
        if (i0 < m) gemm_nt_block(C, ldc, A, lda, B, ldb, k, i0, m - i0, j0, nj);
    }
}

/* Subtract descendant d's update from supernode sn (block X, nsrow rows). */
static void apply_descendant(const opt_snum *P, opt_snum_worker *wk, int d, int sn,
                             const double *Lx, double *X, int nsrow)
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
    if (ndrow1 <= SMALL_UPDATE) {
        /* one product (the upper triangle it also computes is not used):
         * scaf's own kernel when the tree is cut into bins, whatever
         * threads run them (OpenBLAS's, 3-5% faster alone, sums in
         * another order: one kernel for both keeps the bits the same at
         * any thread count), OpenBLAS's when there is one bin */
        if (P->bins > 1) small_gemm_nt(C, ndrow2, Xd, ndrow, Xd, ndrow, ndrow2, ndrow1, ndcol);
        else
            dgemm_("N", "T", &ndrow2, &ndrow1, &ndcol, &one, Xd, &ndrow, Xd, &ndrow, &zero, C,
                   &ndrow2);
    } else {
        dsyrk_("L", "N", &ndrow1, &ndcol, &one, Xd, &ndrow, &zero, C, &ndrow2);
        if (ndrow3 > 0)
            dgemm_("N", "T", &ndrow3, &ndrow1, &ndcol, &one, Xd + ndrow1, &ndrow, Xd, &ndrow, &zero,
                   C + ndrow1, &ndrow2);
    }
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
    if (sn < P->nks)
        for (int t = P->kptr[sn]; t < P->kptr[sn + 1]; t++)
            X[(size_t)(P->kpos[t] >> 16) * (size_t)nsrow + (P->kpos[t] & 0xffffu)] = Ax[P->ksrc[t]];
    for (int t = P->aptr[sn]; t < P->aptr[sn + 1]; t++) X[P->adst[t]] = Ax[P->asrc[t]];
}

/* Subtract the updates of the descendants waiting on sn in head (into X,
 * sn's block or a block-sized buffer); each is relinked into head. */
static void apply_list(const opt_snum *P, opt_snum_worker *wk, int sn, int *head, const double *Lx,
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

/* Width of the column blocks of solve_below's triangular solves. */
#define TRSM_BLOCK 16

/* Rows i0 .. i0 + W - 1 (W a constant in the hot calls, so the row loops
 * become vector operations) of X := X L^-T, L the n x n lower triangle
 * (ldl), rinv its inverted diagonal: column by column, each row's sum kept
 * in a register across the columns before it. */
static inline void trsm_rows(double *X, int ldx, const double *L, int ldl, const double *rinv,
                             int n, int i0, int W)
{
    for (int c = 0; c < n; c++) {
        double acc[8];
        double *xc = X + (size_t)c * (size_t)ldx + i0;
        for (int t = 0; t < W; t++) acc[t] = xc[t];
        for (int k = 0; k < c; k++) {
            double l = L[(size_t)k * (size_t)ldl + c];
            const double *xk = X + (size_t)k * (size_t)ldx + i0;
            for (int t = 0; t < W; t++) acc[t] -= l * xk[t];
        }
        for (int t = 0; t < W; t++) xc[t] = acc[t] * rinv[c];
    }
}

/* X := X L^-T for the m x n block X (ldx) and the n x n (n <= TRSM_BLOCK)
 * lower triangle L (ldl), by blocks of 8 rows. dtrsm's setup and packing
 * outweigh the work at these sizes (aphrodite: 11 GFlop/s). */
VECTOR_CLONES static void small_trsm(double *X, int ldx, const double *L, int ldl, int m, int n)
{
    double rinv[TRSM_BLOCK];
    for (int c = 0; c < n; c++) rinv[c] = 1.0 / L[(size_t)c * (size_t)ldl + c];
    int i0 = 0;
    for (; i0 + 8 <= m; i0 += 8) trsm_rows(X, ldx, L, ldl, rinv, n, i0, 8);
    if (i0 < m) trsm_rows(X, ldx, L, ldl, rinv, n, i0, m - i0);
}

/* Rows [r0, r1) of sn's part below its diagonal block: L21 = A21 L11^-T,
 * by blocks of TRSM_BLOCK columns: each block's triangle solved in place,
 * then the columns after it updated with one dgemm (OpenBLAS's dtrsm on
 * the whole ran at 11-23 GFlop/s on aphrodite's supernodes, this at
 * 17-38). */
static void solve_below(const opt_snum *P, int sn, double *X, int r0, int r1)
{
    int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
    int m = r1 - r0;
    double *B = X + nscol + r0;
    for (int j0 = 0; j0 < nscol && m > 0; j0 += TRSM_BLOCK) {
        int w = nscol - j0 < TRSM_BLOCK ? nscol - j0 : TRSM_BLOCK, rest = nscol - j0 - w;
        const double *Ljj = X + j0 + (size_t)j0 * (size_t)nsrow;
        small_trsm(B + (size_t)j0 * (size_t)nsrow, nsrow, Ljj, nsrow, m, w);
        if (rest > 0)
            dgemm_("N", "T", &m, &rest, &w, &minus_one, B + (size_t)j0 * (size_t)nsrow, &nsrow,
                   Ljj + w, &nsrow, &one, B + (size_t)(j0 + w) * (size_t)nsrow, &nsrow);
    }
}

/* L L^T = A for the w x w lower block A (ldl), w <= TRSM_BLOCK, by
 * columns; -1, or the first column whose pivot is not positive (or NaN),
 * as dpotrf reports it. The strict upper triangle is set to 0. */
VECTOR_CLONES static int small_cholesky(double *A, int ld, int w)
{
    for (int j = 0; j < w; j++) {
        double *cj = A + (size_t)j * (size_t)ld;
        for (int k = 0; k < j; k++) {
            const double *ck = A + (size_t)k * (size_t)ld;
            double l = ck[j];
            for (int i = j; i < w; i++) cj[i] -= l * ck[i];
        }
        double d = cj[j];
        if (!(d > 0.0)) return j;
        d = sqrt(d);
        cj[j] = d;
        double r = 1.0 / d;
        for (int i = j + 1; i < w; i++) cj[i] *= r;
        for (int i = 0; i < j; i++) cj[i] = 0.0;
    }
    return -1;
}

typedef struct diag_job {
    const opt_snum *P;
    double *X;
    int nsrow, nscol, j0, w;
} diag_job;

/* Share k (of P->bins, whatever threads run them) of the rows below
 * column block j0's triangle in the diagonal block: the columns before the block subtracted, then solved
 * against its triangle (factor_diagonal's work on those rows, row by row
 * the same operations). */
static void run_diag_rows(void *ctx, int k)
{
    diag_job *D = ctx;
    int nsrow = D->nsrow, j0 = D->j0, w = D->w;
    size_t below = (size_t)(D->nscol - j0 - w);
    int a = (int)par_chunk_begin(below, D->P->bins, k);
    int m = (int)par_chunk_begin(below, D->P->bins, k + 1) - a;
    if (m <= 0) return;
    double *Xj = D->X + j0 + (size_t)j0 * (size_t)nsrow, *R = Xj + w + a;
    if (j0 > 0)
        dgemm_("N", "T", &m, &w, &j0, &minus_one, D->X + j0 + w + a, &nsrow, D->X + j0, &nsrow,
               &one, R, &nsrow);
    small_trsm(R, nsrow, Xj, nsrow, m, w);
}

/* Factor the diagonal block of sn (nscol x nscol, lower); -1, or the first
 * column where the matrix is not positive definite. Left-looking by blocks
 * of TRSM_BLOCK columns: each block's columns lose the blocks before them
 * (one dgemm, which also writes the block's strict upper triangle, zeroed
 * again by small_cholesky), then its triangle is factored and the rows
 * below it in the diagonal block are solved. dpotrf ran at 1-5 GFlop/s on
 * aphrodite's narrow supernodes. With share (a supernode above the cut),
 * a block's rows below its triangle go to the threads when they hold
 * P->diag_share_min multiply-adds (run_diag_rows): on 1.77M faces the widest top supernode's
 * diagonal block (1,948 columns, 2.5 GFlop) took 94 ms in one thread
 * while the other waited, 52 ms shared. */
static int factor_diagonal(const opt_snum *P, int sn, double *X, int share)
{
    int k1 = P->super[sn], nscol = P->super[sn + 1] - k1, nsrow = P->pi[sn + 1] - P->pi[sn];
    diag_job D = {P, X, nsrow, nscol, 0, 0};
    for (int j0 = 0; j0 < nscol; j0 += TRSM_BLOCK) {
        int w = nscol - j0 < TRSM_BLOCK ? nscol - j0 : TRSM_BLOCK, m = nscol - j0;
        int split = share && (double)(m - w) * (double)w * (double)(j0 + w) >= P->diag_share_min;
        int rows = split ? w : m; /* rows updated here: the triangle's, or all */
        double *Xj = X + j0 + (size_t)j0 * (size_t)nsrow;
        if (j0 > 0)
            dgemm_("N", "T", &rows, &w, &j0, &minus_one, X + j0, &nsrow, X + j0, &nsrow, &one, Xj,
                   &nsrow);
        int j = small_cholesky(Xj, nsrow, w);
        if (j >= 0) return k1 + j0 + j;
        if (split) {
            D.j0 = j0;
            D.w = w;
            par_run(P->bins, run_diag_rows, &D);
        } else if (m > w) {
            small_trsm(Xj + w, nsrow, Xj, nsrow, m - w, w);
        }
    }
    return -1;
}

/* sn done: wait on the supernode of its first row below the diagonal. */
static void link_done(const opt_snum *P, int sn, int *head)
{
    int nscol = P->super[sn + 1] - P->super[sn];
    P->lpos[sn] = nscol;
    link_next(P, head, sn, nscol);
}

/* Supernode sn entirely in one thread (descendants from head). */
static int factor_super(const opt_snum *P, opt_snum_worker *wk, int sn, const double *Ax,
                        double *Lx, int *head)
{
    double *X = Lx + P->px[sn];
    assemble(P, sn, Ax, X);
    apply_list(P, wk, sn, head, Lx, X);
    int minor = factor_diagonal(P, sn, X, 0);
    if (minor >= 0) return minor;
    solve_below(P, sn, X, 0, P->pi[sn + 1] - P->pi[sn] - (P->super[sn + 1] - P->super[sn]));
    link_done(P, sn, head);
    return -1;
}

typedef struct factor_job {
    opt_snum *P;
    const double *Ax;
    double *Lx;
    int sn;      /* top phase: the supernode */
    int forward; /* run the forward sweep too (opt_snum_factor_forward) */
} factor_job;

static void run_bin(void *ctx, int k)
{
    factor_job *J = ctx;
    opt_snum *P = J->P;
    opt_snum_worker *wk = &P->w[k];
    wk->minor = -1;
    for (int i = P->bptr[k]; i < P->bptr[k + 1] && wk->minor < 0; i++) {
        wk->minor = factor_super(P, wk, P->order[i], J->Ax, J->Lx, wk->head);
        if (wk->minor < 0 && J->forward) opt_snum_forward_super(P, wk, P->order[i], J->Lx, wk->acc);
    }
}

/* The part of descendant d's update that falls in columns [c0, c1) of
 * supernode sn (a top-phase thread's share); d's lists are not touched. */
static void apply_descendant_cols(const opt_snum *P, opt_snum_worker *wk, int d, int sn,
                                  const double *Lx, double *X, int c0, int c1)
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
    if (m1 <= SMALL_UPDATE) {
        dgemm_("N", "T", &ldc, &m1, &ndcol, &one, Xd + ja, &ndrow, Xd + ja, &ndrow, &zero, C, &ldc);
    } else {
        dsyrk_("L", "N", &m1, &ndcol, &one, Xd + ja, &ndrow, &zero, C, &ldc);
        if (m3 > 0)
            dgemm_("N", "T", &m3, &m1, &ndcol, &one, Xd + jb, &ndrow, Xd + ja, &ndrow, &zero,
                   C + m1, &ldc);
    }
    for (int jj = 0; jj < m1; jj++) {
        int j = ja + jj;
        double *col = X + (size_t)rel[j] * (size_t)nsrow;
        const double *cj = C + (size_t)jj * (size_t)ldc - ja;
        for (int i = j; i < ndrow2; i++) col[rel[i]] -= cj[i];
    }
}

/* Top phase, share k of P->bins: every waiting descendant's update to
 * its share of sn's columns (shares of about equal work: column c gets
 * nsrow - c rows), descendants in bin order. */
static void run_top_updates(void *ctx, int k)
{
    factor_job *J = ctx;
    opt_snum *P = J->P;
    opt_snum_worker *wk = &P->w[k];
    int sn = J->sn, T = P->bins; /* shares */
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
 * bin 0's lists), as apply_list does. */
static void relink_top(const opt_snum *P, int sn)
{
    int B = P->bins, k2 = P->super[sn + 1];
    for (int h = 0; h < B; h++) {
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
    solve_below(P, sn, J->Lx + P->px[sn], (int)par_chunk_begin((size_t)nrest, P->bins, k),
                (int)par_chunk_begin((size_t)nrest, P->bins, k + 1));
}

/* A supernode above the cut: descendants from every bin's list, in bin
 * order. */
static int factor_top(opt_snum *P, int sn, const double *Ax, double *Lx)
{
    int B = P->bins;
    double *X = Lx + P->px[sn];
    assemble(P, sn, Ax, X);
    factor_job J = {P, Ax, Lx, sn, 0};
    if (opt_snum_top_parallel(P, sn)) {
        par_run(B, run_top_updates, &J);
        relink_top(P, sn);
    } else {
        for (int k = 0; k < B; k++) apply_list(P, &P->w[k], sn, P->w[k].head, Lx, X);
    }
    int minor = factor_diagonal(P, sn, X, opt_snum_top_parallel(P, sn));
    if (minor >= 0) return minor;
    if (opt_snum_top_parallel(P, sn)) par_run(B, run_top_solve, &J);
    else solve_below(P, sn, X, 0, P->pi[sn + 1] - P->pi[sn] - (P->super[sn + 1] - P->super[sn]));
    link_done(P, sn, P->w[0].head);
    return -1;
}

#ifndef NDEBUG
/* After a factorization without a failed pivot: every diagonal entry of L
 * positive and finite (for the assert below). */
static int diagonal_positive(const opt_snum *P, const double *Lx)
{
    for (int sn = 0; sn < P->nsuper; sn++) {
        int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
        for (int j = 0; j < nscol; j++) {
            double d = Lx[P->px[sn] + (size_t)j * (size_t)nsrow + (size_t)j];
            if (!(d > 0.0) || !isfinite(d)) return 0;
        }
    }
    return 1;
}
#endif

static int factor(opt_snum *P, const opt_csc *A, cholmod_factor *L, const double *b)
{
    /* the plan was made for A's pattern on L's structure */
    assert(A->n == P->n && (int)L->n == P->n && L->super == P->super && L->x);
    int B = P->bins, ns = P->nsuper;
    for (int k = 0; k < B; k++) {
        for (int sn = 0; sn < ns; sn++) P->w[k].head[sn] = -1;
        P->w[k].minor = -1;
    }
    if (b) opt_snum_forward_begin(P, L, b);
    /* BLAS one-threaded: the threads are scaf's (bins, then the top's
     * updates and rows); OpenBLAS's own would spin beside them, and its
     * split of a product would change with the thread count */
    int blas = opt_blas_serial_begin();
    factor_job J = {P, A->val, L->x, -1, b != NULL};
    int minor = -1;
    if (B > 1) {
        /* the bins in par_threads() threads (one: in order); each bin's
         * work is the same whichever thread takes it */
        par_run(B, run_bin, &J);
        for (int k = 0; k < B; k++)
            if (P->w[k].minor >= 0 && (minor < 0 || P->w[k].minor < minor)) minor = P->w[k].minor;
        if (b && minor < 0) opt_snum_forward_gather(P);
    }
    for (int i = P->bptr[B > 1 ? B : 0]; i < ns && minor < 0; i++) {
        minor = factor_top(P, P->order[i], A->val, L->x);
        if (b && minor < 0) opt_snum_forward_super(P, &P->w[0], P->order[i], L->x, NULL);
    }
    opt_blas_serial_end(blas);
    L->minor = minor < 0 ? L->n : (size_t)minor;
    assert(minor >= 0 || diagonal_positive(P, L->x));
    return minor;
}

int opt_snum_factor(opt_snum *P, const opt_csc *A, cholmod_factor *L)
{
    return factor(P, A, L, NULL);
}

int opt_snum_factor_forward(opt_snum *P, const opt_csc *A, cholmod_factor *L, const double *b)
{
    return factor(P, A, L, b);
}
