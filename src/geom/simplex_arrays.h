/* geom/simplex_arrays: validating the arrays of a simplicial mesh in 3D
 * (#V by 3 positions, #S by k vertex indices) before exact predicates run
 * on them: every coordinate finite, every index in range. */
#ifndef SCAF_GEOM_SIMPLEX_ARRAYS_H
#define SCAF_GEOM_SIMPLEX_ARRAYS_H

#include "base/error.h"

/* SCAF_OK, or SCAF_ERR_MESH naming the first non-finite vertex or the
 * first simplex with an index outside [0, nv) ("face 3 references vertex
 * 9 but there are 5 vertices"; `what` names the simplex: "face", "tet").
 * SCAF_ERR_USAGE for negative counts or missing arrays. */
scaf_status simplex_arrays_check(int nv, const double *V, int n, const int *S, int corners,
                                 const char *what, scaf_error *err);

#endif
