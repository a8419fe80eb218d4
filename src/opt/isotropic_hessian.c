/* opt/isotropic_hessian: Hessians of the isotropic energies (see
 * isotropic_hessian.h).
 *
 * Per energy only the second derivatives in the singular values are
 * written out, in its row (opt/energy_kind.h: sv_hessian): the d by d
 * scaling block and the flip and twist eigenvalue of each pair, derived
 * from Psi_i as (Psi_i -+ Psi_j) / (s_i -+ s_j) with the division done by
 * hand. Every other piece is shared here: the signed SVD (opt/small_svd) gives the modes,
 * the gradient comes from opt_density_grad (closed form in J). The scaling
 * block is diagonalized by cyclic Jacobi rotations; a diagonal block
 * (symmetric Dirichlet) is taken as it is, so that energy's modes are the
 * plain u_i v_i^T.
 */
#include "opt/isotropic_hessian.h"

#include <math.h>
#include <stddef.h>

#include "opt/energy_kind.h"
#include "opt/small_svd.h"

/* Eigen-decomposition of the symmetric d by d matrix A (overwritten) by
 * cyclic Jacobi rotations: lambda (d) out, E (d by d) out with eigenvector
 * k in column k. A diagonal A is returned as it is (E = I). */
static void block_eigen(int d, double *A, double *lambda, double *E)
{
    for (int i = 0; i < d * d; i++) E[i] = i % (d + 1) == 0 ? 1.0 : 0.0;
    for (int sweep = 0; sweep < 32; sweep++) {
        double off = 0.0, diag = 0.0;
        for (int p = 0; p < d; p++) {
            diag += fabs(A[p * d + p]);
            for (int q = p + 1; q < d; q++) off += fabs(A[p * d + q]);
        }
        if (!(off > 1e-18 * diag)) break; /* also 0 off-diagonal, NaN */
        for (int p = 0; p < d; p++)
            for (int q = p + 1; q < d; q++) {
                double apq = A[p * d + q];
                if (apq == 0.0) continue;
                /* the rotation by t = tan(angle) that zeroes A[p][q]: the
                 * smaller root of t^2 + 2 theta t - 1 = 0 */
                double theta = (A[q * d + q] - A[p * d + p]) / (2.0 * apq);
                double t = fabs(theta) > 1e150
                    ? 0.5 / theta
                    : (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                double c = 1.0 / sqrt(t * t + 1.0), sn = t * c;
                for (int k = 0; k < d; k++) { /* A R */
                    double akp = A[k * d + p], akq = A[k * d + q];
                    A[k * d + p] = c * akp - sn * akq;
                    A[k * d + q] = sn * akp + c * akq;
                }
                for (int k = 0; k < d; k++) { /* R^T (A R) */
                    double apk = A[p * d + k], aqk = A[q * d + k];
                    A[p * d + k] = c * apk - sn * aqk;
                    A[q * d + k] = sn * apk + c * aqk;
                }
                A[p * d + q] = A[q * d + p] = 0.0;
                for (int k = 0; k < d; k++) { /* E R */
                    double ekp = E[k * d + p], ekq = E[k * d + q];
                    E[k * d + p] = c * ekp - sn * ekq;
                    E[k * d + q] = sn * ekp + c * ekq;
                }
            }
    }
    for (int i = 0; i < d; i++) lambda[i] = A[i * d + i];
}

int opt_isotropic_eigensystem(opt_energy e, int d, const double *J, double *lambda, double *Q)
{
    double det = opt_det(d, J);
    if (!(det > 0) || !isfinite(det)) return -1;
    double U[9], s[3], V[9], B[9], E[9], flip[3], twist[3];
    svd_signed(d, J, U, s, V);
    opt_energy_table[e]->sv_hessian(d, s, B, flip, twist);
    block_eigen(d, B, lambda, E);
    int dd = d * d, k = 0;
    for (; k < d; k++) /* scaling: sum_i E[i][k] u_i v_i^T */
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++) {
                double acc = 0.0;
                for (int i = 0; i < d; i++)
                    if (E[i * d + k] != 0.0) acc += E[i * d + k] * U[a * d + i] * V[b * d + i];
                Q[k * dd + a * d + b] = acc;
            }
    const double r = sqrt(0.5);
    for (int i = 0, pair = 0; i < d; i++)
        for (int j = i + 1; j < d; j++, pair++) {
            lambda[k] = flip[pair];
            lambda[k + 1] = twist[pair];
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

int opt_isotropic_hessian(opt_energy e, int d, const double *J, int project, double *H)
{
    double lambda[9], Q[81];
    if (opt_isotropic_eigensystem(e, d, J, lambda, Q) < 0) return -1;
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

int opt_isotropic_simplex_hessian(opt_energy e, const opt_simplices *S, int s, const double *X,
                                  int project, double *en, double *g, double *H)
{
    int d = S->d, nd = (d + 1) * d, dd = d * d;
    double J[9], dJ[9], lambda[9], Q[81], w[12];
    opt_jacobian(S, s, X, J);
    if (opt_isotropic_eigensystem(e, d, J, lambda, Q) < 0) return -1;
    const double *G = S->grad + (size_t)s * nd;
    double wt = S->weight[s];
    *en = wt * opt_density_grad(e, d, J, dJ);
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
