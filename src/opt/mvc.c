/* opt/mvc: mean-value weights and their non-symmetric sparse solve.
 *
 * Weights are computed per triangle corner from the 3D edge vectors with
 * a cancellation-free half-angle tangent; a vertex whose corners are not
 * all finite and positive falls back to uniform weights for its row. The
 * rows of the free vertices are assembled as triplets, compressed by
 * UMFPACK, factored once (opt/supernodal_lu; UMFPACK when it refuses)
 * and solved for u and v.
 */
#include "opt/mvc.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <umfpack.h>

#include "base/parallel.h"
#include "opt/blas_threads.h"
#include "opt/supernodal_lu.h"

/* tan(theta/2) of the angle between u and v, or 0 when it is not a
 * positive finite number (degenerate corner). sin/(1+cos) loses digits
 * near theta = pi, (1-cos)/sin near 0: pick the stable one by the sign of
 * the dot product. */
static double half_tan(const double *u, const double *v)
{
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
           z = u[0] * v[1] - u[1] * v[0];
    double c = sqrt(x * x + y * y + z * z);
    double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) *
        sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double t = d >= 0 ? c / (l + d) : (l - d) / c;
    return isfinite(t) && t > 0 ? t : 0.0;
}

int opt_mvc_corner_weights(int nv, const double *V, int nf, const int *F, double *W,
                           unsigned char *uniform_row)
{
    unsigned char *bad = uniform_row;
    unsigned char *own = NULL;
    if (!bad) {
        own = calloc(nv > 0 ? (size_t)nv : 1, 1);
        bad = own;
    } else {
        memset(bad, 0, (size_t)nv);
    }
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int i = F[3 * f + k], j = F[3 * f + (k + 1) % 3], l = F[3 * f + (k + 2) % 3];
            const double *xi = V + 3 * (size_t)i, *xj = V + 3 * (size_t)j, *xl = V + 3 * (size_t)l;
            double u[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
            double v[3] = {xl[0] - xi[0], xl[1] - xi[1], xl[2] - xi[2]};
            double t = half_tan(u, v);
            double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            double a = t / lu, b = t / lv;
            double *w = W + 6 * (size_t)f + 2 * (size_t)k;
            w[0] = a;
            w[1] = b;
            /* t = 0 marks a degenerate corner; a zero length gives NaN or
             * inf, a huge t over a tiny length can overflow. */
            if (!(t > 0) || !(a > 0) || !(b > 0) || !isfinite(a) || !isfinite(b) ||
                !isfinite(a + b)) {
                if (bad) bad[i] = 1;
                else {
                    w[0] = 1.0;
                    w[1] = 1.0;
                } /* no memory for the row flags: local corner fallback */
            }
        }
    /* Uniform fallback for the whole row of a vertex with a degenerate
     * corner: mixing uniform and mean-value weights in one row would weigh
     * the degenerate corner arbitrarily against the others. */
    int nbad = 0;
    if (bad) {
        for (int f = 0; f < nf; f++)
            for (int k = 0; k < 3; k++)
                if (bad[F[3 * f + k]]) {
                    W[6 * (size_t)f + 2 * (size_t)k] = 1.0;
                    W[6 * (size_t)f + 2 * (size_t)k + 1] = 1.0;
                }
        /* Row sums can still overflow when many huge weights meet at one
         * vertex: check and fall back. */
        double *sum = calloc(nv > 0 ? (size_t)nv : 1, sizeof *sum);
        if (sum) {
            for (int f = 0; f < nf; f++)
                for (int k = 0; k < 3; k++)
                    sum[F[3 * f + k]] +=
                        W[6 * (size_t)f + 2 * (size_t)k] + W[6 * (size_t)f + 2 * (size_t)k + 1];
            for (int f = 0; f < nf; f++)
                for (int k = 0; k < 3; k++) {
                    int i = F[3 * f + k];
                    if (!isfinite(sum[i])) {
                        bad[i] = 1;
                        W[6 * (size_t)f + 2 * (size_t)k] = 1.0;
                        W[6 * (size_t)f + 2 * (size_t)k + 1] = 1.0;
                    }
                }
            free(sum);
        }
        for (int i = 0; i < nv; i++) nbad += bad[i] != 0;
    }
    free(own);
    return nbad;
}

