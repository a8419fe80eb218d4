/* app/chart_init: the initial UV embedding of one chart (see chart_init.h).
 *
 * Builds the fill (one temporary vertex per hole), the weighted graph
 * Laplacian restricted to the free vertices (all but loop 0), and solves
 * for u and v at once with CHOLMOD. Cotangent weights of the fill use the
 * fill's 3D triangles.
 */
#include "app/chart_init.h"

#include <cholmod.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"

#define SCAF_PI 3.14159265358979323846

static double cot3(const double *a, const double *b, const double *c)
{
    /* cotangent of the angle at a in triangle a, b, c */
    double u[3], v[3];
    for (int k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
    }
    double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double s = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    return s > 0.0 ? d / s : 0.0;
}

/* Solve the Dirichlet problem with the given weights. Returns 1 on
 * success, 0 when the matrix is not positive definite, -1 on no memory. */
static int solve_laplace(int N, const double *P, int M, const int *T, const unsigned char *pinned,
                         int harmonic, double *UV, cholmod_common *c)
{
    int *unk = malloc(sizeof(int) * (size_t)N);
    if (!unk) return -1;
    int nu = 0;
    for (int i = 0; i < N; i++) unk[i] = pinned[i] ? -1 : nu++;
    int ret = 1;
    if (nu == 0) {
        free(unk);
        return 1;
    }
    cholmod_triplet *Tr = cholmod_allocate_triplet((size_t)nu, (size_t)nu, 9 * (size_t)M + (size_t)nu, 1,
                                                   CHOLMOD_REAL, c);
    cholmod_dense *B = cholmod_zeros((size_t)nu, 2, CHOLMOD_REAL, c);
    cholmod_sparse *A = NULL;
    cholmod_factor *L = NULL;
    cholmod_dense *X = NULL;
    if (!Tr || !B) {
        ret = -1;
        goto out;
    }
    int *Ti = Tr->i, *Tj = Tr->j;
    double *Tx = Tr->x, *b = B->x;
    size_t nz = 0;
    for (int t = 0; t < M; t++)
        for (int k = 0; k < 3; k++) {
            int i = T[3 * t + (k + 1) % 3], j = T[3 * t + (k + 2) % 3], o = T[3 * t + k];
            double w = harmonic ? 0.5 * cot3(P + 3 * (size_t)o, P + 3 * (size_t)i, P + 3 * (size_t)j) : 0.5;
            /* Each interior edge is seen from two triangles: uniform 0.5 + 0.5. */
            int ui = unk[i], uj = unk[j];
            if (ui >= 0) {
                Ti[nz] = ui; Tj[nz] = ui; Tx[nz] = w; nz++;
                if (uj < 0) {
                    b[ui] += w * UV[2 * (size_t)j];
                    b[nu + ui] += w * UV[2 * (size_t)j + 1];
                }
            }
            if (uj >= 0) {
                Ti[nz] = uj; Tj[nz] = uj; Tx[nz] = w; nz++;
                if (ui < 0) {
                    b[uj] += w * UV[2 * (size_t)i];
                    b[nu + uj] += w * UV[2 * (size_t)i + 1];
                }
            }
            if (ui >= 0 && uj >= 0) {
                Ti[nz] = ui < uj ? ui : uj;
                Tj[nz] = ui < uj ? uj : ui;
                Tx[nz] = -w;
                nz++;
            }
        }
    Tr->nnz = nz;
    A = cholmod_triplet_to_sparse(Tr, nz, c);
    if (!A) {
        ret = -1;
        goto out;
    }
    L = cholmod_analyze(A, c);
    if (!L) {
        ret = -1;
        goto out;
    }
    cholmod_factorize(A, L, c);
    if (c->status != CHOLMOD_OK) {
        ret = c->status == CHOLMOD_OUT_OF_MEMORY ? -1 : 0;
        goto out;
    }
    X = cholmod_solve(CHOLMOD_A, L, B, c);
    if (!X) {
        ret = -1;
        goto out;
    }
    const double *x = X->x;
    for (int i = 0; i < N; i++)
        if (unk[i] >= 0) {
            UV[2 * (size_t)i] = x[unk[i]];
            UV[2 * (size_t)i + 1] = x[nu + unk[i]];
            if (!isfinite(UV[2 * (size_t)i]) || !isfinite(UV[2 * (size_t)i + 1])) ret = 0;
        }
out:
    cholmod_free_triplet(&Tr, c);
    cholmod_free_dense(&B, c);
    cholmod_free_sparse(&A, c);
    cholmod_free_factor(&L, c);
    cholmod_free_dense(&X, c);
    free(unk);
    return ret;
}

