/* geom/chart_gap: distances between charts, packing efficiency (see
 * chart_gap.h).
 *
 * Boundary segments come from sorting the triangles' UV edges; the grid
 * search runs with a radius r: cell size max(r, extent / sqrt(#segments))
 * keeps the cell count linear in the segment count, each segment goes into
 * the cells its box widened by r/2 overlaps, and each pair sharing a cell
 * is measured once (the pair is counted in the cell holding the lower-left
 * corner of the overlap of the two widened boxes). Without a radius the
 * search starts at the mean segment length and doubles it until a pair is
 * found.
 */
#include "geom/chart_gap.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/bijectivity.h"

static int find_root(int *p, int x)
{
    while (p[x] != x) {
        p[x] = p[p[x]];
        x = p[x];
    }
    return x;
}

scaf_status chart_gap_labels(int nuv, int nf, const int *F, int *chart, int *ncharts, scaf_error *err)
{
    int *p = malloc(sizeof(int) * (size_t)(nuv > 0 ? nuv : 1));
    int *lab = malloc(sizeof(int) * (size_t)(nuv > 0 ? nuv : 1));
    if (!p || !lab) {
        free(p);
        free(lab);
        return err_nomem(err, "chart labels");
    }
    for (int i = 0; i < nuv; i++) {
        p[i] = i;
        lab[i] = -1;
    }
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j];
            if (a < 0 || a >= nuv) {
                free(p);
                free(lab);
                return err_set(err, SCAF_ERR_MESH, "triangle %d references UV %d of %d", f, a, nuv);
            }
        }
    for (int f = 0; f < nf; f++)
        for (int j = 1; j < 3; j++) {
            int a = find_root(p, F[3 * f]), b = find_root(p, F[3 * f + j]);
            if (a != b) p[a > b ? a : b] = a < b ? a : b;
        }
    int n = 0;
    for (int f = 0; f < nf; f++) {
        int r = find_root(p, F[3 * f]);
        if (lab[r] < 0) lab[r] = n++;
        chart[f] = lab[r];
    }
    *ncharts = n;
    free(p);
    free(lab);
    return SCAF_OK;
}

static double point_segment(const double *p, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double l2 = dx * dx + dy * dy;
    double t = l2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0.0;
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    double x = a[0] + t * dx - p[0], y = a[1] + t * dy - p[1];
    return sqrt(x * x + y * y);
}

double chart_segment_distance(const double p1[2], const double p2[2], const double q1[2], const double q2[2])
{
    if (bij_segments_meet(p1, p2, q1, q2)) return 0.0;
    double d = point_segment(p1, q1, q2), e;
    if ((e = point_segment(p2, q1, q2)) < d) d = e;
    if ((e = point_segment(q1, p1, p2)) < d) d = e;
    if ((e = point_segment(q2, p1, p2)) < d) d = e;
    return d;
}

double chart_packing_efficiency(int nuv, const double *UV, int nf, const int *F)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, area = 0.0;
    for (int f = 0; f < nf; f++) {
        const double *a = UV + 2 * (size_t)F[3 * f], *b = UV + 2 * (size_t)F[3 * f + 1], *c = UV + 2 * (size_t)F[3 * f + 2];
        area += fabs(0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])));
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 2; k++) {
                double x = UV[2 * (size_t)F[3 * f + j] + k];
                if (x < lo[k]) lo[k] = x;
                if (x > hi[k]) hi[k] = x;
            }
    }
    (void)nuv;
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(side > 0.0) || !isfinite(side)) return 0.0;
    return area / (side * side);
}

/* ---- boundary segments ---------------------------------------------------- */

typedef struct bedge {
    int lo, hi, chart;
} bedge;

static int cmp_bedge(const void *x, const void *y)
{
    const bedge *p = x, *q = y;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    if (p->hi != q->hi) return p->hi < q->hi ? -1 : 1;
    return 0;
}

