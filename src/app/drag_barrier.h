/* app/drag_barrier: the atlas's padding as a barrier in a drag's energy.
 *
 * Why: the padding is a hard constraint checked after the line search
 * (app/atlas's feasibility hook). On a compacted atlas every gap is at the
 * padding and every chart squeezed below its distortion optimum, so any
 * SLIM or Newton direction brings some pair of charts closer than the
 * padding; the hook then halves the whole step, the dragged chart's share
 * too, and a drag barely moves (bench/RESULTS-drag.md). With the padding
 * in the energy the direction itself keeps pairs apart, and a dragged
 * chart pushes the charts in its way as it does with padding 0.
 *
 * Pairs: for a boundary vertex v of one chart and a boundary segment ab
 * of another at squared distance s, kappa b((s - P^2) / (dhat^2 - P^2))
 * with the IPC barrier b(x) = -(x - 1)^2 ln x for 0 < x < 1 (0 above,
 * +infinity at x <= 0; C2 at x = 1, convex), dhat = P (1 + DRAG_BARRIER_BAND)
 * the distance below which pairs repel, and P (per iteration, at the
 * loop's positions: side0, need0 = the hook's padding * side0
 * (atlas_padding_need), g0 the smallest gap) = need0 (1 + gamma) with a
 * growth allowance gamma = min(DRAG_BARRIER_GROWTH, (g0 / need0 - 1) / 2).
 *
 * Walls: the hook asks gap >= c * side, c * side0 = need0, so it couples
 * every close pair with the layout's extent: where the layout grows
 * (charts pushed outward, squeezed charts expanding) pairs at P fail it
 * although the pair barrier holds. Walls make the two separable: every
 * boundary vertex kept inside the box around the layout with sides
 * side0 (1 + gamma) (the layout's box widened evenly on each axis), by
 * kappa b(w / (dhat - P)) for a vertex at distance w inside a wall. Pairs
 * >= P and side <= side0 (1 + gamma) imply what the hook tests. But walls
 * as tight as the closest pair's room also stop the growth a compacted
 * layout needs while its charts relax (human_neutral's drag stalls with
 * them always on, bench/RESULTS-drag.md), so they are part of the barrier
 * for DRAG_BARRIER_WALL_STEPS iterations after the hook rejected a step
 * (atlas.padding_rejects: where growth broke the padding) and at the
 * start (a compacted layout's gaps are all at the padding; spot's drag
 * ends 0.071 of the side from its target without, 0.047 with).
 *
 * kappa = DRAG_BARRIER_WEIGHT * (total rest area) / (boundary segments):
 * the units of the distortion energy (an area), scale-free.
 *
 * Candidates: every pair closer than reach = need0 (1 + DRAG_BARRIER_GROWTH)
 * (1 + DRAG_BARRIER_BAND) + DRAG_BARRIER_REACH * side0 (> dhat) is one (geom/chart_gap's grid) whose barrier the energy sums; a
 * pair farther at the start of a step that gets closer than P within it
 * is not seen by the energy, and the hook catches it (the step is then
 * shortened as without the barrier). The proxy (SLIM, and Newton alike)
 * is the Gauss-Newton matrix kappa b'' grad grad^T (positive
 * semi-definite) with the exact gradient, over pairs closer than dhat and
 * vertices closer than dhat - P to a wall. Nothing here decides validity:
 * the padding is still checked by the hook after the line search and
 * certified exactly on output; the barrier only makes those checks pass.
 *
 * drag_barrier_enable(0) empties the term (compaction steps, whose hooks
 * close gaps to the padding on purpose).
 */
#ifndef SCAF_APP_DRAG_BARRIER_H
#define SCAF_APP_DRAG_BARRIER_H

#include "app/atlas.h"
#include "opt/objective.h"
#include "opt/simplices.h"

/* dhat = P (1 + band) */
#define DRAG_BARRIER_BAND 1.0
/* kappa = weight * total area / boundary segments */
#define DRAG_BARRIER_WEIGHT 1.0
/* candidate radius: see the banner */
#define DRAG_BARRIER_REACH 0.02
/* largest growth allowance gamma (relative, per step) */
#define DRAG_BARRIER_GROWTH 0.05
/* iterations with walls after the padding test rejected a step (1: spot's
 * drag ends 0.11 of the side from its target, 4: 0.047, 10: 0.046 but
 * human_neutral's 0.027 instead of 0.018 (vertex handles)) */
#define DRAG_BARRIER_WALL_STEPS 4

typedef struct drag_barrier {
    const atlas *at; /* positions (at->loop.uv), segments, padding */
    int on;
    double band, weight, reach_ratio, growth; /* the defines (tests may set them) */
    long rejects_seen;                        /* the atlas's padding_rejects at the last setup */
    int walls_left;                           /* iterations the walls stay */
    /* the iteration's barrier (set by the pattern op) */
    int walls;                   /* the walls are part of it */
    double p2, zhat, wall_width; /* P^2, dhat^2 - P^2, dhat - P */
    double wall_lo[2], wall_hi[2];
    double kappa;
    int n, cap;        /* candidate pairs */
    int *pe;           /* n by 3: v, a, b */
    int nact, cap_act; /* the proxy's pairs, then its wall vertices */
    opt_simplices act; /* idx (nact by 3) only: the pattern's "triangles";
                          a wall vertex is (v, v, v) */
    int *act_of;       /* nact: candidate pair k >= 0, or -1 - 4 v - 2 axis - hi */
    int *bv;           /* boundary vertices */
    int nbv;
} drag_barrier;

/* Over atlas a (which must outlive it), on. */
scaf_status drag_barrier_init(drag_barrier *b, const atlas *a, scaf_error *err);
void drag_barrier_enable(drag_barrier *b, int on);
void drag_barrier_free(drag_barrier *b);

/* The term's ops over b (which must outlive it). */
opt_obj_term drag_barrier_make(drag_barrier *b);

#endif /* SCAF_APP_DRAG_BARRIER_H */
