/* app/atlas_pack: raster re-placement of charts (see atlas_pack.h).
 *
 * Occupancy is a byte grid with, per row, the last occupied column at or
 * before each cell and the first free column at or after each occupied
 * cell, so testing a chart at a position costs one lookup per run of
 * covered cells, and a conflict skips the whole occupied block it hit.
 * The run that conflicted last is tested first (neighbouring positions
 * mostly fail on the same run). Positions are scanned row by row and
 * abandoned as soon as they cannot beat the best square found so far.
 * These shortcuts only skip positions that cannot fit, so the layout is
 * the same as testing every position.
 */
#include "app/atlas_pack.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"

typedef struct chart_raster {
    int w, h; /* cover size in cells */
    int nrun;
    int *run;           /* nrun by 3: row, x0, x1 (inclusive) of covered cells */
    int hint;           /* run to test first (the last one that conflicted) */
    int dw, dh;         /* dilated size = w + 2k, h + 2k */
    unsigned char *dil; /* dh by dw dilated cover */
    double m[2];        /* rotated bbox min (cell origin) */
} chart_raster;

enum { NROT = 8 }; /* rotations tried: multiples of 360/NROT degrees */

/* cos and sin of rotation r of NROT (computed once per packing). */
typedef struct rotation {
    int r;
    double c, s;
} rotation;

static rotation rotation_of(int r)
{
    double a = 2.0 * 3.14159265358979323846 * r / NROT;
    rotation R = {r, cos(a), sin(a)};
    return R;
}

/* Rotate p by R; multiples of 90 degrees are exact. */
static inline void rot(const rotation *R, const double *p, double *q)
{
    if (R->r % (NROT / 4)) {
        q[0] = R->c * p[0] - R->s * p[1];
        q[1] = R->s * p[0] + R->c * p[1];
        return;
    }
    switch ((R->r / (NROT / 4)) & 3) {
    case 0:
        q[0] = p[0];
        q[1] = p[1];
        break;
    case 1:
        q[0] = -p[1];
        q[1] = p[0];
        break;
    case 2:
        q[0] = -p[0];
        q[1] = -p[1];
        break;
    default:
        q[0] = p[1];
        q[1] = -p[0];
        break;
    }
}

static inline double dmin(double a, double b) { return b < a ? b : a; }
static inline double dmax(double a, double b) { return b > a ? b : a; }

static void raster_free(chart_raster *c)
{
    free(c->run);
    free(c->dil);
    memset(c, 0, sizeof *c);
}

