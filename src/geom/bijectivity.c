/* geom/bijectivity: exact checker of UV maps (see bijectivity.h).
 *
 * Steps: validate; orient every triangle; group the 3F half-edges by their
 * undirected UV edge (base/half_edges) to
 * find boundary, folded and non-manifold edges and to join triangles into
 * charts; join boundary edges into loops; test boundary segment pairs
 * found through a uniform grid (each pair tested once, in the first grid
 * cell both bounding boxes cover); test the vertices of contact-free loops
 * against all triangles through a grid of those vertices; sort the
 * triangle corners at boundary points by angle and check neighbours. Allocation
 * failures return SCAF_ERR_NOMEM with everything freed.
 */
#include "geom/bijectivity.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "base/union_find.h"
#include "geom/predicates.h"

static int sgn(double x) { return (x > 0) - (x < 0); }

/* Inputs are finite (checked), so plain comparisons do; libm's fmin/fmax
 * are calls because of their NaN rules. */
static inline double dmin(double a, double b) { return a < b ? a : b; }
static inline double dmax(double a, double b) { return a > b ? a : b; }

/* ---- segment contact ---- */

/* c is collinear with a, b: is it within the closed segment? */
static int on_segment(const double *a, const double *b, const double *c)
{
    return dmin(a[0], b[0]) <= c[0] && c[0] <= dmax(a[0], b[0]) && dmin(a[1], b[1]) <= c[1] &&
        c[1] <= dmax(a[1], b[1]);
}

int bij_segments_meet(const double p1[2], const double p2[2], const double q1[2],
                      const double q2[2])
{
    int o1 = sgn(orient2d(p1, p2, q1)), o2 = sgn(orient2d(p1, p2, q2));
    int o3 = sgn(orient2d(q1, q2, p1)), o4 = sgn(orient2d(q1, q2, p2));
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    if ((o1 == 0 && on_segment(p1, p2, q1)) || (o2 == 0 && on_segment(p1, p2, q2)) ||
        (o3 == 0 && on_segment(q1, q2, p1)) || (o4 == 0 && on_segment(q1, q2, p2)))
        return 2;
    return 0;
}

/* Segments s-p and s-q sharing the vertex s: do they overlap along a line
 * (the boundary folds back onto itself)? */
static int adjacent_overlap(const double *s, const double *p, const double *q)
{
    if (orient2d(s, p, q) != 0) return 0;
    int px = sgn(p[0] - s[0]), py = sgn(p[1] - s[1]);
    int qx = sgn(q[0] - s[0]), qy = sgn(q[1] - s[1]);
    if ((px == 0 && py == 0) || (qx == 0 && qy == 0)) return 0; /* zero length */
    return px == qx && py == qy;
}

/* ---- uniform grid over a box ---- */

typedef struct grid {
    double minx, miny, invx, invy;
    int nx, ny;
} grid;

/* A grid of about `cells` square-ish cells over [minx,maxx] x [miny,maxy]. */
static void grid_init(grid *g, double minx, double miny, double maxx, double maxy, long cells)
{
    double w = maxx - minx, h = maxy - miny;
    if (cells < 1) cells = 1;
    if (cells > (1L << 26)) cells = 1L << 26;
    long nx, ny;
    if (!(w > 0 && isfinite(w)) && !(h > 0 && isfinite(h))) {
        nx = ny = 1;
    } else if (!(w > 0 && isfinite(w))) {
        nx = 1, ny = cells;
    } else if (!(h > 0 && isfinite(h))) {
        nx = cells, ny = 1;
    } else {
        /* w / h overflows or underflows for extreme aspect ratios: clamp
         * in double before converting */
        double ax = ceil(sqrt((double)cells * w / h));
        nx = ax < (double)cells ? (long)ax : cells;
        if (nx < 1) nx = 1;
        ny = (cells + nx - 1) / nx;
    }
    g->minx = minx;
    g->miny = miny;
    g->nx = (int)nx;
    g->ny = (int)ny;
    g->invx = (w > 0 && isfinite(w)) ? (double)nx / w : 0.0;
    g->invy = (h > 0 && isfinite(h)) ? (double)ny / h : 0.0;
}

/* Monotone in x, so overlapping boxes get overlapping cell ranges. */
static int cell_x(const grid *g, double x)
{
    double v = (x - g->minx) * g->invx;
    if (!(v >= 0)) return 0;
    if (v >= g->nx) return g->nx - 1;
    return (int)v;
}