/* One search with radius r over segments seg (n by {a, b, chart}). */
static scaf_status grid_search(const double *UV, const int *seg, int n, double r, const double lo[2], double extent,
                               double *best, int pair[2], unsigned char *mark, long *npairs, scaf_error *err)
{
    double cell = extent / sqrt((double)n + 1.0);
    if (r > cell) cell = r;
    if (!(cell > 0.0)) cell = 1.0;
    double h = 0.5 * r;
    int nx = (int)((extent + 2 * h) / cell) + 2, ny = nx;
    if (nx > 1 << 15) nx = ny = 1 << 15;
    /* count, then fill (CSR). */
    size_t ncell = (size_t)nx * (size_t)ny;
    int *start = calloc(ncell + 1, sizeof(int));
    int(*box)[4] = malloc(sizeof *box * (size_t)(n ? n : 1));
    if (!start || !box) {
        free(start);
        free(box);
        return err_nomem(err, "chart gap grid");
    }
    size_t total = 0;
    for (int s = 0; s < n; s++) {
        const double *a = UV + 2 * (size_t)seg[3 * s], *b = UV + 2 * (size_t)seg[3 * s + 1];
        int i0 = (int)floor((fmin(a[0], b[0]) - h - lo[0]) / cell) + 1, i1 = (int)floor((fmax(a[0], b[0]) + h - lo[0]) / cell) + 1;
        int j0 = (int)floor((fmin(a[1], b[1]) - h - lo[1]) / cell) + 1, j1 = (int)floor((fmax(a[1], b[1]) + h - lo[1]) / cell) + 1;
        if (i0 < 0) i0 = 0;
        if (j0 < 0) j0 = 0;
        if (i1 > nx - 1) i1 = nx - 1;
        if (j1 > ny - 1) j1 = ny - 1;
        box[s][0] = i0;
        box[s][1] = j0;
        box[s][2] = i1;
        box[s][3] = j1;
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) start[(size_t)j * nx + i + 1]++;
        total += (size_t)(i1 - i0 + 1) * (size_t)(j1 - j0 + 1);
    }
    for (size_t c = 0; c < ncell; c++) start[c + 1] += start[c];
    int *items = malloc(sizeof(int) * (total ? total : 1));
    int *fill = malloc(sizeof(int) * ncell);
    if (!items || !fill) {
        free(start);
        free(box);
        free(items);
        free(fill);
        return err_nomem(err, "chart gap grid");
    }
    memcpy(fill, start, sizeof(int) * ncell);
    for (int s = 0; s < n; s++)
        for (int j = box[s][1]; j <= box[s][3]; j++)
            for (int i = box[s][0]; i <= box[s][2]; i++) items[fill[(size_t)j * nx + i]++] = s;
    for (size_t c = 0; c < ncell; c++) {
        int ci = (int)(c % (size_t)nx), cj = (int)(c / (size_t)nx);
        for (int x = start[c]; x < start[c + 1]; x++) {
            int s = items[x];
            for (int y = x + 1; y < start[c + 1]; y++) {
                int t = items[y];
                if (seg[3 * s + 2] == seg[3 * t + 2]) continue;
                /* count the pair only in the first cell both boxes share */
                int fi = box[s][0] > box[t][0] ? box[s][0] : box[t][0];
                int fj = box[s][1] > box[t][1] ? box[s][1] : box[t][1];
                if (fi != ci || fj != cj) continue;
                double d = chart_segment_distance(UV + 2 * (size_t)seg[3 * s], UV + 2 * (size_t)seg[3 * s + 1],
                                                  UV + 2 * (size_t)seg[3 * t], UV + 2 * (size_t)seg[3 * t + 1]);
                if (mark && d < r) {
                    mark[seg[3 * s + 2]] = 1;
                    mark[seg[3 * t + 2]] = 1;
                    ++*npairs;
                }
                if (d <= r && d < *best) {
                    *best = d;
                    if (pair) {
                        int p = seg[3 * s + 2], q = seg[3 * t + 2];
                        pair[0] = p < q ? p : q;
                        pair[1] = p < q ? q : p;
                    }
                }
            }
        }
    }
    free(start);
    free(box);
    free(items);
    free(fill);
    return SCAF_OK;
}

