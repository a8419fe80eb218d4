/* mesh/chart_segment: automatic charts (see the header). */
#include "mesh/chart_segment.h"

#include <stdlib.h>

#include "base/half_edges.h"
#include "base/union_find.h"

void chart_segment_defaults(chart_segment_options *o) { o->target_charts = 0; }

scaf_status chart_segment(int nv, const double *V, int nf, const int *F,
                          const chart_segment_options *o, int *face_chart, int *ncharts,
                          scaf_error *err)
{
    (void)V;
    (void)o;
    if (nv < 0 || nf < 0 || (nf > 0 && (!F || !face_chart)) || !ncharts)
        return err_set(err, SCAF_ERR_USAGE, "chart_segment: bad arguments");
    *ncharts = 0;
    if (nf == 0) return SCAF_OK;
    int *order = malloc(sizeof(int) * 3 * (size_t)nf);
    int *parent = malloc(sizeof(int) * (size_t)nf);
    if (!order || !parent) {
        free(order);
        free(parent);
        return err_nomem(err, "chart segmentation");
    }
    int count = 0;
    scaf_status st = half_edges_sort(nv, nf, F, NULL, order, &count, err);
    if (st != SCAF_OK) {
        free(order);
        free(parent);
        return st;
    }
    /* faces sharing an edge are in one chart */
    uf_init(parent, nf);
    for (int i = 1; i < count; i++)
        if (half_edges_same_edge(F, order[i - 1], order[i]))
            uf_union(parent, order[i - 1] / 3, order[i] / 3);
    /* number the charts in order of their first face */
    for (int f = 0; f < nf; f++) face_chart[f] = -1;
    int n = 0;
    for (int f = 0; f < nf; f++) {
        int r = uf_find(parent, f);
        if (face_chart[r] < 0) face_chart[r] = n++;
        face_chart[f] = face_chart[r];
    }
    *ncharts = n;
    free(order);
    free(parent);
    return SCAF_OK;
}
