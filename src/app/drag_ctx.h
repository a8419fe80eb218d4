/* app/drag_ctx: the drag context's fields, shared by the files of the
 * scaf_drag_* API (app/drag: set-up, handles, steps, undo; app/drag_rigid:
 * rigid motions; app/drag_cap: the deform mode's distortion cap). Private
 * to the library: callers use include/scaf/drag.h.
 *
 * Fails: nothing here fails; drag_ctx_changed only drops state.
 */
#ifndef SCAF_APP_DRAG_CTX_H
#define SCAF_APP_DRAG_CTX_H

#include "app/atlas.h"
#include "app/atlas_output.h"
#include "app/drag_barrier.h"
#include "app/drag_handles.h"
#include "base/error.h"
#include "opt/handle_term.h"
#include "scaf/drag.h"

struct drag_rigid;
struct drag_cap;

/* One saved layout. */
typedef struct drag_state {
    double *uv; /* nw by 2 */
    int iterations;
} drag_state;

struct scaf_drag {
    scaf_drag_options_t opt;
    scaf_error err;
    int has_mesh;
    atlas at;             /* layout, loop, padding hooks */
    opt_handle_term term; /* in at.loop once has_mesh */
    drag_barrier barrier; /* the padding in the energy (in at.loop with a padding) */
    drag_handles handles;
    int handles_dirty; /* the term does not reflect the handle set */
    drag_state before; /* the layout before the last step */
    int has_before;
    int *hard_v;     /* pending hard vertex targets: vertices */
    double *hard_xy; /* and targets (nhard by 2) */
    int nhard, cap_hard;
    drag_state *stack; /* checkpoints, oldest first */
    int nstack;
    drag_state *redo; /* layouts undone, the last undone last; a change drops them */
    int nredo;
    /* the verified output of the current layout (out_state: 0 not
     * computed, 1 verified, -1 failed with out_err) */
    int out_state;
    double *UVn;
    atlas_output out;
    scaf_error out_err;
    struct drag_rigid *rigid; /* the rigid motion in progress (app/drag_rigid), or NULL */
    struct drag_cap *cap;     /* the deform cap's buffers (app/drag_cap), or NULL */
    double cap_ratio;         /* the deform cap: 0 the default, < 0 off, else
                                 the ratio (kept across set_mesh) */
};

/* The layout is about to change outside a step (a rigid motion): what was
 * undone can no longer be redone and the verified output is stale. */
void drag_ctx_changed(scaf_drag_t *d);

/* In app/drag_rigid and app/drag_cap: free their state (NULL allowed). */
void drag_rigid_free(scaf_drag_t *d);
void drag_cap_free(scaf_drag_t *d);

/* The deform cap (app/drag_cap), around each iteration of scaf_drag_step:
 * drag_cap_before takes the per-chart E of the drag's start when there is
 * none yet, and keeps the layout; drag_cap_refused, after the iteration,
 * puts that layout back and returns 1 when a chart without a handle rose
 * above the cap. drag_cap_reset forgets the start (a checkpoint, undo,
 * redo, cancel, clearing the handles, a rigid motion, a compaction). */
scaf_status drag_cap_before(scaf_drag_t *d);
int drag_cap_refused(scaf_drag_t *d);
void drag_cap_reset(scaf_drag_t *d);

#endif /* SCAF_APP_DRAG_CTX_H */
