/* opt/cotan_laplacian: the discrete Laplace-Beltrami operator of a
 * triangle surface, as its two matrices.
 *
 *   L  the cotangent stiffness matrix: L_ij = (cot a_ij + cot b_ij) / 2
 *      for an edge ij with opposite angles a_ij, b_ij (one on a boundary
 *      edge), L_ii = -sum_j L_ij. Symmetric, rows sum to zero, negative
 *      semidefinite (libigl's cotmatrix convention), so M - dL is positive
 *      definite for d > 0 and a positive mass M.
 *   M  the lumped (barycentric) mass: a third of the area of every face
 *      around the vertex, a diagonal matrix stored as a vector.
 * Depends on angles only: L is the same for a scaled copy of the surface.
 */
#ifndef SCAF_OPT_COTAN_LAPLACIAN_H
#define SCAF_OPT_COTAN_LAPLACIAN_H

#include "base/error.h"
#include "opt/csc.h"

/* Cotangent of the angle at a in the 3D triangle a b c (inf or nan when
 * the triangle is degenerate). */
double opt_cot_at(const double *a, const double *b, const double *c);

/* Area of the 3D triangle a b c. */
double opt_tri_area3(const double *a, const double *b, const double *c);

/* L (upper part, every diagonal entry stored) of the surface with nv
 * vertices V (#V by 3) and nf faces F (#F by 3, 0-based). A face whose
 * cotangent is not finite (zero area) fails with SCAF_ERR_MESH naming it;
 * SCAF_ERR_NOMEM. */
scaf_status opt_cotan_laplacian(int nv, const double *V, int nf, const int *F, opt_csc *L,
                                scaf_error *err);

/* The barycentric lumped mass of every vertex into mass (nv entries);
 * returns the total area. */
double opt_mass_barycentric(int nv, const double *V, int nf, const int *F, double *mass);

#endif /* SCAF_OPT_COTAN_LAPLACIAN_H */
