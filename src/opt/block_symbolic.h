/* opt/block_symbolic: the supernodal symbolic factor of a system whose
 * unknowns come in interleaved groups of b (the d coordinates of a vertex),
 * from the symbolic factor of its vertex graph.
 *
 * When every nonzero of A is part of a full b x b block (SLIM and Newton
 * systems: a vertex couples all coordinates of its neighbours) and the
 * ordering keeps each vertex's unknowns together, the pattern of L is the
 * vertex graph's pattern with every entry blown up to a b x b block, and
 * each vertex supernode becomes a supernode b times as wide. Analysing the
 * vertex graph (b^2 times fewer entries) and expanding is therefore a
 * valid symbolic factor for A, several times cheaper to compute than
 * analysing the scalar pattern. Its supernodes may differ from those
 * CHOLMOD's relaxed amalgamation would pick for the scalar pattern, so the
 * factorization sums in a different order (last bits of the solution).
 * A block with structural zeros is a superset pattern: still valid (the
 * factor stores the zeros).
 *
 * Kept apart from cholmod_solver.h: only CHOLMOD-facing code includes it. */
#ifndef SCAF_OPT_BLOCK_SYMBOLIC_H
#define SCAF_OPT_BLOCK_SYMBOLIC_H

#include <cholmod.h>

#include "opt/csc.h"

/* The vertex graph of A (upper CSC, n = nb * b): column J holds the row
 * groups of A's scalar columns J*b .. J*b + b - 1, ascending, once each.
 * *cp (nb + 1) and *ri are malloc'ed; returns 0 when out of memory. */
int opt_block_graph(const opt_csc *A, int b, int **cp, int **ri);

/* The vertex permutation behind a scalar one (vperm: n / b entries) when
 * perm keeps every group together and in order (perm[k*b + a] =
 * perm[k*b] + a, perm[k*b] a multiple of b); returns 0 otherwise. */
int opt_block_perm_compress(int n, int b, const int *perm, int *vperm);

/* The supernodal symbolic factor (CHOLMOD_PATTERN, LL') of the scalar
 * system from Lv, the supernodal symbolic factor of its vertex graph:
 * Perm, ColCount, supernodes, row patterns, workspace sizes. NULL with
 * cm->status set on failure. */
cholmod_factor *opt_block_expand_symbolic(const cholmod_factor *Lv, int b, cholmod_common *cm);

#endif /* SCAF_OPT_BLOCK_SYMBOLIC_H */
