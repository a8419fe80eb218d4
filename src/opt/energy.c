/* opt/energy: distortion energies of one simplex's Jacobian and their sums.
 *
 * Values and derivatives use closed forms in J (determinant, adjugate),
 * not the SVD, so they stay accurate for badly shaped simplices; only the
 * SLIM proxy needs the signed SVD (opt/small_svd). For an energy
 * f(s_1..s_d) of the signed singular values with derivative g_i and a
 * target t_i, the SLIM weight is w_i = sqrt(g_i / (2 (s_i - t_i))), so that
 * 2 W^T W (J - T) = U diag(g) V^T = dE/dJ.
 */
#include "opt/energy.h"

#include <math.h>
#include <string.h>

#include "base/parallel.h"
#include "opt/arap_barrier.h"
#include "opt/sd2_lanes.h"
#include "opt/small_svd.h"

const char *opt_energy_name(opt_energy e)
{
    switch (e) {
    case OPT_ENERGY_SYMMETRIC_DIRICHLET: return "symmetric_dirichlet";
    case OPT_ENERGY_ARAP: return "arap";
    case OPT_ENERGY_CONFORMAL: return "conformal";
    }
    return "unknown";
}

int opt_energy_parse(const char *name, opt_energy *e)
{
    static const opt_energy all[] = {OPT_ENERGY_SYMMETRIC_DIRICHLET, OPT_ENERGY_ARAP,
                                     OPT_ENERGY_CONFORMAL};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        if (strcmp(name, opt_energy_name(all[k])) == 0) {
            *e = all[k];
            return 0;
        }
    return -1;
}

double opt_energy_scale_offset(opt_energy e) { return e == OPT_ENERGY_ARAP ? 1.0 : 0.0; }

double opt_det(int d, const double *J)
{
    if (d == 2) return J[0] * J[3] - J[1] * J[2];
    return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
        J[2] * (J[3] * J[7] - J[4] * J[6]);
}

/* Inverse of J through the adjugate; returns det. */
static double inverse(int d, const double *J, double *Ji)
{
    double det = opt_det(d, J);
    if (d == 2) {
        Ji[0] = J[3] / det;
        Ji[1] = -J[1] / det;
        Ji[2] = -J[2] / det;
        Ji[3] = J[0] / det;
        return det;
    }
    Ji[0] = (J[4] * J[8] - J[5] * J[7]) / det;
    Ji[1] = (J[2] * J[7] - J[1] * J[8]) / det;
    Ji[2] = (J[1] * J[5] - J[2] * J[4]) / det;
    Ji[3] = (J[5] * J[6] - J[3] * J[8]) / det;
    Ji[4] = (J[0] * J[8] - J[2] * J[6]) / det;
    Ji[5] = (J[2] * J[3] - J[0] * J[5]) / det;
    Ji[6] = (J[3] * J[7] - J[4] * J[6]) / det;
    Ji[7] = (J[1] * J[6] - J[0] * J[7]) / det;
    Ji[8] = (J[0] * J[4] - J[1] * J[3]) / det;
    return det;
}

static double frob2(int d, const double *A)
{
    double s = 0;
    for (int k = 0; k < d * d; k++) s += A[k] * A[k];
    return s;
}

/* SLIM weight and target of ARAP with its barrier along signed singular
 * value s (det the product of all, s > 0): the squared weight is the
 * largest of 1 (ARAP's own), the secant g / (2 (s - 1)) and half the
 * curvature f'' = 2 + b''(det) (det / s)^2 (the barrier's stiffness, which
 * the secant misses away from the squeezed direction: without it the
 * proxy lets a step squeeze a simplex into the barrier and the line
 * search cuts every step short), and the target t = s - g / (2 w^2)
 * keeps the proxy's gradient exact (g = 2 (s - 1) + b'(det) det / s). */
static inline void arap_weight_target(double s, double det, double *w2, double *t)
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