/* Rasterize chart faces fc (nfc ids) rotated by r with cell h, dilation k. */
static scaf_status raster_chart(const double *uv, const int *F, const int *fc, int nfc,
                                const rotation *r, double h, int k, chart_raster *c,
                                scaf_error *err)
{
    memset(c, 0, sizeof *c);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < nfc; i++)
        for (int j = 0; j < 3; j++) {
            double q[2];
            rot(r, uv + 2 * (size_t)F[3 * fc[i] + j], q);
            for (int a = 0; a < 2; a++) {
                lo[a] = dmin(lo[a], q[a]);
                hi[a] = dmax(hi[a], q[a]);
            }
        }
    c->m[0] = lo[0];
    c->m[1] = lo[1];
    c->w = (int)floor((hi[0] - lo[0]) / h) + 1;
    c->h = (int)floor((hi[1] - lo[1]) / h) + 1;
    size_t nc = (size_t)c->w * (size_t)c->h;
    unsigned char *cov = calloc(nc ? nc : 1, 1);
    c->dw = c->w + 2 * k;
    c->dh = c->h + 2 * k;
    c->dil = calloc((size_t)c->dw * (size_t)c->dh, 1);
    unsigned char *tmp = calloc((size_t)c->dw * (size_t)c->dh, 1);
    if (!cov || !c->dil || !tmp) {
        free(cov);
        free(tmp);
        raster_free(c);
        return err_nomem(err, "chart raster");
    }
    for (int i = 0; i < nfc; i++) {
        double P[3][2];
        for (int j = 0; j < 3; j++) {
            rot(r, uv + 2 * (size_t)F[3 * fc[i] + j], P[j]);
            P[j][0] = (P[j][0] - lo[0]) / h;
            P[j][1] = (P[j][1] - lo[1]) / h;
        }
        double ylo = dmin(P[0][1], dmin(P[1][1], P[2][1])),
               yhi = dmax(P[0][1], dmax(P[1][1], P[2][1]));
        int y0 = (int)floor(ylo), y1 = (int)floor(yhi);
        if (y0 < 0) y0 = 0;
        if (y1 > c->h - 1) y1 = c->h - 1;
        for (int y = y0; y <= y1; y++) {
            /* x-extent of the triangle within the band [y, y+1]: its
             * vertices inside the band and its edges' crossings of the
             * band's two lines (widened a little against rounding) */
            double b0 = y, b1 = y + 1.0, xl = INFINITY, xr = -INFINITY;
            for (int j = 0; j < 3; j++) {
                const double *A = P[j], *B = P[(j + 1) % 3];
                if (A[1] >= b0 && A[1] <= b1) {
                    xl = dmin(xl, A[0]);
                    xr = dmax(xr, A[0]);
                }
                for (int e = 0; e < 2; e++) {
                    double yy = e ? b1 : b0;
                    if ((A[1] - yy) * (B[1] - yy) <= 0.0 && A[1] != B[1]) {
                        double t = (yy - A[1]) / (B[1] - A[1]);
                        double xx = A[0] + t * (B[0] - A[0]);
                        xl = dmin(xl, xx);
                        xr = dmax(xr, xx);
                    }
                }
            }
            if (!(xl <= xr)) continue;
            int x0 = (int)floor(xl - 1e-6), x1 = (int)floor(xr + 1e-6);
            if (x0 < 0) x0 = 0;
            if (x1 > c->w - 1) x1 = c->w - 1;
            if (x1 >= x0) memset(cov + (size_t)y * c->w + x0, 1, (size_t)(x1 - x0 + 1));
        }
    }
    /* runs */
    int nrun = 0;
    for (int y = 0; y < c->h; y++)
        for (int x = 0; x < c->w; x++)
            if (cov[(size_t)y * c->w + x] && (x == 0 || !cov[(size_t)y * c->w + x - 1])) nrun++;
    c->run = malloc(sizeof(int) * 3 * (size_t)(nrun ? nrun : 1));
    if (!c->run) {
        free(cov);
        free(tmp);
        raster_free(c);
        return err_nomem(err, "chart raster");
    }
    c->nrun = 0;
    for (int y = 0; y < c->h; y++)
        for (int x = 0; x < c->w; x++)
            if (cov[(size_t)y * c->w + x] && (x == 0 || !cov[(size_t)y * c->w + x - 1])) {
                int e = x;
                while (e + 1 < c->w && cov[(size_t)y * c->w + e + 1]) e++;
                int *rr = c->run + 3 * c->nrun++;
                rr[0] = y;
                rr[1] = x;
                rr[2] = e;
            }
    /* separable Chebyshev dilation by k: each run widened by k on both
     * sides, then a sliding count over 2k+1 rows per column (contiguous
     * rows, no strided writes) */
    for (int q = 0; q < c->nrun; q++) {
        const int *rr = c->run + 3 * q;
        memset(tmp + (size_t)(rr[0] + k) * c->dw + rr[1], 1, (size_t)(rr[2] - rr[1] + 2 * k + 1));
    }
    int *cnt = calloc((size_t)c->dw, sizeof(int));
    if (!cnt) {
        free(cov);
        free(tmp);
        raster_free(c);
        return err_nomem(err, "chart raster");
    }
    for (int y = 0; y < c->dh; y++) {
        const unsigned char *in = y + k < c->dh ? tmp + (size_t)(y + k) * c->dw : NULL;
        const unsigned char *out = y - k - 1 >= 0 ? tmp + (size_t)(y - k - 1) * c->dw : NULL;
        unsigned char *d = c->dil + (size_t)y * c->dw;
        if (in)
            for (int x = 0; x < c->dw; x++) cnt[x] += in[x];
        if (out)
            for (int x = 0; x < c->dw; x++) cnt[x] -= out[x];
        for (int x = 0; x < c->dw; x++) d[x] = cnt[x] > 0;
    }
    free(cnt);
    free(cov);
    free(tmp);
    return SCAF_OK;
}

