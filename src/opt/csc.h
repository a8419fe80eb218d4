/* opt/csc: symmetric sparse matrices in compressed-column form (upper part).
 *
 * The optimizer's systems are symmetric; only the upper triangle is stored
 * (row <= col), rows ascending within each column, no duplicates. That is
 * CHOLMOD's stype = 1 layout, so the solver wraps these arrays without a
 * copy. opt_csc_from_triplets builds one from (row, col, value) triplets
 * in either triangle, summing duplicates — used for one-off systems
 * (Tutte / harmonic); the SLIM proxy uses the cached-pattern path in
 * opt/proxy_block. Fails only with SCAF_ERR_NOMEM or SCAF_ERR_USAGE
 * (index out of range).
 */
#ifndef SCAF_OPT_CSC_H
#define SCAF_OPT_CSC_H

#include "base/error.h"

typedef struct opt_csc {
    int n;       /* rows = columns */
    int nnz;     /* stored entries */
    int *colptr; /* n+1 column starts */
    int *rowidx; /* nnz row indices, row <= col, ascending per column */
    double *val; /* nnz values */
} opt_csc;

/* Free and reset to empty; safe on a zeroed struct. */
void opt_csc_free(opt_csc *A);

/* y = A x for the symmetric matrix whose upper part A stores. x, y: n. */
void opt_csc_symv(const opt_csc *A, const double *x, double *y);

/* Whether A has the layout above: colptr from 0 to nnz, non-decreasing;
 * in each column rows strictly ascending, in [0, column]. For assert()s of
 * the code that builds systems and of the solver that wraps them. */
int opt_csc_is_upper_sorted(const opt_csc *A);

/* Build the upper part from nt triplets (rows I, columns Jc, values Val),
 * either triangle, duplicates summed. */
scaf_status opt_csc_from_triplets(opt_csc *A, int n, int nt, const int *I, const int *Jc,
                                  const double *Val, scaf_error *err);

/* Expand a vertex-level upper pattern to scalars, d unknowns per vertex
 * interleaved (vertex v owns v*d + 0..d-1): nv columns vcolptr (nv+1) with
 * ascending rows vrowidx, the diagonal last. Vertex entry (I, J) becomes
 * the d by d block of rows I*d.., columns J*d.. (its upper part when
 * I == J). Values zeroed when zero_values, else left unset (for a caller
 * that overwrites them all). On failure A holds what was allocated (free
 * it with opt_csc_free). */
scaf_status opt_csc_expand_vertex_pattern(opt_csc *A, int d, int nv, const int *vcolptr,
                                          const int *vrowidx, int zero_values, scaf_error *err);

/* Whether A's pattern is exactly what opt_csc_expand_vertex_pattern makes
 * of (d, nv, vcolptr, vrowidx). Reads A's whole pattern: for assert()s and
 * for checking a pattern kept by vertices against a scalar one. */
int opt_csc_is_vertex_expansion(const opt_csc *A, int d, int nv, const int *vcolptr,
                                const int *vrowidx);

/* Whether A's first nvc * d columns are the expansion of vertex columns
 * 0..nvc-1 (the others may be anything). */
int opt_csc_starts_with_vertex_expansion(const opt_csc *A, int d, int nvc, const int *vcolptr,
                                         const int *vrowidx);

#endif /* SCAF_OPT_CSC_H */
