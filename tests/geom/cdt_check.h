/* tests/geom/cdt_check: shared input builders and an exact checker for cdt outputs.
 *
 * Header-only (static functions) so each test program can include it.
 * The checker asserts, with the exact predicates: every triangle strictly
 * counter-clockwise, neighbours consistent, every input segment present
 * (unsplittable ones as one edge, splittable ones as a collinear chain),
 * constrained empty circles across every non-segment edge, no triangle
 * inside a chart (winding number of its centroid), the domain area, the
 * Euler characteristic, and the angle / area bounds away from chart
 * edges. It returns statistics so tests can also assert refinement took
 * place.
 */
#ifndef SCAF_TESTS_CDT_CHECK_H
#define SCAF_TESTS_CDT_CHECK_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/cdt.h"
#include "geom/predicates.h"

/* ------------------------------------------------------------ builder */

typedef struct cdt_builder {
    double *pts;
    int np, capp;
    int *seg;
    unsigned char *split, *hole;
    int ns, caps;
    double *seeds;
    int nseeds;
    /* chart loops for the checker: loop l spans segments loop_start[l] .. */
    int nloops, loop_start[4096], loop_len[4096];
    double chart_area; /* signed area enclosed by chart loops (holes negative) */
} cdt_builder;

static inline void cb_init(cdt_builder *b) { memset(b, 0, sizeof *b); }

static inline void cb_free(cdt_builder *b)
{
    free(b->pts);
    free(b->seg);
    free(b->split);
    free(b->hole);
    free(b->seeds);
}

static inline int cb_point(cdt_builder *b, double x, double y)
{
    if (b->np == b->capp) {
        b->capp = b->capp ? 2 * b->capp : 256;
        b->pts = realloc(b->pts, (size_t)b->capp * 2 * sizeof(double));
    }
    b->pts[2 * b->np] = x;
    b->pts[2 * b->np + 1] = y;
    return b->np++;
}

static inline void cb_segment(cdt_builder *b, int u, int w, int splittable, int hole)
{
    if (b->ns == b->caps) {
        b->caps = b->caps ? 2 * b->caps : 256;
        b->seg = realloc(b->seg, (size_t)b->caps * 2 * sizeof(int));
        b->split = realloc(b->split, (size_t)b->caps);
        b->hole = realloc(b->hole, (size_t)b->caps);
    }
    b->seg[2 * b->ns] = u;
    b->seg[2 * b->ns + 1] = w;
    b->split[b->ns] = (unsigned char)splittable;
    b->hole[b->ns] = (unsigned char)hole;
    b->ns++;
}

/* A closed chart loop through xy (n points). The chart lies on the left:
 * counter-clockwise for an outer boundary, clockwise around a chart hole. */
static inline void cb_loop(cdt_builder *b, const double *xy, int n)
{
    int first = b->np;
    if (b->nloops < 4096) {
        b->loop_start[b->nloops] = b->ns;
        b->loop_len[b->nloops] = n;
        b->nloops++;
    }
    double a = 0;
    for (int i = 0; i < n; i++) {
        cb_point(b, xy[2 * i], xy[2 * i + 1]);
        int j = (i + 1) % n;
        a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    b->chart_area += 0.5 * a;
    for (int i = 0; i < n; i++) cb_segment(b, first + i, first + (i + 1) % n, 0, 1);
}

/* An axis-aligned rectangle [x0, x1] x [y0, y1]: four new corners in
 * counter-clockwise order from (x0, y0), joined by splittable segments with
 * nothing marked as hole (a scaffold box). */
static inline void cb_rect(cdt_builder *b, double x0, double y0, double x1, double y1)
{
    int q0 = cb_point(b, x0, y0), q1 = cb_point(b, x1, y0);
    int q2 = cb_point(b, x1, y1), q3 = cb_point(b, x0, y1);
    cb_segment(b, q0, q1, 1, 0);
    cb_segment(b, q1, q2, 1, 0);
    cb_segment(b, q2, q3, 1, 0);
    cb_segment(b, q3, q0, 1, 0);
}

/* The scaffold box: `factor` times the bounding box of the points so far
 * (about its center), splittable, nothing marked as hole. */
static inline void cb_box(cdt_builder *b, double factor, double *box_area)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < b->np; i++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], b->pts[2 * i + k]);
            hi[k] = fmax(hi[k], b->pts[2 * i + k]);
        }
    double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double h = 0.5 * factor * fmax(hi[0] - lo[0], hi[1] - lo[1]);
    cb_rect(b, c[0] - h, c[1] - h, c[0] + h, c[1] + h);
    if (box_area) *box_area = (2 * h) * (2 * h);
}

