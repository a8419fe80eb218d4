/* tests/opt/sym_eigen: eigenvalues of a small dense symmetric matrix.
 *
 * Cyclic Jacobi rotations (accurate to a few ulps of the matrix norm), so
 * tests can check definiteness and ranks without LAPACK. Header-only.
 */
#ifndef SCAF_TESTS_OPT_SYM_EIGEN_H
#define SCAF_TESTS_OPT_SYM_EIGEN_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

static inline int sym_eigen_cmp(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* A: n by n symmetric, row-major (read only). w: n eigenvalues out,
 * ascending. Returns 0, or -1 when out of memory. */
static inline int sym_eigenvalues(int n, const double *A, double *w)
{
    double *M = malloc((size_t)n * n * sizeof *M);
    if (!M) return -1;
    memcpy(M, A, (size_t)n * n * sizeof *M);
    for (int sweep = 0; sweep < 100; sweep++) {
        double off = 0, tot = 0;
        for (int p = 0; p < n; p++)
            for (int q = 0; q < n; q++) {
                double v = M[p * n + q] * M[p * n + q];
                tot += v;
                if (p != q) off += v;
            }
        if (off <= 1e-30 * tot || off == 0) break;
        for (int p = 0; p < n; p++)
            for (int q = p + 1; q < n; q++) {
                double apq = M[p * n + q];
                if (apq == 0) continue;
                double theta = (M[q * n + q] - M[p * n + p]) / (2 * apq);
                double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; k++) { /* columns p, q */
                    double mkp = M[k * n + p], mkq = M[k * n + q];
                    M[k * n + p] = c * mkp - s * mkq;
                    M[k * n + q] = s * mkp + c * mkq;
                }
                for (int k = 0; k < n; k++) { /* rows p, q */
                    double mpk = M[p * n + k], mqk = M[q * n + k];
                    M[p * n + k] = c * mpk - s * mqk;
                    M[q * n + k] = s * mpk + c * mqk;
                }
            }
    }
    for (int k = 0; k < n; k++) w[k] = M[k * n + k];
    free(M);
    qsort(w, (size_t)n, sizeof *w, sym_eigen_cmp);
    return 0;
}

#endif /* SCAF_TESTS_OPT_SYM_EIGEN_H */