static int cell_y(const grid *g, double y)
{
    double v = (y - g->miny) * g->invy;
    if (!(v >= 0)) return 0;
    if (v >= g->ny) return g->ny - 1;
    return (int)v;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* ---- the check ---- */

typedef struct seg {
    int a, b;     /* UV indices, in the direction of their triangle */
    int lox, loy; /* first grid cell of the bounding box */
    int hix, hiy;
} seg;

typedef struct work {
    signed char *ori;
    unsigned char *tri_bnd; /* bit k: edge k of the triangle is boundary */
    unsigned char *bvert;   /* UV point is on a boundary edge */
    int *hedges, *parent, *vparent, *chart_of, *bdeg, *loop_of;
    unsigned char *loop_nested;
    seg *segs;
    int *cell_start, *cell_items;
    int *chart_ccw, *chart_cw, *ids;
} work;

static void work_free(work *w)
{
    free(w->ori);
    free(w->tri_bnd);
    free(w->bvert);
    free(w->parent);
    free(w->vparent);
    free(w->chart_of);
    free(w->bdeg);
    free(w->loop_of);
    free(w->loop_nested);
    free(w->hedges);
    free(w->segs);
    free(w->cell_start);
    free(w->cell_items);
    free(w->chart_ccw);
    free(w->chart_cw);
    free(w->ids);
    memset(w, 0, sizeof *w);
}

static scaf_status nomem(work *w, scaf_error *err, const char *what)
{
    work_free(w);
    return err_nomem(err, what);
}

/* Count crossing and touching boundary segment pairs with a grid. */
static scaf_status test_segments(const double *UV, seg *segs, int nseg, work *w,
                                 unsigned char *contact, const int *loop_of_vertex, bij_report *rep,
                                 scaf_error *err)
{
    if (nseg < 2) return SCAF_OK;
    double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
    for (int i = 0; i < nseg; i++) {
        const double *p = UV + 2 * (size_t)segs[i].a, *q = UV + 2 * (size_t)segs[i].b;
        minx = dmin(minx, dmin(p[0], q[0]));
        maxx = dmax(maxx, dmax(p[0], q[0]));
        miny = dmin(miny, dmin(p[1], q[1]));
        maxy = dmax(maxy, dmax(p[1], q[1]));
    }
    grid g;
    long cells = nseg;
    long total;
    /* Coarsen when long segments would fill too many cells. */
    for (;;) {
        grid_init(&g, minx, miny, maxx, maxy, cells);
        total = 0;
        for (int i = 0; i < nseg; i++) {
            seg *s = &segs[i];
            const double *p = UV + 2 * (size_t)s->a, *q = UV + 2 * (size_t)s->b;
            s->lox = cell_x(&g, dmin(p[0], q[0]));
            s->hix = cell_x(&g, dmax(p[0], q[0]));
            s->loy = cell_y(&g, dmin(p[1], q[1]));
            s->hiy = cell_y(&g, dmax(p[1], q[1]));
            total += (long)(s->hix - s->lox + 1) * (s->hiy - s->loy + 1);
        }
        if (total <= 16L * nseg + 4096 || cells <= 16) break;
        cells /= 4;
    }
    size_t ncell = (size_t)g.nx * (size_t)g.ny;
    w->cell_start = calloc(ncell + 1, sizeof *w->cell_start);
    w->cell_items = malloc((size_t)total * sizeof *w->cell_items);
    if (!w->cell_start || !w->cell_items) return err_nomem(err, "boundary segment grid");
    for (int i = 0; i < nseg; i++)
        for (int y = segs[i].loy; y <= segs[i].hiy; y++)
            for (int x = segs[i].lox; x <= segs[i].hix; x++)
                w->cell_start[(size_t)y * g.nx + x + 1]++;
    for (size_t c = 0; c < ncell; c++) w->cell_start[c + 1] += w->cell_start[c];
    int *fill = malloc((ncell + 1) * sizeof *fill);
    if (!fill) return err_nomem(err, "boundary segment grid");
    memcpy(fill, w->cell_start, (ncell + 1) * sizeof *fill);
    for (int i = 0; i < nseg; i++)
        for (int y = segs[i].loy; y <= segs[i].hiy; y++)
            for (int x = segs[i].lox; x <= segs[i].hix; x++)
                w->cell_items[fill[(size_t)y * g.nx + x]++] = i;
    free(fill);

    for (int cy = 0; cy < g.ny; cy++)
        for (int cx = 0; cx < g.nx; cx++) {
            size_t c = (size_t)cy * g.nx + cx;
            int b = w->cell_start[c], e = w->cell_start[c + 1];
            for (int i = b; i < e; i++) {
                const seg *s = &segs[w->cell_items[i]];
                const double *p1 = UV + 2 * (size_t)s->a, *p2 = UV + 2 * (size_t)s->b;
                for (int j = i + 1; j < e; j++) {
                    const seg *t = &segs[w->cell_items[j]];
                    /* test each pair once: in the first cell both cover */
                    int fx = s->lox > t->lox ? s->lox : t->lox;
                    int fy = s->loy > t->loy ? s->loy : t->loy;
                    if (fx != cx || fy != cy) continue;
                    const double *q1 = UV + 2 * (size_t)t->a, *q2 = UV + 2 * (size_t)t->b;
                    if (dmax(p1[0], p2[0]) < dmin(q1[0], q2[0]) ||
                        dmax(q1[0], q2[0]) < dmin(p1[0], p2[0]) ||
                        dmax(p1[1], p2[1]) < dmin(q1[1], q2[1]) ||
                        dmax(q1[1], q2[1]) < dmin(p1[1], p2[1]))
                        continue;
                    int shared = -1, op = -1, oq = -1;
                    if (s->a == t->a) shared = s->a, op = s->b, oq = t->b;
                    else if (s->a == t->b) shared = s->a, op = s->b, oq = t->a;
                    else if (s->b == t->a) shared = s->b, op = s->a, oq = t->b;
                    else if (s->b == t->b) shared = s->b, op = s->a, oq = t->a;
                    if (shared >= 0) {
                        if (adjacent_overlap(UV + 2 * (size_t)shared, UV + 2 * (size_t)op,
                                             UV + 2 * (size_t)oq)) {
                            rep->boundary_foldbacks++;
                            contact[loop_of_vertex[s->a]] = contact[loop_of_vertex[t->a]] = 1;
                        }
                        continue;
                    }
                    int m = bij_segments_meet(p1, p2, q1, q2);
                    if (m == 1) rep->boundary_crossings++;
                    else if (m == 2) rep->boundary_touchings++;
                    if (m) contact[loop_of_vertex[s->a]] = contact[loop_of_vertex[t->a]] = 1;
                }
            }
        }
    free(w->cell_start);
    free(w->cell_items);
    w->cell_start = w->cell_items = NULL;
    return SCAF_OK;
}

/* Is loop vertex v (not a corner of t) in the interior of the region of
 * triangle t's chart, without touching a boundary item there? */
static int vertex_in_triangle(const double *UV, const int *F, const work *w, int t, int v)
{
    const int *c = F + 3 * (size_t)t;
    const double *p = UV + 2 * (size_t)v;
    int s = w->ori[t];
    int o[3];
    for (int k = 0; k < 3; k++) {
        o[k] = s * sgn(orient2d(UV + 2 * (size_t)c[k], UV + 2 * (size_t)c[(k + 1) % 3], p));
        if (o[k] < 0) return 0;
    }
    int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros == 0) return 1;
    if (zeros == 1) {
        int k = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
        return !(w->tri_bnd[t] & (1u << k)); /* on a boundary edge: a touching */
    }
    /* on a corner: edges k and k+1 meet at corner k+1 */
    int corner = o[0] == 0 ? (o[1] == 0 ? 1 : 0) : 2;
    return !w->bvert[c[corner]];
}

