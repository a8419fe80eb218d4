/* geom/tet_quality: the volume-length ratio of a tetrahedron (see the
 * header). With det = det[b - a, c - a, d - a] = 6 V and S the sum of the
 * six squared edge lengths, q = 12 sqrt(3) det / S^(3/2). */
#include "geom/tet_quality.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define Q_SCALE 20.784609690826528 /* 12 sqrt(3): q = 1 for the regular tet */

static void sub3(const double *p, const double *q, double *r)
{
    r[0] = p[0] - q[0], r[1] = p[1] - q[1], r[2] = p[2] - q[2];
}

static double dot3(const double *p, const double *q)
{
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

static void cross3(const double *p, const double *q, double *r)
{
    r[0] = p[1] * q[2] - p[2] * q[1];
    r[1] = p[2] * q[0] - p[0] * q[2];
    r[2] = p[0] * q[1] - p[1] * q[0];
}

double tet_quality(const double a[3], const double b[3], const double c[3], const double d[3])
{
    double u[3], v[3], w[3], x[3], y[3], z[3], n[3];
    sub3(b, a, u), sub3(c, a, v), sub3(d, a, w);
    sub3(c, b, x), sub3(d, b, y), sub3(d, c, z);
    cross3(v, w, n);
    double det = dot3(u, n);
    double S = dot3(u, u) + dot3(v, v) + dot3(w, w) + dot3(x, x) + dot3(y, y) + dot3(z, z);
    if (!(S > 0)) return 0;
    return Q_SCALE * det / (S * sqrt(S));
}

double tet_quality_grad(const double a[3], const double b[3], const double c[3], const double d[3],
                        double grad_a[3])
{
    double u[3], v[3], w[3], x[3], y[3], z[3], n[3], gdet[3];
    sub3(b, a, u), sub3(c, a, v), sub3(d, a, w);
    sub3(c, b, x), sub3(d, b, y), sub3(d, c, z);
    cross3(v, w, n);
    double det = dot3(u, n);
    double S = dot3(u, u) + dot3(v, v) + dot3(w, w) + dot3(x, x) + dot3(y, y) + dot3(z, z);
    if (!(S > 0)) {
        memset(grad_a, 0, 3 * sizeof(double));
        return 0;
    }
    /* d det / d a = (d - b) x (c - b); d S / d a = -2 (u + v + w) */
    cross3(y, x, gdet);
    double s32 = S * sqrt(S);
    double q = Q_SCALE * det / s32;
    for (int k = 0; k < 3; k++) {
        double gS = -2 * (u[k] + v[k] + w[k]);
        grad_a[k] = Q_SCALE * gdet[k] / s32 - 1.5 * q / S * gS;
    }
    return q;
}

/* Median-of-three pivots. */
double tet_quality_kth(double *x, int n, int k)
{
    int lo = 0, hi = n - 1;
    while (hi > lo) {
        int mid = lo + (hi - lo) / 2;
        double a = x[lo], b = x[mid], c = x[hi];
        double pivot = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
        int i = lo, j = hi;
        while (i <= j) {
            while (x[i] < pivot) i++;
            while (x[j] > pivot) j--;
            if (i <= j) {
                double t = x[i];
                x[i++] = x[j];
                x[j--] = t;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return x[k];
    }
    return x[k];
}

int tet_quality_summary(int n, const double *q, double *min, double *p5)
{
    *min = 0, *p5 = 0;
    if (n <= 0) return 0;
    double *x = malloc(sizeof *x * (size_t)n);
    if (!x) return -1;
    memcpy(x, q, sizeof *x * (size_t)n);
    double m = x[0];
    for (int i = 1; i < n; i++)
        if (x[i] < m) m = x[i];
    *min = m;
    *p5 = tet_quality_kth(x, n, (int)(0.05 * n));
    free(x);
    return 0;
}
