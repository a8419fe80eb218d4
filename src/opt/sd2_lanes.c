/* opt/sd2_lanes: see sd2_lanes.h. Each batch: the Jacobians gathered into
 * lane arrays, the arithmetic of symmetric Dirichlet's row
 * (opt/energy_symmetric_dirichlet.c, opt/energy.c's 2D proxy) written
 * lane by lane (a vector operation per line: no lane depends on another),
 * then the weighted values added one by one in simplex order. */
#include "opt/sd2_lanes.h"

#include <float.h>
#include <math.h>

#include "opt/sd_weight.h"
#include "opt/small_svd.h"
#include "opt/vector_clones.h"

/* Simplices per batch: enough that the lane loops stay loops, which the
 * compiler turns into vector code (a loop of 8 it unrolls into scalar
 * operations instead). */
#define LANES 64

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

/* J at X (j0..j3) and at D (d0..d3) of triangles s0 .. s0 + m - 1, each
 * triangle's corners and gradients read once: opt_jacobian's operations. */
static inline void gather_jacobian_pairs(const opt_simplices *S, const double *X, const double *D,
                                         size_t s0, int m, double *j0, double *j1, double *j2,
                                         double *j3, double *d0, double *d1, double *d2, double *d3)
{
    for (int l = 0; l < m; l++) {
        size_t s = s0 + (size_t)l;
        const int *ix = S->idx + s * 3;
        const double *G = S->grad + s * 6;
        size_t i0 = 2 * (size_t)ix[0], i1 = 2 * (size_t)ix[1], i2 = 2 * (size_t)ix[2];
        j0[l] = X[i0] * G[0] + X[i1] * G[2] + X[i2] * G[4];
        j1[l] = X[i0] * G[1] + X[i1] * G[3] + X[i2] * G[5];
        j2[l] = X[i0 + 1] * G[0] + X[i1 + 1] * G[2] + X[i2 + 1] * G[4];
        j3[l] = X[i0 + 1] * G[1] + X[i1 + 1] * G[3] + X[i2 + 1] * G[5];
        d0[l] = D[i0] * G[0] + D[i1] * G[2] + D[i2] * G[4];
        d1[l] = D[i0] * G[1] + D[i1] * G[3] + D[i2] * G[5];
        d2[l] = D[i0 + 1] * G[0] + D[i1 + 1] * G[2] + D[i2 + 1] * G[4];
        d3[l] = D[i0 + 1] * G[1] + D[i1 + 1] * G[3] + D[i2 + 1] * G[5];
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
        double dt[LANES];
        gather_jacobians(S, X, s0, m, j0, j1, j2, j3);
        for (int l = 0; l < LANES; l++) {
            double det = j0[l] * j3[l] - j1[l] * j2[l];
            double i0 = j3[l] / det, i1 = -j1[l] / det, i2 = -j2[l] / det, i3 = j0[l] / det;
            double fj = j0[l] * j0[l] + j1[l] * j1[l] + j2[l] * j2[l] + j3[l] * j3[l];
            double fi = i0 * i0 + i1 * i1 + i2 * i2 + i3 * i3;
            dt[l] = det;
            v[l] = fj + fi;
        }
        /* The sign test here, in the ordered sum, not in the lane loop:
         * a select there kept GCC from vectorizing it. */
        for (int l = 0; l < m; l++)
            acc += S->weight[s0 + (size_t)l] * (dt[l] > 0 ? v[l] : INFINITY);
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
        double v[LANES], dot[LANES], dt[LANES];
        gather_jacobian_pairs(S, X, D, s0, m, j0, j1, j2, j3, d0, d1, d2, d3);
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
            dt[l] = det;
            v[l] = fj + fi;
            dot[l] = g0 * d0[l] + g1 * d1[l] + g2 * d2[l] + g3 * d3[l];
        }
        for (int l = 0; l < m; l++) { /* the sign test as in energy_lanes */
            double w = S->weight[s0 + (size_t)l];
            int ok = dt[l] > 0;
            sa += w * (ok ? dot[l] : NAN);
            ea += w * (ok ? v[l] : INFINITY);
        }
    }
    *e = ea;
    *slope = sa;
}

