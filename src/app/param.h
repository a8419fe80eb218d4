/* app/param: internals of the scaf_param_* API shared with the program.
 *
 * The public API is in include/scaf/scaf.h. This header gives the
 * command-line program read access to the working state (current map,
 * per-face energy, last scaffold), the mapping of the public options onto
 * the loop's, and the tests a look at the loop itself.
 */
#ifndef SCAF_APP_PARAM_H
#define SCAF_APP_PARAM_H

#include <stddef.h>

#include "base/error.h"
#include "scaf/scaf.h"
#include "scaffold/scaf_loop.h"

/* The loop of a context whose mesh is set (NULL otherwise): for tests
 * that look inside; programs use the functions below. */
const scaf_loop *param_loop(const scaf_param_t *p);

/* The loop's options for the public options (the energy, the scaffold's
 * weight, box and quality, the line search's first step). */
scaf_loop_options param_loop_options(const scaf_options_t *o);

/* The current map as the context holds it: nuv UV positions (nuv by 2)
 * and nf faces (nf by 3 UV indices, the mesh's faces in order: the FT of
 * scaf_param_get_uv). Pointers valid until the next call that changes p.
 * Returns 0 (m zeroed) when no mesh is set. */
typedef struct param_map {
    int nuv, nf;
    const double *uv;
    const int *FT;
} param_map;
int param_working_map(const scaf_param_t *p, param_map *m);

/* Symmetric Dirichlet energy of each face of the current map (nf values).
 * Returns 0 when no mesh is set. */
int param_face_energy(const scaf_param_t *p, double *E);

/* The scaffold of the last iteration (n = 0 before the first), for
 * pictures; valid until the next run. Returns 0 when no mesh is set. */
int param_last_scaffold(const scaf_param_t *p, scaffold_view *v);

/* Why set_mesh used its seam source (scaf_param_seams_used), for the
 * terminal; "" without a mesh. */
const char *param_seams_why(const scaf_param_t *p);

/* Validate options: SCAF_OK or SCAF_ERR_USAGE with a message. */
scaf_status param_options_check(const scaf_options_t *o, char *msg, size_t size);

/* Validate the arrays of scaf_param_set_mesh (same arguments): non-empty,
 * non-NULL, UV and FT together, indices in range (SCAF_ERR_USAGE naming
 * the face and index), finite positions (SCAF_ERR_MESH naming the vertex). */
scaf_status param_check_arrays(const double *V, int nv, const int *F, int nf, const double *UV,
                               int nuv, const int *FT, scaf_error *err);

#endif /* SCAF_APP_PARAM_H */
