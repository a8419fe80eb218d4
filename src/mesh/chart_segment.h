/* mesh/chart_segment: automatic charts, the faces of a manifold triangle
 * mesh grouped into charts for a texture atlas.
 *
 * Labels every face with a chart 0..ncharts-1; every chart is
 * edge-connected. A chart need not be a disk: mesh/cut_graph cuts what is
 * not (handles, closed pieces) afterwards, so segmentation only decides
 * where seams are worth having (distortion, packing, visibility).
 *
 * This first version gives one chart per edge-connected component; the
 * D-Charts / VSA-style segmentation replaces it behind the same call.
 * Fails with SCAF_ERR_NOMEM, or SCAF_ERR_USAGE on bad arguments.
 */
#ifndef SCAF_MESH_CHART_SEGMENT_H
#define SCAF_MESH_CHART_SEGMENT_H

#include "base/error.h"

typedef struct chart_segment_options {
    int target_charts; /* 0: decided from the surface (curvature); > 0: about this many */
} chart_segment_options;

/* Defaults (target_charts 0). */
void chart_segment_defaults(chart_segment_options *o);

/* input:  nv, V   #V by 3 positions
 *         nf, F   #F by 3 vertex indices in [0, nv), a manifold mesh
 *         o       options (NULL: defaults)
 * output: face_chart  #F chart of each face
 *         ncharts     how many charts */
scaf_status chart_segment(int nv, const double *V, int nf, const int *F,
                          const chart_segment_options *o, int *face_chart, int *ncharts,
                          scaf_error *err);

#endif /* SCAF_MESH_CHART_SEGMENT_H */
