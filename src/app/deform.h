/* app/deform: planar deformation with soft handles inside a scaffold box.
 *
 * The rest shape is a planar triangle mesh (P, nv by 2, every triangle
 * counter-clockwise); the map starts at the rest shape and the SCAF loop
 * (scaffold/scaf_loop) minimizes the symmetric Dirichlet distortion plus
 * the soft positional term of opt/handle_term (handles pulled to their
 * targets, weight ratio default OPT_HANDLE_WEIGHT_RATIO_DEFAULT). The
 * scaffold fills the box around the mesh, so no triangle flips and the
 * shape never overlaps itself, at every iteration, whatever the targets.
 * no_remesh freezes the scaffold's connectivity after the first iteration
 * (scaffold/scaffold_frozen: the paper's Figure 4 baseline, which locks).
 *
 * A drag (waypoints before the targets) changes the handles' targets
 * between iterations; nothing is rebuilt for it (opt/handle_term).
 * Pins and hard targets (deform_options): pinned vertices never move (bit
 * for bit); a hard target is met exactly once a flip-free placement there
 * exists, then pinned. Held positions that flip a triangle are refused
 * before any work (infeasible); hard targets that the run cannot reach
 * end it after a bounded stall (never an endless loop), reported.
 * Stops at the iteration cap, when no step lowers the energy (zero_step),
 * when the relative decrease of the total energy falls below tolerance, or
 * when the progress callback returns nonzero (cancelled). Fails with
 * SCAF_ERR_MESH (a triangle not counter-clockwise / degenerate at rest, a
 * mesh without boundary), SCAF_ERR_USAGE (a handle out of range, bad
 * options), or the loop's errors; on failure `out` holds the last
 * bijective state.
 */
#ifndef SCAF_APP_DEFORM_H
#define SCAF_APP_DEFORM_H

#include "base/error.h"
#include "scaf/scaf.h"

typedef struct deform_options {
    int iterations;       /* cap (100) */
    double tolerance;     /* relative total-energy decrease (1e-12; 0 = off) */
    double weight_ratio;  /* handle weight ratio, dimensionless (see opt/handle_term) */
    int no_remesh;        /* freeze the scaffold after the first iteration */
    int frame_iterations; /* iterations per waypoint of a drag (4) */
    /* Hard positional constraints (NULL / 0: none). hard: nh flags, 1
     * for a handle whose target must be met exactly: it pulls with the
     * soft weight until its vertex can be placed exactly on the target
     * without a flip (scaf_loop_place, checked after every iteration once
     * the drag's waypoints are done), and is pinned there from then on.
     * pins: npins vertices held at their rest positions, bit for bit,
     * from the start (scaf_loop_pin). */
    const unsigned char *hard;
    int npins;
    const int *pins;
    int stall_iterations;            /* hard targets still missing after this many
                             iterations in a row without one reached and
                             without their error shrinking by 1e-3
                             relatively: infeasible (20) */
    scaf_param_progress_fn progress; /* after each iteration (may be NULL) */
    void *user;
    /* what the callback may read: the positions after the iteration */
    const double *current; /* set by deform_run during the run */
} deform_options;

deform_options deform_options_default(void);

typedef struct deform_result {
    double energy;           /* reported E (symmetric Dirichlet, 4 = isometry) */
    double max_handle_error; /* largest handle-to-target distance */
    int iterations;
    scaf_stop_reason stop;
    int hard;         /* hard targets asked */
    int hard_reached; /* of them, met exactly (and pinned) */
    int infeasible;   /* 1: the pins and hard targets admit no bijective map
                         (a triangle with all three corners held, flipped
                         at their positions: found before any iteration,
                         SCAF_ERR_MESH); 2: hard targets still missing when
                         the run stalled, stopped or hit the cap (SCAF_OK,
                         the last bijective state in out) */
} deform_result;

/* nv positions P (nv by 2), nf triangles F, nh handles (vertex indices hv,
 * targets ht nh by 2), optionally dragged there: nframes waypoints
 * (frames: nframes by nh by 2), each the handles' targets for
 * frame_iterations iterations before ht (the stopping rules other than the
 * cap apply from then on). out nv by 2 receives the deformed positions. o
 * may be NULL (defaults); o->current is updated while the callback runs. */
scaf_status deform_run(int nv, const double *P, int nf, const int *F, int nh, const int *hv,
                       const double *ht, int nframes, const double *frames, deform_options *o,
                       double *out, deform_result *r, scaf_error *err);

#endif /* SCAF_APP_DEFORM_H */