/* Test every boundary vertex of the contact-free loops against all
 * triangles not incident to it (through a grid of those vertices): a loop
 * is nested when one of its vertices lies in the interior of another
 * chart's region (or of its own chart elsewhere). */
static scaf_status test_nesting(const double *UV, int nf, const int *F, work *w, int nq,
                                const int *qv, const int *ql, bij_report *rep, int nloops,
                                scaf_error *err)
{
    if (nq == 0) return SCAF_OK;
    double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
    for (int q = 0; q < nq; q++) {
        const double *p = UV + 2 * (size_t)qv[q];
        minx = dmin(minx, p[0]), maxx = dmax(maxx, p[0]);
        miny = dmin(miny, p[1]), maxy = dmax(maxy, p[1]);
    }
    grid g;
    grid_init(&g, minx, miny, maxx, maxy, nq);
    size_t ncell = (size_t)g.nx * (size_t)g.ny;
    w->cell_start = calloc(ncell + 1, sizeof *w->cell_start);
    w->cell_items = malloc((size_t)nq * sizeof *w->cell_items);
    w->loop_nested = calloc((size_t)nloops + 1, 1);
    if (!w->cell_start || !w->cell_items || !w->loop_nested) return err_nomem(err, "loop grid");
    for (int q = 0; q < nq; q++) {
        const double *p = UV + 2 * (size_t)qv[q];
        w->cell_start[(size_t)cell_y(&g, p[1]) * g.nx + cell_x(&g, p[0]) + 1]++;
    }
    for (size_t c = 0; c < ncell; c++) w->cell_start[c + 1] += w->cell_start[c];
    int *fill = malloc((ncell + 1) * sizeof *fill);
    if (!fill) return err_nomem(err, "loop grid");
    memcpy(fill, w->cell_start, (ncell + 1) * sizeof *fill);
    for (int q = 0; q < nq; q++) {
        const double *p = UV + 2 * (size_t)qv[q];
        w->cell_items[fill[(size_t)cell_y(&g, p[1]) * g.nx + cell_x(&g, p[0])]++] = q;
    }
    free(fill);

    for (int t = 0; t < nf; t++) {
        if (w->ori[t] == 0) continue;
        const int *c = F + 3 * (size_t)t;
        const double *a = UV + 2 * (size_t)c[0], *b = UV + 2 * (size_t)c[1],
                     *d = UV + 2 * (size_t)c[2];
        double tminx = dmin(a[0], dmin(b[0], d[0])), tmaxx = dmax(a[0], dmax(b[0], d[0]));
        double tminy = dmin(a[1], dmin(b[1], d[1])), tmaxy = dmax(a[1], dmax(b[1], d[1]));
        if (tmaxx < minx || tminx > maxx || tmaxy < miny || tminy > maxy) continue;
        int x0 = cell_x(&g, tminx), x1 = cell_x(&g, tmaxx);
        int y0 = cell_y(&g, tminy), y1 = cell_y(&g, tmaxy);
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++) {
                size_t cell = (size_t)y * g.nx + x;
                for (int i = w->cell_start[cell]; i < w->cell_start[cell + 1]; i++) {
                    int q = w->cell_items[i];
                    int v = qv[q];
                    if (w->loop_nested[ql[q]] || v == c[0] || v == c[1] || v == c[2]) continue;
                    const double *p = UV + 2 * (size_t)v;
                    if (p[0] < tminx || p[0] > tmaxx || p[1] < tminy || p[1] > tmaxy) continue;
                    if (vertex_in_triangle(UV, F, w, t, v)) w->loop_nested[ql[q]] = 1;
                }
            }
    }
    for (int l = 0; l < nloops; l++) rep->nested_loops += w->loop_nested[l];
    return SCAF_OK;
}

