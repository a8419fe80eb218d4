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

#endif
