/* opt/energy_symmetric_dirichlet: Psi = ||J||_F^2 + ||J^-1||_F^2, 2d at a
 * rotation (the default energy, and the scaffold's). A row of
 * opt/energy_table (see opt/energy_kind.h). Its SLIM targets are the
 * closest rotation (t_i = 1) with weights opt_sd_w2; its Hessian in the
 * singular values is diagonal (uncoupled), 2 + 6 / s_i^4, with the pair
 * eigenvalues written without s_i - s_j in a denominator:
 *   flip 2 + 2 (s_i^2 + s_i s_j + s_j^2) / (s_i s_j)^3,
 *   twist 2 - 2 (s_i^2 - s_i s_j + s_j^2) / (s_i s_j)^3
 * (negative for anisotropic or compressed pairs; opt/isotropic_hessian
 * projects them). In 2D the sums and proxies of whole terms go through
 * opt/sd2_lanes instead, with the same operations in the same order.
 */
#include <math.h>

#include "opt/energy_kind.h"
#include "opt/sd_weight.h"

static inline double density_d(int d, const double *J)
{
    double Ji[9];
    double det = opt_ek_inverse(d, J, Ji);
    if (!(det > 0)) return INFINITY;
    return opt_ek_frob2(d, J) + opt_ek_frob2(d, Ji);
}

static inline double density_grad_d(int d, const double *J, double *G)
{
    double Ji[9];
    double det = opt_ek_inverse(d, J, Ji);
    if (!(det > 0)) {
        for (int k = 0; k < d * d; k++) G[k] = NAN;
        return INFINITY;
    }
    /* d/dJ ||J^-1||^2 = -2 J^-T J^-1 J^-T. */
    double A[9];
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double acc = 0; /* (J^-T J^-1)[a][b] = sum_k Ji[k][a] Ji[k][b] */
            for (int k = 0; k < d; k++) acc += Ji[k * d + a] * Ji[k * d + b];
            A[a * d + b] = acc;
        }
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double acc = 0; /* (A J^-T)[a][b] = sum_k A[a][k] Ji[b][k] */
            for (int k = 0; k < d; k++) acc += A[a * d + k] * Ji[b * d + k];
            G[a * d + b] = 2.0 * J[a * d + b] - 2.0 * acc;
        }
    return opt_ek_frob2(d, J) + opt_ek_frob2(d, Ji);
}

/* d a compile-time constant in the hot 2D case: the small loops unroll,
 * the operations and their order stay the same. */
static double density(int d, const double *J) { return d == 2 ? density_d(2, J) : density_d(d, J); }

static double density_grad(int d, const double *J, double *G)
{
    return d == 2 ? density_grad_d(2, J, G) : density_grad_d(d, J, G);
}

static void slim_weights(int d, const double *s, double *w2, double *t)
{
    for (int i = 0; i < d; i++) {
        t[i] = 1.0;
        w2[i] = opt_sd_w2(s[i]);
    }
}

static int slim_rotation2(const double *J, double s0, double s1, double *w0, double *w1)
{
    (void)J;
    *w0 = opt_sd_w2(s0);
    *w1 = opt_sd_w2(s1);
    return 1;
}

static inline void sv_hessian_d(int d, const double *s, double *B, double *flip, double *twist)
{
    for (int i = 0, k = 0; i < d; i++)
        for (int j = i + 1; j < d; j++, k++) {
            double p = s[i] * s[j];
            B[i * d + j] = B[j * d + i] = 0.0;
            double p3 = p * p * p, q = s[i] * s[i] + s[j] * s[j];
            flip[k] = 2.0 + 2.0 * (q + p) / p3;
            twist[k] = 2.0 - 2.0 * (q - p) / p3;
        }
    for (int i = 0; i < d; i++) {
        double s2 = s[i] * s[i];
        B[i * d + i] = 2.0 + 6.0 / (s2 * s2);
    }
}

/* d a compile-time constant in the hot 2D case (Newton's fill), as the
 * density's dispatch. */
static void sv_hessian(int d, const double *s, double *B, double *flip, double *twist)
{
    if (d == 2) sv_hessian_d(2, s, B, flip, twist);
    else sv_hessian_d(d, s, B, flip, twist);
}

const opt_energy_kind opt_energy_symmetric_dirichlet = {
    .name = "symmetric_dirichlet",
    .aliases = "sd",
    .help = "||J||^2 + ||J^-1||^2 (the default): 4 at an isometry, penalizes "
            "stretch and compression alike",
    .scale_offset = 0.0,
    .density = density,
    .density_grad = density_grad,
    .slim_weights = slim_weights,
    .slim_rotation2 = slim_rotation2,
    .sv_hessian = sv_hessian,
};