/* ---- corners at boundary points ---- */

/* Angular order of directions p - v, exact: upper half-plane first (y > 0,
 * or y == 0 and x > 0), then counter-clockwise. */
typedef struct sector {
    const double *v, *a, *b; /* apex, start and end of a ccw corner */
} sector;

static int half(const double *v, const double *p)
{
    return (p[1] > v[1] || (p[1] == v[1] && p[0] > v[0])) ? 0 : 1;
}

static int sector_cmp(const void *x, const void *y)
{
    const sector *s = x, *t = y;
    int hs = half(s->v, s->a), ht = half(t->v, t->a);
    if (hs != ht) return hs - ht;
    double o = orient2d(s->v, s->a, t->a);
    return o > 0 ? -1 : o < 0 ? 1 : 0;
}

/* Same direction from v (collinear, same side)? */
static int same_direction(const double *v, const double *p, const double *q)
{
    return orient2d(v, p, q) == 0 && half(v, p) == half(v, q);
}

/* At every boundary point the corners of the incident ccw triangles must
 * not overlap. That matters where the boundary passes more than once (fans
 * joined only at the point) or where a triangle reaches by index into
 * another chart's fan; the vertex-in-triangle test skips incident
 * triangles, this covers them. Sort the corners by start direction and
 * check each against the next, cyclically (each corner is below 180
 * degrees, so an overlap always shows between neighbours). */
