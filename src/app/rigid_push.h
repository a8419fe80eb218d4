/* app/rigid_push: make room for charts moved rigidly by translating the
 * others (the engine of the drag API's rigid mode, app/drag_rigid).
 *
 * Given a layout whose "fixed" charts (the moved selection, pinned charts)
 * are where they must be, every other chart is translated, never turned
 * or bent, so that every two charts are at least r apart (the smallest
 * distance between their boundary segments, floating point). Charts are
 * placed one by one in order of distance from the selection; each is
 * pushed, when it is closer than r to a chart placed before it, along the
 * direction (away from the selection, the drag direction, or one of eight
 * compass directions) that needs the shortest push, by the smallest
 * distance that clears every placed chart and does not leave it inside one.
 * A pushed chart can then push the charts placed after it, so pushes
 * propagate, and every chart is placed once.
 *
 * Why the push distance is exact enough: the set of offsets s at which
 * two segments, one moving by s e, are closer than r is an interval (the
 * distance of two convex sets under translation is convex in s), the hull
 * of where an endpoint of one enters the r-capsule of the other; the
 * smallest s >= 0 outside every interval is the first clear offset. The
 * caller decides the result exactly afterwards (app/drag_rigid: the exact
 * checker and the padding certificate); this file only proposes.
 *
 * Fails: SCAF_ERR_NOMEM; fixed charts closer than r to each other are not
 * moved (the caller's exact checks then refuse the layout).
 */
#ifndef SCAF_APP_RIGID_PUSH_H
#define SCAF_APP_RIGID_PUSH_H

#include "base/error.h"

typedef struct rigid_charts {
    int ncharts, nw;
    int *vstart, *verts; /* chart c's vertices: verts[vstart[c] .. vstart[c+1]) */
    int *sstart, *segs;  /* chart c's boundary segments (rows of seg) */
    const int *seg;      /* nseg by {a, b, chart} (chart_gap_segments) */
    int nseg;
} rigid_charts;

/* wchart: nw chart ids (0..ncharts-1) of the layout vertices; seg: the
 * boundary segments, kept by reference. */
scaf_status rigid_charts_init(rigid_charts *rc, const int *wchart, int nw, int ncharts,
                              const int *seg, int nseg, scaf_error *err);
void rigid_charts_free(rigid_charts *rc);

/* Translate the charts that are not fixed so every pair is >= r apart.
 *   X      in/out, nw by 2 positions
 *   fixed  ncharts flags: 1 = may not move
 *   early  ncharts flags (may be NULL): charts placed before all others
 *          (the moved selection's charts but one)
 *   from   where the motion happens (the selection's centroid): charts
 *          are placed in order of distance from it and pushed away from it
 *   dir    the drag direction (need not be unit; may be NULL or zero)
 *   r      the distance to keep (> 0)
 *   moved  out, ncharts flags (may be NULL): 1 for the charts translated */
scaf_status rigid_push(const rigid_charts *rc, double *X, const unsigned char *fixed,
                       const unsigned char *early, const double from[2], const double dir[2],
                       double r, unsigned char *moved, scaf_error *err);

#endif /* SCAF_APP_RIGID_PUSH_H */
