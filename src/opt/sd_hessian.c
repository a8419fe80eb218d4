/* opt/sd_hessian: Hessian of the symmetric Dirichlet energy, projected PSD.
 *
 * With psi_i = dPsi/ds_i = 2 s_i - 2 s_i^-3, the general isotropic
 * eigenvalues of a pair are (psi_i + psi_j) / (s_i + s_j) (twist) and
 * (psi_i - psi_j) / (s_i - s_j) (flip); for symmetric Dirichlet the
 * division is exact: s_i^-3 +- s_j^-3 = (s_j^3 +- s_i^3) / (s_i s_j)^3 and
 * s_i^3 +- s_j^3 = (s_i +- s_j)(s_i^2 -+ s_i s_j + s_j^2). The scaling
 * block d2Psi/ds_i ds_j = diag(2 + 6 s_i^-4) is already diagonal. The
 * gradient comes from opt_density_grad (closed form in J, no SVD), the
 * modes from the signed SVD (opt/small_svd).
 */
#include "opt/sd_hessian.h"

#include <math.h>
#include <stddef.h>

#include "opt/energy.h"
#include "opt/small_svd.h"

int opt_sd_eigensystem(int d, const double *J, double *lambda, double *Q)
{
    double det = opt_det(d, J);
    if (!(det > 0) || !isfinite(det)) return -1;
    double U[9], s[3], V[9];
    svd_signed(d, J, U, s, V);
    int dd = d * d, k = 0;
    for (int i = 0; i < d; i++, k++) {
        double s2 = s[i] * s[i];
        lambda[k] = 2.0 + 6.0 / (s2 * s2);
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++) Q[k * dd + a * d + b] = U[a * d + i] * V[b * d + i];
    }
    const double r = sqrt(0.5);
    for (int i = 0; i < d; i++)
        for (int j = i + 1; j < d; j++) {
            double p = s[i] * s[j], p3 = p * p * p, q = s[i] * s[i] + s[j] * s[j];
            lambda[k] = 2.0 + 2.0 * (q + p) / p3;     /* flip */
            lambda[k + 1] = 2.0 - 2.0 * (q - p) / p3; /* twist */
            for (int a = 0; a < d; a++)
                for (int b = 0; b < d; b++) {
                    double x = U[a * d + i] * V[b * d + j], y = U[a * d + j] * V[b * d + i];
                    Q[k * dd + a * d + b] = r * (x + y);
                    Q[(k + 1) * dd + a * d + b] = r * (x - y);
                }
            k += 2;
        }
    return 0;
}

/* Copy the upper triangle of the n by n matrix H to the lower one, so the
 * result is exactly symmetric. */
static void mirror_upper(int n, double *H)
{
    for (int m = 0; m < n; m++)
        for (int k = m + 1; k < n; k++) H[k * n + m] = H[m * n + k];
}

int opt_sd_hessian(int d, const double *J, int project, double *H)
{
    double lambda[9], Q[81];
    if (opt_sd_eigensystem(d, J, lambda, Q) < 0) return -1;
    int dd = d * d, neg = 0;
    for (int m = 0; m < dd * dd; m++) H[m] = 0.0;
    for (int k = 0; k < dd; k++) {
        double l = lambda[k];
        if (l < 0) {
            neg++;
            if (project) continue;
        }
        const double *q = Q + k * dd;
        for (int m = 0; m < dd; m++)
            for (int n = m; n < dd; n++) H[m * dd + n] += l * q[m] * q[n];
    }
    mirror_upper(dd, H);
    return neg;
}

int opt_sd_simplex_hessian(const opt_simplices *S, int s, const double *X, int project, double *e,
                           double *g, double *H)
{
    int d = S->d, nd = (d + 1) * d, dd = d * d;
    double J[9], dJ[9], lambda[9], Q[81], w[12];
    opt_jacobian(S, s, X, J);
    if (opt_sd_eigensystem(d, J, lambda, Q) < 0) return -1;
    const double *G = S->grad + (size_t)s * nd;
    double wt = S->weight[s];
    *e = wt * opt_density_grad(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, dJ);
    opt_pullback(d, G, dJ, g);
    for (int m = 0; m < nd; m++) g[m] *= wt;
    for (int m = 0; m < nd * nd; m++) H[m] = 0.0;
    int neg = 0;
    for (int k = 0; k < dd; k++) {
        double l = lambda[k];
        if (l < 0) {
            neg++;
            if (project) continue;
        }
        /* Mode k pulled back to the corners: H += weight * l * w w^T. */
        opt_pullback(d, G, Q + k * dd, w);
        double c = wt * l;
        for (int m = 0; m < nd; m++) {
            double cm = c * w[m];
            for (int n = m; n < nd; n++) H[m * nd + n] += cm * w[n];
        }
    }
    mirror_upper(nd, H);
    return neg;
}
