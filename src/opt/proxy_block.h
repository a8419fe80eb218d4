/* opt/proxy_block: one term's share of the SLIM proxy system, cached pattern.
 *
 * The SLIM proxy of a term is sum_s weight_s ||W_s (J_s(x) - T_s)||_F^2.
 * Unknowns are the coordinates of free vertices, interleaved: vertex v
 * with dof[v] = k >= 0 owns unknowns k*d + 0..d-1; dof[v] = -1 marks a
 * fixed vertex (its terms move to the right-hand side). The normal
 * equations are A x = b with, per simplex, the (d+1)d square block
 * weight * (G G^T) (x) (W^T W) (Kronecker product) and
 * b_(i,a) = weight * (W^T W T G^T)[a][i] minus the fixed-corner couplings.
 *
 * A block owns: a vertex-level pattern (which free vertex pairs interact),
 * the scalar upper CSC it expands to, and a map from each simplex's vertex
 * pairs to vertex-level entries. opt_proxy_block_pattern does the sorting
 * once; opt_proxy_block_fill is then a pure value fill (no search, no
 * allocation) and may be repeated as long as the simplices' vertex indices
 * and the dof numbering of their vertices do not change. Keep one block for
 * the chart (its pattern survives every iteration) and one for the
 * scaffold (rebuilt every iteration); opt/proxy_system sums them.
 */
#ifndef SCAF_OPT_PROXY_BLOCK_H
#define SCAF_OPT_PROXY_BLOCK_H

#include "opt/csc.h"
#include "opt/energy.h"
#include "opt/fill_split.h"

typedef struct opt_proxy_block {
    int d;                 /* dimension of the simplices */
    int ns;                /* number of simplices the pattern was built for */
    int nfree;             /* 1 + the largest dof its simplices use: the block's
                      matrix is nfree*d square (a leading part of the
                      whole system when other blocks use higher dofs) */
    int *vcolptr;          /* nfree+1: vertex-level upper pattern, columns by dof */
    int *vrowidx;          /* vertex-level rows (dofs), ascending, diagonal last */
    int *map;              /* pair and vertex blocks: the vertex-level entry of
                             each pair (see their pattern functions) */
    int *pos;              /* simplex blocks, ns by (d+1)(d+2)/2: where the
                             block of each local corner pair (i <= j) starts
                             in A's values (its first scalar column), -1
                             when a corner is fixed */
    int *stride;           /* simplex blocks, nfree: for each vertex column,
                             the distance in A's values between its first two
                             scalar columns (column a2 of the pair block at
                             pos starts at pos + a2 * stride + a2 (a2 - 1) / 2) */
    unsigned short *first; /* simplex blocks, ns: bit p set when the simplex
                              is the first (in simplex order) to write corner
                              pair p's entry; a SLIM fill stores there
                              instead of adding, so it needs no zeroing */
    opt_csc A;             /* scalar upper CSC, nfree*d square; values from fill */
    unsigned version;      /* incremented each time the pattern is rebuilt */
    opt_fill_split split;  /* a parallel fill's per-batch column ranges,
                             kept with the pattern */
} opt_proxy_block;

/* Number the free vertices: fixed[v] != 0 marks vertex v fixed (fixed may
 * be NULL: none). dof gets nv entries, ascending from 0 over the free
 * vertices, -1 for the fixed ones; returns the number of free ones. */
int opt_dof_numbering(int nv, const unsigned char *fixed, int *dof);

/* Free everything; safe on a zeroed block. */
void opt_proxy_block_free(opt_proxy_block *b);

/* (Re)build the pattern for the simplices S under the numbering dof (one
 * entry per vertex of X: a dof in [0, nfree) or -1). Values are zeroed.
 * Number the chart's free vertices first (dofs 0..m-1) and the scaffold's
 * after them: the chart block's pattern then never depends on the
 * scaffold, whose vertex count changes every iteration. */
