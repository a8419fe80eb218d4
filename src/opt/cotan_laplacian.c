/* opt/cotan_laplacian: cotangent stiffness and lumped mass (see the header). */
#include "opt/cotan_laplacian.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void cross3(const double *a, const double *b, const double *c, double u[3], double v[3],
                   double x[3])
{
    for (int k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
    }
    x[0] = u[1] * v[2] - u[2] * v[1];
    x[1] = u[2] * v[0] - u[0] * v[2];
    x[2] = u[0] * v[1] - u[1] * v[0];
}

double opt_cot_at(const double *a, const double *b, const double *c)
{
    double u[3], v[3], x[3];
    cross3(a, b, c, u, v, x);
    double cr = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / cr;
}

double opt_tri_area3(const double *a, const double *b, const double *c)
{
    double u[3], v[3], x[3];
    cross3(a, b, c, u, v, x);
    return 0.5 * sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

scaf_status opt_cotan_laplacian(int nv, const double *V, int nf, const int *F, opt_csc *L,
                                scaf_error *err)
{
    memset(L, 0, sizeof *L);
    /* per face and corner: the off-diagonal pair and two diagonal terms;
     * plus one zero per vertex so every diagonal entry is stored */
    size_t cap = 9 * (size_t)nf + (size_t)nv;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *W = malloc(cap * sizeof *W);
    scaf_status st = SCAF_OK;
    if (!I || !J || !W) {
        st = err_nomem(err, "cotangent Laplacian");
        goto done;
    }
    int nt = 0;
    for (int v = 0; v < nv; v++) {
        I[nt] = J[nt] = v;
        W[nt++] = 0;
    }
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int o = F[3 * f + k], i = F[3 * f + (k + 1) % 3], j = F[3 * f + (k + 2) % 3];
            double w = 0.5 * opt_cot_at(V + 3 * (size_t)o, V + 3 * (size_t)i, V + 3 * (size_t)j);
            if (!isfinite(w)) {
                st = err_set(err, SCAF_ERR_MESH, "face %d has zero area: no cotangent weight", f);
                goto done;
            }
            I[nt] = i;
            J[nt] = j;
            W[nt++] = w;
            I[nt] = i;
            J[nt] = i;
            W[nt++] = -w;
            I[nt] = j;
            J[nt] = j;
            W[nt++] = -w;
        }
    st = opt_csc_from_triplets(L, nv, nt, I, J, W, err);
done:
    free(I);
    free(J);
    free(W);
    return st;
}

double opt_mass_barycentric(int nv, const double *V, int nf, const int *F, double *mass)
{
    double total = 0;
    for (int v = 0; v < nv; v++) mass[v] = 0;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * (size_t)f;
        double a = opt_tri_area3(V + 3 * (size_t)t[0], V + 3 * (size_t)t[1], V + 3 * (size_t)t[2]);
        for (int k = 0; k < 3; k++) mass[t[k]] += a / 3;
        total += a;
    }
    return total;
}
