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

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "geom/bijectivity.h"
#include "geom/coord_scale.h"
#include "geom/expansion.h"

static int find_root(int *p, int x)
{
    while (p[x] != x) {
        p[x] = p[p[x]];
        x = p[x];
    }
    return x;
}

scaf_status chart_gap_labels(int nuv, int nf, const int *F, int *chart, int *ncharts,
                             scaf_error *err)
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

double chart_segment_distance(const double p1[2], const double p2[2], const double q1[2],
                              const double q2[2])
{
    if (bij_segments_meet(p1, p2, q1, q2)) return 0.0;
    double d = point_segment(p1, q1, q2), e;
    if ((e = point_segment(p2, q1, q2)) < d) d = e;
    if ((e = point_segment(q1, p1, p2)) < d) d = e;
    if ((e = point_segment(q2, p1, p2)) < d) d = e;
    return d;
}

/* ---- exact decisions ------------------------------------------------------ */

/* Every number below is a polynomial of degree <= 4 in coordinate
 * differences; with every coordinate 0 or of magnitude in [2^-200, 2^200]
 * (checked by the caller) no expansion component overflows or underflows,
 * so the expansion arithmetic is exact. */

/* h = x1 * y1 + x2 * y2 for expansions (lengths <= 16 each). */
static int exp_dot2(int lx1, const double *x1, int ly1, const double *y1, int lx2, const double *x2,
                    int ly2, const double *y2, double *h)
{
    double a[128], b[128], work[512];
    int la = exp_mul(lx1, x1, ly1, y1, a, work);
    int lb = exp_mul(lx2, x2, ly2, y2, b, work);
    return exp_sum(la, a, lb, b, h);
}

/* sign(|w|^2 - P^2), w an expansion pair (lengths <= 2); P2 the expansion
 * of P^2 (length lp). */
static double sq_minus(int lwx, const double *wx, int lwy, const double *wy, int lp,
                       const double *P2)
{
    double n[16], neg[2], h[20];
    int ln = exp_dot2(lwx, wx, lwx, wx, lwy, wy, lwy, wy, n);
    exp_negate(lp, P2, neg);
    int lh = exp_sum(ln, n, lp, neg, h);
    return exp_sign_estimate(lh, h);
}

/* Exactly: is the distance from p to the closed segment ab at least P
 * (P2 = the expansion of P^2)? */
static int point_segment_at_least(const double *p, const double *a, const double *b, int lp,
                                  const double *P2)
{
    double dx[2], dy[2], wx[2], wy[2], vx[2], vy[2], dot[16];
    int ldx = exp_from_diff(b[0], a[0], dx), ldy = exp_from_diff(b[1], a[1], dy);
    int lwx = exp_from_diff(p[0], a[0], wx), lwy = exp_from_diff(p[1], a[1], wy);
    /* nearest point a: (p - a).(b - a) <= 0 (also a == b) */
    int ld = exp_dot2(lwx, wx, ldx, dx, lwy, wy, ldy, dy, dot);
    if (exp_sign_estimate(ld, dot) <= 0.0) return sq_minus(lwx, wx, lwy, wy, lp, P2) >= 0.0;
    /* nearest point b: (p - b).(b - a) >= 0 */
    int lvx = exp_from_diff(p[0], b[0], vx), lvy = exp_from_diff(p[1], b[1], vy);
    ld = exp_dot2(lvx, vx, ldx, dx, lvy, vy, ldy, dy, dot);
    if (exp_sign_estimate(ld, dot) >= 0.0) return sq_minus(lvx, vx, lvy, vy, lp, P2) >= 0.0;
    /* interior: cross(d, w)^2 >= P^2 |d|^2 */
    double mwy[2], cr[16], cr2[512], d2[16], pd[64], work[1024], h[576];
    exp_negate(ldy, dy, mwy);
    int lc = exp_dot2(ldx, dx, lwy, wy, ldy, mwy, lwx, wx, cr);
    int lc2 = exp_mul(lc, cr, lc, cr, cr2, work);
    int ld2 = exp_dot2(ldx, dx, ldx, dx, ldy, dy, ldy, dy, d2);
    int lpd = exp_mul(lp, P2, ld2, d2, pd, work);
    exp_negate(lpd, pd, pd);
    int lh = exp_sum(lc2, cr2, lpd, pd, h);
    return exp_sign_estimate(lh, h) >= 0.0;
}