static scaf_status test_corners(const double *UV, int nuv, int nf, const int *F, work *w,
                                const int *bdeg, bij_report *rep, scaf_error *err)
{
    int *start = calloc((size_t)nuv + 1, sizeof *start);
    if (!start) return err_nomem(err, "corners at boundary points");
    int any = 0;
    for (int t = 0; t < nf; t++) {
        if (w->ori[t] <= 0) continue;
        for (int k = 0; k < 3; k++)
            if (bdeg[F[3 * (size_t)t + k]] > 0) start[F[3 * (size_t)t + k] + 1]++, any = 1;
    }
    if (!any) {
        free(start);
        return SCAF_OK;
    }
    for (int v = 0; v < nuv; v++) start[v + 1] += start[v];
    sector *sec = malloc(((size_t)start[nuv] + 1) * sizeof *sec);
    int *pos = malloc(((size_t)nuv + 1) * sizeof *pos);
    if (!sec || !pos) {
        free(start), free(sec), free(pos);
        return err_nomem(err, "corners at boundary points");
    }
    memcpy(pos, start, ((size_t)nuv + 1) * sizeof *pos);
    for (int t = 0; t < nf; t++) {
        if (w->ori[t] <= 0) continue;
        const int *c = F + 3 * (size_t)t;
        for (int k = 0; k < 3; k++)
            if (bdeg[c[k]] > 0) {
                sector s = {UV + 2 * (size_t)c[k], UV + 2 * (size_t)c[(k + 1) % 3],
                            UV + 2 * (size_t)c[(k + 2) % 3]};
                sec[pos[c[k]]++] = s;
            }
    }
    for (int v = 0; v < nuv; v++) {
        int n = start[v + 1] - start[v];
        if (n < 2) continue;
        sector *S = sec + start[v];
        qsort(S, (size_t)n, sizeof *S, sector_cmp);
        for (int i = 0; i < n; i++) {
            const sector *s = &S[i], *t = &S[(i + 1) % n];
            if (same_direction(s->v, s->a, t->a) ||
                (orient2d(s->v, s->a, t->a) > 0 && orient2d(s->v, t->a, s->b) > 0)) {
                rep->corner_overlaps++;
                break;
            }
        }
    }
    free(start), free(sec), free(pos);
    return SCAF_OK;
}

