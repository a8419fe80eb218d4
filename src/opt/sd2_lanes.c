/* opt/sd2_lanes: see sd2_lanes.h. Each batch: the Jacobians gathered into
 * lane arrays, the arithmetic of opt/energy's symmetric Dirichlet written
 * lane by lane (a vector operation per line: no lane depends on another),
 * then the weighted values added one by one in simplex order. */
#include "opt/sd2_lanes.h"

#include <math.h>

#include "opt/vector_clones.h"

#define LANES 8

/* J (j0..j3, row-major 2 x 2) of triangles s0 .. s0 + m - 1 at X. */
static inline void gather_jacobians(const opt_simplices *S, const double *X, size_t s0, int m,
                                    double *j0, double *j1, double *j2, double *j3)
{
    for (int l = 0; l < m; l++) {
        double J[4];
        opt_jacobian(S, (int)(s0 + (size_t)l), X, J);
        j0[l] = J[0];
        j1[l] = J[1];
        j2[l] = J[2];
        j3[l] = J[3];
    }
}

/* The kernels are static: a target_clones function's resolver would be
 * exported from the shared library whatever the visibility. */
VECTOR_CLONES static double energy_lanes(const opt_simplices *S, const double *X, size_t lo,
                                         size_t hi)
{
    double acc = 0;
    for (size_t s0 = lo; s0 < hi; s0 += LANES) {
        int m = hi - s0 < LANES ? (int)(hi - s0) : LANES;
        double j0[LANES] = {0}, j1[LANES] = {0}, j2[LANES] = {0}, j3[LANES] = {0}, v[LANES];
        gather_jacobians(S, X, s0, m, j0, j1, j2, j3);
        for (int l = 0; l < LANES; l++) {
            double det = j0[l] * j3[l] - j1[l] * j2[l];
            double i0 = j3[l] / det, i1 = -j1[l] / det, i2 = -j2[l] / det, i3 = j0[l] / det;
            double fj = j0[l] * j0[l] + j1[l] * j1[l] + j2[l] * j2[l] + j3[l] * j3[l];
            double fi = i0 * i0 + i1 * i1 + i2 * i2 + i3 * i3;
            v[l] = det > 0 ? fj + fi : INFINITY;
        }
        for (int l = 0; l < m; l++) acc += S->weight[s0 + (size_t)l] * v[l];
    }
    return acc;
}

VECTOR_CLONES static void energy_slope_lanes(const opt_simplices *S, const double *X,
                                             const double *D, size_t lo, size_t hi, double *e,
                                             double *slope)
{
    double ea = *e, sa = *slope;
    for (size_t s0 = lo; s0 < hi; s0 += LANES) {
        int m = hi - s0 < LANES ? (int)(hi - s0) : LANES;
        double j0[LANES] = {0}, j1[LANES] = {0}, j2[LANES] = {0}, j3[LANES] = {0};
        double d0[LANES] = {0}, d1[LANES] = {0}, d2[LANES] = {0}, d3[LANES] = {0};
        double v[LANES], dot[LANES];
        gather_jacobians(S, X, s0, m, j0, j1, j2, j3);
        gather_jacobians(S, D, s0, m, d0, d1, d2, d3);
        for (int l = 0; l < LANES; l++) {
            double det = j0[l] * j3[l] - j1[l] * j2[l];
            double i0 = j3[l] / det, i1 = -j1[l] / det, i2 = -j2[l] / det, i3 = j0[l] / det;
            /* A = J^-T J^-1, then dE/dJ = 2 J - 2 A J^-T (opt/energy) */
            double a00 = i0 * i0 + i2 * i2, a01 = i0 * i1 + i2 * i3;
            double a10 = i1 * i0 + i3 * i2, a11 = i1 * i1 + i3 * i3;
            double g0 = 2.0 * j0[l] - 2.0 * (a00 * i0 + a01 * i1);
            double g1 = 2.0 * j1[l] - 2.0 * (a00 * i2 + a01 * i3);
            double g2 = 2.0 * j2[l] - 2.0 * (a10 * i0 + a11 * i1);
            double g3 = 2.0 * j3[l] - 2.0 * (a10 * i2 + a11 * i3);
            double fj = j0[l] * j0[l] + j1[l] * j1[l] + j2[l] * j2[l] + j3[l] * j3[l];
            double fi = i0 * i0 + i1 * i1 + i2 * i2 + i3 * i3;
            int ok = det > 0;
            v[l] = ok ? fj + fi : INFINITY;
            double p = g0 * d0[l] + g1 * d1[l] + g2 * d2[l] + g3 * d3[l];
            dot[l] = ok ? p : NAN;
        }
        for (int l = 0; l < m; l++) {
            double w = S->weight[s0 + (size_t)l];
            sa += w * dot[l];
            ea += w * v[l];
        }
    }
    *e = ea;
    *slope = sa;
}

double opt_sd2_energy_range(const opt_simplices *S, const double *X, size_t lo, size_t hi)
{
    return energy_lanes(S, X, lo, hi);
}

void opt_sd2_energy_slope_range(const opt_simplices *S, const double *X, const double *D,
                                size_t lo, size_t hi, double *e, double *slope)
{
    energy_slope_lanes(S, X, D, lo, hi, e, slope);
}