/* The u and v solves with one LU: independent (each allocates its own
 * workspace; the factor is only read), so they run side by side when
 * there are threads. */
typedef struct uv_solves {
    SuiteSparse_long n;
    const SuiteSparse_long *Ap, *Ai;
    const double *Ax, *b;
    double *x;
    void *num;
    int rc[2];
} uv_solves;

static void solve_one(void *ctx, int c)
{
    uv_solves *S = ctx;
    double info[UMFPACK_INFO];
    size_t off = (size_t)c * (size_t)S->n;
    S->rc[c] = umfpack_dl_solve(UMFPACK_A, S->Ap, S->Ai, S->Ax, S->x + off, S->b + off, S->num,
                                NULL, info);
}

/* x (2n: u then v) = A^-1 b by opt/supernodal_lu, A given with 64-bit
 * indices (UMFPACK's triplet conversion). SCAF_ERR_NUMERIC or
 * SCAF_ERR_USAGE when the LU refuses A (err untouched then). */
static scaf_status lu_solve(SuiteSparse_long n, const SuiteSparse_long *Ap,
                            const SuiteSparse_long *Ai, const double *Ax, const double *b,
                            double *x, scaf_error *err)
{
    if (Ap[n] > INT_MAX) return SCAF_ERR_USAGE;
    int *p = malloc(((size_t)n + 1) * sizeof *p), *i = malloc(((size_t)Ap[n] + 1) * sizeof *i);
    if (!p || !i) {
        free(p);
        free(i);
        return err_nomem(err, "mean-value system");
    }
    for (SuiteSparse_long k = 0; k <= n; k++) p[k] = (int)Ap[k];
    for (SuiteSparse_long k = 0; k < Ap[n]; k++) i[k] = (int)Ai[k];
    scaf_error e;
    err_clear(&e);
    /* BLAS in one thread: OpenBLAS's products in several threads sum in
     * another order (camelhead's start differed between --threads 1 and
     * 2), and the start must be the same bits at any thread count */
    int blas = opt_blas_serial_begin();
    opt_lu *F = opt_lu_factor((int)n, p, i, Ax, &e);
    free(p);
    free(i);
    if (F) {
        opt_lu_solve(F, b, x);
        opt_lu_solve(F, b + n, x + n);
        opt_lu_free(F);
    }
    opt_blas_serial_end(blas);
    if (!F) return e.code == SCAF_ERR_NOMEM ? err_nomem(err, "mean-value factorization") : e.code;
    return SCAF_OK;
}