static inline cdt_input cb_input(const cdt_builder *b)
{
    cdt_input in;
    memset(&in, 0, sizeof in);
    in.npoints = b->np;
    in.points = b->pts;
    in.nsegments = b->ns;
    in.segments = b->seg;
    in.splittable = b->split;
    in.left_is_hole = b->hole;
    in.nholes = b->nseeds;
    in.holes = b->seeds;
    return in;
}

/* A star-like wiggly polygon: n vertices on r(t) = r0 (1 + amp sin(k t)). */
static inline void wiggly(double *xy, int n, double cx, double cy, double r0, double amp, int k,
                          int cw)
{
    for (int i = 0; i < n; i++) {
        double t = 2 * 3.14159265358979323846 * i / n * (cw ? -1 : 1);
        double r = r0 * (1 + amp * sin(k * t));
        xy[2 * i] = cx + r * cos(t);
        xy[2 * i + 1] = cy + r * sin(t);
    }
}

/* A wiggly chart loop (see wiggly; cw: clockwise, around a chart hole). */
static inline void cb_wiggly_loop(cdt_builder *b, int n, double cx, double cy, double r0,
                                  double amp, int k, int cw)
{
    double *xy = malloc((size_t)n * 2 * sizeof(double));
    if (!xy) {
        fprintf(stderr, "cb_wiggly_loop: out of memory\n");
        abort();
    }
    wiggly(xy, n, cx, cy, r0, amp, k, cw);
    cb_loop(b, xy, n);
    free(xy);
}

/* The commonest test domain: b starts empty, gets one counter-clockwise
 * wiggly chart (see wiggly) and the 3x scaffold box (area into box_area
 * when given). */
static inline void cb_wiggly_in_box(cdt_builder *b, int n, double cx, double cy, double r0,
                                    double amp, int k, double *box_area)
{
    cb_init(b);
    cb_wiggly_loop(b, n, cx, cy, r0, amp, k, 0);
    cb_box(b, 3.0, box_area);
}

/* ------------------------------------------------------------ checker */

typedef struct cdt_check_stats {
    int ok;
    char why[256];
    double min_angle_all;  /* degrees, over all triangles */
    double min_angle_free; /* over triangles touching no unsplittable segment vertex */
    int nfree, nfree_bad;  /* such triangles, and those below the bound */
    double area;           /* sum of triangle areas */
    int euler;             /* V - E + F */
} cdt_check_stats;

static inline int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

static inline uint64_t ekey(int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    return ((uint64_t)(uint32_t)a << 32) | (uint32_t)b;
}

static inline int has_key(const uint64_t *k, int n, uint64_t x)
{
    return bsearch(&x, k, (size_t)n, sizeof *k, cmp_u64) != NULL;
}

#define CDT_FAIL(...)                                                                              \
    do {                                                                                           \
        snprintf(st->why, sizeof st->why, __VA_ARGS__);                                            \
        st->ok = 0;                                                                                \
        goto done;                                                                                 \
    } while (0)

/* winding number of q with respect to the chart loops of b */
static inline int chart_winding(const cdt_builder *b, const double *q)
{
    int wn = 0;
    for (int l = 0; l < b->nloops; l++) {
        for (int s = b->loop_start[l]; s < b->loop_start[l] + b->loop_len[l]; s++) {
            const double *pa = b->pts + 2 * b->seg[2 * s], *pb = b->pts + 2 * b->seg[2 * s + 1];
            if (pa[1] <= q[1]) {
                if (pb[1] > q[1] && orient2d(pa, pb, q) > 0) wn++;
            } else if (pb[1] <= q[1] && orient2d(pa, pb, q) < 0) {
                wn--;
            }
        }
    }
    return wn;
}