int chart_segment_distance_at_least(const double p1[2], const double p2[2], const double q1[2],
                                    const double q2[2], double P)
{
    if (!(P > 0.0)) return 1;
    if (bij_segments_meet(p1, p2, q1, q2)) return 0;
    double P2[2], x, y;
    two_product(P, P, &x, &y);
    int lp = 0;
    if (y != 0.0) P2[lp++] = y;
    P2[lp++] = x;
    /* two disjoint segments: their distance is the smallest of the four
     * endpoint-to-segment distances */
    return point_segment_at_least(p1, q1, q2, lp, P2) &&
        point_segment_at_least(p2, q1, q2, lp, P2) && point_segment_at_least(q1, p1, p2, lp, P2) &&
        point_segment_at_least(q2, p1, p2, lp, P2);
}

double chart_packing_efficiency(int nuv, const double *UV, int nf, const int *F)
{
    (void)nuv;
    /* scale-free: computed on the points divided by a power of two, so
     * subnormal and huge layouts get the same number as unit ones */
    int e = coord_scale_exponent(UV, 2, 3 * (size_t)nf, F);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, area = 0.0;
    for (int f = 0; f < nf; f++) {
        double p[3][2];
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 2; k++) {
                double x = ldexp(UV[2 * (size_t)F[3 * f + j] + k], -e);
                p[j][k] = x;
                lo[k] = fmin(lo[k], x);
                hi[k] = fmax(hi[k], x);
            }
        area += fabs(0.5 *
                     ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                      (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])));
    }
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(side > 0.0) || !isfinite(side) || !isfinite(area)) return 0.0;
    /* divided twice: side * side underflows to 0 when the extent is tiny
     * next to the coordinates (area 0 / 0 was NaN, fuzz_uv_numbers);
     * area <= nf side^2 / 2 keeps area / side from overflowing */
    return area / side / side;
}

/* ---- boundary segments ---------------------------------------------------- */

/* Cells per side for a span of x cells: in [1, 2^15], NaN and infinity
 * included (2^30 cells at most; the caller's cell size keeps it near
 * sqrt(#segments)). */
static int cell_count(double x)
{
    if (!(x >= 1.0)) return 1;
    return x < (double)(1 << 15) ? (int)x : 1 << 15;
}

/* Grid cell (1-based: cell 0 holds what lies left of lo) of the offset t
 * cells from lo, clamped to [0, n - 1] whatever t is. */
static int cell_index(double t, int n)
{
    double c = floor(t) + 1.0;
    if (!(c > 0.0)) return 0;
    return c < (double)(n - 1) ? (int)c : n - 1;
}

/* Segment pairs found closer than the radius (chart_gap_close_pairs). */
typedef struct pair_list {
    int *st; /* 2 per pair */
    long n, cap;
    int nomem;
} pair_list;

static void pair_list_push(pair_list *l, int s, int t)
{
    if (l->nomem) return;
    if (l->n == l->cap) {
        long cap = l->cap ? 2 * l->cap : 256;
        int *q = realloc(l->st, sizeof(int) * 2 * (size_t)cap);
        if (!q) {
            l->nomem = 1;
            return;
        }
        l->st = q;
        l->cap = cap;
    }
    l->st[2 * l->n] = s;
    l->st[2 * l->n + 1] = t;
    l->n++;
}

/* One search with radius r over segments seg (n by {a, b, chart}); list
 * (may be NULL) gets every pair closer than r. */
