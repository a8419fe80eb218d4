/* opt/surface_arap_term: a closed (or open) triangle surface in R^3 pulled
 * toward a target shape, "spokes and rims" as-rigid-as-possible, as an
 * objective term (opt/objective) of the 3D SCAF loop.
 *
 * Energy (Chao et al. 2010; libigl's ARAP_ENERGY_TYPE_SPOKES_AND_RIMS):
 *   E(x) = w sum_k sum_{f incident to k} sum_{edges (i,j) of f}
 *            c_ij^f || (x_i - x_j) - R_k (t_i - t_j) ||^2
 * with t the target positions, c_ij^f = cot(angle opposite (i, j) in the
 * TARGET triangle f) / 2 and R_k one rotation per vertex. Each triangle
 * enters the sums of its three vertices; its part is the Dirichlet energy
 * of the linear map x - R_k t over the target triangle, so every term is
 * >= 0 (also with obtuse triangles, whose negative cotangents are
 * balanced inside the triangle) and E = 0 exactly at a rigid motion of
 * the target. Per face edge, sum_k R_k over the face's three vertices
 * M_f folds the sum into
 *   w c (3 ||dx||^2 - 2 dx . M_f dt + 3 ||dt||^2).
 *
 * Rotations are re-fitted (local step of ARAP: R_k = the rotation closest
 * to sum c dx dt^T, opt/small_svd) at the start of every iteration — in
 * fill and hessian_fill, at the iteration's positions — and held during
 * its line search. With fixed rotations the energy is quadratic in x, so
 * the SLIM proxy is the energy itself and the Newton fill is exact: the
 * block is 3wc I on the diagonals of (i, j) and -3wc I between them (half
 * the Hessian), the right-hand side w c M_f dt (half the negative gradient
 * at 0); Newton doubles the matrix and takes -gradient at x. Re-fitting
 * only lowers E, so the loop's energy decreases across iterations.
 * Where target triangles are obtuse (negative cotangents), a vertex's
 * sum c dt dt^T may be indefinite and its best rotation at the target
 * itself not the identity: E at the target is then slightly above 0
 * (3e-5 of the floor on the dimpled sphere of tests/app); the local step
 * is kept exact so that E never rises.
 *
 * Weight: w = weight_ratio / A (A the target's area) makes E dimensionless
 * (the same for a scaled problem); E / w / A <= about 2 * 3 for a surface
 * shrunk to nothing. The authors of SCAF weight their ARAP term 1e5 against
 * a scaffold whose weight follows the mesh energy; scaf's 3D loop weights
 * the scaffold from this term's energy plus a floor (scaffold/scaf_loop:
 * scaf_loop_init_volume), so only the ratio of the two matters and
 * weight_ratio = 1 is the default.
 *
 * The term touches vertices 0..nv-1 of X (the loop's mesh vertices). No
 * barrier, no max step, no validity test: the scaffold keeps the surface
 * from passing through itself. Fails with SCAF_ERR_MESH on a target
 * triangle of zero area or non-finite cotangent (naming it),
 * SCAF_ERR_USAGE on a bad index, SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_SURFACE_ARAP_TERM_H
#define SCAF_OPT_SURFACE_ARAP_TERM_H

#include "opt/objective.h"

typedef struct opt_surface_arap {
    int nv, nf;
    int *F;         /* nf by 3 */
    double *target; /* nv by 3 target positions t */
    double *cot;    /* nf by 3: c of the edge opposite corner e of face f */
    double *R;      /* nv by 9 rotations, row-major (identity at first) */
    double *Mdt;    /* nf by 3 by 3: M_f dt of each face edge (fit) */
    int *pairs;     /* 3 nf by 2: the face edges, for the system pattern */
    double w;       /* the weight */
    double area;    /* target area A */
    int *built_dof; /* nv: the dofs the block's pattern was built for */
    int built;      /* the pattern exists */
} opt_surface_arap;

/* Set up over nv vertices with faces F (nf by 3) and target positions
 * target (nv by 3), weight w = weight_ratio / (target area). Copies. */
scaf_status opt_surface_arap_init(opt_surface_arap *s, int nv, int nf, const int *F,
                                  const double *target, double weight_ratio, scaf_error *err);

/* Re-fit the rotations to the positions X (at least nv by 3). */
void opt_surface_arap_fit(opt_surface_arap *s, const double *X);

/* The energy at X with the current rotations. */
double opt_surface_arap_energy(const opt_surface_arap *s, const double *X);

/* The term's ops over s (which must outlive it). */
opt_obj_term opt_surface_arap_make(opt_surface_arap *s);

void opt_surface_arap_free(opt_surface_arap *s);

#endif /* SCAF_OPT_SURFACE_ARAP_TERM_H */
