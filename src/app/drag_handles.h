/* app/drag_handles: the handle set of a drag context (scaf/drag.h).
 *
 * Two kinds of handles over the layout vertices of an atlas: vertex
 * handles (one vertex, an absolute target) and chart handles (every vertex
 * of a chart, the targets a rigid motion — rotation about the grab pose's
 * centroid, then translation — of the chart's pose when the handle was
 * created). drag_handles_build turns the set into the arrays of the soft
 * positional term (opt/handle_term) in a fixed order (vertex handles by
 * vertex, then chart handles by chart, each chart's vertices in
 * increasing order), so the term's pattern is rebuilt only when the set
 * of held vertices changes, never when targets move. Weights: every
 * handle weighs weight_ratio / (number of handles) (opt_handle_weight), a
 * chart handle spread evenly over its vertices, so dragging a chart and
 * dragging a vertex pull alike whatever the chart's size.
 *
 * Errors (SCAF_ERR_USAGE, nothing changed): an index out of range, a
 * target or motion that is not finite; SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_DRAG_HANDLES_H
#define SCAF_APP_DRAG_HANDLES_H

#include "base/error.h"
#include "opt/handle_term.h"

typedef struct drag_handles {
    int nw, ncharts;
    int *cstart, *cverts; /* chart c's vertices: cverts[cstart[c] .. cstart[c+1]) */
    unsigned char *vheld; /* nw: vertex handle there */
    double *vtarget;      /* nw by 2 */
    int nvheld;
    unsigned char *cheld; /* ncharts: chart handle there */
    double *grab;         /* nw by 2: grab pose of held charts' vertices */
    double *pivot;        /* ncharts by 2: grab pose centroid */
    double *motion;       /* ncharts by 3: dx, dy, angle */
    int ncheld;
    int *hv; /* scratch of build: vertices, targets, weight factors */
    double *ht, *hs;
} drag_handles;

/* Empty set over nw layout vertices, wchart[v] its chart (0..ncharts-1). */
scaf_status drag_handles_init(drag_handles *h, int nw, const int *wchart, int ncharts,
                              scaf_error *err);
void drag_handles_free(drag_handles *h);

scaf_status drag_handles_move_vertex(drag_handles *h, int v, double x, double y, scaf_error *err);

/* uv: the current layout (nw by 2), the grab pose when the handle is new;
 * centroid: the chart's area-weighted UV centroid there (the pivot). */
scaf_status drag_handles_move_chart(drag_handles *h, int c, const double *uv,
                                    const double centroid[2], double dx, double dy, double angle,
                                    scaf_error *err);

scaf_status drag_handles_clear_vertex(drag_handles *h, int v, scaf_error *err);
scaf_status drag_handles_clear_chart(drag_handles *h, int c, scaf_error *err);
void drag_handles_clear(drag_handles *h);

/* Handles (vertex + chart) in the set. */
int drag_handles_count(const drag_handles *h);

/* Put the set into term t (weight_ratio, total_area: opt_handle_weight). */
scaf_status drag_handles_build(drag_handles *h, opt_handle_term *t, double weight_ratio,
                               double total_area, scaf_error *err);

#endif /* SCAF_APP_DRAG_HANDLES_H */
