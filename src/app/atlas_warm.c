/* app/atlas_warm: a start from charts flattened before (see the header). */
#include "app/atlas_warm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"

/* The gap between two charts' boxes, times the square root of the mean
 * box area: room for the scaffold between them, as the Tutte start leaves
 * (its circles sit in cells 2.5 times their radius). */
#define GAP_FRACTION 0.25

typedef struct chart_faces {
    int *start; /* ncharts + 1 */
    int *face;  /* nf, grouped by chart */
} chart_faces;

static int group(int nf, const int *Fw, const int *wchart, int ncharts, chart_faces *g)
{
    g->start = calloc((size_t)ncharts + 1, sizeof(int));
    g->face = malloc(sizeof(int) * (size_t)(nf > 0 ? nf : 1));
    int *pos = malloc(sizeof(int) * (size_t)(ncharts > 0 ? ncharts : 1));
    if (!g->start || !g->face || !pos) {
        free(pos);
        return 0;
    }
    for (int f = 0; f < nf; f++) g->start[wchart[Fw[3 * f]] + 1]++;
    for (int c = 0; c < ncharts; c++) g->start[c + 1] += g->start[c];
    for (int c = 0; c < ncharts; c++) pos[c] = g->start[c];
    for (int f = 0; f < nf; f++) g->face[pos[wchart[Fw[3 * f]]]++] = f;
    free(pos);
    return 1;
}

/* Every triangle of chart c counter-clockwise (exactly) with finite corners. */
static int chart_valid(const chart_faces *g, int c, const int *Fw, const double *X)
{
    for (int i = g->start[c]; i < g->start[c + 1]; i++) {
        const int *t = Fw + 3 * g->face[i];
        const double *p = X + 2 * (size_t)t[0], *q = X + 2 * (size_t)t[1],
                     *r = X + 2 * (size_t)t[2];
        if (!isfinite(p[0] + p[1] + q[0] + q[1] + r[0] + r[1])) return 0;
        if (!(orient2d(p, q, r) > 0.0)) return 0;
    }
    return 1;
}

typedef struct box {
    double lo[2], w, h, x, y; /* source box; placed corner */
    int chart;
} box;

static int box_cmp(const void *x, const void *y)
{
    const box *a = x, *b = y;
    if (a->h != b->h) return a->h > b->h ? -1 : 1;
    return a->chart - b->chart;
}

/* Shelves of boxes (tallest first) in rows about as long as the layout is
 * tall, gap g between boxes; returns the layout's longest side. */
static double shelve(box *b, int n, double g)
{
    double total = 0.0, widest = 0.0;
    for (int i = 0; i < n; i++) {
        total += (b[i].w + g) * (b[i].h + g);
        if (b[i].w > widest) widest = b[i].w;
    }
    double row_len = fmax(widest, sqrt(total));
    double x = 0.0, y = 0.0, row_h = 0.0, width = 0.0;
    for (int i = 0; i < n; i++) {
        if (x > 0.0 && x + b[i].w > row_len) {
            y += row_h + g;
            x = 0.0;
            row_h = 0.0;
        }
        b[i].x = x;
        b[i].y = y;
        x += b[i].w + g;
        if (b[i].h > row_h) row_h = b[i].h;
        if (x - g > width) width = x - g;
    }
    return fmax(width, y + row_h);
}

scaf_status atlas_warm_layout(int nw, int nf, const int *Fw, const int *wchart, int ncharts,
                              const double *shape, const double *fallback, double min_gap,
                              double *out, int *warm, scaf_error *err)
{
    chart_faces g = {NULL, NULL};
    unsigned char *use = calloc((size_t)(ncharts > 0 ? ncharts : 1), 1);
    box *b = malloc(sizeof *b * (size_t)(ncharts > 0 ? ncharts : 1));
    int *slot = malloc(sizeof(int) * (size_t)(ncharts > 0 ? ncharts : 1));
    double *X = malloc(sizeof(double) * 2 * (size_t)(nw > 0 ? nw : 1));
    scaf_status st = SCAF_OK;
    if (!use || !b || !slot || !X || !group(nf, Fw, wchart, ncharts, &g)) {
        st = err_nomem(err, "warm start");
        goto out;
    }
    for (int c = 0; c < ncharts; c++) use[c] = (unsigned char)chart_valid(&g, c, Fw, shape);
    /* a chart whose placed shape rounds to a bad triangle falls back; at
     * most once per chart, so this ends */
    for (int pass = 0; pass <= ncharts; pass++) {
        for (int c = 0; c < ncharts; c++) {
            b[c].chart = c;
            b[c].lo[0] = b[c].lo[1] = INFINITY;
            double hi[2] = {-INFINITY, -INFINITY};
            const double *src = use[c] ? shape : fallback;
            for (int i = g.start[c]; i < g.start[c + 1]; i++)
                for (int j = 0; j < 3; j++) {
                    const double *p = src + 2 * (size_t)Fw[3 * g.face[i] + j];
                    for (int k = 0; k < 2; k++) {
                        if (p[k] < b[c].lo[k]) b[c].lo[k] = p[k];
                        if (p[k] > hi[k]) hi[k] = p[k];
                    }
                }
            if (g.start[c] == g.start[c + 1]) b[c].lo[0] = b[c].lo[1] = hi[0] = hi[1] = 0.0;
            b[c].w = hi[0] - b[c].lo[0];
            b[c].h = hi[1] - b[c].lo[1];
        }
        double mean = 0.0;
        for (int c = 0; c < ncharts; c++) mean += b[c].w * b[c].h;
        double gap = GAP_FRACTION * sqrt(mean / (ncharts > 0 ? ncharts : 1));
        qsort(b, (size_t)ncharts, sizeof *b, box_cmp);
        double side = shelve(b, ncharts, gap);
        /* the padding must hold at the start: widen until it does */
        for (int k = 0; k < 60 && min_gap > 0.0 && !(gap > 2.0 * min_gap * side); k++) {
            gap = 4.0 * min_gap * side;
            side = shelve(b, ncharts, gap);
        }
        for (int i = 0; i < ncharts; i++) slot[b[i].chart] = i;
        for (int w = 0; w < nw; w++) {
            const box *q = b + slot[wchart[w]];
            const double *src = use[q->chart] ? shape : fallback;
            X[2 * (size_t)w] = (src[2 * (size_t)w] - q->lo[0]) + q->x;
            X[2 * (size_t)w + 1] = (src[2 * (size_t)w + 1] - q->lo[1]) + q->y;
        }
        int again = 0;
        for (int c = 0; c < ncharts; c++)
            if (use[c] && !chart_valid(&g, c, Fw, X)) {
                use[c] = 0;
                again = 1;
            }
        if (!again) break;
    }
    memcpy(out, X, sizeof(double) * 2 * (size_t)nw);
    if (warm) {
        *warm = 0;
        for (int c = 0; c < ncharts; c++) *warm += use[c];
    }
out:
    free(g.start);
    free(g.face);
    free(use);
    free(b);
    free(slot);
    free(X);
    return st;
}