scaf_status opt_mvc_solve(int nv, const double *V, int nf, const int *F, const unsigned char *fixed,
                          double *UV, scaf_error *err)
{
    scaf_status st = SCAF_OK;
    int *dof = malloc((nv > 0 ? (size_t)nv : 1) * sizeof *dof);
    double *W = malloc((nf > 0 ? 6 * (size_t)nf : 1) * sizeof *W);
    size_t cap = 9 * (size_t)nf + 1;
    /* 64-bit indices (umfpack_dl_*): the int version runs out of its
     * int-indexed workspace on millions of unknowns (7.1M faces) */
    SuiteSparse_long *Ti = malloc(cap * sizeof *Ti), *Tj = malloc(cap * sizeof *Tj);
    double *Tx = malloc(cap * sizeof *Tx);
    SuiteSparse_long *Ap = NULL, *Ai = NULL;
    double *Ax = NULL, *b = NULL, *x = NULL;
    void *sym = NULL, *num = NULL;
    if (!dof || !W || !Ti || !Tj || !Tx) {
        st = err_nomem(err, "mean-value system");
        goto done;
    }
    int n = 0;
    for (int v = 0; v < nv; v++) dof[v] = fixed[v] ? -1 : n++;
    if (n == 0) goto done;
    b = calloc(2 * (size_t)n, sizeof *b);
    x = malloc(2 * (size_t)n * sizeof *x);
    Ap = malloc(((size_t)n + 1) * sizeof *Ap);
    Ai = malloc(cap * sizeof *Ai);
    Ax = malloc(cap * sizeof *Ax);
    if (!b || !x || !Ap || !Ai || !Ax) {
        st = err_nomem(err, "mean-value system");
        goto done;
    }
    opt_mvc_corner_weights(nv, V, nf, F, W, NULL);
    int nt = 0;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int i = F[3 * f + k], di = dof[i];
            if (di < 0) continue;
            int j = F[3 * f + (k + 1) % 3], l = F[3 * f + (k + 2) % 3];
            double wj = W[6 * (size_t)f + 2 * (size_t)k], wl = W[6 * (size_t)f + 2 * (size_t)k + 1];
            Ti[nt] = di;
            Tj[nt] = di;
            Tx[nt++] = wj + wl;
            if (dof[j] >= 0) {
                Ti[nt] = di;
                Tj[nt] = dof[j];
                Tx[nt++] = -wj;
            } else {
                b[di] += wj * UV[2 * (size_t)j];
                b[n + di] += wj * UV[2 * (size_t)j + 1];
            }
            if (dof[l] >= 0) {
                Ti[nt] = di;
                Tj[nt] = dof[l];
                Tx[nt++] = -wl;
            } else {
                b[di] += wl * UV[2 * (size_t)l];
                b[n + di] += wl * UV[2 * (size_t)l + 1];
            }
        }
    int rc = umfpack_dl_triplet_to_col(n, n, nt, Ti, Tj, Tx, Ap, Ai, Ax, NULL);
    if (rc == UMFPACK_ERROR_out_of_memory) {
        st = err_nomem(err, "mean-value system");
        goto done;
    }
    if (rc != UMFPACK_OK) {
        st = err_set(err, SCAF_ERR_NUMERIC,
                     "mean-value system: UMFPACK triplet conversion failed (status %d)", rc);
        goto done;
    }
    /* Every weight is positive (opt_mvc_corner_weights), so the matrix is
     * an M-matrix: the LU without pivots on the symmetric pattern's
     * supernodes (opt/supernodal_lu) is exact and far faster than
     * UMFPACK's; UMFPACK stays for what that LU refuses (a singular
     * system, whose error it words). */
    st = lu_solve(n, Ap, Ai, Ax, b, x, err);
    if (st == SCAF_OK) goto place;
    if (st == SCAF_ERR_NOMEM) goto done;
    st = SCAF_OK;
    double info[UMFPACK_INFO];
    /* BLAS in one thread: the two solves take the threads, and the
     * factorization's products then sum in the same order at any thread
     * count */
    int blas = opt_blas_serial_begin();
    rc = umfpack_dl_symbolic(n, n, Ap, Ai, Ax, &sym, NULL, info);
    if (rc == UMFPACK_OK) rc = umfpack_dl_numeric(Ap, Ai, Ax, sym, &num, NULL, info);
    if (rc == UMFPACK_OK) {
        uv_solves S = {n, Ap, Ai, Ax, b, x, num, {UMFPACK_OK, UMFPACK_OK}};
        par_run(2, solve_one, &S);
        rc = S.rc[0] != UMFPACK_OK ? S.rc[0] : S.rc[1];
    }
    opt_blas_serial_end(blas);
    if (rc == UMFPACK_ERROR_out_of_memory) {
        st = err_nomem(err, "mean-value factorization");
        goto done;
    }
    /* A warning (singular matrix) counts as failure too: the map would not
     * be a convex-combination embedding. */
    if (rc != UMFPACK_OK) {
        st = err_set(err, SCAF_ERR_NUMERIC,
                     "mean-value system is singular or ill-posed (UMFPACK status %d): a component "
                     "not connected to the boundary?",
                     rc);
        goto done;
    }
place:
    for (int v = 0; v < nv; v++)
        if (dof[v] >= 0) {
            double u0 = x[dof[v]], u1 = x[n + dof[v]];
            if (!isfinite(u0) || !isfinite(u1)) {
                st = err_set(err, SCAF_ERR_NUMERIC,
                             "mean-value solve gave a non-finite position for vertex %d", v);
                goto done;
            }
            UV[2 * (size_t)v] = u0;
            UV[2 * (size_t)v + 1] = u1;
        }
done:
    if (num) umfpack_dl_free_numeric(&num);
    if (sym) umfpack_dl_free_symbolic(&sym);
    free(dof);
    free(W);
    free(Ti);
    free(Tj);
    free(Tx);
    free(Ap);
    free(Ai);
    free(Ax);
    free(b);
    free(x);
    return st;
}
