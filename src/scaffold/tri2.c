/* scaffold/tri2: per-triangle 2D distortion kernels (see tri2.h).
 *
 * The 2 by 2 SVD is closed form: J = U diag(s1, s2) V^T with s1 >= s2 > 0
 * for det J > 0, from the conformal/anticonformal split of J. SLIM weights
 * follow Rabinovich et al. 2017: w_i = sqrt(E'(s_i) / (2 (s_i - 1))),
 * W = U diag(w) U^T, with w_i = 1 near s_i = 1.
 */
#include "scaffold/tri2.h"

#include <math.h>

double tri2_rest_from_3d(const double p0[3], const double p1[3], const double p2[3], double Dminv[4])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = p1[k] - p0[k];
        e2[k] = p2[k] - p0[k];
    }
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0]};
    double twice = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    if (!(l1 > 0.0) || !(twice > 0.0)) return 0.0;
    double qx = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
    double qy = twice / l1;
    /* Dm = [[l1, qx], [0, qy]] */
    Dminv[0] = 1.0 / l1;
    Dminv[1] = -qx / (l1 * qy);
    Dminv[2] = 0.0;
    Dminv[3] = 1.0 / qy;
    return 0.5 * twice;
}

double tri2_rest_from_2d(const double a[2], const double b[2], const double c[2], double eps,
                         double Dminv[4])
{
    double m00 = b[0] - a[0], m01 = c[0] - a[0], m10 = b[1] - a[1], m11 = c[1] - a[1];
    double det = m00 * m11 - m01 * m10;
    if (!(0.5 * det >= eps) || !(det > 0.0)) {
        /* Equilateral triangle of area eps (at least a tiny positive area). */
        double area = eps > 0.0 ? eps : 1e-300;
        double s = sqrt(4.0 * area / sqrt(3.0));
        m00 = s;
        m10 = 0.0;
        m01 = 0.5 * s;
        m11 = 0.5 * sqrt(3.0) * s;
        det = m00 * m11 - m01 * m10;
    }
    Dminv[0] = m11 / det;
    Dminv[1] = -m01 / det;
    Dminv[2] = -m10 / det;
    Dminv[3] = m00 / det;
    return 0.5 * det;
}

void tri2_jacobian(const double a[2], const double b[2], const double c[2], const double Dminv[4],
                   double J[4])
{
    double s00 = b[0] - a[0], s01 = c[0] - a[0], s10 = b[1] - a[1], s11 = c[1] - a[1];
    J[0] = s00 * Dminv[0] + s01 * Dminv[2];
    J[1] = s00 * Dminv[1] + s01 * Dminv[3];
    J[2] = s10 * Dminv[0] + s11 * Dminv[2];
    J[3] = s10 * Dminv[1] + s11 * Dminv[3];
}

/* Closed-form signed SVD of a 2 by 2 matrix: J = U diag(s) V^T, U, V
 * rotations given by angles; s[0] >= |s[1]|. */
static void svd2(const double J[4], double U[4], double s[2], double V[4])
{
    double E = 0.5 * (J[0] + J[3]), Fv = 0.5 * (J[0] - J[3]);
    double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
    double Q = sqrt(E * E + H * H), Rr = sqrt(Fv * Fv + G * G);
    s[0] = Q + Rr;
    s[1] = Q - Rr;
    double a1 = atan2(G, Fv), a2 = atan2(H, E);
    double theta = 0.5 * (a2 - a1), phi = 0.5 * (a2 + a1);
    double ct = cos(theta), st = sin(theta), cp = cos(phi), sp = sin(phi);
    U[0] = cp; U[1] = -sp; U[2] = sp; U[3] = cp;
    V[0] = ct; V[1] = st; V[2] = -st; V[3] = ct;
    /* J = U diag(s) V^T with V^T = rotation(theta): V = rotation(-theta). */
}

static double frob2(const double J[4]) { return J[0] * J[0] + J[1] * J[1] + J[2] * J[2] + J[3] * J[3]; }
static double det2(const double J[4]) { return J[0] * J[3] - J[1] * J[2]; }

double tri2_energy(scaf_energy e, const double J[4])
{
    double det = det2(J);
    if (!(det > 0.0)) return INFINITY;
    double f = frob2(J);
    switch (e) {
    case SCAF_ENERGY_ARAP: {
        double U[4], s[2], V[4];
        svd2(J, U, s, V);
        return (s[0] - 1.0) * (s[0] - 1.0) + (s[1] - 1.0) * (s[1] - 1.0);
    }
    case SCAF_ENERGY_CONFORMAL: return f / det;
    case SCAF_ENERGY_SYMMETRIC_DIRICHLET:
    default: return f + f / (det * det);
    }
}

void tri2_energy_grad(scaf_energy e, const double J[4], double G[4])
{
    double det = det2(J), f = frob2(J);
    double cof[4] = {J[3], -J[2], -J[1], J[0]}; /* d det / dJ */
    switch (e) {
    case SCAF_ENERGY_ARAP: {
        double U[4], s[2], V[4];
        svd2(J, U, s, V);
        /* R = U V^T */
        double R[4] = {U[0] * V[0] + U[1] * V[1], U[0] * V[2] + U[1] * V[3],
                       U[2] * V[0] + U[3] * V[1], U[2] * V[2] + U[3] * V[3]};
        for (int k = 0; k < 4; k++) G[k] = 2.0 * (J[k] - R[k]);
        return;
    }
    case SCAF_ENERGY_CONFORMAL:
        for (int k = 0; k < 4; k++) G[k] = 2.0 * J[k] / det - f / (det * det) * cof[k];
        return;
    case SCAF_ENERGY_SYMMETRIC_DIRICHLET:
    default: {
        double d2 = det * det;
        for (int k = 0; k < 4; k++) G[k] = 2.0 * J[k] * (1.0 + 1.0 / d2) - 2.0 * f / (d2 * det) * cof[k];
        return;
    }
    }
}