scaf_status chart_embed(int n, const double *P, int m, const int *T, int nloops, const int *loop_start,
                        const int *loop_v, int harmonic, double *uv, int *used_harmonic,
                        scaf_error *err)
{
    if (used_harmonic) *used_harmonic = 0;
    if (nloops < 1) return err_set(err, SCAF_ERR_MESH, "the chart has no boundary");
    int nh = nloops - 1;
    int nfill = loop_start[nloops] - loop_start[1];
    int N = n + nh, M = m + nfill;
    double *PP = malloc(sizeof(double) * 3 * (size_t)N);
    int *TT = malloc(sizeof(int) * 3 * (size_t)(M ? M : 1));
    double *UV = calloc(2 * (size_t)N, sizeof(double));
    unsigned char *pinned = calloc((size_t)N, 1);
    cholmod_common c;
    cholmod_start(&c);
    c.print = 0;
    scaf_status st = SCAF_OK;
    if (!PP || !TT || !UV || !pinned) {
        st = err_nomem(err, "chart embedding");
        goto done;
    }
    memcpy(PP, P, sizeof(double) * 3 * (size_t)n);
    memcpy(TT, T, sizeof(int) * 3 * (size_t)m);
    int mt = m;
    for (int h = 1; h < nloops; h++) {
        int ctr = n + h - 1, s = loop_start[h], e = loop_start[h + 1], k = e - s;
        double *q = PP + 3 * (size_t)ctr;
        q[0] = q[1] = q[2] = 0.0;
        for (int i = s; i < e; i++)
            for (int d = 0; d < 3; d++) q[d] += P[3 * (size_t)loop_v[i] + d] / k;
        for (int i = 0; i < k; i++) {
            int a = loop_v[s + i], b = loop_v[s + (i + 1) % k];
            TT[3 * mt] = b;
            TT[3 * mt + 1] = a;
            TT[3 * mt + 2] = ctr;
            mt++;
        }
    }
    /* Chart area and outer loop on the circle, by arc length. */
    double area = 0.0;
    for (int t = 0; t < m; t++) {
        const double *a = P + 3 * (size_t)T[3 * t], *b = P + 3 * (size_t)T[3 * t + 1], *cc = P + 3 * (size_t)T[3 * t + 2];
        double u[3], v[3];
        for (int d = 0; d < 3; d++) {
            u[d] = b[d] - a[d];
            v[d] = cc[d] - a[d];
        }
        double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    }
    double R = sqrt(area / SCAF_PI);
    int s0 = loop_start[0], k0 = loop_start[1] - s0;
    double total = 0.0;
    for (int i = 0; i < k0; i++) {
        const double *a = P + 3 * (size_t)loop_v[s0 + i], *b = P + 3 * (size_t)loop_v[s0 + (i + 1) % k0];
        total += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
    double run = 0.0;
    for (int i = 0; i < k0; i++) {
        int v = loop_v[s0 + i];
        double ang = total > 0.0 ? 2.0 * SCAF_PI * run / total : 2.0 * SCAF_PI * i / k0;
        UV[2 * (size_t)v] = R * cos(ang);
        UV[2 * (size_t)v + 1] = R * sin(ang);
        pinned[v] = 1;
        const double *a = P + 3 * (size_t)v, *b = P + 3 * (size_t)loop_v[s0 + (i + 1) % k0];
        run += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
    for (int pass = harmonic ? 0 : 1; pass < 2; pass++) {
        int r = solve_laplace(N, PP, M, TT, pinned, pass == 0, UV, &c);
        if (r < 0) {
            st = err_nomem(err, "chart embedding system");
            goto done;
        }
        int ok = r > 0;
        for (int t = 0; ok && t < m; t++)
            if (!(orient2d(UV + 2 * (size_t)T[3 * t], UV + 2 * (size_t)T[3 * t + 1], UV + 2 * (size_t)T[3 * t + 2]) > 0.0))
                ok = 0;
        if (ok) {
            if (used_harmonic) *used_harmonic = pass == 0;
            memcpy(uv, UV, sizeof(double) * 2 * (size_t)n);
            goto done;
        }
    }
    st = err_set(err, SCAF_ERR_NUMERIC,
                 "the Tutte embedding has a flipped triangle in floating point (degenerate geometry?)");
done:
    cholmod_finish(&c);
    free(PP);
    free(TT);
    free(UV);
    free(pinned);
    return st;
}