/* Occupancy of the packing grid (G by G cells), per row:
 *   occ[x]   1 where a placed chart's dilated cover is;
 *   rowmax   the largest occupied column (-1: empty row);
 *   last[x]  the largest occupied column <= x, valid for x <= rowmax
 *            (beyond it the answer is rowmax, so a placement never has to
 *            propagate it across the empty rest of the row);
 *   nxt[x]   the first free column >= x, valid where occ[x] (the only
 *            place it is read).
 * Stale entries of a previous strategy are never read, so resetting the
 * grid costs one memset of occ and of rowmax. */
typedef struct occ_grid {
    int G;
    unsigned char *occ;
    int *last, *nxt, *rowmax;
} occ_grid;

static void grid_reset(occ_grid *g)
{
    memset(g->occ, 0, (size_t)g->G * (size_t)g->G);
    for (int y = 0; y < g->G; y++) g->rowmax[y] = -1;
}

/* The largest occupied column <= x in row y, or -1. */
static inline int grid_last(const occ_grid *g, int y, int x)
{
    int rm = g->rowmax[y];
    return x >= rm ? rm : g->last[(size_t)y * g->G + x];
}

/* Row y gained occupied cells within [x0, x1) (x1 <= G): bring last, nxt
 * and rowmax up to date, touching only what can have changed. */
static void grid_row_update(occ_grid *g, int y, int x0, int x1)
{
    size_t base = (size_t)y * g->G;
    const unsigned char *o = g->occ + base;
    int *last = g->last + base, *nxt = g->nxt + base;
    int rm = g->rowmax[y];
    /* last: from x0 (or from just past the old rowmax, whose stale
     * entries become readable) rightwards; past x1 only within the old
     * rowmax and while it changes */
    int xs = x0 < rm + 1 ? x0 : rm + 1;
    int l = xs > 0 ? grid_last(g, y, xs - 1) : -1;
    for (int x = xs; x < g->G; x++) {
        if (x >= x1 && (x > rm || last[x] >= l)) break;
        if (o[x]) l = x;
        last[x] = l;
    }
    int nrm = rm;
    for (int x = x1 - 1; x >= x0 && x > nrm; x--)
        if (o[x]) nrm = x;
    g->rowmax[y] = nrm;
    /* nxt: from x1 leftwards; past x0 only through occupied cells */
    int n = x1 < g->G && o[x1] ? nxt[x1] : x1;
    for (int x = x1 - 1; x >= 0; x--) {
        if (!o[x]) {
            if (x < x0) break;
            n = x;
        }
        nxt[x] = n;
    }
}

/* Returns -1 when the cover of cr at (x, y) misses every occupied cell,
 * else the smallest x' > x that could possibly fit in this row: the
 * conflicting run moved past the whole occupied block it hit (every
 * position in between puts that run on an occupied cell of the block). */
static int fit_next(chart_raster *cr, const occ_grid *g, int x, int y)
{
    if (x < 0 || y < 0 || x + cr->w > g->G || y + cr->h > g->G) return x + 1;
    /* start with the run that conflicted last: neighbouring positions
     * mostly fail on the same run */
    for (int i = 0, q = cr->hint; i < cr->nrun; i++, q = q + 1 < cr->nrun ? q + 1 : 0) {
        const int *rr = cr->run + 3 * q;
        int occ = grid_last(g, y + rr[0], x + rr[2]);
        if (occ >= x + rr[1]) {
            int nx = g->nxt[(size_t)(y + rr[0]) * g->G + occ] - rr[1];
            cr->hint = q;
            return nx > x ? nx : x + 1;
        }
    }
    return -1;
}

static int fits(chart_raster *cr, const occ_grid *g, int x, int y)
{
    return x >= 0 && y >= 0 && fit_next(cr, g, x, y) < 0;
}

