/* opt/given_symbolic: CHOLMOD's supernodal symbolic analysis for a given
 * fill-reducing permutation, with fewer passes over the matrix.
 *
 * cholmod_analyze_p with a given permutation forms triu(A(p,p)) by two
 * transposes, then, after the etree's weighted postorder, forms it again
 * by two more. opt_given_symbolic builds triu(A(p,p)) in one pass, its
 * transpose by one CHOLMOD transpose and the postordered matrix by
 * relabelling, and calls CHOLMOD's own steps (etree, column counts,
 * postorder, supernodes) on them: the factor (Perm, ColCount, supernodes,
 * row patterns) is the one cholmod_analyze_p would give. The relaxation
 * (cm->nrelax, zrelax) and cm->postorder apply as in CHOLMOD.
 *
 * Why it is kept (against cholmod_analyze_p, callgrind, one run each,
 * same commit but this module: bench/RESULTS-param.md "Symbolic analysis
 * in three passes"): analysis instructions camelhead 227.5 M -> 186.2 M
 * (-18%), aphrodite 895.5 M -> 712.1 M (-20.5%); whole iterations -2.9%.
 *
 * Kept apart from cholmod_solver.h: only CHOLMOD-facing code includes it. */
#ifndef SCAF_OPT_GIVEN_SYMBOLIC_H
#define SCAF_OPT_GIVEN_SYMBOLIC_H

#include <cholmod.h>

/* The supernodal symbolic factor (LL', pattern only) of the n x n
 * symmetric pattern whose upper triangle is columns colptr (n + 1) /
 * rowidx (entries below the diagonal are ignored; columns need not be
 * sorted) under perm (n entries). NULL with cm->status set when out of
 * memory, or with status OK when perm is not a permutation. */
cholmod_factor *opt_given_symbolic(cholmod_common *cm, int n, const int *colptr, const int *rowidx,
                                   const int *perm);

#endif /* SCAF_OPT_GIVEN_SYMBOLIC_H */
