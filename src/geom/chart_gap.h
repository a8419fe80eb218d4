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
 * Certified padding (chart_gap_certify): "the layout has padding P" means,
 * for the UV coordinates exactly as the doubles given (the real numbers
 * they represent, no rounding) and P exactly as the double given: every
 * point of one chart's boundary is at Euclidean distance >= P from every
 * point of any other chart's boundary (so charts are >= P apart, touching
 * at exactly P is allowed). It is decided without error: two boundary
 * segments that meet fail; for two disjoint segments the distance is the
 * smallest endpoint-to-segment distance, and dist(p, ab) >= P is decided
 * by signs of polynomials in the coordinates evaluated in exact expansion
 * arithmetic (geom/expansion): with w = p - a, d = b - a, the nearest
 * point is a when w.d <= 0 (test |w|^2 >= P^2), b when (p - b).d >= 0
 * (test |p - b|^2 >= P^2), else interior (test cross(d, w)^2 >= P^2 |d|^2).
 * P^2 is formed exactly (two_product). The test needs every coordinate and
 * P to be 0 or of magnitude in [2^-200, 2^200] (so no expansion component
 * overflows or underflows); anything else is refused (SCAF_ERR_NUMERIC),
 * never guessed. The OBJ writer prints doubles that read back identically,
 * so a certified layout is certified in the written file too.
 *
 * Packing efficiency: total UV area of the triangles divided by the area
 * of the smallest axis-aligned square containing the layout, i.e. by
 * (max(width, height))^2 of the UV bounding box: the fraction of the unit
 * square a layout normalized by one uniform scale into it covers.
 *
 * Units: distances and efficiency are computed on the layout divided by
 * a power of two that brings its largest coordinate into [1, 2)
 * (geom/coord_scale; exact), so any finite layout, subnormal to near the
 * largest double, gets a finite answer, and a layout scaled by 2^k gets
 * the gap scaled by exactly 2^k and the same efficiency. A chart without
 * a boundary edge (a point, a doubly covered piece) counts by one of its
 * points. The grids size themselves with overflow-safe arithmetic.
 *
 * Fails only on invalid arguments (SCAF_ERR_MESH: index out of range,
 * non-finite coordinate), a smallest gap beyond the largest double
 * (SCAF_ERR_NUMERIC) or out of memory.
 */
#ifndef SCAF_GEOM_CHART_GAP_H
#define SCAF_GEOM_CHART_GAP_H

#include "base/error.h"

/* Chart of each triangle: triangles sharing a UV index are in one chart.
 *   chart  #F out, ids 0..*ncharts-1 in order of first triangle. */
scaf_status chart_gap_labels(int nuv, int nf, const int *F, int *chart, int *ncharts,
                             scaf_error *err);

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
scaf_status chart_gap_min(int nuv, const double *UV, int nf, const int *F, const int *chart,
                          double radius, double *gap, int pair[2], scaf_error *err);

/* The boundary segments (UV edges used by one triangle): *seg (malloc'd,
 * free it) gets *nseg rows {a, b, chart}. */
scaf_status chart_gap_segments(int nf, const int *F, const int *chart, int **seg, int *nseg,
                               scaf_error *err);

/* chart_gap_min on precomputed segments (UV indices into UV). */
scaf_status chart_gap_min_segments(const double *UV, const int *seg, int nseg, double radius,
                                   double *gap, int pair[2], scaf_error *err);

/* Mark (mark[chart] = 1) both charts of every segment pair of different
 * charts closer than radius (> 0); mark has one entry per chart id.
 * Returns the number of such pairs found (pairs, not charts). */
scaf_status chart_gap_mark_close(const double *UV, const int *seg, int nseg, double radius,
                                 unsigned char *mark, long *npairs, scaf_error *err);

/* Every pair of boundary segments of different charts closer than radius
 * (> 0; floating-point distance, as chart_gap_min): *pairs (malloc'd, NULL
 * when there is none; free it) gets *npairs rows {s, t} of segment indices
 * into seg. */
scaf_status chart_gap_close_pairs(const double *UV, const int *seg, int nseg, double radius,
                                  int **pairs, long *npairs, scaf_error *err);

/* The smallest nonzero padding (and coordinate magnitude) the exact
 * certificate takes, and the largest: 2^-200 and 2^200. */
#define CHART_GAP_EXACT_MIN 0x1p-200
#define CHART_GAP_EXACT_MAX 0x1p200

/* Exact certificate (definition above): *ok = 1 when every pair of
 * boundary segments of different charts is at distance >= padding, else 0
 * with pair (may be NULL) = two charts of a failing pair.
 *   UV        positions (referenced by seg), each 0 or |x| in [2^-200, 2^200]
 *   seg       nseg by {a, b, chart} (chart_gap_segments)
 *   padding   P >= 0 (0: always certified; non-overlap is the checker's)
 * Candidate pairs come from the grid with radius 2P; pairs whose bounding
 * boxes are more than P apart along an axis (decided by a floating-point
 * subtraction, whose rounding is monotone) pass; the others are decided
 * exactly. SCAF_ERR_NUMERIC for coordinates outside the exact range. */
scaf_status chart_gap_certify(const double *UV, const int *seg, int nseg, double padding, int *ok,
                              int pair[2], scaf_error *err);

/* Exactly: is the distance between the closed segments p1p2 and q1q2 at
 * least P (P > 0; coordinates in the range above)? 1 yes, 0 no. */
int chart_segment_distance_at_least(const double p1[2], const double p2[2], const double q1[2],
                                    const double q2[2], double P);

/* Total unsigned UV area of the triangles / (longest side of the UV bounding
 * box of the referenced points)^2; 0 for an empty or flat layout. */
double chart_packing_efficiency(int nuv, const double *UV, int nf, const int *F);

/* Distance between the closed segments p1p2 and q1q2 (0 when they meet,
 * decided exactly). */
double chart_segment_distance(const double p1[2], const double p2[2], const double q1[2],
                              const double q2[2]);

#endif /* SCAF_GEOM_CHART_GAP_H */