scaf_status chart_gap_segments(int nf, const int *F, const int *chart, int **seg_out, int *nseg, scaf_error *err)
{
    *seg_out = NULL;
    *nseg = 0;
    size_t nh = 3 * (size_t)nf;
    bedge *e = malloc(sizeof *e * (nh ? nh : 1));
    int *seg = malloc(sizeof(int) * 3 * (nh ? nh : 1));
    if (!e || !seg) {
        free(e);
        free(seg);
        return err_nomem(err, "chart boundary segments");
    }
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j], b = F[3 * f + (j + 1) % 3];
            bedge *x = &e[3 * (size_t)f + j];
            x->lo = a < b ? a : b;
            x->hi = a < b ? b : a;
            x->chart = chart[f];
        }
    qsort(e, nh, sizeof *e, cmp_bedge);
    int n = 0;
    for (size_t i = 0; i < nh;) {
        size_t j = i + 1;
        while (j < nh && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        if (j - i == 1) {
            seg[3 * n] = e[i].lo;
            seg[3 * n + 1] = e[i].hi;
            seg[3 * n + 2] = e[i].chart;
            n++;
        }
        i = j;
    }
    free(e);
    *seg_out = seg;
    *nseg = n;
    return SCAF_OK;
}

scaf_status chart_gap_min_segments(const double *UV, const int *seg, int n, double radius, double *gap, int pair[2],
                                   scaf_error *err)
{
    *gap = INFINITY;
    if (pair) pair[0] = pair[1] = -1;
    if (n < 2) return SCAF_OK;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, len = 0.0;
    for (int s = 0; s < n; s++) {
        const double *a = UV + 2 * (size_t)seg[3 * s], *b = UV + 2 * (size_t)seg[3 * s + 1];
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], fmin(a[c], b[c]));
            hi[c] = fmax(hi[c], fmax(a[c], b[c]));
        }
        len += hypot(a[0] - b[0], a[1] - b[1]);
    }
    double extent = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(extent > 0.0)) extent = 1.0;
    if (radius > 0.0 && isfinite(radius)) return grid_search(UV, seg, n, radius, lo, extent, gap, pair, NULL, NULL, err);
    double r = len / n;
    if (!(r > 0.0)) r = extent / n;
    for (;;) {
        scaf_status st = grid_search(UV, seg, n, r, lo, extent, gap, pair, NULL, NULL, err);
        if (st != SCAF_OK || isfinite(*gap) || r > 4.0 * extent) return st;
        r *= 2.0;
    }
}

scaf_status chart_gap_min(int nuv, const double *UV, int nf, const int *F, const int *chart, double radius,
                          double *gap, int pair[2], scaf_error *err)
{
    *gap = INFINITY;
    if (pair) pair[0] = pair[1] = -1;
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j];
            if (a < 0 || a >= nuv) return err_set(err, SCAF_ERR_MESH, "triangle %d references UV %d of %d", f, a, nuv);
            if (!isfinite(UV[2 * (size_t)a]) || !isfinite(UV[2 * (size_t)a + 1]))
                return err_set(err, SCAF_ERR_MESH, "UV %d has a non-finite coordinate", a);
        }
    int *own = NULL, *seg = NULL, n = 0;
    scaf_status st = SCAF_OK;
    if (!chart) {
        int nc;
        own = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
        if (!own) return err_nomem(err, "chart gap");
        st = chart_gap_labels(nuv, nf, F, own, &nc, err);
        chart = own;
    }
    if (st == SCAF_OK) st = chart_gap_segments(nf, F, chart, &seg, &n, err);
    if (st == SCAF_OK) st = chart_gap_min_segments(UV, seg, n, radius, gap, pair, err);
    free(own);
    free(seg);
    return st;
}

scaf_status chart_gap_mark_close(const double *UV, const int *seg, int n, double radius, unsigned char *mark,
                                 long *npairs, scaf_error *err)
{
    *npairs = 0;
    if (n < 2 || !(radius > 0.0)) return SCAF_OK;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int s = 0; s < n; s++)
        for (int k = 0; k < 2; k++) {
            const double *a = UV + 2 * (size_t)seg[3 * s + k];
            for (int c = 0; c < 2; c++) {
                lo[c] = fmin(lo[c], a[c]);
                hi[c] = fmax(hi[c], a[c]);
            }
        }
    double extent = fmax(hi[0] - lo[0], hi[1] - lo[1]), g = INFINITY;
    if (!(extent > 0.0)) extent = 1.0;
    return grid_search(UV, seg, n, radius, lo, extent, &g, NULL, mark, npairs, err);
}
