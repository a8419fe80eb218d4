/* opt/supernodal_lu: A = L U without pivoting, supernodal, for a sparse
 * square matrix whose pattern is symmetric and whose elimination needs no
 * pivoting: an M-matrix (off-diagonal entries <= 0, rows diagonally
 * dominant), such as the mean-value system (opt/mvc). Its Schur
 * complements stay M-matrices, so every pivot is positive and the
 * factorization is stable without pivots (Gaussian elimination on
 * M-matrices). L and U then have the pattern of the Cholesky factor of
 * the symmetric pattern: CHOLMOD's supernodal analysis (fill-reducing
 * order, supernodes) serves both, and the dense work goes to the BLAS.
 *
 * A pivot that is not positive (or is below 1e-14 of its row's original
 * diagonal: a singular or nearly singular system) stops the
 * factorization with SCAF_ERR_NUMERIC: the caller then takes a pivoting
 * LU (opt/mvc: UMFPACK), which also tells a singular system apart.
 *
 * Why it is kept (against UMFPACK on the same mean-value systems, the two
 * binaries alternated: bench/RESULTS-param.md "The mean-value start
 * without UMFPACK"): setup aphrodite 0.74 -> 0.51 s, 1.77M faces 20.5 ->
 * 13.2 s, peak memory 2.73 -> 2.51 GB.
 */
#ifndef SCAF_OPT_SUPERNODAL_LU_H
#define SCAF_OPT_SUPERNODAL_LU_H

#include "base/error.h"

typedef struct opt_lu opt_lu;

/* Factor the n x n matrix A (CSC: Ap n + 1, Ai / Ax Ap[n]; both triangles;
 * rows sorted and unique in each column; every diagonal entry present).
 * NULL on failure, with err set: SCAF_ERR_USAGE (the pattern is not
 * symmetric, or a diagonal entry is missing), SCAF_ERR_NUMERIC (a pivot
 * that is not positive, see above), SCAF_ERR_NOMEM. */
opt_lu *opt_lu_factor(int n, const int *Ap, const int *Ai, const double *Ax, scaf_error *err);

/* x = A^-1 b (x may be b). Uses F's workspace: one solve at a time. */
void opt_lu_solve(opt_lu *F, const double *b, double *x);

/* Stored entries of L and U together (statistics). */
double opt_lu_entries(const opt_lu *F);

void opt_lu_free(opt_lu *F);

#endif /* SCAF_OPT_SUPERNODAL_LU_H */
