/* scaffold/tri2: per-triangle 2D distortion kernels used by the SCAF loop.
 *
 * A triangle's rest shape is stored as the inverse of its rest edge matrix
 * (Dm^-1, 2 by 2) and a weight; the Jacobian of the map rest -> UV is
 * J = Ds Dm^-1 with Ds = [u1-u0 | u2-u0]. Provides energies (symmetric
 * Dirichlet, ARAP, conformal/MIPS) on J, their derivative dE/dJ (for the
 * Armijo test), SLIM weights and closest rotations, and the 6 by 6 SLIM
 * proxy element matrix. Pure functions; a triangle with det J <= 0 has
 * infinite energy (the line search never accepts it).
 * Matrices are row-major 2 by 2: M[2*r + c].
 */
#ifndef SCAF_SCAFFOLD_TRI2_H
#define SCAF_SCAFFOLD_TRI2_H

#include "scaf/scaf.h"

/* Rest frame of a 3D triangle laid flat isometrically.
 *   p0, p1, p2  3D corners; Dminv out 2 by 2; returns the 3D area
 *   (0 for a degenerate triangle, Dminv then undefined). */
double tri2_rest_from_3d(const double p0[3], const double p1[3], const double p2[3], double Dminv[4]);

/* Rest frame from a 2D triangle (counter-clockwise). When its area is below
 * eps (> 0), an equilateral triangle of area eps is used instead (SCAF's
 * degeneracy guard). Returns the area used. */
double tri2_rest_from_2d(const double a[2], const double b[2], const double c[2], double eps,
                         double Dminv[4]);

/* J = Ds Dminv for UV corners a, b, c. */
void tri2_jacobian(const double a[2], const double b[2], const double c[2], const double Dminv[4],
                   double J[4]);

/* Energy of J (+inf when det J <= 0). SD: ||J||^2 + ||J^-1||^2;
 * ARAP: ||J - R||^2; conformal: ||J||^2 / det J. */
double tri2_energy(scaf_energy e, const double J[4]);

/* dE/dJ (2 by 2) at J with det J > 0. */
void tri2_energy_grad(scaf_energy e, const double J[4], double G[4]);

/* SLIM: weight matrix W (symmetric 2 by 2) and closest rotation R of J
 * with det J > 0, for energy e. */
void tri2_slim_weights(scaf_energy e, const double J[4], double W[4], double R[4]);

/* The proxy a * ||W (J(x) - R)||^2 as 0.5 x^T K x - b^T x + const over the
 * 6 unknowns x = (u0, v0, u1, v1, u2, v2):
 *   K 6 by 6 (row-major) out, b 6 out. */
void tri2_slim_element(double a, const double Dminv[4], const double W[4], const double R[4],
                       double K[36], double b[6]);

/* Coefficients of det(Ds + t dDs) = c0 + c1 t + c2 t^2 and its smallest
 * positive root (+inf when none). */
double tri2_max_step(const double a[2], const double b[2], const double c[2], const double da[2],
                     const double db[2], const double dc[2]);

#endif /* SCAF_SCAFFOLD_TRI2_H */
