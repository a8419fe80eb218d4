/* app/drag_handles: the handle set of a drag context (see drag_handles.h). */
#include "app/drag_handles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void drag_handles_free(drag_handles *h)
{
    if (!h) return;
    free(h->cstart);
    free(h->cverts);
    free(h->vheld);
    free(h->vtarget);
    free(h->cheld);
    free(h->grab);
    free(h->pivot);
    free(h->motion);
    free(h->hv);
    free(h->ht);
    free(h->hs);
    memset(h, 0, sizeof *h);
}

scaf_status drag_handles_init(drag_handles *h, int nw, const int *wchart, int ncharts,
                              scaf_error *err)
{
    memset(h, 0, sizeof *h);
    h->nw = nw;
    h->ncharts = ncharts;
    size_t n = (size_t)(nw > 0 ? nw : 1), nc = (size_t)(ncharts > 0 ? ncharts : 1);
    /* at most every vertex twice: its own handle and its chart's */
    h->cstart = calloc(nc + 1, sizeof(int));
    h->cverts = malloc(n * sizeof(int));
    h->vheld = calloc(n, 1);
    h->vtarget = malloc(2 * n * sizeof(double));
    h->cheld = calloc(nc, 1);
    h->grab = malloc(2 * n * sizeof(double));
    h->pivot = malloc(2 * nc * sizeof(double));
    h->motion = malloc(3 * nc * sizeof(double));
    h->hv = malloc(2 * n * sizeof(int));
    h->ht = malloc(4 * n * sizeof(double));
    h->hs = malloc(2 * n * sizeof(double));
    if (!h->cstart || !h->cverts || !h->vheld || !h->vtarget || !h->cheld || !h->grab ||
        !h->pivot || !h->motion || !h->hv || !h->ht || !h->hs) {
        drag_handles_free(h);
        return err_nomem(err, "drag handles");
    }
    for (int v = 0; v < nw; v++) h->cstart[wchart[v] + 1]++;
    for (int c = 0; c < ncharts; c++) h->cstart[c + 1] += h->cstart[c];
    int *fill = h->hv; /* scratch: next free slot per chart */
    memcpy(fill, h->cstart, sizeof(int) * (size_t)ncharts);
    for (int v = 0; v < nw; v++) h->cverts[fill[wchart[v]]++] = v;
    return SCAF_OK;
}

static scaf_status check_vertex(const drag_handles *h, int v, scaf_error *err)
{
    if (v < 0 || v >= h->nw)
        return err_set(err, SCAF_ERR_USAGE, "vertex %d does not exist: the layout has %d (0..%d)",
                       v, h->nw, h->nw - 1);
    return SCAF_OK;
}

static scaf_status check_chart(const drag_handles *h, int c, scaf_error *err)
{
    if (c < 0 || c >= h->ncharts)
        return err_set(err, SCAF_ERR_USAGE, "chart %d does not exist: the layout has %d (0..%d)", c,
                       h->ncharts, h->ncharts - 1);
    return SCAF_OK;
}

scaf_status drag_handles_move_vertex(drag_handles *h, int v, double x, double y, scaf_error *err)
{
    scaf_status st = check_vertex(h, v, err);
    if (st != SCAF_OK) return st;
    if (!isfinite(x) || !isfinite(y))
        return err_set(err, SCAF_ERR_USAGE, "vertex %d: target (%g, %g) is not finite", v, x, y);
    if (!h->vheld[v]) h->nvheld++;
    h->vheld[v] = 1;
    h->vtarget[2 * (size_t)v] = x;
    h->vtarget[2 * (size_t)v + 1] = y;
    return SCAF_OK;
}

scaf_status drag_handles_move_chart(drag_handles *h, int c, const double *uv,
                                    const double centroid[2], double dx, double dy, double angle,
                                    scaf_error *err)
{
    scaf_status st = check_chart(h, c, err);
    if (st != SCAF_OK) return st;
    if (!isfinite(dx) || !isfinite(dy) || !isfinite(angle))
        return err_set(err, SCAF_ERR_USAGE,
                       "chart %d: motion (dx %g, dy %g, angle %g) is not finite", c, dx, dy, angle);
    if (!h->cheld[c]) {
        for (int k = h->cstart[c]; k < h->cstart[c + 1]; k++) {
            size_t v = (size_t)h->cverts[k];
            h->grab[2 * v] = uv[2 * v];
            h->grab[2 * v + 1] = uv[2 * v + 1];
        }
        h->pivot[2 * (size_t)c] = centroid[0];
        h->pivot[2 * (size_t)c + 1] = centroid[1];
        h->cheld[c] = 1;
        h->ncheld++;
    }
    h->motion[3 * (size_t)c] = dx;
    h->motion[3 * (size_t)c + 1] = dy;
    h->motion[3 * (size_t)c + 2] = angle;
    return SCAF_OK;
}

scaf_status drag_handles_clear_vertex(drag_handles *h, int v, scaf_error *err)
{
    scaf_status st = check_vertex(h, v, err);
    if (st != SCAF_OK) return st;
    if (h->vheld[v]) h->nvheld--;
    h->vheld[v] = 0;
    return SCAF_OK;
}

scaf_status drag_handles_clear_chart(drag_handles *h, int c, scaf_error *err)
{
    scaf_status st = check_chart(h, c, err);
    if (st != SCAF_OK) return st;
    if (h->cheld[c]) h->ncheld--;
    h->cheld[c] = 0;
    return SCAF_OK;
}

void drag_handles_clear(drag_handles *h)
{
    if (h->nw > 0) memset(h->vheld, 0, (size_t)h->nw);
    if (h->ncharts > 0) memset(h->cheld, 0, (size_t)h->ncharts);
    h->nvheld = h->ncheld = 0;
}

int drag_handles_count(const drag_handles *h) { return h->nvheld + h->ncheld; }

scaf_status drag_handles_build(drag_handles *h, opt_handle_term *t, double weight_ratio,
                               double total_area, scaf_error *err)
{
    int n = 0;
    for (int v = 0; v < h->nw; v++)
        if (h->vheld[v]) {
            h->hv[n] = v;
            h->ht[2 * (size_t)n] = h->vtarget[2 * (size_t)v];
            h->ht[2 * (size_t)n + 1] = h->vtarget[2 * (size_t)v + 1];
            h->hs[n] = 1.0;
            n++;
        }
    for (int c = 0; c < h->ncharts; c++) {
        if (!h->cheld[c]) continue;
        const double *m = h->motion + 3 * (size_t)c, *p = h->pivot + 2 * (size_t)c;
        double cs = cos(m[2]), sn = sin(m[2]);
        int k0 = h->cstart[c], k1 = h->cstart[c + 1];
        for (int k = k0; k < k1; k++) {
            size_t v = (size_t)h->cverts[k];
            double x = h->grab[2 * v] - p[0], y = h->grab[2 * v + 1] - p[1];
            h->hv[n] = (int)v;
            h->ht[2 * (size_t)n] = p[0] + cs * x - sn * y + m[0];
            h->ht[2 * (size_t)n + 1] = p[1] + sn * x + cs * y + m[1];
            h->hs[n] = 1.0 / (double)(k1 - k0);
            n++;
        }
    }
    double w = opt_handle_weight(weight_ratio, total_area, drag_handles_count(h));
    return opt_handle_term_set_scaled(t, n, h->hv, h->ht, h->hs, w, err);
}
