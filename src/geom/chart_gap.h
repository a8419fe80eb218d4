/* geom/chart_gap: how far apart the charts of a UV layout are, and how
 * much of its square they fill.
 *
 * The gap between two charts is the smallest Euclidean distance between a
 * point of one and a point of the other. For charts that do not overlap,
 * that is the smallest distance between a boundary segment (a UV edge used
 * by exactly one triangle) of one chart and a boundary segment of the
 * other. Segment pairs are found with a uniform grid (each segment's box
 * widened by half the search radius, so every pair closer than the radius
 * shares a cell); pairs that meet are decided exactly (distance 0), the
 * distance of the others is computed in floating point from the four
 * endpoint-to-segment distances (relative error a few ulps).
 *
 * Packing efficiency: total UV area of the triangles divided by the area
 * of the smallest axis-aligned square containing the layout, i.e. by
 * (max(width, height))^2 of the UV bounding box: the fraction of the unit
 * square a layout normalized by one uniform scale into it covers.
 *
 * Fails only on invalid arguments (SCAF_ERR_MESH: index out of range,
 * non-finite coordinate) or out of memory.
 */
#ifndef SCAF_GEOM_CHART_GAP_H
#define SCAF_GEOM_CHART_GAP_H

#include "base/error.h"

/* Chart of each triangle: triangles sharing a UV index are in one chart.
 *   chart  #F out, ids 0..*ncharts-1 in order of first triangle. */
scaf_status chart_gap_labels(int nuv, int nf, const int *F, int *chart, int *ncharts, scaf_error *err);

/* Smallest distance between boundary segments of different charts.
 *   nuv, UV  #UV by 2 positions
 *   nf, F    #F by 3 UV indices per triangle
 *   chart    #F chart id per triangle, or NULL (chart_gap_labels)
 *   radius   search radius: pairs farther apart than it are ignored;
 *            <= 0 or INFINITY: no limit (the grid radius grows until a
 *            pair is found)
 *   gap      out: the smallest distance, INFINITY when there is no pair
 *            within the radius (or fewer than two charts)
 *   pair     optional out (may be NULL): the two charts realizing it */
scaf_status chart_gap_min(int nuv, const double *UV, int nf, const int *F, const int *chart, double radius,
                          double *gap, int pair[2], scaf_error *err);

/* The boundary segments (UV edges used by one triangle): *seg (malloc'd,
 * free it) gets *nseg rows {a, b, chart}. */
scaf_status chart_gap_segments(int nf, const int *F, const int *chart, int **seg, int *nseg, scaf_error *err);

/* chart_gap_min on precomputed segments (UV indices into UV). */
scaf_status chart_gap_min_segments(const double *UV, const int *seg, int nseg, double radius, double *gap,
                                   int pair[2], scaf_error *err);

/* Mark (mark[chart] = 1) both charts of every segment pair of different
 * charts closer than radius (> 0); mark has one entry per chart id.
 * Returns the number of such pairs found (pairs, not charts). */
scaf_status chart_gap_mark_close(const double *UV, const int *seg, int nseg, double radius, unsigned char *mark,
                                 long *npairs, scaf_error *err);

/* Total unsigned UV area of the triangles / (longest side of the UV bounding
 * box of the referenced points)^2; 0 for an empty or flat layout. */
double chart_packing_efficiency(int nuv, const double *UV, int nf, const int *F);

/* Distance between the closed segments p1p2 and q1q2 (0 when they meet,
 * decided exactly). */
double chart_segment_distance(const double p1[2], const double p2[2], const double q1[2], const double q2[2]);

#endif /* SCAF_GEOM_CHART_GAP_H */
