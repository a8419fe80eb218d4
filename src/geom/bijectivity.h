/* geom/bijectivity: does a UV map cover the plane at most once?
 *
 * An independent verifier of 2D maps: given UV points and triangles it
 * decides with exact predicates (geom/predicates), never a tolerance,
 *  - per triangle: positively oriented (counter-clockwise), flipped
 *    (clockwise) or degenerate (exactly zero area);
 *  - per chart (triangles connected through shared UV edges): consistently
 *    mirrored (every non-degenerate triangle clockwise) or mixed;
 *  - overlaps between charts and within a chart: pairs of UV boundary
 *    segments (edges used by exactly one triangle) that properly cross, and
 *    pairs that touch (at a point, or overlapping along a line) counted
 *    apart, and adjacent segments folding back onto each other apart again; interior edges whose two triangles lie on the same side
 *    (folds) and edges shared by more than two triangles; boundary loops
 *    lying inside another chart (or inside their own chart elsewhere)
 *    without any boundary contact (nesting); overlapping triangle corners
 *    at boundary points (pinch points, where the boundary passes through a
 *    UV index more than once, and triangles sharing only vertices).
 * Soundness: with no flipped or degenerate triangles, no fold, no
 * non-manifold edge, and boundary loops that neither cross nor touch, the
 * number of triangles covering a point is the sum of the winding numbers
 * of the boundary loops around it; testing the boundary vertices against
 * the triangles not incident to them, plus the corners at boundary
 * points, then shows whether any point is covered twice.
 * So `bijective` is exact: every triangle positively oriented and every
 * point of the plane covered by at most one closed triangle, except that
 * triangles may share the vertices and edges they share by index.
 *
 * A consistently mirrored chart is a valid map of the mirrored surface but
 * not orientation-preserving, so it makes the map NOT bijective (its
 * triangles count as flipped); it is reported in mirrored_charts so
 * callers can tell a mirrored chart from folds.
 *
 * Cost: O(F + B + pairs found), with B boundary segments, using sorted
 * edge buckets and uniform grids; no recursion. Works on any input, also
 * non-manifold and overlapping ones; fails only on invalid arguments
 * (index out of range, non-finite coordinate) or out of memory.
 */
#ifndef SCAF_GEOM_BIJECTIVITY_H
#define SCAF_GEOM_BIJECTIVITY_H

#include <stddef.h>

#include "base/error.h"

typedef struct bij_report {
    int triangles;                /* number of triangles checked */
    int positive;                 /* counter-clockwise, nonzero area */
    int flipped;                  /* clockwise (including mirrored charts) */
    int degenerate;               /* exactly zero area (incl. repeated indices) */
    int charts;                   /* charts (given, or by shared UV edges) */
    int mirrored_charts;          /* charts with clockwise and no ccw triangles */
    int mixed_charts;             /* charts with both ccw and clockwise ones */
    int boundary_edges;           /* UV edges used by exactly one triangle */
    int boundary_loops;           /* connected components of boundary edges */
    long long boundary_crossings; /* properly crossing segment pairs that
                                     share no UV index */
    long long boundary_touchings; /* other contacts of segment pairs that
                                     share no UV index: touching at a point
                                     (incl. distinct coincident vertices,
                                     zero-length segments), collinear
                                     overlap */
    long long boundary_foldbacks; /* pairs of segments sharing one UV index
                                     that overlap along a line (the boundary
                                     turns back on itself by 180 degrees) */
    int folded_edges;             /* interior edges with both triangles on one side */
    int nonmanifold_edges;        /* UV edges used by more than two triangles */
    int nested_loops;             /* boundary loops without any boundary contact
                               that have a vertex in the interior of another
                               chart's region (or of their own chart) */
    int corner_overlaps;          /* boundary UV points where the corners of the
                               triangles using the point overlap: fans
                               joined only at the point (the boundary passes
                               more than once), or a triangle reaching into
                               another chart's fan by a shared index */
    int bijective;                /* 1 when all of the above counts of defects are
                               zero (flipped, degenerate, crossings,
                               touchings, foldbacks, folds, non-manifold,
                               nesting, corner overlaps) */
} bij_report;

/* Check the UV map.
 *   nuv     number of UV points
 *   UV      #UV by 2 coordinates (row-major)
 *   nf      number of triangles
 *   F       #F by 3 UV indices per triangle (row-major), 0-based
 *   chart   #F chart ids >= 0, or NULL to compute charts from shared UV
 *           edges (two triangles sharing an edge by UV indices)
 *   orient  optional output, #F entries: +1 ccw, -1 cw, 0 degenerate
 *   rep     filled on success
 * Returns SCAF_OK, SCAF_ERR_MESH (index out of range, negative chart id,
 * non-finite coordinate; the message names the triangle / point) or
 * SCAF_ERR_NOMEM. */
scaf_status bij_check(int nuv, const double *UV, int nf, const int *F, const int *chart,
                      signed char *orient, bij_report *rep, scaf_error *err);

/* How two closed segments p1p2 and q1q2 meet, decided exactly:
 * 0 disjoint, 1 proper crossing (a single point interior to both),
 * 2 any other contact (an endpoint on the other segment, collinear
 * overlap, coincident endpoints). */
int bij_segments_meet(const double p1[2], const double p2[2], const double q1[2],
                      const double q2[2]);

/* The defects of a report as text, "flipped 177, mirrored_charts 1,
 * nested_loops 1" (every nonzero defect count, named as the keys of
 * `scaf check --json`), or "none"; truncated to size bytes. So every
 * message about a map's bijectivity quotes the same counts. */
void bij_report_defects(const bij_report *rep, char *buf, size_t size);

#endif /* SCAF_GEOM_BIJECTIVITY_H */