typedef struct order_item {
    double area;
    int chart;
} order_item;

static int cmp_order(const void *x, const void *y)
{
    const order_item *p = x, *q = y;
    if (p->area != q->area) return p->area > q->area ? -1 : 1;
    return p->chart - q->chart;
}

int atlas_pack_strategies(int ncharts)
{
    if (ncharts <= 1) return 4; /* one chart: only its rotation matters */
    return ncharts <= 32 ? 64 : 2;
}

/* ---- the packer ---------------------------------------------------------- */

/* What the steps of one packing share. */
typedef struct packer {
    const double *uv;
    const int *F, *chart;
    int nf, ncharts;
    int *start, *faces; /* faces of chart c: faces[start[c] .. start[c+1]-1] */
    chart_raster *R;    /* ncharts by NROT rasters */
    int k;              /* dilation in cells */
    int maxdim;         /* largest raster side in cells */
    occ_grid grid;
    order_item *ord; /* placement order of the current strategy */
    int *place;      /* ncharts by (x, y, rotation) of the current strategy */
} packer;

/* Group the faces by chart; *total gets the layout's UV area. */
static scaf_status group_faces(packer *pk, double *total, scaf_error *err)
{
    *total = 0.0;
    for (int f = 0; f < pk->nf; f++) {
        const double *uv = pk->uv;
        const int *F = pk->F;
        pk->start[pk->chart[f] + 1]++;
        const double *a = uv + 2 * (size_t)F[3 * f], *b = uv + 2 * (size_t)F[3 * f + 1],
                     *d = uv + 2 * (size_t)F[3 * f + 2];
        *total += 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    }
    for (int c = 0; c < pk->ncharts; c++) pk->start[c + 1] += pk->start[c];
    int *fill = malloc(sizeof(int) * (size_t)(pk->ncharts ? pk->ncharts : 1));
    if (!fill) return err_nomem(err, "packing");
    memcpy(fill, pk->start, sizeof(int) * (size_t)pk->ncharts);
    for (int f = 0; f < pk->nf; f++) pk->faces[fill[pk->chart[f]]++] = f;
    free(fill);
    return SCAF_OK;
}

/* Cell size: the estimated square (area / 0.8) over `cells` cells; long
 * thin charts get coarser cells, so no chart spans more than 2 * cells
 * (the grid stays O(cells^2)). */
static double cell_size(const packer *pk, double total, int cells)
{
    double h = sqrt(total / 0.8) / cells;
    for (int c = 0; c < pk->ncharts; c++) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int i = pk->start[c]; i < pk->start[c + 1]; i++)
            for (int j = 0; j < 3; j++)
                for (int q = 0; q < 2; q++) {
                    double x = pk->uv[2 * (size_t)pk->F[3 * pk->faces[i] + j] + q];
                    lo[q] = fmin(lo[q], x);
                    hi[q] = fmax(hi[q], x);
                }
        double diam = hypot(hi[0] - lo[0], hi[1] - lo[1]);
        if (diam > 2.0 * cells * h) h = diam / (2.0 * cells);
    }
    return h;
}

/* Every chart rasterized in every rotation; sets maxdim. */
static scaf_status raster_charts(packer *pk, const rotation *rots, double h, scaf_error *err)
{
    pk->maxdim = 0;
    for (int c = 0; c < pk->ncharts; c++) {
        if (c % 1024 == 0) { /* a million charts take seconds: listen for SIGINT / SIGTERM */
            scaf_status st = interrupt_check(c ? NULL : "pack", "packing the charts", err);
            if (st != SCAF_OK) return st;
        }
        for (int r = 0; r < NROT; r++) {
            chart_raster *cr = &pk->R[NROT * c + r];
            scaf_status st =
                raster_chart(pk->uv, pk->F, pk->faces + pk->start[c],
                             pk->start[c + 1] - pk->start[c], &rots[r], h, pk->k, cr, err);
            if (st != SCAF_OK) return st;
            if (cr->w > pk->maxdim) pk->maxdim = cr->w;
            if (cr->h > pk->maxdim) pk->maxdim = cr->h;
        }
    }
    return SCAF_OK;
}