static inline double density_d(opt_energy e, int d, const double *J)
{
    switch (e) {
    case OPT_ENERGY_SYMMETRIC_DIRICHLET: {
        double Ji[9];
        double det = inverse(d, J, Ji);
        if (!(det > 0)) return INFINITY;
        return frob2(d, J) + frob2(d, Ji);
    }
    case OPT_ENERGY_ARAP: {
        double det = opt_det(d, J);
        if (!(det > 0)) return INFINITY;
        double R[9], sv[3], acc = 0;
        closest_rotation(d, J, R, sv);
        for (int k = 0; k < d; k++) acc += (sv[k] - 1) * (sv[k] - 1);
        return acc + arap_barrier(det);
    }
    case OPT_ENERGY_CONFORMAL: {
        double det = opt_det(d, J);
        if (!(det > 0)) return INFINITY;
        return frob2(d, J) / (d * pow(det, 2.0 / d));
    }
    }
    return NAN;
}

static inline double density_grad_d(opt_energy e, int d, const double *J, double *G)
{
    switch (e) {
    case OPT_ENERGY_SYMMETRIC_DIRICHLET: {
        double Ji[9];
        double det = inverse(d, J, Ji);
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
        return frob2(d, J) + frob2(d, Ji);
    }
    case OPT_ENERGY_ARAP: {
        double Ji[9];
        double det = inverse(d, J, Ji);
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
    case OPT_ENERGY_CONFORMAL: {
        double Ji[9];
        double det = inverse(d, J, Ji);
        if (!(det > 0)) {
            for (int k = 0; k < d * d; k++) G[k] = NAN;
            return INFINITY;
        }
        double delta = pow(det, 2.0 / d), n2 = frob2(d, J);
        double c = 2.0 / (d * delta);
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++)
                G[a * d + b] = c * (J[a * d + b] - (n2 / d) * Ji[b * d + a]);
        return n2 / (d * delta);
    }
    }
    return NAN;
}

/* Dispatch with d a compile-time constant in the hot 2D case: the small
 * loops unroll, the operations and their order stay the same. */
double opt_density(opt_energy e, int d, const double *J)
{
    return d == 2 ? density_d(e, 2, J) : density_d(e, d, J);
}

double opt_density_grad(opt_energy e, int d, const double *J, double *G)
{
    return d == 2 ? density_grad_d(e, 2, J, G) : density_grad_d(e, d, J, G);
}

void opt_slim_proxy(opt_energy e, int d, const double *J, double *W, double *T)
{
    opt_slim_proxy_capped(e, d, J, INFINITY, W, T);
}

/* 2D symmetric Dirichlet / ARAP without trigonometry: with J split into
 * its similarity part (E, H) and anti-similarity part (F, G), the closest
 * rotation U V^T is the rotation by angle(E, H), and U diag(w) U^T =
 * mean(w) I + half-difference(w) * reflection by angle(F, G) + angle(E, H). */
static double proxy2_rotation_target(opt_energy e, const double *J, double w2_cap, double *W,
                                     double *T)
{
    double E = 0.5 * (J[0] + J[3]), F = 0.5 * (J[0] - J[3]);
    double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
    double Q = svd_hypot(E, H), R = svd_hypot(F, G);
    double s0 = Q + R, s1 = Q - R;
    double w0 = e == OPT_ENERGY_ARAP ? 1.0 : opt_sd_w2(s0),
           w1 = e == OPT_ENERGY_ARAP ? 1.0 : opt_sd_w2(s1);
    double w2max = w0 > w1 ? w0 : w1;
    if (w0 > w2_cap) w0 = w2_cap;
    if (w1 > w2_cap) w1 = w2_cap;
    double ca = Q > 0 ? E / Q : 1.0, sa = Q > 0 ? H / Q : 0.0;
    T[0] = ca;
    T[1] = -sa;
    T[2] = sa;
    T[3] = ca;
    double r0 = sqrt(w0), r1 = sqrt(w1), m = 0.5 * (r0 + r1), h = 0.5 * (r0 - r1);
    double c2 = 1.0, s2 = 0.0;
    if (R > 0 && Q > 0) {
        c2 = (F * E - G * H) / (R * Q);
        s2 = (G * E + F * H) / (R * Q);
    }
    W[0] = m + h * c2;
    W[1] = h * s2;
    W[2] = h * s2;
    W[3] = m - h * c2;
    return w2max;
}

