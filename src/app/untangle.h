/* app/untangle: remove the self-intersections of a closed genus-0
 * surface (the SCAF paper's Figure 9): flow it out with conformalized
 * mean curvature flow until it is free, then pull it back toward its
 * original shape with the 3D SCAF loop, which can never let it pass
 * through itself.
 *
 * 1. Input: a closed manifold surface, one component, genus 0, no
 *    zero-area face (mesh/closed_surface; SCAF_ERR_MESH naming what is
 *    wrong). Genus > 0 is refused: the flow rounds a genus-0 surface
 *    into a sphere, but thins a handle into a ring (a torus flowed 50
 *    steps becomes a thin hoop), which is no shape to pull back from.
 *    An input the exact checker (geom/self_intersect) finds free is
 *    returned unchanged (already_free, no flow, no iteration).
 * 2. Flow out (opt/cmcf, time step delta): the shape is normalized, one
 *    step at a time flowed, and mapped back into the input's frame
 *    (centroid and area, cmcf_frame); the first step whose surface, in
 *    the input's frame, is proved free ends the flow. SCAF_ERR_NUMERIC
 *    when none of flow_steps is.
 * 3. Flow back (app/volume_deform): the flowed surface is the start, the
 *    input the target of the surface ARAP term. ARAP alone is blind to
 *    rigid motions: measured on leg-intersect.off, the shape came back
 *    while the whole surface drifted up the box (RMS distance 0.12 of the
 *    diagonal after the flow, 0.27 after 30 iterations). An anchor term
 *    (opt/handle_term) pulls every vertex toward its input position,
 *    weight anchor_ratio / (nv A): a mean squared offset of A (the target
 *    area) costs anchor_ratio, as a unit ARAP distortion costs 1. Both
 *    terms are lowest at the input, so the anchor does not change what
 *    the flow back aims at, only holds it in place. The tet scaffold keeps
 *    every tet positive (exact), so the surface stays free at every
 *    iteration (with verify, the exact checker proves it after each
 *    iteration: SCAF_ERR_INTERNAL if it ever fails). The surface energy
 *    alone need not fall at every iteration (the loop lowers it plus the
 *    scaffold's, where the rest-volume guard holds flat tets), so the loop
 *    follows the lowest energy so far and stops when the last
 *    UNTANGLE_WINDOW iterations lowered it by at most tolerance times its
 *    value before them; or when an iteration cannot move at all; or after
 *    `iterations`. The result is the iterate of lowest energy.
 * Distances are those of each vertex to its input position, relative to
 * the input's bounding-box diagonal: root mean square and maximum.
 */
#ifndef SCAF_APP_UNTANGLE_H
#define SCAF_APP_UNTANGLE_H

#include "app/volume_deform.h"
#include "base/error.h"

#define UNTANGLE_WINDOW SCAF_UNTANGLE_WINDOW /* scaf/volume.h */
#define UNTANGLE_ANCHOR_DEFAULT 1000.0

typedef struct untangle_options {
    double delta;        /* flow time step (unit-area frame), default 1e-3 */
    int flow_steps;      /* at most this many flow steps, default 1000 */
    int iterations;      /* at most this many flow-back iterations, default 300 */
    double tolerance;    /* relative decrease over UNTANGLE_WINDOW iterations
                         below which the flow back stops; default 1e-2 */
    int verify;          /* 1: exact self-intersection check after every iteration */
    double anchor_ratio; /* weight of the anchor (see above), default UNTANGLE_ANCHOR_DEFAULT */
    volume_deform_options deform; /* the flow back's box, weights, solver: app/volume_deform's
                                     defaults but SLIM, and the scaffold improvement
                                     pass without splits (faster and nearer here:
                                     bench/RESULTS-untangle.md) */
} untangle_options;

untangle_options untangle_options_default(void);

/* SCAF_ERR_USAGE naming the bad option. */
scaf_status untangle_options_check(const untangle_options *o, scaf_error *err);

typedef enum untangle_phase {
    UNTANGLE_FLOW, /* a flow step */
    UNTANGLE_BACK  /* an iteration of the flow back */
} untangle_phase;

/* One step of either phase. */
typedef struct untangle_event {
    untangle_phase phase;
    int step;        /* 1-based within its phase */
    double seconds;  /* wall time (flow: the step and its exact check) */
    long long pairs; /* intersecting face pairs after it (back: -1 without verify) */
    double energy;   /* back: surface energy after the iteration (ARAP + anchor) */
    double arap;     /* back: its ARAP part */
    double rms, max; /* distance to the input, relative to its diagonal */
    int tets;        /* back: scaffold tets */
    double quality;  /* back: minimum scaffold tet quality */
    const double *X; /* the positions after it (#V by 3, input's frame); valid
                         during the callback only (NULL in the result's log) */
} untangle_event;

/* Called after every step; a nonzero return cancels (SCAF_ERR_CANCELLED). */
typedef int (*untangle_progress)(const untangle_event *e, void *user);

typedef enum untangle_stop {
    UNTANGLE_ALREADY_FREE, /* the input had no self-intersection */
    UNTANGLE_CONVERGED,    /* the energy stopped decreasing */
    UNTANGLE_NO_STEP,      /* the loop could not move the surface */
    UNTANGLE_ITERATION_LIMIT
} untangle_stop;

/* The stop reason as a word (for reports). */
const char *untangle_stop_name(untangle_stop s);

typedef struct untangle_result {
    long long input_pairs;                   /* intersecting face pairs of the input */
    int flow_steps;                          /* steps the flow needed (0: already free) */
    double *flowed;                          /* nv by 3, the freed surface in the input's frame
                              (a copy of the input when already free) */
    double *X;                               /* nv by 3, the result */
    double diagonal;                         /* of the input's bounding box */
    double flowed_rms, flowed_max, rms, max; /* relative distances */
    int iterations;                          /* flow-back iterations done */
    int best_iteration;                      /* the one whose positions are X (lowest energy) */
    untangle_stop stop;
    int nlog; /* entries of log: the flow steps, then the iterations */
    untangle_event *log;
} untangle_result;

/* Untangle the surface (nv, V, nf, F) (#V by 3 positions, #F by 3
 * faces). o: NULL for the defaults; progress may be NULL. On success r
 * holds the result (free with untangle_result_free); on failure r is
 * left freed. Errors: SCAF_ERR_USAGE, SCAF_ERR_MESH (not a closed
 * manifold genus-0 surface, naming why), SCAF_ERR_NUMERIC (the flow did
 * not free the surface, a solve failed), SCAF_ERR_NOMEM,
 * SCAF_ERR_CANCELLED, SCAF_ERR_INTERNAL. */
scaf_status untangle_run(int nv, const double *V, int nf, const int *F, const untangle_options *o,
                         untangle_progress progress, void *user, untangle_result *r,
                         scaf_error *err);

void untangle_result_free(untangle_result *r);

#endif /* SCAF_APP_UNTANGLE_H */