scaf_status bij_check(int nuv, const double *UV, int nf, const int *F, const int *chart,
                      signed char *orient, bij_report *rep, scaf_error *err)
{
    memset(rep, 0, sizeof *rep);
    work w;
    memset(&w, 0, sizeof w);
    scaf_status st;

    /* ---- check inputs ---- */
    if (nuv < 0 || nf < 0 || (nuv > 0 && !UV) || (nf > 0 && !F))
        return err_set(err, SCAF_ERR_USAGE, "bij_check: bad arguments (nuv %d, nf %d)", nuv, nf);
    for (int i = 0; i < nuv; i++)
        if (!isfinite(UV[2 * (size_t)i]) || !isfinite(UV[2 * (size_t)i + 1]))
            return err_set(err, SCAF_ERR_MESH, "UV point %d is not finite (%g, %g)", i,
                           UV[2 * (size_t)i], UV[2 * (size_t)i + 1]);
    for (int t = 0; t < nf; t++)
        for (int k = 0; k < 3; k++) {
            int v = F[3 * (size_t)t + k];
            if (v < 0 || v >= nuv)
                return err_set(err, SCAF_ERR_MESH,
                               "triangle %d corner %d: UV index %d out of range [0, %d)", t, k, v,
                               nuv);
        }
    if (chart)
        for (int t = 0; t < nf; t++)
            if (chart[t] < 0)
                return err_set(err, SCAF_ERR_MESH, "triangle %d: negative chart id %d", t,
                               chart[t]);
    rep->triangles = nf;

    /* ---- orientation ---- */
    w.ori = malloc((size_t)nf + 1);
    if (!w.ori) return nomem(&w, err, "triangle orientations");
    for (int t = 0; t < nf; t++) {
        const int *c = F + 3 * (size_t)t;
        int s = sgn(orient2d(UV + 2 * (size_t)c[0], UV + 2 * (size_t)c[1], UV + 2 * (size_t)c[2]));
        w.ori[t] = (signed char)s;
        if (s > 0) rep->positive++;
        else if (s < 0) rep->flipped++;
        else rep->degenerate++;
        if (orient) orient[t] = (signed char)s;
    }

    /* ---- group half-edges by undirected UV edge ---- */
    w.hedges = malloc(3 * (size_t)nf * sizeof *w.hedges + 1);
    w.tri_bnd = calloc((size_t)nf + 1, 1);
    w.bvert = calloc((size_t)nuv + 1, 1);
    w.parent = malloc(((size_t)nf + 1) * sizeof *w.parent);
    if (!w.hedges || !w.tri_bnd || !w.bvert || !w.parent) return nomem(&w, err, "edge table");
    uf_init(w.parent, nf);
    int nhe = 0;
    if (half_edges_sort(nuv, nf, F, NULL, w.hedges, &nhe, err) != SCAF_OK)
        return nomem(&w, err, "edge table");
    int nseg = 0, segcap = 0;
    for (int i = 0; i < nhe;) {
        int j = i + 1;
        while (j < nhe && half_edges_same_edge(F, w.hedges[j], w.hedges[i])) j++;
        int n = j - i;
        if (half_edge_lo(F, w.hedges[i]) == half_edge_hi(F, w.hedges[i])) {
            /* a side with both ends at one UV point joins nothing */
        } else if (n == 1) {
            int h = w.hedges[i], t = h / 3, k = h % 3;
            if (nseg == segcap) {
                segcap = segcap ? 2 * segcap : 1024;
                seg *ns = realloc(w.segs, (size_t)segcap * sizeof *ns);
                if (!ns) return nomem(&w, err, "boundary segments");
                w.segs = ns;
            }
            seg *s = &w.segs[nseg++];
            s->a = F[3 * (size_t)t + k];
            s->b = F[3 * (size_t)t + (k + 1) % 3];
            w.tri_bnd[t] |= (unsigned char)(1u << k);
            w.bvert[s->a] = w.bvert[s->b] = 1;
        } else {
            if (n == 2) {
                if (F[w.hedges[i]] == F[w.hedges[i + 1]]) rep->folded_edges++;
            } else {
                rep->nonmanifold_edges++;
            }
            for (int q = i + 1; q < j; q++) uf_union(w.parent, w.hedges[i] / 3, w.hedges[q] / 3);
        }
        i = j;
    }
    rep->boundary_edges = nseg;
    free(w.hedges);
    w.hedges = NULL;

    /* ---- charts ---- */
    w.chart_of = malloc(((size_t)nf + 1) * sizeof *w.chart_of);
    if (!w.chart_of) return nomem(&w, err, "charts");
    if (chart) {
        w.ids = malloc(((size_t)nf + 1) * sizeof *w.ids);
        if (!w.ids) return nomem(&w, err, "charts");
        memcpy(w.ids, chart, (size_t)nf * sizeof *w.ids);
        qsort(w.ids, (size_t)nf, sizeof *w.ids, cmp_int);
        int n = 0;
        for (int t = 0; t < nf; t++)
            if (t == 0 || w.ids[t] != w.ids[t - 1]) w.ids[n++] = w.ids[t];
        rep->charts = n;
        for (int t = 0; t < nf; t++) {
            int *f = bsearch(&chart[t], w.ids, (size_t)n, sizeof *w.ids, cmp_int);
            w.chart_of[t] = (int)(f - w.ids);
        }
    } else {
        int n = 0;
        for (int t = 0; t < nf; t++) {
            int r = uf_find(w.parent, t);
            if (r == t) w.chart_of[t] = n++;
            else w.chart_of[t] = w.chart_of[r]; /* roots are the smallest index */
        }
        rep->charts = n;
    }
    w.chart_ccw = calloc((size_t)rep->charts + 1, sizeof *w.chart_ccw);
    w.chart_cw = calloc((size_t)rep->charts + 1, sizeof *w.chart_cw);
    if (!w.chart_ccw || !w.chart_cw) return nomem(&w, err, "charts");
    for (int t = 0; t < nf; t++) {
        if (w.ori[t] > 0) w.chart_ccw[w.chart_of[t]]++;
        if (w.ori[t] < 0) w.chart_cw[w.chart_of[t]]++;
    }
    for (int c = 0; c < rep->charts; c++) {
        if (w.chart_cw[c] > 0 && w.chart_ccw[c] == 0) rep->mirrored_charts++;
        if (w.chart_cw[c] > 0 && w.chart_ccw[c] > 0) rep->mixed_charts++;
    }

    /* ---- boundary loops ---- */
    w.vparent = malloc(((size_t)nuv + 1) * sizeof *w.vparent);
    w.loop_of = malloc(((size_t)nuv + 1) * sizeof *w.loop_of);
    w.bdeg = calloc((size_t)nuv + 1, sizeof *w.bdeg); /* boundary segments at each point */
    if (!w.vparent || !w.loop_of || !w.bdeg) return nomem(&w, err, "boundary loops");
    int *bdeg = w.bdeg;
    uf_init(w.vparent, nuv);
    for (int i = 0; i < nseg; i++) {
        uf_union(w.vparent, w.segs[i].a, w.segs[i].b);
        bdeg[w.segs[i].a]++;
        bdeg[w.segs[i].b]++;
    }
    int nloops = 0, nbv = 0;
    for (int v = 0; v < nuv; v++)
        if (w.bvert[v] && uf_find(w.vparent, v) == v) w.loop_of[v] = nloops++;
    for (int v = 0; v < nuv; v++) {
        if (!w.bvert[v]) continue;
        w.loop_of[v] = w.loop_of[uf_find(w.vparent, v)]; /* the root's loop, then v's */
        nbv++;
    }
    rep->boundary_loops = nloops;

    /* ---- overlaps ---- */
    unsigned char *contact = calloc((size_t)nloops + 1, 1);
    if (!contact) return nomem(&w, err, "boundary loops");
    st = test_segments(UV, w.segs, nseg, &w, contact, w.loop_of, rep, err);
    int *qv = NULL, *ql = NULL, nq = 0;
    if (st == SCAF_OK) {
        qv = malloc(((size_t)nbv + 1) * sizeof *qv);
        ql = malloc(((size_t)nbv + 1) * sizeof *ql);
        if (!qv || !ql) st = err_nomem(err, "boundary vertices");
    }
    if (st == SCAF_OK) {
        for (int v = 0; v < nuv; v++)
            if (w.bvert[v] && !contact[w.loop_of[v]]) qv[nq] = v, ql[nq++] = w.loop_of[v];
        st = test_nesting(UV, nf, F, &w, nq, qv, ql, rep, nloops, err);
    }
    if (st == SCAF_OK) st = test_corners(UV, nuv, nf, F, &w, bdeg, rep, err);
    free(contact);
    free(qv);
    free(ql);
    if (st != SCAF_OK) {
        work_free(&w);
        return st;
    }

    rep->bijective = rep->flipped == 0 && rep->degenerate == 0 && rep->boundary_crossings == 0 &&
        rep->boundary_touchings == 0 && rep->boundary_foldbacks == 0 && rep->folded_edges == 0 &&
        rep->corner_overlaps == 0 && rep->nonmanifold_edges == 0 && rep->nested_loops == 0;
    work_free(&w);
    return SCAF_OK;
}

void bij_report_defects(const bij_report *rep, char *buf, size_t size)
{
    const struct {
        const char *name;
        long long n;
    } d[] = {
        {"flipped", rep->flipped},
        {"degenerate", rep->degenerate},
        {"mirrored_charts", rep->mirrored_charts},
        {"boundary_crossings", rep->boundary_crossings},
        {"boundary_touchings", rep->boundary_touchings},
        {"boundary_foldbacks", rep->boundary_foldbacks},
        {"folded_edges", rep->folded_edges},
        {"nonmanifold_edges", rep->nonmanifold_edges},
        {"nested_loops", rep->nested_loops},
        {"corner_overlaps", rep->corner_overlaps},
    };
    if (!buf || !size) return;
    size_t at = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < sizeof d / sizeof *d; i++) {
        if (d[i].n == 0) continue;
        int w = snprintf(buf + at, size - at, "%s%s %lld", at ? ", " : "", d[i].name, d[i].n);
        if (w < 0 || (size_t)w >= size - at) return; /* truncated */
        at += (size_t)w;
    }
    if (at == 0) snprintf(buf, size, "none");
}