double opt_slim_proxy_capped(opt_energy e, int d, const double *J, double w2_cap, double *W,
                             double *T)
{
    /* (ARAP inside its barrier's range needs the general targets below) */
    if (d == 2 &&
        (e == OPT_ENERGY_SYMMETRIC_DIRICHLET ||
         (e == OPT_ENERGY_ARAP && opt_det(2, J) >= OPT_ARAP_BARRIER_DET)))
        return proxy2_rotation_target(e, J, w2_cap, W, T);
    double U[9], V[9], s[3], w2[3], t[3];
    svd_signed(d, J, U, s, V);
    switch (e) {
    case OPT_ENERGY_SYMMETRIC_DIRICHLET:
        for (int i = 0; i < d; i++) {
            t[i] = 1.0;
            /* g/(2(s-1)) with g = 2s - 2/s^3, simplified: no 0/0 at s = 1. */
            w2[i] = opt_sd_w2(s[i]);
        }
        break;
    case OPT_ENERGY_ARAP: {
        double det = s[0] * s[1] * (d == 3 ? s[2] : 1.0);
        for (int i = 0; i < d; i++) {
            t[i] = 1.0;
            w2[i] = 1.0;
            if (det > 0 && det < OPT_ARAP_BARRIER_DET) arap_weight_target(s[i], det, &w2[i], &t[i]);
        }
        break;
    }
    case OPT_ENERGY_CONFORMAL: {
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
            w2[i] =
                (isfinite(r) && r > 1e-8 * fallback && fabs(s[i] - c) > 1e-12 * c) ? r : fallback;
        }
        break;
    }
    default:
        for (int i = 0; i < d; i++) {
            t[i] = 1.0;
            w2[i] = 1.0;
        }
    }
    double w2max = 0;
    for (int i = 0; i < d; i++) {
        if (w2[i] > w2max) w2max = w2[i];
        if (w2[i] > w2_cap) w2[i] = w2_cap;
    }
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double wa = 0, ta = 0;
            for (int k = 0; k < d; k++) {
                wa += U[a * d + k] * sqrt(w2[k]) * U[b * d + k];
                ta += U[a * d + k] * t[k] * V[b * d + k];
            }
            W[a * d + b] = wa;
            T[a * d + b] = ta;
        }
    return w2max;
}

/* sum weight * density over simplices [lo, hi), in order */
static double energy_range(const opt_term *t, const double *X, size_t lo, size_t hi)
{
    const opt_simplices *S = t->s;
    if (S->d == 2 && t->energy == OPT_ENERGY_SYMMETRIC_DIRICHLET)
        return opt_sd2_energy_range(S, X, lo, hi); /* the same sum, in vector lanes */
    double acc = 0, J[9];
    for (size_t s = lo; s < hi; s++) {
        opt_jacobian(S, (int)s, X, J);
        acc += S->weight[s] * opt_density(t->energy, S->d, J);
    }
    return acc;
}

typedef struct energy_ctx {
    const opt_term *t;
    const double *X;
} energy_ctx;

static double energy_chunk(const void *ctx, size_t lo, size_t hi)
{
    const energy_ctx *c = ctx;
    return energy_range(c->t, c->X, lo, hi);
}

/* Chunked (base/parallel): partial sums added in chunk order. */
double opt_term_energy(const opt_term *t, const double *X)
{
    energy_ctx c = {t, X};
    return par_sum((size_t)t->s->n, energy_chunk, &c);
}

double opt_term_mean_energy(const opt_term *t, const double *X)
{
    double w = 0;
    for (int s = 0; s < t->s->n; s++) w += t->s->weight[s];
    return w > 0 ? opt_term_energy(t, X) / w : 0.0;
}

void opt_term_gradient(const opt_term *t, const double *X, double *g)
{
    const opt_simplices *S = t->s;
    int d = S->d;
    double J[9], dJ[9], gc[12];
    for (int s = 0; s < S->n; s++) {
        opt_jacobian(S, s, X, J);
        opt_density_grad(t->energy, d, J, dJ);
        const int *ix = S->idx + (size_t)s * (d + 1);
        opt_pullback(d, S->grad + (size_t)s * (d + 1) * d, dJ, gc);
        double w = S->weight[s];
        for (int i = 0; i <= d; i++)
            for (int a = 0; a < d; a++) g[(size_t)ix[i] * d + a] += w * gc[i * d + a];
    }
}
