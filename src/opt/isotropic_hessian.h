/* opt/isotropic_hessian: Hessians of the isotropic energies, projected PSD.
 *
 * Each density of opt/energy is a function Psi(s_1..s_d) of the signed
 * singular values of the d by d Jacobian J = U diag(s) V^T (d = 2 or 3,
 * det J > 0 so every s_i > 0). Its Hessian d2Psi/dJ2 (d^2 by d^2, over
 * vec(J) in row-major order: index a*d + b for J[a][b]) has a closed
 * eigensystem (Smith, De Goes, Kim 2019, "Analytic eigensystems for
 * isotropic distortion energies"), with Psi_i = dPsi/ds_i:
 *   scaling  Q = sum_i e_i u_i v_i^T, (e, lambda) an eigenpair of the d by
 *            d block d2Psi/ds_i ds_j (diagonal for symmetric Dirichlet;
 *            coupled through det J for ARAP's barrier and for conformal)
 *   flip     Q = (u_i v_j^T + u_j v_i^T)/sqrt2 lambda = (Psi_i - Psi_j) / (s_i - s_j)
 *   twist    Q = (u_i v_j^T - u_j v_i^T)/sqrt2 lambda = (Psi_i + Psi_j) / (s_i + s_j)
 * for i < j: d + d(d-1) = d^2 modes, orthonormal in the Frobenius product.
 * Each energy's row (opt/energy_kind.h) writes its scaling block and pair
 * eigenvalues in closed form without s_i - s_j in a denominator, so
 * repeated singular values (a rotation, a similarity) need no special
 * case; its file says which modes can be negative.
 * The projected Hessian keeps every mode with its eigenvalue clamped to 0
 * (exactly 0, no floor: a caller needing strict definiteness regularizes
 * the assembled system), so H_proj - H is PSD with rank = the number of
 * clamped modes, and H_proj = H when H is already PSD.
 *
 * Per simplex the same is pulled back to the corner positions through the
 * simplex's gradient operator (opt_pullback): with D = dJ/dx the corner
 * Hessian is weight * D^T H D, a ((d+1)d)^2 matrix (unknown (i, a) =
 * coordinate a of corner i at index i*d + a), PSD when H is projected.
 * Nothing here allocates; an inverted or degenerate J (det <= 0 or
 * non-finite) is reported by a negative return value.
 */
#ifndef SCAF_OPT_ISOTROPIC_HESSIAN_H
#define SCAF_OPT_ISOTROPIC_HESSIAN_H

#include "opt/energy.h"
#include "opt/simplices.h"

/* Eigensystem of d2Psi/dJ2 of energy e at J (d by d, det > 0). lambda: d^2
 * eigenvalues out (scaling modes first, then a flip and a twist per pair
 * i < j). Q: d^2 modes out, each a d by d matrix (mode k at Q + k*d*d),
 * unit Frobenius norm. Returns 0, or -1 when det J <= 0 (outputs
 * undefined). */
int opt_isotropic_eigensystem(opt_energy e, int d, const double *J, double *lambda, double *Q);

/* Hessian of Psi at J: H (d^2 by d^2, row-major) out. project != 0 clamps
 * negative eigenvalues to 0. Returns the number of negative eigenvalues
 * (clamped when projecting), or -1 when det J <= 0 (H undefined). */
int opt_isotropic_hessian(opt_energy e, int d, const double *J, int project, double *H);

/* Simplex s of S at positions X (#X by d): en = weight * Psi(J) out, g
 * ((d+1)d) = weight * gradient w.r.t. the corner positions out, H
 * (((d+1)d)^2, row-major) = weight * Hessian w.r.t. them out, projected
 * when project != 0. Returns the number of negative eigenvalues of
 * d2Psi/dJ2, or -1 when the simplex is inverted or degenerate (det J <= 0;
 * outputs undefined). */
int opt_isotropic_simplex_hessian(opt_energy e, const opt_simplices *S, int s, const double *X,
                                  int project, double *en, double *g, double *H);

#endif /* SCAF_OPT_ISOTROPIC_HESSIAN_H */