VECTOR_CLONES static double proxy_lanes(const opt_simplices *S, const double *X, size_t lo,
                                        size_t hi, double w2_cap, double *loc)
{
    double w2max = 0;
    for (size_t s0 = lo; s0 < hi; s0 += LANES) {
        int m = hi - s0 < LANES ? (int)(hi - s0) : LANES;
        double j0[LANES] = {0}, j1[LANES] = {0}, j2[LANES] = {0}, j3[LANES] = {0};
        double E[LANES], F[LANES], G[LANES], H[LANES], Q[LANES], R[LANES], w2[LANES];
        gather_jacobians(S, X, s0, m, j0, j1, j2, j3);
        int slow = 0;
        for (int l = 0; l < LANES; l++) {
            E[l] = 0.5 * (j0[l] + j3[l]);
            F[l] = 0.5 * (j0[l] - j3[l]);
            G[l] = 0.5 * (j2[l] + j1[l]);
            H[l] = 0.5 * (j2[l] - j1[l]);
            double q = E[l] * E[l] + H[l] * H[l], r = F[l] * F[l] + G[l] * G[l];
            /* q, r >= 0 or NaN (then slow): the guard only tells GCC that
             * sqrt needs no branch, which keeps the loop vector code */
            Q[l] = sqrt(q > 0 ? q : 0.0);
            R[l] = sqrt(r > 0 ? r : 0.0);
            slow |= !((q >= DBL_MIN) & (q <= DBL_MAX)) | !((r >= DBL_MIN) & (r <= DBL_MAX));
        }
        if (slow) /* svd_hypot's own choice, lane by lane (rare) */
            for (int l = 0; l < LANES; l++) {
                Q[l] = svd_hypot(E[l], H[l]);
                R[l] = svd_hypot(F[l], G[l]);
            }
        for (int l = 0; l < LANES; l++) {
            /* opt/energy's proxy2_rotation_target, then proxy_block's
             * M = W^T W, MT = M T and lin = pullback(G_s, MT) */
            double s0v = Q[l] + R[l], s1v = Q[l] - R[l];
            double w0 = opt_sd_w2(s0v), w1 = opt_sd_w2(s1v);
            w2[l] = w0 > w1 ? w0 : w1;
            if (w0 > w2_cap) w0 = w2_cap;
            if (w1 > w2_cap) w1 = w2_cap;
            double ca = Q[l] > 0 ? E[l] / Q[l] : 1.0, sa = Q[l] > 0 ? H[l] / Q[l] : 0.0;
            double t0 = ca, t1 = -sa, t2 = sa, t3 = ca;
            double r0 = sqrt(w0), r1 = sqrt(w1), mm = 0.5 * (r0 + r1), h = 0.5 * (r0 - r1);
            int both = R[l] > 0 && Q[l] > 0;
            double c2 = both ? (F[l] * E[l] - G[l] * H[l]) / (R[l] * Q[l]) : 1.0;
            double s2 = both ? (G[l] * E[l] + F[l] * H[l]) / (R[l] * Q[l]) : 0.0;
            double W0 = mm + h * c2, W1 = h * s2, W2 = h * s2, W3 = mm - h * c2;
            double M0 = W0 * W0 + W2 * W2, M1 = W0 * W1 + W2 * W3;
            double M2 = W1 * W0 + W3 * W2, M3 = W1 * W1 + W3 * W3;
            j0[l] = M0;
            j1[l] = M1;
            j2[l] = M2;
            j3[l] = M3;
            E[l] = M0 * t0 + M1 * t2; /* MT, kept in the lane arrays */
            F[l] = M0 * t1 + M1 * t3;
            G[l] = M2 * t0 + M3 * t2;
            H[l] = M2 * t1 + M3 * t3;
        }
        for (int l = 0; l < m; l++) {
            size_t s = s0 + (size_t)l;
            const double *Gs = S->grad + 6 * s;
            double *out = loc + 10 * (s - lo);
            out[0] = j0[l];
            out[1] = j1[l];
            out[2] = j2[l];
            out[3] = j3[l];
            for (int i = 0; i < 3; i++) {
                out[4 + 2 * i] = E[l] * Gs[2 * i] + F[l] * Gs[2 * i + 1];
                out[5 + 2 * i] = G[l] * Gs[2 * i] + H[l] * Gs[2 * i + 1];
            }
            if (w2[l] > w2max) w2max = w2[l];
        }
    }
    return w2max;
}

double opt_sd2_proxy_range(const opt_simplices *S, const double *X, size_t lo, size_t hi,
                           double w2_cap, double *loc)
{
    return proxy_lanes(S, X, lo, hi, w2_cap, loc);
}

double opt_sd2_energy_range(const opt_simplices *S, const double *X, size_t lo, size_t hi)
{
    return energy_lanes(S, X, lo, hi);
}

void opt_sd2_energy_slope_range(const opt_simplices *S, const double *X, const double *D, size_t lo,
                                size_t hi, double *e, double *slope)
{
    energy_slope_lanes(S, X, D, lo, hi, e, slope);
}
