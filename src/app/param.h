/* app/param: internals of the scaf_param_* API shared with the program.
 *
 * The public API is in include/scaf/scaf.h. This header gives the
 * command-line program and the tests read access to the working state:
 * the SCAF loop (working mesh, current UV, last scaffold) and the map from
 * input corners to working vertices.
 */
#ifndef SCAF_APP_PARAM_H
#define SCAF_APP_PARAM_H

#include <stddef.h>

#include "base/error.h"
#include "scaf/scaf.h"
#include "scaffold/scaf_loop.h"

/* The loop of a context whose mesh is set (NULL otherwise). */
const scaf_loop *param_loop(const scaf_param_t *p);

/* Validate options: SCAF_OK or SCAF_ERR_USAGE with a message. */
scaf_status param_options_check(const scaf_options_t *o, char *msg, size_t size);

/* Validate the arrays of scaf_param_set_mesh (same arguments): non-empty,
 * non-NULL, UV and FT together, indices in range (SCAF_ERR_USAGE naming
 * the face and index), finite positions (SCAF_ERR_MESH naming the vertex). */
scaf_status param_check_arrays(const double *V, int nv, const int *F, int nf, const double *UV, int nuv,
                               const int *FT, scaf_error *err);

#endif /* SCAF_APP_PARAM_H */