static inline double tri_min_angle(const double *a, const double *b, const double *c)
{
    const double *p[3] = {a, b, c};
    double best = 180;
    for (int i = 0; i < 3; i++) {
        const double *o = p[i], *u = p[(i + 1) % 3], *w = p[(i + 2) % 3];
        double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
        double ang =
            atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / 3.14159265358979323846;
        if (ang < best) best = ang;
    }
    return best;
}

/* Check out against the builder's input. expect_chi: expected Euler
 * characteristic (or INT32_MIN to skip); check_winding: test centroids
 * against the chart loops. */
static inline cdt_check_stats cdt_check(const cdt_builder *b, const cdt_options *opt,
                                        const cdt_output *out, int expect_chi, int check_winding)
{
    cdt_check_stats s0;
    memset(&s0, 0, sizeof s0);
    cdt_check_stats *st = &s0;
    st->ok = 1;
    st->min_angle_all = st->min_angle_free = 180;
    int T = out->ntriangles, P = out->npoints;
    uint64_t *edges = malloc((size_t)(3 * T + 1) * sizeof *edges);
    uint64_t *subs = malloc((size_t)(out->nsubsegments + 1) * sizeof *subs);
    unsigned char *used = calloc((size_t)P + 1, 1), *chartv = calloc((size_t)P + 1, 1);
    int ne = 0;

    /* input points first, unchanged */
    if (P < b->np) CDT_FAIL("fewer output points (%d) than input points (%d)", P, b->np);
    for (int i = 0; i < b->np; i++)
        if (out->points[2 * i] != b->pts[2 * i] || out->points[2 * i + 1] != b->pts[2 * i + 1])
            CDT_FAIL("output point %d moved", i);
    for (int s = 0; s < b->ns; s++)
        if (!b->split[s]) chartv[b->seg[2 * s]] = chartv[b->seg[2 * s + 1]] = 1;

    /* orientation, neighbours, edges */
    for (int t = 0; t < T; t++) {
        const int *v = out->triangles + 3 * t;
        for (int k = 0; k < 3; k++) {
            if (v[k] < 0 || v[k] >= P) CDT_FAIL("triangle %d has vertex %d out of range", t, v[k]);
            used[v[k]] = 1;
            edges[ne++] = ekey(v[(k + 1) % 3], v[(k + 2) % 3]);
        }
        const double *a = out->points + 2 * v[0], *bb = out->points + 2 * v[1],
                     *c = out->points + 2 * v[2];
        if (!(orient2d(a, bb, c) > 0))
            CDT_FAIL("triangle %d (%d %d %d) is not strictly counter-clockwise", t, v[0], v[1],
                     v[2]);
        for (int k = 0; k < 3; k++) {
            int n = out->neighbors[3 * t + k];
            if (n < 0) continue;
            if (n >= T) CDT_FAIL("triangle %d neighbour out of range", t);
            int back = 0;
            for (int j = 0; j < 3; j++)
                if (out->neighbors[3 * n + j] == t) {
                    const int *w = out->triangles + 3 * n;
                    if (w[(j + 1) % 3] == v[(k + 2) % 3] && w[(j + 2) % 3] == v[(k + 1) % 3])
                        back = 1;
                }
            if (!back)
                CDT_FAIL("triangles %d and %d are not mutual neighbours across their edge", t, n);
        }
        double ang = tri_min_angle(a, bb, c);
        st->min_angle_all = fmin(st->min_angle_all, ang);
        st->area += 0.5 * ((bb[0] - a[0]) * (c[1] - a[1]) - (bb[1] - a[1]) * (c[0] - a[0]));
        if (!chartv[v[0]] && !chartv[v[1]] && !chartv[v[2]]) {
            st->nfree++;
            st->min_angle_free = fmin(st->min_angle_free, ang);
            if (opt && opt->min_angle_deg > 0 && ang < opt->min_angle_deg - 1e-9) st->nfree_bad++;
            if (opt && opt->max_area > 0 && 0.5 * orient2d(a, bb, c) > opt->max_area * (1 + 1e-9))
                CDT_FAIL("triangle %d exceeds the maximum area", t);
        }
        if (check_winding) {
            double q[2] = {(a[0] + bb[0] + c[0]) / 3, (a[1] + bb[1] + c[1]) / 3};
            if (chart_winding(b, q) != 0)
                CDT_FAIL("triangle %d (centroid %.17g %.17g) lies inside a chart", t, q[0], q[1]);
        }
    }
    for (int i = 0; i < P; i++)
        if (!used[i]) CDT_FAIL("output point %d is in no triangle", i);
    qsort(edges, (size_t)ne, sizeof *edges, cmp_u64);
    int nu = 0;
    for (int i = 0; i < ne; i++)
        if (nu == 0 || edges[i] != edges[nu - 1]) edges[nu++] = edges[i];
    st->euler = P - nu + T;
    if (expect_chi != INT32_MIN && st->euler != expect_chi)
        CDT_FAIL("Euler characteristic V-E+F = %d-%d+%d = %d, expected %d", P, nu, T, st->euler,
                 expect_chi);

    /* segments */
    for (int i = 0; i < out->nsubsegments; i++) {
        int u = out->subsegments[2 * i], w = out->subsegments[2 * i + 1], s = out->subsegment_of[i];
        if (s < 0 || s >= b->ns) CDT_FAIL("subsegment %d names segment %d", i, s);
        if (!has_key(edges, nu, ekey(u, w)))
            CDT_FAIL("subsegment %d (%d %d) is not an edge", i, u, w);
        const double *pa = b->pts + 2 * b->seg[2 * s], *pb = b->pts + 2 * b->seg[2 * s + 1];
        if (orient2d(pa, pb, out->points + 2 * u) != 0 ||
            orient2d(pa, pb, out->points + 2 * w) != 0)
            CDT_FAIL("subsegment %d is off its segment %d", i, s);
        subs[i] = ekey(u, w);
    }
    qsort(subs, (size_t)out->nsubsegments, sizeof *subs, cmp_u64);
    for (int s = 0; s < b->ns; s++) {
        int u = b->seg[2 * s], w = b->seg[2 * s + 1];
        if (!b->split[s]) {
            if (!has_key(edges, nu, ekey(u, w)) || !has_key(subs, out->nsubsegments, ekey(u, w)))
                CDT_FAIL("unsplittable segment %d (%d %d) is not an output edge", s, u, w);
        } else {
            /* the chain: subsegments of s must connect u to w */
            double len = 0,
                   want =
                       hypot(b->pts[2 * w] - b->pts[2 * u], b->pts[2 * w + 1] - b->pts[2 * u + 1]);
            for (int i = 0; i < out->nsubsegments; i++)
                if (out->subsegment_of[i] == s) {
                    const double *p = out->points + 2 * out->subsegments[2 * i];
                    const double *q = out->points + 2 * out->subsegments[2 * i + 1];
                    len += hypot(q[0] - p[0], q[1] - p[1]);
                }
            int dup = 0; /* a segment given twice is kept (and reported) once */
            for (int s2 = 0; s2 < b->ns; s2++)
                if (s2 != s && ekey(b->seg[2 * s2], b->seg[2 * s2 + 1]) == ekey(u, w)) dup = 1;
            if (dup && len == 0) continue;
            if (fabs(len - want) > 1e-9 * want)
                CDT_FAIL("splittable segment %d: chain length %.17g, segment %.17g", s, len, want);
        }
    }

    /* constrained Delaunay: every non-segment edge has an empty circle */
    for (int t = 0; t < T; t++) {
        const int *v = out->triangles + 3 * t;
        for (int k = 0; k < 3; k++) {
            int n = out->neighbors[3 * t + k];
            int u = v[(k + 1) % 3], w = v[(k + 2) % 3];
            int is_sub = has_key(subs, out->nsubsegments, ekey(u, w));
            if (n < 0) {
                if (!is_sub) CDT_FAIL("triangle %d: boundary edge %d-%d is on no segment", t, u, w);
                continue;
            }
            if (is_sub) continue;
            int opp = -1;
            for (int j = 0; j < 3; j++)
                if (out->neighbors[3 * n + j] == t) opp = out->triangles[3 * n + j];
            if (incircle(out->points + 2 * v[0], out->points + 2 * v[1], out->points + 2 * v[2],
                         out->points + 2 * opp) > 0)
                CDT_FAIL("triangles %d and %d: edge %d-%d is not constrained Delaunay", t, n, u, w);
        }
    }
done:
    free(edges);
    free(subs);
    free(used);
    free(chartv);
    return s0;
}

#endif /* SCAF_TESTS_CDT_CHECK_H */
