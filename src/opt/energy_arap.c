/* opt/energy_arap: Psi = ||J - R||_F^2 + b(det J), R the closest rotation,
 * 0 at a rotation. A row of opt/energy_table (see opt/energy_kind.h).
 *
 * ARAP alone is no barrier: a simplex can be squeezed to zero area at a
 * finite cost, and where the unconstrained ARAP minimum would invert
 * simplices the SCAF loop then crushes them (its line search stops each
 * step at a fraction of the flip-free bound, so the simplex loses most of
 * its area every iteration). b (opt/arap_barrier) prevents it: 0 above
 * det J = OPT_ARAP_BARRIER_DET, so the energy is ARAP itself wherever no
 * simplex is squeezed below a tenth of its rest area, infinite at zero.
 * Its scale offset is 1: E + 1 then weighs like symmetric Dirichlet's
 * E >= 4 in the scaffold weight and the convergence test.
 * Hessian in the singular values (det = prod s_k): the scaling block is
 * 2 I plus the barrier's coupling b''(det) (det/s_i)(det/s_j) +
 * b'(det) det/(s_i s_j) off the diagonal; flip 2 - b'(det) det / (s_i s_j),
 * twist 2 (s_i + s_j - 2) / (s_i + s_j) + b'(det) det / (s_i s_j).
 */
#include <math.h>

#include "opt/arap_barrier.h"
#include "opt/energy_kind.h"
#include "opt/small_svd.h"

/* Closest rotation U V^T and the signed singular values. */
static void closest_rotation(int d, const double *J, double *R, double *sv)
{
    double U[9], V[9];
    svd_signed(d, J, U, sv, V);
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double acc = 0;
            for (int k = 0; k < d; k++) acc += U[a * d + k] * V[b * d + k];
            R[a * d + b] = acc;
        }
}

static inline double density_d(int d, const double *J)
{
    double det = opt_ek_det(d, J);
    if (!(det > 0)) return INFINITY;
    double R[9], sv[3], acc = 0;
    closest_rotation(d, J, R, sv);
    for (int k = 0; k < d; k++) acc += (sv[k] - 1) * (sv[k] - 1);
    return acc + arap_barrier(det);
}

static inline double density_grad_d(int d, const double *J, double *G)
{
    double Ji[9];
    double det = opt_ek_inverse(d, J, Ji);
    if (!(det > 0)) {
        for (int k = 0; k < d * d; k++) G[k] = NAN;
        return INFINITY;
    }
    double R[9], sv[3], acc = 0;
    closest_rotation(d, J, R, sv);
    for (int k = 0; k < d; k++) acc += (sv[k] - 1) * (sv[k] - 1);
    /* d det / dJ = det J^-T */
    double c = arap_barrier_slope(det) * det;
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++)
            G[a * d + b] = 2.0 * (J[a * d + b] - R[a * d + b]) + c * Ji[b * d + a];
    return acc + arap_barrier(det);
}

static double density(int d, const double *J) { return d == 2 ? density_d(2, J) : density_d(d, J); }

static double density_grad(int d, const double *J, double *G)
{
    return d == 2 ? density_grad_d(2, J, G) : density_grad_d(d, J, G);
}

/* Weight and target along signed singular value s (det the product of
 * all, s > 0) inside the barrier's range: the squared weight is the
 * largest of 1 (ARAP's own), the secant g / (2 (s - 1)) and half the
 * curvature f'' = 2 + b''(det) (det / s)^2 (the barrier's stiffness, which
 * the secant misses away from the squeezed direction: without it the
 * proxy lets a step squeeze a simplex into the barrier and the line
 * search cuts every step short), and the target t = s - g / (2 w^2)
 * keeps the proxy's gradient exact (g = 2 (s - 1) + b'(det) det / s). */
static inline void barrier_weight_target(double s, double det, double *w2, double *t)
{
    double g = 2.0 * (s - 1.0) + arap_barrier_slope(det) * det / s;
    double o = det / s, w = 0.5 * (2.0 + arap_barrier_curvature(det) * o * o);
    if (w < 1.0) w = 1.0;
    if (s < 1.0) {
        double sec = g / (2.0 * (s - 1.0));
        if (sec > w) w = sec;
    }
    *w2 = w;
    *t = s - g / (2.0 * w);
}

static void slim_weights(int d, const double *s, double *w2, double *t)
{
    double det = s[0] * s[1] * (d == 3 ? s[2] : 1.0);
    for (int i = 0; i < d; i++) {
        t[i] = 1.0;
        w2[i] = 1.0;
        if (det > 0 && det < OPT_ARAP_BARRIER_DET) barrier_weight_target(s[i], det, &w2[i], &t[i]);
    }
}

/* Outside the barrier's range ARAP's proxy is the closest rotation with
 * unit weights. */
static int slim_rotation2(const double *J, double s0, double s1, double *w0, double *w1)
{
    (void)s0;
    (void)s1;
    if (!(opt_ek_det(2, J) >= OPT_ARAP_BARRIER_DET)) return 0;
    *w0 = 1.0;
    *w1 = 1.0;
    return 1;
}

static inline void sv_hessian_d(int d, const double *s, double *B, double *flip, double *twist)
{
    double D = s[0] * s[1] * (d == 3 ? s[2] : 1.0), other[3];
    for (int i = 0; i < d; i++) /* det / s_i without a division */
        other[i] = d == 2 ? s[1 - i] : s[(i + 1) % 3] * s[(i + 2) % 3];
    for (int i = 0, k = 0; i < d; i++)
        for (int j = i + 1; j < d; j++, k++) {
            /* det / (s_i s_j): 1 in 2D, the third singular value in 3D */
            double o = d == 2 ? 1.0 : s[3 - i - j];
            B[i * d + j] = B[j * d + i] =
                arap_barrier_curvature(D) * other[i] * other[j] + arap_barrier_slope(D) * o;
            double b = arap_barrier_slope(D) * o;
            flip[k] = 2.0 - b;
            twist[k] = 2.0 * (s[i] + s[j] - 2.0) / (s[i] + s[j]) + b;
        }
    for (int i = 0; i < d; i++)
        B[i * d + i] = 2.0 + arap_barrier_curvature(D) * other[i] * other[i];
}

/* d a compile-time constant in the hot 2D case (Newton's fill), as the
 * density's dispatch. */
static void sv_hessian(int d, const double *s, double *B, double *flip, double *twist)
{
    if (d == 2) sv_hessian_d(2, s, B, flip, twist);
    else sv_hessian_d(d, s, B, flip, twist);
}

const opt_energy_kind opt_energy_arap = {
    .name = "arap",
    .aliases = "",
    .help = "||J - R||^2 + b(det J): 0 at a rotation; b, 0 above det J = 0.1, "
            "keeps simplices from collapsing",
    .scale_offset = 1.0,
    .density = density,
    .density_grad = density_grad,
    .slim_weights = slim_weights,
    .slim_rotation2 = slim_rotation2,
    .sv_hessian = sv_hessian,
};