static int grid_alloc(occ_grid *g, int G)
{
    g->G = G;
    g->occ = malloc((size_t)G * (size_t)G);
    g->last = malloc((size_t)G * (size_t)G * sizeof(int));
    g->nxt = malloc((size_t)G * (size_t)G * sizeof(int));
    g->rowmax = malloc((size_t)G * sizeof(int));
    return g->occ && g->last && g->nxt && g->rowmax;
}

static void grid_free(occ_grid *g)
{
    free(g->occ);
    free(g->last);
    free(g->nxt);
    free(g->rowmax);
}

/* Mark the dilated cover of cr placed at (bx, by) and update the touched
 * rows. */
static void grid_mark(occ_grid *g, const chart_raster *cr, int bx, int by, int k)
{
    int G = g->G;
    for (int yy = 0; yy < cr->dh; yy++) {
        int gy = by - k + yy;
        if (gy < 0 || gy >= G) continue;
        for (int xx = 0; xx < cr->dw; xx++) {
            int gx = bx - k + xx;
            if (gx < 0 || gx >= G) continue;
            if (cr->dil[(size_t)yy * cr->dw + xx]) g->occ[(size_t)gy * G + gx] = 1;
        }
        int x0 = bx - k < 0 ? 0 : bx - k, x1 = bx - k + cr->dw > G ? G : bx - k + cr->dw;
        grid_row_update(g, gy, x0, x1);
    }
}

/* The deterministic xorshift32 that perturbs chart orders. */
static unsigned xorshift(unsigned *rng)
{
    *rng ^= *rng << 13;
    *rng ^= *rng >> 17;
    *rng ^= *rng << 5;
    return *rng;
}

/* Strategies: chart order (area / longest side), rotations (multiples of
 * 90 degrees only / all), tie rule (lowest bottom / lowest top); with many
 * charts only the two cheapest (90-degree rotations). */
typedef struct strategy_rule {
    int by_dim, all_rot, top, perturbed;
} strategy_rule;

static strategy_rule strategy_rule_of(int strat, int ncharts)
{
    strategy_rule s = {0, 0, strat & 1, strat >= 8};
    if (ncharts <= 32) {
        s.by_dim = strat & 1;
        s.all_rot = (strat >> 1) & 1;
        s.top = (strat >> 2) & 1;
    }
    return s;
}

/* The placement order: largest area (or longest raster side) first;
 * perturbed orders scale each key by a factor in [1, 1.6). */