scaf_status opt_proxy_block_pattern(opt_proxy_block *b, const opt_simplices *S, const int *dof,
                                    int nfree, scaf_error *err);

/* A block of per-vertex terms (soft positional constraints and the
 * like): its pattern holds the d by d diagonal block of each free vertex
 * of verts (n entries, repeats allowed, fixed ones skipped) and nothing
 * else. Values are zeroed; add them with opt_proxy_block_add_diagonal. */
scaf_status opt_proxy_block_pattern_vertices(opt_proxy_block *b, int d, int n, const int *verts,
                                             const int *dof, int nfree, scaf_error *err);

/* A block of vertex-pair couplings (a surface term's edges): its pattern
 * holds, for each pair k of pairs (n by 2 vertex ids; (v, v) allowed) whose
 * two vertices are free, the d by d block coupling them, plus the diagonal
 * block of every free vertex a pair touches. b->map gets n + nfree
 * entries, the first n the pairs' vertex-level entries (-1 when a vertex
 * is fixed). Values are zeroed; add them with opt_proxy_block_add_pair
 * and opt_proxy_block_add_diagonal. */
scaf_status opt_proxy_block_pattern_pairs(opt_proxy_block *b, int d, int n, const int *pairs,
                                          const int *dof, int nfree, scaf_error *err);

/* Add w * I (d by d) to the block of pair k (the pattern's pairs and
 * dof); nothing when one of its vertices is fixed. A pair (v, v) adds to
 * the diagonal block. Values accumulate. */
void opt_proxy_block_add_pair(opt_proxy_block *b, int k, const int *dof, const int *pairs,
                              double w);

/* Add w * I (d by d) to the diagonal block of the free vertex with dof k,
 * which must be in the pattern (any block: the diagonal sorts last in its
 * column). Values accumulate: a term refilling a kept pattern zeroes
 * A.val (A.nnz entries) first. */
void opt_proxy_block_add_diagonal(opt_proxy_block *b, int k, double w);

/* Zero the values (A.nnz), big blocks in base/parallel's threads. */
void opt_proxy_block_zero(opt_proxy_block *b);
/* Fill values with the SLIM proxy of term t at positions X (#X by d):
 * per simplex the signed SVD of J, weights W and targets T
 * (opt_slim_proxy). rhs (nfree*d) is ACCUMULATED into (zero it first).
 * t->s must be the simplex set the pattern was built for. Big sets run in
 * base/parallel's threads; the values are the serial fill's, bit for bit,
 * whatever the thread count. */
void opt_proxy_block_fill(opt_proxy_block *b, const opt_term *t, const int *dof, const double *X,
                          double *rhs);

/* The same with squared SLIM weights capped at w2_cap (see
 * opt_slim_proxy_capped). Returns the largest uncapped squared weight, so
 * the caller knows whether the cap changed anything. */
double opt_proxy_block_fill_capped(opt_proxy_block *b, const opt_term *t, const int *dof,
                                   const double *X, double *rhs, double w2_cap);

/* Accumulate one simplex's full local matrix into the block's values, for
 * fills other than SLIM's Kronecker form (projected Newton, opt/newton_fill).
 * s: a simplex of the set the pattern was built for. K: ((d+1)d) square,
 * symmetric, row-major, unknown (corner i, coordinate a) at i*d + a.
 * Couplings with fixed corners (dof -1) are dropped: the caller's unknowns
 * are then steps of the free vertices, which fixed ones do not take. */
void opt_proxy_block_add_local(opt_proxy_block *b, const opt_simplices *S, int s, const int *dof,
                               const double *K);

/* The same, only into the columns of free vertices with dofs in [lo, hi)
 * (a thread's share of a parallel fill). */
void opt_proxy_block_add_local_range(opt_proxy_block *b, const opt_simplices *S, int s,
                                     const int *dof, const double *K, int lo, int hi);

#endif /* SCAF_OPT_PROXY_BLOCK_H */