static scaf_status grid_search(const double *UV, const int *seg, int n, double r,
                               const double lo[2], double extent, double *best, int pair[2],
                               unsigned char *mark, long *npairs, double cert, int *bad,
                               pair_list *list, scaf_error *err)
{
    double cell = extent / sqrt((double)n + 1.0);
    if (r > cell) cell = r;
    if (!(cell > 0.0) || !isfinite(cell)) cell = extent > 0.0 && isfinite(extent) ? extent : 1.0;
    double h = 0.5 * r;
    /* sizes and indices are clamped in double before any conversion to int,
     * so no extent, radius or coordinate can overflow them */
    int nx = cell_count((extent + 2 * h) / cell + 2.0), ny = nx;
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
        int i0 = cell_index((fmin(a[0], b[0]) - h - lo[0]) / cell, nx),
            i1 = cell_index((fmax(a[0], b[0]) + h - lo[0]) / cell, nx);
        int j0 = cell_index((fmin(a[1], b[1]) - h - lo[1]) / cell, ny),
            j1 = cell_index((fmax(a[1], b[1]) + h - lo[1]) / cell, ny);
        box[s][0] = i0;
        box[s][1] = j0;
        box[s][2] = i1;
        box[s][3] = j1;
        total += (size_t)(i1 - i0 + 1) * (size_t)(j1 - j0 + 1);
        if (total > INT_MAX) { /* cell offsets are ints */
            free(start);
            free(box);
            return err_set(err, SCAF_ERR_NOMEM, "chart gap grid: more than %d segment-cell entries",
                           INT_MAX);
        }
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) start[(size_t)j * nx + i + 1]++;
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
                const double *p1 = UV + 2 * (size_t)seg[3 * s],
                             *p2 = UV + 2 * (size_t)seg[3 * s + 1];
                const double *q1 = UV + 2 * (size_t)seg[3 * t],
                             *q2 = UV + 2 * (size_t)seg[3 * t + 1];
                if (cert > 0.0) {
                    /* boxes apart by more than cert along an axis: far
                     * enough (rounding is monotone, so fl(gap) > cert
                     * implies gap > cert); otherwise decide exactly */
                    int apart = 0;
                    for (int c = 0; c < 2; c++)
                        if (fmin(q1[c], q2[c]) - fmax(p1[c], p2[c]) > cert ||
                            fmin(p1[c], p2[c]) - fmax(q1[c], q2[c]) > cert)
                            apart = 1;
                    if (apart) continue;
                    if (!chart_segment_distance_at_least(p1, p2, q1, q2, cert)) {
                        if (!*bad && pair) {
                            int p = seg[3 * s + 2], q = seg[3 * t + 2];
                            pair[0] = p < q ? p : q;
                            pair[1] = p < q ? q : p;
                        }
                        *bad = 1;
                    }
                    continue;
                }
                double d = chart_segment_distance(p1, p2, q1, q2);
                if (list && d < r) pair_list_push(list, s, t);
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

scaf_status chart_gap_segments(int nf, const int *F, const int *chart, int **seg_out, int *nseg,
                               scaf_error *err)
{
    *seg_out = NULL;
    *nseg = 0;
    size_t nh = 3 * (size_t)nf;
    int *order = malloc(sizeof(int) * (nh ? nh : 1));
    int *seg = malloc(sizeof(int) * 3 * (nh ? nh : 1));
    int nhe = 0;
    scaf_status st = order && seg
        ? half_edges_sort(half_edges_index_count(nf, F), nf, F, NULL, order, &nhe, err)
        : SCAF_ERR_NOMEM;
    if (st != SCAF_OK) {
        free(order);
        free(seg);
        return err_nomem(err, "chart boundary segments");
    }
    int n = 0;
    for (int i = 0; i < nhe;) {
        int j = i + 1;
        while (j < nhe && half_edges_same_edge(F, order[j], order[i])) j++;
        if (j - i == 1) {
            seg[3 * n] = half_edge_lo(F, order[i]);
            seg[3 * n + 1] = half_edge_hi(F, order[i]);
            seg[3 * n + 2] = chart[order[i] / 3];
            n++;
        }
        i = j;
    }
    /* A chart without a boundary edge (a point: one UV index three times;
     * faces covering each other twice) still has points: give it a
     * zero-length segment at its first corner so its distance to the other
     * charts counts. Room: its edges, all paired, took no row. */
    int nch = 0;
    for (int f = 0; f < nf; f++)
        if (chart[f] + 1 > nch) nch = chart[f] + 1;
    unsigned char *has = calloc((size_t)(nch ? nch : 1), 1);
    if (!has) {
        free(order);
        free(seg);
        return err_nomem(err, "chart boundary segments");
    }
    for (int s = 0; s < n; s++) has[seg[3 * s + 2]] = 1;
    for (int f = 0; f < nf; f++)
        if (!has[chart[f]]) {
            has[chart[f]] = 1;
            seg[3 * n] = seg[3 * n + 1] = F[3 * f];
            seg[3 * n + 2] = chart[f];
            n++;
        }
    free(has);
    free(order);
    *seg_out = seg;
    *nseg = n;
    return SCAF_OK;
}