static void order_charts(packer *pk, const strategy_rule *s, unsigned *rng)
{
    order_item *ord = pk->ord;
    for (int c = 0; c < pk->ncharts; c++) {
        ord[c].chart = c;
        ord[c].area = 0.0;
        if (s->by_dim) {
            const chart_raster *r0 = &pk->R[NROT * c];
            ord[c].area = r0->w > r0->h ? r0->w : r0->h;
        }
    }
    if (!s->by_dim)
        for (int f = 0; f < pk->nf; f++) {
            const double *uv = pk->uv;
            const int *F = pk->F;
            const double *p0 = uv + 2 * (size_t)F[3 * f], *p1 = uv + 2 * (size_t)F[3 * f + 1],
                         *p2 = uv + 2 * (size_t)F[3 * f + 2];
            ord[pk->chart[f]].area +=
                (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
        }
    if (s->perturbed)
        for (int c = 0; c < pk->ncharts; c++)
            ord[c].area *= 1.0 + 0.6 * (xorshift(rng) % 1000) / 1000.0;
    qsort(ord, (size_t)pk->ncharts, sizeof *ord, cmp_order);
}

/* Where chart c goes: the position and rotation that keep the occupied
 * square (cur_x by cur_y so far) smallest; ties: the lowest key (bottom
 * row, or top row with the top rule), then the lowest column. side < 0:
 * nothing fits. */
typedef struct placement {
    long side;
    int x, y, r, key;
} placement;

static placement best_position(packer *pk, int c, const strategy_rule *s, int cur_x, int cur_y)
{
    placement b = {-1, 0, 0, 0, 0};
    int G = pk->grid.G;
    for (int r = 0; r < NROT; r += s->all_rot ? 1 : NROT / 4) {
        chart_raster *cr = &pk->R[NROT * c + r];
        for (int y = 0; y + cr->h <= G; y++) {
            long sy = cur_y > y + cr->h ? cur_y : y + cr->h;
            if (b.side >= 0 && sy > b.side) break;
            int key = s->top ? y + cr->h : y;
            if (b.side >= 0 && sy == b.side && s->top && key > b.key + pk->maxdim) break;
            for (int x = 0, nx; x + cr->w <= G; x = nx) {
                long sz = cur_x > x + cr->w ? cur_x : x + cr->w;
                if (sy > sz) sz = sy;
                if (b.side >= 0 &&
                    (sz > b.side || (sz == b.side && (key > b.key || (key == b.key && x >= b.x)))))
                    break;
                nx = fit_next(cr, &pk->grid, x, y);
                if (nx < 0) {
                    b = (placement){sz, x, y, r, key};
                    break;
                }
            }
        }
    }
    return b;
}

/* Place every chart in order; place gets the result. Returns the side of
 * the occupied square in cells, or G + 1 when a chart did not fit or the
 * square grew beyond topk[keep - 1] (it cannot be among the keep best). */
static long run_strategy(packer *pk, const strategy_rule *s, int keep, int ntop, const long *topk)
{
    int G = pk->grid.G, cur_x = 0, cur_y = 0;
    grid_reset(&pk->grid);
    for (int oi = 0; oi < pk->ncharts; oi++) {
        int c = pk->ord[oi].chart;
        placement b = best_position(pk, c, s, cur_x, cur_y);
        if (b.side < 0) return G + 1;
        chart_raster *cr = &pk->R[NROT * c + b.r];
        /* slide left, then down, while it fits (closes the gaps the
         * row scan leaves beside concave neighbours) */
        for (int moved = 1; moved;) {
            moved = 0;
            while (fits(cr, &pk->grid, b.x - 1, b.y)) b.x--, moved = 1;
            while (fits(cr, &pk->grid, b.x, b.y - 1)) b.y--, moved = 1;
        }
        pk->place[3 * c] = b.x;
        pk->place[3 * c + 1] = b.y;
        pk->place[3 * c + 2] = b.r;
        if (b.x + cr->w > cur_x) cur_x = b.x + cr->w;
        if (b.y + cr->h > cur_y) cur_y = b.y + cr->h;
        if (keep > 0 && ntop == keep && (cur_x > cur_y ? cur_x : cur_y) > topk[keep - 1])
            return G + 1;
        grid_mark(&pk->grid, cr, b.x, b.y, pk->k);
    }
    return cur_x > cur_y ? cur_x : cur_y;
}

/* Insert side into the ascending list topk (*ntop of at most keep entries),
 * dropping the largest when full. */
static void topk_insert(long *topk, int *ntop, int keep, long side)
{
    int i = *ntop < keep ? (*ntop)++ : *ntop - 1;
    while (i > 0 && topk[i - 1] > side) {
        topk[i] = topk[i - 1];
        i--;
    }
    topk[i] = side;
}

/* Move the charts rigidly to their places (vertices of no chart stay). */
static void move_charts(const packer *pk, const rotation *rots, double h, int nw, const int *wchart,
                        double *out)
{
    for (int v = 0; v < nw; v++) {
        int c = wchart[v];
        if (c < 0) {
            out[2 * (size_t)v] = pk->uv[2 * (size_t)v];
            out[2 * (size_t)v + 1] = pk->uv[2 * (size_t)v + 1];
            continue;
        }
        const int *pl = pk->place + 3 * c;
        const chart_raster *cr = &pk->R[NROT * c + pl[2]];
        double q[2];
        rot(&rots[pl[2]], pk->uv + 2 * (size_t)v, q);
        out[2 * (size_t)v] = (q[0] - cr->m[0]) + pl[0] * h;
        out[2 * (size_t)v + 1] = (q[1] - cr->m[1]) + pl[1] * h;
    }
}

scaf_status atlas_pack(int nw, const double *uv, int nf, const int *F, const int *chart,
                       const int *wchart, int ncharts, int cells, double gap, int strategy,
                       int keep, int *chosen, long *strat_side, double *out, scaf_error *err)
{
    scaf_status st = SCAF_OK;
    rotation rots[NROT];
    for (int r = 0; r < NROT; r++) rots[r] = rotation_of(r);
    packer pk = {uv, F, chart, nf, ncharts, NULL, NULL, NULL, 0, 0, {0}, NULL, NULL};
    pk.start = calloc((size_t)ncharts + 1, sizeof(int));
    pk.faces = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    pk.ord = malloc(sizeof *pk.ord * (size_t)(ncharts ? ncharts : 1));
    pk.R = calloc((size_t)ncharts * NROT, sizeof *pk.R);
    pk.place = malloc(sizeof(int) * 3 * (size_t)(ncharts ? ncharts : 1));
    int *best = malloc(sizeof(int) * 3 * (size_t)(ncharts ? ncharts : 1));
    if (!pk.start || !pk.faces || !pk.ord || !pk.R || !pk.place || !best) {
        st = err_nomem(err, "packing");
        goto done;
    }
    double total;
    st = group_faces(&pk, &total, err);
    if (st != SCAF_OK) goto done;
    if (!(total > 0.0) || !isfinite(total)) {
        st = err_set(err, SCAF_ERR_NUMERIC, "packing: the layout has no positive area");
        goto done;
    }
    if (cells < 16) cells = 16;
    double h = cell_size(&pk, total, cells);
    pk.k = (int)ceil(gap / h) + 1;
    st = raster_charts(&pk, rots, h, err);
    if (st != SCAF_OK) goto done;
    int G = 2 * cells + pk.maxdim + 2 * pk.k + 2;
    if (!grid_alloc(&pk.grid, G)) {
        st = err_nomem(err, "packing grid");
        goto done;
    }
    long best_side = -1;
    /* the keep smallest completed sides, ascending (branch and bound) */
    long topk[16];
    int ntop = 0;
    if (strategy >= 0 || keep < 0) keep = 0;
    if (keep > 16) keep = 16;
    int nstrat = atlas_pack_strategies(ncharts);
    unsigned rng = 2463534242u;
    for (int strat = 0; strat < nstrat; strat++) {
        if (strat_side) strat_side[strat] = -1;
        strategy_rule s = strategy_rule_of(strat, ncharts);
        if (strategy >= 0 && strat != strategy) {
            /* keep the perturbation sequence identical to a full run */
            if (s.perturbed)
                for (int c = 0; c < ncharts; c++) xorshift(&rng);
            continue;
        }
        order_charts(&pk, &s, &rng);
        long side = run_strategy(&pk, &s, keep, ntop, topk);
        if (strat_side) strat_side[strat] = side <= G ? side : -1;
        if (keep > 0 && side <= G && (ntop < keep || side < topk[ntop - 1]))
            topk_insert(topk, &ntop, keep, side);
        if (side <= G && (best_side < 0 || side < best_side)) {
            best_side = side;
            if (chosen) *chosen = strat;
            memcpy(best, pk.place, sizeof(int) * 3 * (size_t)ncharts);
        }
    }
    if (best_side < 0) {
        st = err_set(err, SCAF_ERR_NUMERIC, "packing: the charts do not fit the grid");
        goto done;
    }
    memcpy(pk.place, best, sizeof(int) * 3 * (size_t)ncharts);
    move_charts(&pk, rots, h, nw, wchart, out);
done:
    if (pk.R)
        for (int i = 0; i < NROT * ncharts; i++) raster_free(&pk.R[i]);
    free(pk.R);
    free(pk.start);
    free(pk.faces);
    free(pk.ord);
    free(pk.place);
    grid_free(&pk.grid);
    free(best);
    return st;
}
