/* app/inflate: the scaled target and the growth measure (see inflate.h). */
#include "app/inflate.h"

#include <math.h>
#include <stddef.h>

void inflate_target(int nv, const double *V, int nf, const int *F, double K, double *target)
{
    double c[3] = {0, 0, 0}, area = 0.0;
    for (int f = 0; f < nf; f++) {
        const double *a = V + 3 * (size_t)F[3 * f], *b = V + 3 * (size_t)F[3 * f + 1],
                     *d = V + 3 * (size_t)F[3 * f + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double n0 = u[1] * v[2] - u[2] * v[1], n1 = u[2] * v[0] - u[0] * v[2],
               n2 = u[0] * v[1] - u[1] * v[0];
        double A = 0.5 * sqrt(n0 * n0 + n1 * n1 + n2 * n2);
        area += A;
        for (int k = 0; k < 3; k++) c[k] += A * (a[k] + b[k] + d[k]) / 3.0;
    }
    if (area > 0.0) {
        for (int k = 0; k < 3; k++) c[k] /= area;
    } else {
        c[0] = c[1] = c[2] = 0.0;
        for (int i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++) c[k] += V[3 * (size_t)i + k] / nv;
    }
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            target[3 * (size_t)i + k] = c[k] + K * (V[3 * (size_t)i + k] - c[k]);
}

double inflate_bbox_diagonal(int nv, const double *V)
{
    if (nv < 1) return 0.0;
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = V[k];
    for (int i = 1; i < nv; i++)
        for (int k = 0; k < 3; k++) {
            double x = V[3 * (size_t)i + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
    double s = 0.0;
    for (int k = 0; k < 3; k++) s += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(s);
}
