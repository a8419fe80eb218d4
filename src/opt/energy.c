/* opt/energy: distortion energies of one simplex's Jacobian and their sums.
 *
 * Every energy-specific formula is in the energy's row (opt/energy_kind.h,
 * opt/energy_table.c); this file dispatches on it and builds what is
 * common: the SLIM proxy's W and T from the row's weights and targets
 * along the signed SVD (opt/small_svd), and the sums over a term. For an
 * energy f(s_1..s_d) of the signed singular values with derivative g_i
 * and a target t_i, the SLIM weight is w_i = sqrt(g_i / (2 (s_i - t_i))),
 * so that 2 W^T W (J - T) = U diag(g) V^T = dE/dJ.
 */
#include "opt/energy.h"

#include <math.h>
#include <string.h>

#include "base/parallel.h"
#include "opt/energy_kind.h"
#include "opt/sd2_lanes.h"
#include "opt/small_svd.h"

static const opt_energy_kind *kind(opt_energy e) { return opt_energy_table[e]; }

int opt_energy_count(void) { return opt_energy_table_size; }

int opt_energy_valid(int e) { return e >= 0 && e < opt_energy_table_size; }

const char *opt_energy_name(opt_energy e)
{
    return opt_energy_valid((int)e) ? kind(e)->name : "unknown";
}

/* Whether name is the identifier id, with '-' accepted for '_'. */
static int same_name(const char *name, const char *id)
{
    for (; *name && *id; name++, id++)
        if (*name != *id && !(*name == '-' && *id == '_')) return 0;
    return !*name && !*id;
}

/* Whether name is one of the space-separated words of list. */
static int in_list(const char *name, const char *list)
{
    size_t n = strlen(name);
    for (const char *w = list; *w;) {
        size_t k = strcspn(w, " ");
        if (k == n && n > 0 && strncmp(w, name, n) == 0) return 1;
        w += k;
        while (*w == ' ') w++;
    }
    return 0;
}

int opt_energy_parse(const char *name, opt_energy *e)
{
    for (int k = 0; k < opt_energy_table_size; k++)
        if (same_name(name, opt_energy_table[k]->name) ||
            in_list(name, opt_energy_table[k]->aliases)) {
            *e = (opt_energy)k;
            return 0;
        }
    return -1;
}

double opt_energy_scale_offset(opt_energy e) { return kind(e)->scale_offset; }

double opt_det(int d, const double *J) { return opt_ek_det(d, J); }

double opt_density(opt_energy e, int d, const double *J) { return kind(e)->density(d, J); }

double opt_density_grad(opt_energy e, int d, const double *J, double *G)
{
    return kind(e)->density_grad(d, J, G);
}

void opt_slim_proxy(opt_energy e, int d, const double *J, double *W, double *T)
{
    opt_slim_proxy_capped(e, d, J, INFINITY, W, T);
}

/* 2D proxy aiming at the closest rotation, without trigonometry: with J
 * split into its similarity part (E, H) and anti-similarity part (F, G),
 * the closest rotation U V^T is the rotation by angle(E, H), and
 * U diag(w) U^T = mean(w) I + half-difference(w) * reflection by
 * angle(F, G) + angle(E, H). Returns 0 when the row declines (its
 * general path applies), else 1 with *w2max the largest uncapped squared
 * weight. */
static int proxy2_rotation_target(const opt_energy_kind *k, const double *J, double w2_cap,
                                  double *W, double *T, double *w2max)
{
    double E = 0.5 * (J[0] + J[3]), F = 0.5 * (J[0] - J[3]);
    double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
    double Q = svd_hypot(E, H), R = svd_hypot(F, G);
    double s0 = Q + R, s1 = Q - R;
    double w0, w1;
    if (!k->slim_rotation2(J, s0, s1, &w0, &w1)) return 0;
    *w2max = w0 > w1 ? w0 : w1;
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
    return 1;
}

double opt_slim_proxy_capped(opt_energy e, int d, const double *J, double w2_cap, double *W,
                             double *T)
{
    const opt_energy_kind *k = kind(e);
    double w2max = 0;
    if (d == 2 && k->slim_rotation2 && proxy2_rotation_target(k, J, w2_cap, W, T, &w2max))
        return w2max;
    double U[9], V[9], s[3], w2[3], t[3];
    svd_signed(d, J, U, s, V);
    k->slim_weights(d, s, w2, t);
    for (int i = 0; i < d; i++) {
        if (w2[i] > w2max) w2max = w2[i];
        if (w2[i] > w2_cap) w2[i] = w2_cap;
    }
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double wa = 0, ta = 0;
            for (int q = 0; q < d; q++) {
                wa += U[a * d + q] * sqrt(w2[q]) * U[b * d + q];
                ta += U[a * d + q] * t[q] * V[b * d + q];
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
