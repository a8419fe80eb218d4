/* opt/ordering_reuse: extend a fixed ordering of the chart to chart + scaffold.
 *
 * SCAF's system changes pattern every iteration, but only in the scaffold:
 * the chart's unknowns (the leading dofs) and their couplings stay. A good
 * nested-dissection ordering (METIS) of the chart is expensive to compute
 * (seconds at a million faces) yet saves a factor ~3 in flops over AMD on
 * large meshes. This module computes it once and, each iteration, places
 * the scaffold's vertices into it: a scaffold vertex gets the position
 * right after the latest of its already placed neighbours (chart vertices
 * by their rank, scaffold vertices by breadth-first layers out from the
 * chart). Scaffold vertices next to a chart separator therefore join that
 * separator — the separator is extended through the scaffold, as nested
 * dissection of the whole domain would do — and the others join the
 * subdomain they touch. The result feeds opt_chol_analyze_given
 * (cholmod_analyze_p): only the symbolic analysis is redone.
 * Any permutation is valid for the factorization; this one only decides
 * speed. Errors: SCAF_ERR_USAGE (sizes), SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_ORDERING_REUSE_H
#define SCAF_OPT_ORDERING_REUSE_H

#include "opt/csc.h"

/* A: the whole system (upper CSC, unknowns interleaved d per vertex, n =
 * nvert*d). nlead: vertices whose dofs are 0..nlead-1 (the chart).
 * lead_perm: nlead*d scalar permutation of the chart system (e.g. from
 * opt_chol_compute_ordering or opt_chol_permutation on the chart block);
 * only the order in which it visits the vertices is used. perm: n out. */
scaf_status opt_ordering_extend(const opt_csc *A, int d, int nlead, const int *lead_perm,
                                int *perm, scaf_error *err);

#endif /* SCAF_OPT_ORDERING_REUSE_H */
