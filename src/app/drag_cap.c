/* app/drag_cap: the deform mode's distortion cap (scaf_drag_set_energy_cap
 * in include/scaf/drag.h).
 *
 * A deforming drag pushes the charts in its way through the scaffold, and
 * SCAF's energy balance may squash one of them into a sliver to let the
 * dragged chart through (issue 34: E of spot's atlas from 5.45 to 8.51 in
 * one drag). The cap refuses any iteration after which a chart that has
 * no handle has E above ratio times its E when the drag started (the
 * first step after a checkpoint, undo, redo, cancel or clearing the
 * handles): the layout before that iteration is put back, so a drag stops
 * where going on would wreck a neighbour. The layout put back is one the
 * loop left (bijective, padded), so nothing else needs checking.
 *
 * Fails only out of memory (SCAF_ERR_NOMEM from drag_cap_before).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/drag_ctx.h"

typedef struct drag_cap {
    int has_start;          /* start holds the drag's start */
    double *start;          /* ncharts: E when the drag started */
    double *E;              /* ncharts: scratch */
    double *prev;           /* nw by 2: the layout before the iteration */
    int prev_iter;          /* its iteration count */
    long refused;           /* iterations refused since set_mesh */
    unsigned char *handled; /* ncharts: a handle acts on the chart */
} drag_cap;

static drag_cap *cap_of(scaf_drag_t *d)
{
    if (d->cap) return d->cap;
    drag_cap *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    d->cap = c;
    return c;
}

void drag_cap_free(scaf_drag_t *d)
{
    if (!d->cap) return;
    free(d->cap->start);
    free(d->cap->E);
    free(d->cap->prev);
    free(d->cap->handled);
    free(d->cap);
    d->cap = NULL;
}

void drag_cap_reset(scaf_drag_t *d)
{
    if (d->cap) d->cap->has_start = 0;
}

/* The ratio in force (0: off). */
static double ratio_of(const scaf_drag_t *d)
{
    return d->cap_ratio == 0.0 ? SCAF_DRAG_ENERGY_CAP_DEFAULT
                               : (d->cap_ratio < 0.0 ? 0.0 : d->cap_ratio);
}

scaf_status drag_cap_before(scaf_drag_t *d)
{
    drag_cap *c = cap_of(d);
    if (!c) return err_nomem(&d->err, "the deform cap");
    if (!(ratio_of(d) > 0.0)) return SCAF_OK;
    size_t nc = (size_t)d->at.ncharts, n2 = 2 * (size_t)d->at.nw;
    if (!c->start) {
        c->start = malloc(sizeof(double) * nc);
        c->E = malloc(sizeof(double) * nc);
        c->prev = malloc(sizeof(double) * n2);
        c->handled = malloc(nc);
        if (!c->start || !c->E || !c->prev || !c->handled) {
            drag_cap_free(d);
            return err_nomem(&d->err, "the deform cap");
        }
    }
    if (!c->has_start) {
        atlas_chart_energy(&d->at, c->start);
        c->has_start = 1;
    }
    memcpy(c->prev, d->at.loop.uv, sizeof(double) * n2);
    c->prev_iter = d->at.loop.iterations;
    return SCAF_OK;
}

int drag_cap_refused(scaf_drag_t *d)
{
    drag_cap *c = d->cap;
    double ratio = ratio_of(d);
    if (!c || !(ratio > 0.0) || !c->has_start) return 0;
    const drag_handles *h = &d->handles;
    for (int k = 0; k < d->at.ncharts; k++) c->handled[k] = h->cheld[k];
    for (int v = 0; v < d->at.nw; v++)
        if (h->vheld[v]) c->handled[d->at.wchart[v]] = 1;
    atlas_chart_energy(&d->at, c->E);
    for (int k = 0; k < d->at.ncharts; k++) {
        if (c->handled[k] || c->E[k] <= ratio * c->start[k]) continue;
        memcpy(d->at.loop.uv, c->prev, sizeof(double) * 2 * (size_t)d->at.nw);
        d->at.loop.iterations = c->prev_iter;
        c->refused++;
        return 1;
    }
    return 0;
}

scaf_status scaf_drag_set_energy_cap(scaf_drag_t *d, double ratio)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    if (!(ratio == 0.0 || (ratio >= 1.0 && isfinite(ratio))))
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "energy cap %g: give 0 (no cap) or a finite ratio >= 1", ratio);
    d->cap_ratio = ratio == 0.0 ? -1.0 : ratio;
    drag_cap_reset(d);
    return SCAF_OK;
}

double scaf_drag_energy_cap(const scaf_drag_t *d) { return d ? ratio_of(d) : NAN; }

long scaf_drag_capped_count(const scaf_drag_t *d) { return d && d->cap ? d->cap->refused : 0; }
