/* opt/energy_exp_symmetric_dirichlet: the exponential symmetric Dirichlet
 * energy (Rabinovich et al. 2017, sec. 6), Psi = exp(k (SD - 2d)) with SD
 * = ||J||_F^2 + ||J^-1||_F^2 and k = EXP_SD_K: 1 at a rotation, and it
 * weighs the most distorted simplices far above the rest, so the worst
 * distortion of a map comes down at some cost to the mean. A row of
 * opt/energy_table (see opt/energy_kind.h); its value, gradient and
 * Hessian are those of symmetric Dirichlet's row (read through the
 * table) composed with exp:
 *   dPsi/dJ = k Psi dSD/dJ;
 *   SLIM: the same targets (the closest rotation, t_i = 1) and squared
 *     weights k Psi w_i^2(SD) (Psi_i / (2 (s_i - 1)) with Psi_i = k Psi
 *     SD_i), so they stay positive;
 *   Hessian in the singular values: k Psi (SD_ij + k SD_i SD_j) (the
 *     scaling block, coupled through Psi), flip and twist k Psi times
 *     symmetric Dirichlet's (the divided differences of k Psi SD_i).
 * Psi overflows to +INFINITY once k (SD - 2d) > 709 (SD above ~7000
 * with k = 0.1: a singular value below ~0.012); a start that squeezed
 * then has infinite energy, and no step can lower it. k = 0.1 is small
 * enough that mean-value starts of the test meshes stay finite, large
 * enough that Psi differs from 1 + k (SD - 2d) where distortion is high.
 */
#include <math.h>

#include "opt/energy.h"
#include "opt/energy_kind.h"
#include "opt/sd_weight.h"

#define EXP_SD_K 0.1

static const opt_energy_kind *sd(void) { return opt_energy_table[OPT_ENERGY_SYMMETRIC_DIRICHLET]; }

static double density(int d, const double *J)
{
    double v = sd()->density(d, J);
    return v < INFINITY ? exp(EXP_SD_K * (v - 2.0 * d)) : INFINITY;
}

static double density_grad(int d, const double *J, double *G)
{
    double v = sd()->density_grad(d, J, G); /* G NaN where det J <= 0 */
    if (!(v < INFINITY)) return INFINITY;
    double psi = exp(EXP_SD_K * (v - 2.0 * d)), c = EXP_SD_K * psi;
    for (int k = 0; k < d * d; k++) G[k] *= c;
    return psi;
}

/* Psi at signed singular values s (all > 0 for a finite value). */
static double psi_of(int d, const double *s)
{
    double v = 0.0;
    for (int i = 0; i < d; i++) v += s[i] * s[i] + 1.0 / (s[i] * s[i]);
    return exp(EXP_SD_K * (v - 2.0 * d));
}

static void slim_weights(int d, const double *s, double *w2, double *t)
{
    double c = EXP_SD_K * psi_of(d, s);
    for (int i = 0; i < d; i++) {
        t[i] = 1.0;
        w2[i] = c * opt_sd_w2(s[i]);
    }
}

static int slim_rotation2(const double *J, double s0, double s1, double *w0, double *w1)
{
    (void)J;
    double s[2] = {s0, s1}, c = EXP_SD_K * psi_of(2, s);
    *w0 = c * opt_sd_w2(s0);
    *w1 = c * opt_sd_w2(s1);
    return 1;
}

static void sv_hessian(int d, const double *s, double *B, double *flip, double *twist)
{
    sd()->sv_hessian(d, s, B, flip, twist);
    double c = EXP_SD_K * psi_of(d, s), g[3];
    for (int i = 0; i < d; i++) g[i] = 2.0 * s[i] - 2.0 / (s[i] * s[i] * s[i]); /* SD_i */
    for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++) B[i * d + j] = c * (B[i * d + j] + EXP_SD_K * g[i] * g[j]);
    for (int k = 0; k < d * (d - 1) / 2; k++) {
        flip[k] *= c;
        twist[k] *= c;
    }
}

const opt_energy_kind opt_energy_exp_symmetric_dirichlet = {
    .name = "exp_symmetric_dirichlet",
    .aliases = "esd",
    .help = "exp(0.1 (||J||^2 + ||J^-1||^2 - 2d)): 1 at an isometry; the worst "
            "triangles weigh far more than with symmetric-dirichlet",
    .scale_offset = 0.0,
    .density = density,
    .density_grad = density_grad,
    .slim_weights = slim_weights,
    .slim_rotation2 = slim_rotation2,
    .sv_hessian = sv_hessian,
};
