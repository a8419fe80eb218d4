/* app/surface_flow: conformalized mean curvature flow of a closed surface
 * step by step (opt/cmcf), optionally until the exact checker
 * (geom/self_intersect) proves it free of self-intersections: the one
 * flow-until-free loop, used by `scaf flow` (scaf_flow) and by the first
 * phase of app/untangle.
 *
 * The surface is normalized (area-weighted centroid at the origin, unit
 * area), flowed, and after each step either left in that normalized frame
 * (input_frame 0: what `scaf flow` writes) or mapped back into the input's
 * frame, centre + sqrt(area) U (input_frame 1: what untangle pulls back
 * from); the exact check runs on the positions in that frame. With
 * until_free the start (the normalized input, or the input itself) is
 * checked first and an input already free is not flowed at all. The
 * progress callback sees the start (step 0) and every step.
 * Errors: from opt/cmcf (SCAF_ERR_USAGE, SCAF_ERR_MESH a zero-area face,
 * SCAF_ERR_NUMERIC a failed solve or zero area), geom/self_intersect,
 * SCAF_ERR_NOMEM, SCAF_ERR_CANCELLED (the progress callback). Not being
 * free after the last step is no error here: the caller says what it
 * means (r->defects).
 */
#ifndef SCAF_APP_SURFACE_FLOW_H
#define SCAF_APP_SURFACE_FLOW_H

#include "base/error.h"

typedef struct surface_flow_options {
    double delta;    /* time step on the unit-area surface, > 0 */
    int steps;       /* at most this many steps, >= 0 */
    int until_free;  /* 1: check after every step, stop at the first free one */
    int input_frame; /* 1: positions in the input's frame, 0: normalized */
} surface_flow_options;

/* The start (step 0: the input, checked with until_free) or one step. */
typedef struct surface_flow_event {
    int step;             /* 0: the start, then 1-based */
    double seconds;       /* the flow step */
    double check_seconds; /* its exact check */
    long long pairs;      /* intersecting face pairs after it; -1 unchecked */
    int degenerate_faces; /* zero-area faces after it */
    const double *X;      /* the positions (#V by 3); valid during the call */
} surface_flow_event;

/* Nonzero return: stop (SCAF_ERR_CANCELLED). */
typedef int (*surface_flow_progress)(const surface_flow_event *e, void *user);

typedef struct surface_flow_result {
    int steps;               /* steps done */
    long long input_defects; /* pairs + zero-area faces of the start; -1 unchecked */
    long long defects;       /* ... after the last step (the start's when none ran) */
    long long pairs;         /* their split, after the last step */
    int degenerate_faces;
} surface_flow_result;

/* Flow the surface (nv, V, nf, F); X (#V by 3, the caller's) receives the
 * positions after each step (the start before the first). On
 * SCAF_ERR_CANCELLED X and r are those of the last finished step. */
scaf_status surface_flow_run(int nv, const double *V, int nf, const int *F,
                             const surface_flow_options *o, double *X,
                             surface_flow_progress progress, void *user, surface_flow_result *r,
                             scaf_error *err);

#endif /* SCAF_APP_SURFACE_FLOW_H */
