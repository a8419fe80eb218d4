/* opt/supernodal_solve: see supernodal_solve.h. */
#include "opt/supernodal_solve.h"

#include <assert.h>

#include "base/parallel.h"
#include "opt/blas_threads.h"
#include "opt/dense_blas.h"

static const double one = 1.0, zero = 0.0, minus_one = -1.0;
static const int inc1 = 1;

/* Triangles of supernodes at most this wide are solved by trsv_lower_t. */
#define SMALL_TRIANGLE 64

/* y := L^-T y for the n x n lower triangle L (ld), by rows of L: each x_k
 * found is subtracted from the entries before it at once (the row is in
 * cache: the block is small). dtrsv takes a dot product per column
 * instead, a chain of dependent additions: about half of the backward
 * sweep on aphrodite, whose values sit mostly in 17-32 column supernodes
 * (the sweep 9.7-10.1 -> 8.3-8.7 ms). */
static void trsv_lower_t(const double *L, int ld, int n, double *y)
{
    for (int k = n - 1; k >= 0; k--) {
        const double *row = L + k;
        double xk = y[k] / row[(size_t)k * (size_t)ld];
        y[k] = xk;
        for (int c = 0; c < k; c++) y[c] -= row[(size_t)c * (size_t)ld] * xk;
    }
}

void opt_snum_forward_super(const opt_snum *P, opt_snum_worker *wk, int sn, const double *Lx,
                            double *acc)
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

/* How far below the block being solved the backward sweep prefetches (in
 * doubles: 16 KB). The sweep walks the factor's blocks from the last to
 * the first, each block upwards: the hardware follows the run inside a
 * block but not the jump to the block below, so every block started with
 * a wait on memory (aphrodite: the backward sweep 7.8-8.0 -> 5.5-5.7 ms;
 * 4 KB ahead 7.2-7.5, 32-128 KB the same as 16 KB). */
#define PREFETCH_AHEAD 2048

/* Prefetch the factor's values from *cur down to PREFETCH_AHEAD below
 * start (the block being solved, ending at end); *cur restarts at start
 * when the last block solved was not just above this one. */
static void prefetch_below(const double *Lx, size_t *cur, size_t start, size_t end)
{
    if (*cur > end || *cur + PREFETCH_AHEAD < start) *cur = start;
    size_t want = start > PREFETCH_AHEAD ? start - PREFETCH_AHEAD : 0;
    while (*cur > want) {
        *cur = *cur > 8 ? *cur - 8 : 0;
        __builtin_prefetch(Lx + *cur);
    }
}

/* Backward step of supernode sn: y_s = L_ss^-T (y_s - L_below^T y_below). */
static void backward_super(const opt_snum *P, opt_snum_worker *wk, int sn, const double *Lx)
{
    size_t start = (size_t)P->px[sn], end = (size_t)P->px[sn + 1];
    prefetch_below(Lx, &wk->prefetch, start, end);
    int k1 = P->super[sn], nscol = P->super[sn + 1] - k1;
    int nsrow = P->pi[sn + 1] - P->pi[sn], nrest = nsrow - nscol;
    const double *X = Lx + P->px[sn];
    double *ys = P->y + k1;
    if (nrest > 0) {
        const int *rows = P->s + P->pi[sn] + nscol;
        for (int i = 0; i < nrest; i++) wk->tmp[i] = P->y[rows[i]];
        dgemv_("T", &nrest, &nscol, &minus_one, X + nscol, &nsrow, wk->tmp, &inc1, &one, ys, &inc1);
    }
    if (nscol <= SMALL_TRIANGLE) trsv_lower_t(X, nsrow, nscol, ys);
    else dtrsv_("L", "T", "N", &nscol, X, &nsrow, ys, &inc1);
}

typedef struct solve_job {
    opt_snum *P;
    const double *Lx;
} solve_job;

static void run_bin_forward(void *ctx, int k)
{
    solve_job *J = ctx;
    opt_snum_worker *wk = &J->P->w[k];
    for (int i = J->P->bptr[k]; i < J->P->bptr[k + 1]; i++)
        opt_snum_forward_super(J->P, wk, J->P->order[i], J->Lx, wk->acc);
}

static void run_bin_backward(void *ctx, int k)
{
    solve_job *J = ctx;
    J->P->w[k].prefetch = (size_t)-1;
    for (int i = J->P->bptr[k + 1] - 1; i >= J->P->bptr[k]; i--)
        backward_super(J->P, &J->P->w[k], J->P->order[i], J->Lx);
}

void opt_snum_forward_begin(opt_snum *P, const cholmod_factor *L, const double *b)
{
    assert((int)L->n == P->n && L->super == P->super); /* also called as the factor begins */
    const int *perm = L->Perm;
    for (int k = 0; k < P->n; k++) P->y[k] = b[perm[k]];
    for (int h = 0; h < P->bins; h++)
        for (int t = 0; t < P->ntop; t++) P->w[h].acc[t] = 0;
}

void opt_snum_forward_gather(opt_snum *P)
{
    if (P->bins < 2) return;
    for (int k = 0; k < P->n; k++) {
        int t = P->toprow[k];
        if (t < 0) continue;
        for (int h = 0; h < P->bins; h++) P->y[k] -= P->w[h].acc[t];
    }
}

void opt_snum_backward(opt_snum *P, const cholmod_factor *L, double *x)
{
    assert((int)L->n == P->n && L->super == P->super && L->minor == L->n);
    int B = P->bins, ns = P->nsuper, top = P->bptr[B > 1 ? B : 0];
    const int *perm = L->Perm;
    solve_job J = {P, L->x};
    int blas = opt_blas_serial_begin();
    P->w[0].prefetch = (size_t)-1;
    for (int i = ns - 1; i >= top; i--) backward_super(P, &P->w[0], P->order[i], L->x);
    if (B > 1) par_run(B, run_bin_backward, &J);
    opt_blas_serial_end(blas);
    for (int k = 0; k < P->n; k++) x[perm[k]] = P->y[k];
}

void opt_snum_solve(opt_snum *P, const cholmod_factor *L, int nrhs, const double *B, double *X)
{
    int n = P->n, nb = P->bins, ns = P->nsuper, top = P->bptr[nb > 1 ? nb : 0];
    solve_job J = {P, L->x};
    for (int r = 0; r < nrhs; r++) {
        const double *b = B + (size_t)r * (size_t)n;
        double *x = X + (size_t)r * (size_t)n;
        opt_snum_forward_begin(P, L, b);
        int blas = opt_blas_serial_begin();
        if (nb > 1) par_run(nb, run_bin_forward, &J);
        opt_snum_forward_gather(P);
        for (int i = top; i < ns; i++) opt_snum_forward_super(P, &P->w[0], P->order[i], L->x, NULL);
        opt_blas_serial_end(blas);
        opt_snum_backward(P, L, x);
    }
}
