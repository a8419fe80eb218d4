/* mesh/chart_segment: automatic charts, the faces of a manifold triangle
 * mesh grouped into charts for a texture atlas.
 *
 * Labels every face with a chart 0..ncharts-1; every chart is
 * edge-connected. A chart need not be a disk: mesh/cut_graph cuts what is
 * not (handles, closed pieces) afterwards, so segmentation only decides
 * where seams are worth having (distortion, packing, visibility).
 *
 * The method is of the D-Charts / VSA family (Julius, Kraevoy and Sheffer
 * 2005; Cohen-Steiner, Alliez and Desbrun 2004), adapted to SCAF, which
 * keeps every chart bijective whatever its shape: charts are only cut
 * where flattening would distort, so there are few of them.
 *  1. Gaussian curvature (angle defects), diffused over a fixed fraction
 *     of the surface's size so that scan noise of either sign cancels;
 *     each edge-connected component gets about
 *     sum |K| / curvature_per_chart charts (at least one).
 *  2. Seeds by farthest-point sampling in a metric stretched by curvature
 *     density, so that every chart gets a similar share of area plus
 *     curvature.
 *  3. A few Lloyd rounds: charts grow from their seeds by a Dijkstra
 *     front whose step cost grows with the face normal's deviation from
 *     the chart's proxy normal (the normal cone) and with the crease the
 *     step crosses (concave creases most: seams there are cheap and
 *     hidden); proxies are re-fitted and each seed moves to the face
 *     deepest inside its chart.
 *  4. Boundaries are smoothed (a face whose two or three neighbours lie in
 *     one other chart joins it, which never disconnects a chart) and
 *     charts much smaller than the average are absorbed by the neighbour
 *     they share the longest boundary with.
 * Deterministic (ties by face index), O(n log n) per round.
 * Fails with SCAF_ERR_NOMEM, or SCAF_ERR_USAGE on bad arguments.
 */
#ifndef SCAF_MESH_CHART_SEGMENT_H
#define SCAF_MESH_CHART_SEGMENT_H

#include "base/error.h"

typedef struct chart_segment_options {
    int target_charts; /* 0: decided from the surface (curvature); > 0: about this many */
    /* Total |Gaussian curvature| one chart may hold (radians; <= 0: the
     * default CHART_SEGMENT_CURVATURE_PER_CHART). */
    double curvature_per_chart;
    int lloyd_rounds; /* grow / re-fit rounds (<= 0: default 8) */
} chart_segment_options;

/* The default curvature budget of one chart: pi (a sphere makes four). */
#define CHART_SEGMENT_CURVATURE_PER_CHART 3.14159265358979323846

/* Defaults (target_charts 0). */
void chart_segment_defaults(chart_segment_options *o);

/* input:  nv, V   #V by 3 positions
 *         nf, F   #F by 3 vertex indices in [0, nv), a manifold mesh
 *         o       options (NULL: defaults)
 * output: face_chart  #F chart of each face (numbered in order of first face)
 *         ncharts     how many charts */
scaf_status chart_segment(int nv, const double *V, int nf, const int *F,
                          const chart_segment_options *o, int *face_chart, int *ncharts,
                          scaf_error *err);

#endif /* SCAF_MESH_CHART_SEGMENT_H */