/* The segments' end points divided by 2^*e (max |coordinate| of the result
 * in [1, 2)): *xy (2 points per segment) and *seg2 (rows {2s, 2s + 1,
 * chart}), both malloc'd. Exact, and grid searches on them cannot overflow
 * (the extent is at most 4) whatever the units of the layout. */
static scaf_status scaled_segments(const double *UV, const int *seg, int n, double **xy, int **seg2,
                                   int *e, scaf_error *err)
{
    *xy = malloc(sizeof(double) * 4 * (size_t)n);
    *seg2 = malloc(sizeof(int) * 3 * (size_t)n);
    if (!*xy || !*seg2) {
        free(*xy);
        free(*seg2);
        *xy = NULL;
        *seg2 = NULL;
        return err_nomem(err, "chart gap segments");
    }
    for (int s = 0; s < n; s++) {
        (*seg2)[3 * s] = 2 * s;
        (*seg2)[3 * s + 1] = 2 * s + 1;
        (*seg2)[3 * s + 2] = seg[3 * s + 2];
    }
    double m = 0.0;
    for (int s = 0; s < n; s++)
        for (int k = 0; k < 2; k++)
            for (int c = 0; c < 2; c++) m = fmax(m, fabs(UV[2 * (size_t)seg[3 * s + k] + c]));
    *e = m > 0.0 && isfinite(m) ? ilogb(m) : 0;
    for (int s = 0; s < n; s++)
        for (int k = 0; k < 2; k++)
            for (int c = 0; c < 2; c++)
                (*xy)[4 * (size_t)s + 2 * k + c] = ldexp(UV[2 * (size_t)seg[3 * s + k] + c], -*e);
    return SCAF_OK;
}

/* lo and the extent (longest side, 1 when flat) of the points of seg. */
static double segment_extent(const double *UV, const int *seg, int n, double lo[2])
{
    double hi[2] = {-INFINITY, -INFINITY};
    lo[0] = lo[1] = INFINITY;
    for (int s = 0; s < n; s++)
        for (int k = 0; k < 2; k++) {
            const double *a = UV + 2 * (size_t)seg[3 * s + k];
            for (int c = 0; c < 2; c++) {
                lo[c] = fmin(lo[c], a[c]);
                hi[c] = fmax(hi[c], a[c]);
            }
        }
    double extent = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    return extent > 0.0 && isfinite(extent) ? extent : 1.0;
}

scaf_status chart_gap_min_segments(const double *UV, const int *seg, int n, double radius,
                                   double *gap, int pair[2], scaf_error *err)
{
    *gap = INFINITY;
    if (pair) pair[0] = pair[1] = -1;
    if (n < 2) return SCAF_OK;
    double *xy;
    int *sg, e;
    scaf_status st = scaled_segments(UV, seg, n, &xy, &sg, &e, err);
    if (st != SCAF_OK) return st;
    double lo[2], len = 0.0, g = INFINITY;
    double extent = segment_extent(xy, sg, n, lo);
    for (int s = 0; s < n; s++)
        len += hypot(xy[4 * (size_t)s] - xy[4 * (size_t)s + 2],
                     xy[4 * (size_t)s + 1] - xy[4 * (size_t)s + 3]);
    if (radius > 0.0 && isfinite(radius)) {
        /* a radius below 2^-1074 after scaling finds touching pairs only */
        st = grid_search(xy, sg, n, ldexp(radius, -e), lo, extent, &g, pair, NULL, NULL, 0.0, NULL,
                         NULL, err);
    } else {
        double r = len / n;
        if (!(r > 0.0)) r = extent / n;
        for (;;) {
            st = grid_search(xy, sg, n, r, lo, extent, &g, pair, NULL, NULL, 0.0, NULL, NULL, err);
            if (st != SCAF_OK || isfinite(g) || r > 4.0 * extent) break;
            r *= 2.0;
        }
    }
    free(xy);
    free(sg);
    if (st != SCAF_OK) return st;
    *gap = ldexp(g, e);
    /* a positive gap below the smallest double is not a touching (0) */
    if (g > 0.0 && *gap == 0.0) *gap = nextafter(0.0, 1.0);
    if (isfinite(g) && !isfinite(*gap))
        return err_set(err, SCAF_ERR_NUMERIC,
                       "the smallest chart gap (%g * 2^%d) exceeds the largest double", g, e);
    return SCAF_OK;
}

