/* opt/mvc: mean-value coordinates (Floater 2003) for the initial embedding.
 *
 * Every free vertex i is placed at the convex combination of its
 * neighbours with weights w_ij = (tan(a_ij/2) + tan(b_ij/2)) / |x_i - x_j|,
 * where a_ij and b_ij are the 3D angles at i of the two triangles on edge
 * ij. The weights are positive for non-degenerate triangles, so with the
 * boundary on a convex polygon the map is a bijective embedding (Floater's
 * theorem also holds for non-symmetric positive weights). The system is not
 * symmetric; it is solved with UMFPACK (sparse LU with iterative
 * refinement), a direct solve, so the result is as exact as a Tutte solve.
 * A vertex with any degenerate incident 3D triangle (zero angle, zero
 * edge, a weight that overflows) gets uniform weights for its whole row, so
 * no NaN or non-positive weight reaches the system.
 * Errors: SCAF_ERR_NUMERIC (UMFPACK reports a singular matrix, e.g. a
 * component not connected to a fixed vertex), SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_MVC_H
#define SCAF_OPT_MVC_H

#include "base/error.h"

/* Per-corner weights. nv vertices V (#V by 3), nf faces F (#F by 3).
 * W: #F*3 by 2 out; for the corner at F[3f+k] = i, W[2(3f+k)] is its
 * contribution to w_ij with j = F[3f+(k+1)%3] and W[2(3f+k)+1] to w_ik
 * with k = F[3f+(k+2)%3]. Every entry is finite and > 0.
 * uniform_row (#V, may be NULL): set to 1 for the vertices that fell back
 * to uniform weights (their corners all get weight 1), else 0.
 * Returns the number of such vertices. */
int opt_mvc_corner_weights(int nv, const double *V, int nf, const int *F, double *W,
                           unsigned char *uniform_row);

/* Solve the mean-value system. fixed (#V): nonzero for vertices whose UV
 * is given. UV: #V by 2; fixed rows are read, the others written. A free
 * vertex used by no face gets a singular system (SCAF_ERR_NUMERIC). */
scaf_status opt_mvc_solve(int nv, const double *V, int nf, const int *F, const unsigned char *fixed,
                          double *UV, scaf_error *err);

#endif /* SCAF_OPT_MVC_H */
