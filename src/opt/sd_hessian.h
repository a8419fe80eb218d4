/* opt/sd_hessian: Hessian of the symmetric Dirichlet energy, projected PSD:
 * the symmetric Dirichlet case of opt/isotropic_hessian (same eigensystem
 * and conventions; kept as the short names for that energy).
 *
 * Density Psi(J) = ||J||_F^2 + ||J^-1||_F^2 of the d by d Jacobian J
 * (row-major, d = 2 or 3, det J > 0). Its Hessian d2Psi/dJ2 (d^2 by d^2,
 * over vec(J) in row-major order: index a*d + b for J[a][b]) has a closed
 * eigensystem in the singular values s_1..s_d of J = U diag(s) V^T
 * (Smith, De Goes, Kim 2019, "Analytic eigensystems for isotropic
 * distortion energies"):
 *   scaling  Q = u_i v_i^T                     lambda = 2 + 6 / s_i^4
 *   flip     Q = (u_i v_j^T + u_j v_i^T)/sqrt2 lambda = 2 + 2 (s_i^2 + s_i s_j + s_j^2) / (s_i s_j)^3
 *   twist    Q = (u_i v_j^T - u_j v_i^T)/sqrt2 lambda = 2 - 2 (s_i^2 - s_i s_j + s_j^2) / (s_i s_j)^3
 * for i < j: d + d(d-1) = d^2 modes, orthonormal in the Frobenius product.
 * Scaling and flip eigenvalues are always positive; only twists can be
 * negative, in 2D and 3D: when s_i^2 - s_i s_j + s_j^2 > (s_i s_j)^3, i.e.
 * an anisotropic or compressed pair (s = (2, 0.5): twist -4.5; zero at a
 * rotation, positive for a uniform scale > 1).
 * The projected Hessian keeps every mode with its eigenvalue clamped to 0
 * (exactly 0, no floor: a caller needing strict definiteness regularizes
 * the assembled system), so H_proj - H is PSD with rank = the number of
 * clamped modes, and H_proj = H when H is already PSD. The eigenvalue
 * formulas are written without s_i - s_j in a denominator, so repeated
 * singular values (a rotation, a similarity) need no special case.
 *
 * Per simplex the same is pulled back to the corner positions through the
 * simplex's gradient operator (opt_pullback): with D = dJ/dx the corner
 * Hessian is weight * D^T H D, a ((d+1)d)^2 matrix (unknown (i, a) =
 * coordinate a of corner i at index i*d + a), PSD when H is projected.
 * Nothing here allocates; an inverted or degenerate J (det <= 0 or
 * non-finite) is reported by a negative return value.
 */
#ifndef SCAF_OPT_SD_HESSIAN_H
#define SCAF_OPT_SD_HESSIAN_H

#include "opt/simplices.h"

/* Eigensystem of d2Psi/dJ2 at J (d by d, det > 0). lambda: d^2 eigenvalues
 * out (scaling modes first, then a flip and a twist per pair i < j).
 * Q: d^2 modes out, each a d by d matrix (mode k at Q + k*d*d), unit
 * Frobenius norm. Returns 0, or -1 when det J <= 0 (outputs undefined). */
int opt_sd_eigensystem(int d, const double *J, double *lambda, double *Q);

/* Hessian of Psi at J: H (d^2 by d^2, row-major) out. project != 0 clamps
 * negative eigenvalues to 0. Returns the number of negative eigenvalues
 * (clamped when projecting), or -1 when det J <= 0 (H undefined). */
int opt_sd_hessian(int d, const double *J, int project, double *H);

/* Simplex s of S at positions X (#X by d): e = weight * Psi(J) out, g
 * ((d+1)d) = weight * gradient w.r.t. the corner positions out, H
 * (((d+1)d)^2, row-major) = weight * Hessian w.r.t. them out, projected
 * when project != 0. Returns the number of negative eigenvalues of
 * d2Psi/dJ2, or -1 when the simplex is inverted or degenerate (det J <= 0;
 * outputs undefined). */
int opt_sd_simplex_hessian(const opt_simplices *S, int s, const double *X, int project, double *e,
                           double *g, double *H);

#endif /* SCAF_OPT_SD_HESSIAN_H */
