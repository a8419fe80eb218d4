/* opt/small_svd: signed SVD of 2x2 and 3x3 matrices (Jacobians).
 *
 * 2x2: J = R(phi) diag(s0, s1) R(theta) from the split of J into a
 * similarity part (E, H) and an anti-similarity part (F, G); exact up to
 * rounding for any input. 3x3: Jacobi eigen-decomposition of J^T J (stable,
 * converges in a few sweeps), then U from J V with Gram-Schmidt, the third
 * column as a cross product so det U = +1, and the signed s[2] read off as
 * u2 . J v2 (accurate even when J^T J squares away small values).
 */
#include "opt/small_svd.h"

#include <math.h>

void svd2_signed(const double J[4], double U[4], double s[2], double V[4])
{
    double E = 0.5 * (J[0] + J[3]), F = 0.5 * (J[0] - J[3]);
    double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
    double Q = svd_hypot(E, H), R = svd_hypot(F, G);
    s[0] = Q + R;
    s[1] = Q - R;
    double a1 = atan2(G, F), a2 = atan2(H, E);
    double theta = 0.5 * (a2 - a1), phi = 0.5 * (a2 + a1);
    double cp = cos(phi), sp = sin(phi), ct = cos(theta), st = sin(theta);
    U[0] = cp;
    U[1] = -sp;
    U[2] = sp;
    U[3] = cp;
    /* J = U diag(s) R(theta), so V = R(theta)^T. */
    V[0] = ct;
    V[1] = st;
    V[2] = -st;
    V[3] = ct;
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* A unit vector orthogonal to unit a. */
static void any_perp(const double a[3], double p[3])
{
    double e[3] = {0, 0, 0};
    int k = 0;
    if (fabs(a[1]) < fabs(a[k])) k = 1;
    if (fabs(a[2]) < fabs(a[k])) k = 2;
    e[k] = 1.0;
    cross3(a, e, p);
    double n = norm3(p);
    p[0] /= n;
    p[1] /= n;
    p[2] /= n;
}

/* Symmetric 3x3 eigen-decomposition A = V diag(l) V^T by cyclic Jacobi. */
static void jacobi_eigen3(const double Ain[9], double l[3], double V[9])
{
    double A[9];
    for (int i = 0; i < 9; i++) {
        A[i] = Ain[i];
        V[i] = (i % 4 == 0) ? 1.0 : 0.0;
    }
    for (int sweep = 0; sweep < 32; sweep++) {
        double off = A[1] * A[1] + A[2] * A[2] + A[5] * A[5];
        double dia = A[0] * A[0] + A[4] * A[4] + A[8] * A[8];
        if (off <= 1e-34 * dia || off == 0.0) break;
        for (int p = 0; p < 2; p++) {
            for (int q = p + 1; q < 3; q++) {
                double apq = A[3 * p + q];
                if (apq == 0.0) continue;
                double app = A[3 * p + p], aqq = A[3 * q + q];
                double tau = (aqq - app) / (2.0 * apq);
                double t = (tau >= 0 ? 1.0 : -1.0) / (fabs(tau) + sqrt(1.0 + tau * tau));
                double c = 1.0 / sqrt(1.0 + t * t), sn = t * c;
                /* A <- G^T A G with G the rotation in the (p, q) plane. */
                for (int k = 0; k < 3; k++) {
                    double akp = A[3 * k + p], akq = A[3 * k + q];
                    A[3 * k + p] = c * akp - sn * akq;
                    A[3 * k + q] = sn * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = A[3 * p + k], aqk = A[3 * q + k];
                    A[3 * p + k] = c * apk - sn * aqk;
                    A[3 * q + k] = sn * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = V[3 * k + p], vkq = V[3 * k + q];
                    V[3 * k + p] = c * vkp - sn * vkq;
                    V[3 * k + q] = sn * vkp + c * vkq;
                }
            }
        }
    }
    l[0] = A[0];
    l[1] = A[4];
    l[2] = A[8];
}

void svd3_signed(const double J[9], double U[9], double s[3], double V[9])
{
    double A[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            A[3 * r + c] = J[r] * J[c] + J[3 + r] * J[3 + c] + J[6 + r] * J[6 + c];
    double l[3], W[9];
    jacobi_eigen3(A, l, W);
    /* Sort eigenpairs by decreasing eigenvalue. */
    int ord[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (l[ord[j]] > l[ord[i]]) {
                int t = ord[i];
                ord[i] = ord[j];
                ord[j] = t;
            }
    double v[3][3];
    for (int k = 0; k < 3; k++)
        for (int r = 0; r < 3; r++) v[k][r] = W[3 * r + ord[k]];
    /* Make V a proper rotation. */
    double c01[3];
    cross3(v[0], v[1], c01);
    if (c01[0] * v[2][0] + c01[1] * v[2][1] + c01[2] * v[2][2] < 0) {
        v[2][0] = -v[2][0];
        v[2][1] = -v[2][1];
        v[2][2] = -v[2][2];
    }
    double u[3][3], Jv[3][3];
    for (int k = 0; k < 3; k++)
        for (int r = 0; r < 3; r++)
            Jv[k][r] = J[3 * r] * v[k][0] + J[3 * r + 1] * v[k][1] + J[3 * r + 2] * v[k][2];
    double n0 = norm3(Jv[0]);
    if (n0 > 0 && isfinite(n0)) {
        for (int r = 0; r < 3; r++) u[0][r] = Jv[0][r] / n0;
    } else {
        u[0][0] = 1;
        u[0][1] = 0;
        u[0][2] = 0;
    }
    /* Gram-Schmidt the second column against the first. */
    double d01 = u[0][0] * Jv[1][0] + u[0][1] * Jv[1][1] + u[0][2] * Jv[1][2];
    for (int r = 0; r < 3; r++) u[1][r] = Jv[1][r] - d01 * u[0][r];
    double n1 = norm3(u[1]);
    if (n1 > 1e-300 * (n0 > 1 ? n0 : 1) && n1 > 0) {
        for (int r = 0; r < 3; r++) u[1][r] /= n1;
    } else {
        any_perp(u[0], u[1]);
    }
    cross3(u[0], u[1], u[2]);
    s[0] = n0;
    s[1] = u[1][0] * Jv[1][0] + u[1][1] * Jv[1][1] + u[1][2] * Jv[1][2];
    s[2] = u[2][0] * Jv[2][0] + u[2][1] * Jv[2][1] + u[2][2] * Jv[2][2];
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            U[3 * r + k] = u[k][r];
            V[3 * r + k] = v[k][r];
        }
}

void svd_signed(int d, const double *J, double *U, double *s, double *V)
{
    if (d == 2) svd2_signed(J, U, s, V);
    else svd3_signed(J, U, s, V);
}
