/* opt/cholmod_view: an opt_csc seen as a CHOLMOD matrix, without copying.
 *
 * Kept apart from cholmod_solver.h so that only code which talks to
 * CHOLMOD directly (the solver, benchmarks) includes cholmod.h. */
#ifndef SCAF_OPT_CHOLMOD_VIEW_H
#define SCAF_OPT_CHOLMOD_VIEW_H

#include <cholmod.h>

#include "opt/csc.h"

/* A header over A's arrays (upper triangle, stype 1, int indices, sorted,
 * packed). CHOLMOD must never free it: it owns nothing. */
cholmod_sparse opt_csc_cholmod_view(const opt_csc *A);

/* A pattern-only header (no values) over n columns p (n+1 offsets) and
 * row indices i, upper triangle (stype 1), int indices, packed; sorted
 * says whether each column's rows are ascending. Owns nothing either. */
cholmod_sparse opt_cholmod_pattern_view(int n, int *p, int *i, int sorted);

#endif