/* dE/ds for a singular value s of energy e (the other one is `o`). */
static double dE_ds(scaf_energy e, double s, double o)
{
    switch (e) {
    case SCAF_ENERGY_ARAP: return 2.0 * (s - 1.0);
    case SCAF_ENERGY_CONFORMAL: return 1.0 / o - o / (s * s);
    case SCAF_ENERGY_SYMMETRIC_DIRICHLET:
    default: return 2.0 * (s - 1.0 / (s * s * s));
    }
}

void tri2_slim_weights(scaf_energy e, const double J[4], double W[4], double R[4])
{
    double U[4], s[2], V[4];
    svd2(J, U, s, V);
    R[0] = U[0] * V[0] + U[1] * V[1];
    R[1] = U[0] * V[2] + U[1] * V[3];
    R[2] = U[2] * V[0] + U[3] * V[1];
    R[3] = U[2] * V[2] + U[3] * V[3];
    double w[2];
    for (int i = 0; i < 2; i++) {
        double si = s[i], oi = s[1 - i];
        if (fabs(si - 1.0) < 1e-8 || !(si > 0.0)) {
            w[i] = 1.0;
            continue;
        }
        double q = dE_ds(e, si, oi) / (2.0 * (si - 1.0));
        w[i] = q > 1e-12 ? sqrt(q) : 1e-6;
        if (!isfinite(w[i])) w[i] = 1.0;
    }
    /* W = U diag(w) U^T */
    W[0] = U[0] * U[0] * w[0] + U[1] * U[1] * w[1];
    W[1] = U[0] * U[2] * w[0] + U[1] * U[3] * w[1];
    W[2] = W[1];
    W[3] = U[2] * U[2] * w[0] + U[3] * U[3] * w[1];
}

void tri2_slim_element(double a, const double Dminv[4], const double W[4], const double R[4],
                       double K[36], double b[6])
{
    /* J[r][c] = sum_i x_i[r] g_i[c], g1 = row 0 of Dminv, g2 = row 1,
     * g0 = -(g1 + g2). Energy a ||W J - W R||^2 gives
     * K[(i,k),(j,l)] = 2a (W^T W)[k][l] (g_i . g_j), b[(i,k)] = 2a sum_c g_i[c] (W^T W R)[k][c]. */
    double g[3][2] = {{-(Dminv[0] + Dminv[2]), -(Dminv[1] + Dminv[3])},
                      {Dminv[0], Dminv[1]},
                      {Dminv[2], Dminv[3]}};
    double M[4] = {W[0] * W[0] + W[2] * W[2], W[0] * W[1] + W[2] * W[3],
                   W[1] * W[0] + W[3] * W[2], W[1] * W[1] + W[3] * W[3]};
    double MR[4] = {M[0] * R[0] + M[1] * R[2], M[0] * R[1] + M[1] * R[3],
                    M[2] * R[0] + M[3] * R[2], M[2] * R[1] + M[3] * R[3]};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double gg = g[i][0] * g[j][0] + g[i][1] * g[j][1];
            for (int k = 0; k < 2; k++)
                for (int l = 0; l < 2; l++)
                    K[(2 * i + k) * 6 + 2 * j + l] = 2.0 * a * M[2 * k + l] * gg;
        }
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 2; k++)
            b[2 * i + k] = 2.0 * a * (g[i][0] * MR[2 * k] + g[i][1] * MR[2 * k + 1]);
}

double tri2_max_step(const double a[2], const double b[2], const double c[2], const double da[2],
                     const double db[2], const double dc[2])
{
    double A00 = b[0] - a[0], A01 = c[0] - a[0], A10 = b[1] - a[1], A11 = c[1] - a[1];
    double B00 = db[0] - da[0], B01 = dc[0] - da[0], B10 = db[1] - da[1], B11 = dc[1] - da[1];
    double c0 = A00 * A11 - A01 * A10;
    double c1 = A00 * B11 + A11 * B00 - A01 * B10 - A10 * B01;
    double c2 = B00 * B11 - B01 * B10;
    double best = INFINITY;
    double scale = fabs(c0) + fabs(c1) + fabs(c2);
    if (scale == 0.0) return best;
    if (fabs(c2) <= 1e-14 * scale) {
        if (c1 != 0.0) {
            double t = -c0 / c1;
            if (t > 0.0) best = t;
        }
        return best;
    }
    double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return best;
    double sq = sqrt(disc);
    /* Stable roots: q = -(c1 + sign(c1) sq) / 2, t1 = q / c2, t2 = c0 / q. */
    double q = -0.5 * (c1 + (c1 >= 0.0 ? sq : -sq));
    double r1 = q / c2, r2 = q != 0.0 ? c0 / q : INFINITY;
    if (r1 > 0.0 && r1 < best) best = r1;
    if (r2 > 0.0 && r2 < best) best = r2;
    return best;
}
