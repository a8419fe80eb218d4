/* opt/energy_conformal: Psi = ||J||_F^2 / (d det(J)^(2/d)), conformal
 * (MIPS; in 2D ||J||^2 / (2 det J)), 1 at a similarity. A row of
 * opt/energy_table (see opt/energy_kind.h). Scale-free, so areas may vary
 * widely. Its SLIM proxy aims at the closest similarity (scale c =
 * det^(1/d)); the exact secant weight can be negative (the energy is not
 * convex along every singular value) and then falls back to 1 / c^2, so
 * the proxy's gradient is exact only where the secant is positive.
 * Hessian in the singular values, with c = 1 / (d det^(2/d)),
 * N = sum s_k^2: flip c (2 + 2 N / (d s_i s_j)), twist
 * c (2 - 2 N / (d s_i s_j)) (negative for every twist of a non-similarity
 * in 2D); the scaling block has a zero mode along s (scale invariance),
 * which rounding may make slightly negative.
 */
#include <math.h>
#include <stddef.h>

#include "opt/energy_kind.h"

static inline double density_d(int d, const double *J)
{
    double det = opt_ek_det(d, J);
    if (!(det > 0)) return INFINITY;
    return opt_ek_frob2(d, J) / (d * pow(det, 2.0 / d));
}

static inline double density_grad_d(int d, const double *J, double *G)
{
    double Ji[9];
    double det = opt_ek_inverse(d, J, Ji);
    if (!(det > 0)) {
        for (int k = 0; k < d * d; k++) G[k] = NAN;
        return INFINITY;
    }
    double delta = pow(det, 2.0 / d), n2 = opt_ek_frob2(d, J);
    double c = 2.0 / (d * delta);
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) G[a * d + b] = c * (J[a * d + b] - (n2 / d) * Ji[b * d + a]);
    return n2 / (d * delta);
}

static double density(int d, const double *J) { return d == 2 ? density_d(2, J) : density_d(d, J); }

static double density_grad(int d, const double *J, double *G)
{
    return d == 2 ? density_grad_d(2, J, G) : density_grad_d(d, J, G);
}

static void slim_weights(int d, const double *s, double *w2, double *t)
{
    double det = s[0] * s[1] * (d == 3 ? s[2] : 1.0);
    double c = det > 0 ? pow(det, 1.0 / d) : 1.0;
    double s2 = 0;
    for (int i = 0; i < d; i++) s2 += s[i] * s[i];
    for (int i = 0; i < d; i++) {
        /* Target the closest similarity: scale c = det^(1/d). */
        t[i] = c;
        double g = 2.0 / (d * c * c) * (s[i] - s2 / (d * s[i]));
        double r = g / (2.0 * (s[i] - c));
        double fallback = 1.0 / (c * c);
        w2[i] = (isfinite(r) && r > 1e-8 * fallback && fabs(s[i] - c) > 1e-12 * c) ? r : fallback;
    }
}

static inline void sv_hessian_d(int d, const double *s, double *B, double *flip, double *twist)
{
    double D = s[0] * s[1] * (d == 3 ? s[2] : 1.0), N = 0.0;
    double c = 1.0 / (d * pow(D, 2.0 / d));
    for (int i = 0; i < d; i++) N += s[i] * s[i];
    for (int i = 0, k = 0; i < d; i++)
        for (int j = i + 1; j < d; j++, k++) {
            double p = s[i] * s[j];
            B[i * d + j] = B[j * d + i] =
                c * (-(4.0 / d) * (s[i] / s[j] + s[j] / s[i]) + 4.0 * N / (d * d * p));
            double r = 2.0 * N / (d * p);
            flip[k] = c * (2.0 + r);
            twist[k] = c * (2.0 - r);
        }
    for (int i = 0; i < d; i++)
        B[i * d + i] = c * (2.0 - 8.0 / d + (4.0 / (d * d) + 2.0 / d) * N / (s[i] * s[i]));
}

/* d a compile-time constant in the hot 2D case (Newton's fill), as the
 * density's dispatch. */
static void sv_hessian(int d, const double *s, double *B, double *flip, double *twist)
{
    if (d == 2) sv_hessian_d(2, s, B, flip, twist);
    else sv_hessian_d(d, s, B, flip, twist);
}

const opt_energy_kind opt_energy_conformal = {
    .name = "conformal",
    .aliases = "mips",
    .help = "||J||^2 / (2 det J) (MIPS): 1 at a similarity; keeps angles, lets "
            "areas vary widely",
    .scale_offset = 0.0,
    .density = density,
    .density_grad = density_grad,
    .slim_weights = slim_weights,
    .slim_rotation2 = NULL,
    .sv_hessian = sv_hessian,
};