scaf_status chart_gap_min(int nuv, const double *UV, int nf, const int *F, const int *chart,
                          double radius, double *gap, int pair[2], scaf_error *err)
{
    *gap = INFINITY;
    if (pair) pair[0] = pair[1] = -1;
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j];
            if (a < 0 || a >= nuv)
                return err_set(err, SCAF_ERR_MESH, "triangle %d references UV %d of %d", f, a, nuv);
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

/* A search with radius (> 0) on the segments scaled into [1, 2) (exact,
 * see scaled_segments) marking close charts or listing close pairs. */
static scaf_status scaled_search(const double *UV, const int *seg, int n, double radius,
                                 unsigned char *mark, long *npairs, pair_list *list,
                                 scaf_error *err)
{
    double *xy;
    int *sg, e;
    scaf_status st = scaled_segments(UV, seg, n, &xy, &sg, &e, err);
    if (st != SCAF_OK) return st;
    double lo[2], g = INFINITY;
    double extent = segment_extent(xy, sg, n, lo);
    st = grid_search(xy, sg, n, ldexp(radius, -e), lo, extent, &g, NULL, mark, npairs, 0.0, NULL,
                     list, err);
    free(xy);
    free(sg);
    return st;
}

scaf_status chart_gap_mark_close(const double *UV, const int *seg, int n, double radius,
                                 unsigned char *mark, long *npairs, scaf_error *err)
{
    *npairs = 0;
    if (n < 2 || !(radius > 0.0)) return SCAF_OK;
    return scaled_search(UV, seg, n, radius, mark, npairs, NULL, err);
}

/* Coordinates the exact test can take: 0 or magnitude in [2^-200, 2^200]
 * (no expansion component of a degree-4 polynomial in their differences
 * overflows or underflows). */
static int exact_range(double x)
{
    double ax = fabs(x);
    return ax == 0.0 || (ax >= CHART_GAP_EXACT_MIN && ax <= CHART_GAP_EXACT_MAX);
}

scaf_status chart_gap_certify(const double *UV, const int *seg, int n, double padding, int *ok,
                              int pair[2], scaf_error *err)
{
    *ok = 1;
    if (pair) pair[0] = pair[1] = -1;
    if (!(padding >= 0.0) || !exact_range(padding))
        return err_set(err, SCAF_ERR_NUMERIC,
                       "chart gap certificate: padding %g outside [2^-200, 2^200]", padding);
    if (n < 2 || padding == 0.0) return SCAF_OK;
    for (int s = 0; s < n; s++)
        for (int k = 0; k < 2; k++) {
            int v = seg[3 * s + k];
            for (int c = 0; c < 2; c++)
                if (!exact_range(UV[2 * (size_t)v + c]))
                    return err_set(err, SCAF_ERR_NUMERIC,
                                   "chart gap certificate: UV %d coordinate %g is not 0 and "
                                   "outside [2^-200, 2^200]",
                                   v, UV[2 * (size_t)v + c]);
        }
    double lo[2], g = INFINITY;
    double extent = segment_extent(UV, seg, n, lo);
    int bad = 0;
    /* search radius 2 * padding: boxes widened by a whole padding on each
     * side, so every pair closer than the padding shares a cell with a
     * margin far above the rounding of the cell indices */
    scaf_status st = grid_search(UV, seg, n, 2.0 * padding, lo, extent, &g, pair, NULL, NULL,
                                 padding, &bad, NULL, err);
    *ok = !bad;
    return st;
}

scaf_status chart_gap_close_pairs(const double *UV, const int *seg, int n, double radius,
                                  int **pairs, long *npairs, scaf_error *err)
{
    *pairs = NULL;
    *npairs = 0;
    if (n < 2 || !(radius > 0.0)) return SCAF_OK;
    pair_list list = {NULL, 0, 0, 0};
    scaf_status st = scaled_search(UV, seg, n, radius, NULL, NULL, &list, err);
    if (st == SCAF_OK && list.nomem) st = err_nomem(err, "close chart segment pairs");
    if (st != SCAF_OK) {
        free(list.st);
        return st;
    }
    *pairs = list.st;
    *npairs = list.n;
    return SCAF_OK;
}
