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

#include "scaf/scaf.h"
#include "scaffold/scaf_loop.h"

/* The loop of a context whose mesh is set (NULL otherwise). */
const scaf_loop *param_loop(const scaf_param_t *p);

/* Validate options: SCAF_OK or SCAF_ERR_USAGE with a message. */
scaf_status param_options_check(const scaf_options_t *o, char *msg, size_t size);

#endif /* SCAF_APP_PARAM_H */
