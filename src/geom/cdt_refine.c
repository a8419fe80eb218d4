/* geom/cdt_refine: quality refinement (Ruppert / Chew style, with off-centers).
 *
 * Two FIFO queues drive the work: encroached splittable subsegments
 * (served first) and candidate bad triangles. A bad triangle is a domain
 * triangle whose smallest angle is below the bound, unless that angle lies
 * between two segments (a small input angle, left alone), or whose area
 * exceeds max_area. Its Steiner point is Ungor's off-center on the
 * bisector of the shortest edge when that is closer than the circumcenter
 * (fewer points, same grading), else the circumcenter. The point is found
 * by a walk that may not cross constrained edges. A point beyond a
 * constrained edge, or inside the diametral circle of a splittable
 * subsegment on its cavity's boundary, is not inserted: that subsegment is
 * split instead and the triangle retried (three times at most). A point
 * that would spoil an unsplittable segment on its cavity's boundary (lie in
 * its diametral lens, or nearly on its line close to an end: see spoils())
 * is not inserted either; a second point (half-way to the shortest edge,
 * or the centroid for an area-bad triangle) is tried, and if it fails too
 * the triangle stays as it is (refinement is best-effort next to chart
 * edges). Splits use the midpoint, or concentric shells (a power-of-two
 * distance from the segment's input endpoint) so small angles between
 * splittable segments cannot ping-pong; a split point must lie exactly on
 * its segment or the segment stays whole. Geometric
 * positions are computed in floating point (scaled by exact powers of two,
 * so any input scale works); every topological decision is exact (see
 * cdt_mesh.c), and an insertion whose fan would not be strictly
 * counter-clockwise is refused.
 */
#include "geom/cdt_refine.h"

#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"

typedef struct rq {
    int *v;
    long n, cap, head;
    int width;
} rq;

static int rq_push(rq *q, const int *item)
{
    if (q->head > 0 && q->head * 2 >= q->n && q->n >= 1024) {
        long live = q->n - q->head;
        for (long i = 0; i < live * q->width; i++) q->v[i] = q->v[q->head * q->width + i];
        q->n = live;
        q->head = 0;
    }
    if (q->n >= q->cap) {
        long nc = q->cap ? 2 * q->cap : 256;
        int *nv = realloc(q->v, (size_t)nc * (size_t)q->width * sizeof(int));
        if (!nv) return -1;
        q->v = nv;
        q->cap = nc;
    }
    for (int k = 0; k < q->width; k++) q->v[q->n * q->width + k] = item[k];
    q->n++;
    return 0;
}

typedef struct refiner {
    cdt_mesh *m;
    const cdt_refine_params *prm;
    cdt_refine_stats *st;
    double sin2;       /* sin^2 of the angle bound */
    double offh;       /* off-center height / shortest edge length */
    double cos1, cos2; /* cos(bound), cos(2 bound) for the lens test */
    rq segq;           /* a, b, forced */
    rq triq;           /* t, v0, v1, v2, tries */
} refiner;

static int seg_splittable(const refiner *r, int code)
{
    return code >= 0 && !(code & 1) && r->prm->splittable[code >> 1];
}

/* 2^-e with 2^e the binade of s: multiplying by it is exact and brings
 * s into [0.5, 1), so the floating-point geometry below neither
 * overflows nor underflows at any input scale. */
static double unit_scale(double s)
{
    int e;
    frexp(s, &e);
    return ldexp(1.0, -e);
}

static double max_abs4(double a, double b, double c, double d)
{
    return fmax(fmax(fabs(a), fabs(b)), fmax(fabs(c), fabs(d)));
}

/* p in the closed diametral circle of u-w */
static int encroaches(const double *u, const double *w, const double *p)
{
    double ux = u[0] - p[0], uy = u[1] - p[1], wx = w[0] - p[0], wy = w[1] - p[1];
    double s = max_abs4(ux, uy, wx, wy);
    if (s == 0) return 1;
    double f = unit_scale(s);
    return (ux * f) * (wx * f) + (uy * f) * (wy * f) <= 0;
}

/* Would a Steiner point p next to unsplittable segment u-w spoil it? True
 * when p lies in the segment's diametral lens (the triangle (u, w, p)
 * would have an angle above 180 - 2 * bound at p), or when that triangle
 * would have an angle below the bound at u or w while p is closer to an
 * endpoint than the segment is long. A point outside this region makes a
 * triangle with the segment whose shortest edge is the segment or whose
 * angles are good, so no cascade of ever closer points can start there. */
static int spoils(const refiner *r, const double *u, const double *w, const double *p)
{
    double ux = u[0] - p[0], uy = u[1] - p[1], wx = w[0] - p[0], wy = w[1] - p[1];
    double sx = w[0] - u[0], sy = w[1] - u[1];
    double sc = fmax(max_abs4(ux, uy, wx, wy), fmax(fabs(sx), fabs(sy)));
    if (sc == 0) return 1;
    double f = unit_scale(sc);
    ux *= f, uy *= f, wx *= f, wy *= f, sx *= f, sy *= f;
    double lu = sqrt(ux * ux + uy * uy), lw = sqrt(wx * wx + wy * wy), ls = sqrt(sx * sx + sy * sy);
    if (!(lu > 0 && lw > 0 && ls > 0)) return 1;
    if (ux * wx + uy * wy < -r->cos2 * lu * lw) /* angle at p */
        return 1;
    if (lu >= ls && lw >= ls) return 0;
    if (-(ux * sx + uy * sy) > r->cos1 * lu * ls) /* angle at u */
        return 1;
    if (wx * sx + wy * sy > r->cos1 * lw * ls) /* angle at w */
        return 1;
    return 0;
}

/* 0 good, 1 bad angle, 2 too big. *k gets the corner of the smallest
 * angle; *f the exact power-of-two scale used (edge vectors times *f are
 * below 1 in every coordinate). */
static int badness(const refiner *r, int t, int *kmin, double *fscale)
{
    const cdt_mesh *m = r->m;
    const int *v = m->V + 3 * t;
    const double *p0 = m->xy + 2 * v[0], *p1 = m->xy + 2 * v[1], *p2 = m->xy + 2 * v[2];
    double e[3][2] = {{p2[0] - p1[0], p2[1] - p1[1]},
                      {p0[0] - p2[0], p0[1] - p2[1]},
                      {p1[0] - p0[0], p1[1] - p0[1]}};
    double sc =
        fmax(max_abs4(e[0][0], e[0][1], e[1][0], e[1][1]), fmax(fabs(e[2][0]), fabs(e[2][1])));
    *kmin = 0;
    if (fscale) *fscale = sc > 0 ? unit_scale(sc) : 1.0;
    if (!(sc > 0)) return 0;
    double f = unit_scale(sc), l[3];
    for (int i = 0; i < 3; i++) {
        e[i][0] *= f;
        e[i][1] *= f;
        l[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1];
    }
    double a2 = e[2][0] * (-e[1][1]) - e[2][1] * (-e[1][0]); /* (p1-p0) x (p2-p0), scaled */
    int k = 0;
    if (l[1] < l[k]) k = 1;
    if (l[2] < l[k]) k = 2;
    *kmin = k;
    if (r->prm->max_area > 0 && 0.5 * a2 / f / f > r->prm->max_area) return 2;
    if (r->sin2 <= 0) return 0;
    double ln = l[(k + 1) % 3], lp = l[(k + 2) % 3];
    if (!(a2 * a2 < r->sin2 * ln * lp)) return 0;
    /* smallest angle between two segments: an input angle, leave it */
    if (m->S[3 * t + (k + 1) % 3] >= 0 && m->S[3 * t + (k + 2) % 3] >= 0) return 0;
    return 1;
}

static int push_tri(refiner *r, int t, int tries)
{
    int k;
    if (r->m->reg[t] != CDT_REG_DOMAIN || !badness(r, t, &k, NULL)) return 0;
    const int *v = r->m->V + 3 * t;
    int item[5] = {t, v[0], v[1], v[2], tries};
    return rq_push(&r->triq, item);
}

/* Queue the subsegment facing corner c when it is splittable and (forced
 * or) an apex of an adjacent domain triangle encroaches it. */
static int check_seg(refiner *r, int c, int forced)
{
    cdt_mesh *m = r->m;
    if (!seg_splittable(r, m->S[c])) return 0;
    int u = m->V[cdt_next(c)], w = m->V[cdt_prev(c)];
    int enc = forced;
    if (!enc && m->reg[c / 3] == CDT_REG_DOMAIN)
        enc = encroaches(m->xy + 2 * u, m->xy + 2 * w, m->xy + 2 * m->V[c]);
    int n = m->N[c];
    if (!enc && n >= 0 && m->reg[n / 3] == CDT_REG_DOMAIN)
        enc = encroaches(m->xy + 2 * u, m->xy + 2 * w, m->xy + 2 * m->V[n]);
    if (!enc) return 0;
    int item[3] = {u, w, forced};
    return rq_push(&r->segq, item);
}

static void freeze(cdt_mesh *m, int c)
{
    m->S[c] |= 1;
    if (m->N[c] >= 0) m->S[m->N[c]] |= 1;
}

/* After a commit: queue new bad triangles and encroached subsegments. */
static int after_insert(refiner *r)
{
    cdt_mesh *m = r->m;
    int k = m->ncav;
    r->st->nsteiner++;
    for (int j = 0; j < k + 2; j++) {
        int t = j < k ? m->cav[j] : m->nt - 2 + (j - k);
        if (push_tri(r, t, 0)) return -1;
        for (int i = 0; i < 3; i++) {
            int c = 3 * t + i;
            if (m->S[c] >= 0 && check_seg(r, c, 0)) return -1;
        }
    }
    return 0;
}

/* Make p lie exactly on the open segment a-b, moving it by at most one ulp
 * per coordinate (axis-aligned segments need no move). 0 if impossible. */
static int on_segment_exactly(const double *a, const double *b, double *p)
{
    double x0 = p[0], y0 = p[1];
    for (int dx = 0; dx < 3; dx++)
        for (int dy = 0; dy < 3; dy++) {
            double q[2] = {dx == 0 ? x0 : nextafter(x0, dx == 1 ? INFINITY : -INFINITY),
                           dy == 0 ? y0 : nextafter(y0, dy == 1 ? INFINITY : -INFINITY)};
            if (orient2d(a, b, q) != 0) continue;
            if ((q[0] == a[0] && q[1] == a[1]) || (q[0] == b[0] && q[1] == b[1])) continue;
            if (q[0] < fmin(a[0], b[0]) || q[0] > fmax(a[0], b[0]) || q[1] < fmin(a[1], b[1]) ||
                q[1] > fmax(a[1], b[1]))
                continue;
            p[0] = q[0];
            p[1] = q[1];
            return 1;
        }
    return 0;
}

static int split_segment(refiner *r, int a, int b, int forced)
{
    cdt_mesh *m = r->m;
    int c = cdt_mesh_find_edge(m, a, b);
    if (c < 0) c = cdt_mesh_find_edge(m, b, a);
    if (c < 0 || !seg_splittable(r, m->S[c])) return 0;
    if (!forced) { /* still encroached? */
        int u = m->V[cdt_next(c)], w = m->V[cdt_prev(c)], n = m->N[c], enc = 0;
        if (m->reg[c / 3] == CDT_REG_DOMAIN)
            enc = encroaches(m->xy + 2 * u, m->xy + 2 * w, m->xy + 2 * m->V[c]);
        if (!enc && n >= 0 && m->reg[n / 3] == CDT_REG_DOMAIN)
            enc = encroaches(m->xy + 2 * u, m->xy + 2 * w, m->xy + 2 * m->V[n]);
        if (!enc) return 0;
    }
    if (m->N[c] < 0) {
        freeze(m, c);
        return 0;
    }
    /* split point: concentric shells around an input endpoint */
    int v0 = a, v1 = b;
    if (a >= r->prm->ninput && b < r->prm->ninput) {
        v0 = b;
        v1 = a;
    }
    const double *p0 = m->xy + 2 * v0, *p1 = m->xy + 2 * v1;
    double len = hypot(p1[0] - p0[0], p1[1] - p0[1]), f = 0.5;
    if ((v0 < r->prm->ninput) != (v1 < r->prm->ninput) && len > 0) {
        double d = exp2(round(log2(0.5 * len)));
        f = d / len;
    }
    double p[2] = {p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1])};
    if (!on_segment_exactly(p0, p1, p)) {
        freeze(m, c);
        r->st->nrejected++;
        return 0;
    }
    int ok = cdt_mesh_cavity(m, p, c / 3, m->N[c] / 3);
    if (ok < 0) return -1;
    if (ok == 1) { /* no Steiner point inside an unsplittable segment's diametral circle */
        for (int j = 0; j < m->nbnd; j++) {
            int e = m->bnd[j];
            if (m->S[e] >= 0 && !seg_splittable(r, m->S[e]) &&
                spoils(r, m->xy + 2 * m->V[cdt_next(e)], m->xy + 2 * m->V[cdt_prev(e)], p)) {
                ok = 0;
                break;
            }
        }
    }
    if (ok != 1) {
        freeze(m, c);
        r->st->nrejected++;
        return 0;
    }
    int code = m->S[c];
    int v = cdt_mesh_add_vertex(m, p[0], p[1]);
    if (v < 0 || cdt_mesh_commit(m, v, code, a, b) < 0) return -1;
    return after_insert(r);
}

/* Insert Steiner point p for bad triangle t if allowed. Returns 0 when
 * inserted, 2 when refused, 3 when splittable segments were queued
 * instead, -1 when memory ran out. */
static int try_point(refiner *r, int t, const double p[2])
{
    cdt_mesh *m = r->m;
    if (!isfinite(p[0]) || !isfinite(p[1])) return 2;
    int blocker, lt = cdt_mesh_walk_constrained(m, t, p, &blocker);
    if (lt < 0) {
        if (blocker >= 0 && seg_splittable(r, m->S[blocker])) {
            int it[3] = {m->V[cdt_next(blocker)], m->V[cdt_prev(blocker)], 1};
            return rq_push(&r->segq, it) ? -1 : 3;
        }
        return 2;
    }
    for (int i = 0; i < 3; i++) {
        const double *q = m->xy + 2 * m->V[3 * lt + i];
        if (q[0] == p[0] && q[1] == p[1]) return 2;
    }
    int ok = cdt_mesh_cavity(m, p, lt, -1);
    if (ok <= 0) return ok < 0 ? -1 : 2;
    int retry = 0, refuse = 0;
    for (int j = 0; j < m->nbnd; j++) {
        int e = m->bnd[j];
        if (m->S[e] < 0) continue;
        const double *eu = m->xy + 2 * m->V[cdt_next(e)], *ew = m->xy + 2 * m->V[cdt_prev(e)];
        if (seg_splittable(r, m->S[e])) {
            if (!encroaches(eu, ew, p)) continue;
            int it[3] = {m->V[cdt_next(e)], m->V[cdt_prev(e)], 1};
            if (rq_push(&r->segq, it)) return -1;
            retry = 1;
        } else if (spoils(r, eu, ew, p)) {
            refuse = 1;
        }
    }
    if (retry) return 3;
    if (refuse) return 2;
    int nv = cdt_mesh_add_vertex(m, p[0], p[1]);
    if (nv < 0 || cdt_mesh_commit(m, nv, -1, -1, -1) < 0) return -1;
    return after_insert(r) ? -1 : 0;
}

static int refine_triangle(refiner *r, const int *item)
{
    cdt_mesh *m = r->m;
    int t = item[0];
    const int *v = m->V + 3 * t;
    if (v[0] != item[1] || v[1] != item[2] || v[2] != item[3] || m->reg[t] != CDT_REG_DOMAIN)
        return 0;
    int k;
    double f;
    int bad = badness(r, t, &k, &f);
    if (!bad) return 0;
    /* circumcenter and off-center in coordinates relative to pp, scaled by f */
    const double *pp = m->xy + 2 * v[(k + 1) % 3], *pq = m->xy + 2 * v[(k + 2) % 3];
    const double *pr = m->xy + 2 * v[k];
    double bx = (pq[0] - pp[0]) * f, by = (pq[1] - pp[1]) * f;
    double cx = (pr[0] - pp[0]) * f, cy = (pr[1] - pp[1]) * f;
    double den = 2.0 * (bx * cy - by * cx);
    if (!(den > 0)) {
        r->st->nrejected++;
        return 0;
    }
    double bb = bx * bx + by * by, cc = cx * cx + cy * cy;
    double ux = (cy * bb - by * cc) / den, uy = (bx * cc - cx * bb) / den;
    double mx = 0.5 * bx, my = 0.5 * by;
    if (bad == 1) {
        double dist = hypot(ux - mx, uy - my), h = r->offh * sqrt(bb);
        if (dist > h) { /* the off-center: a triangle just meeting the bound on pp-pq */
            ux = mx + (ux - mx) * (h / dist);
            uy = my + (uy - my) * (h / dist);
        }
    }
    /* second choice when the first is refused next to an unsplittable
       segment: the centroid (area), or a point half as far from the
       shortest edge (angle: still a good triangle on that edge) */
    double vx = bad == 2 ? (bx + cx) / 3.0 : mx + 0.5 * (ux - mx);
    double vy = bad == 2 ? (by + cy) / 3.0 : my + 0.5 * (uy - my);
    double p[2] = {pp[0] + ux / f, pp[1] + uy / f};
    double p2[2] = {pp[0] + vx / f, pp[1] + vy / f};
    int verdict = try_point(r, t, p);
    if (verdict == 2) verdict = try_point(r, t, p2);
    if (verdict < 0) return -1;
    if (verdict == 0) return 0;
    if (verdict == 3 && item[4] < 3) { /* splittable segments queued first */
        int again[5] = {item[0], item[1], item[2], item[3], item[4] + 1};
        return rq_push(&r->triq, again);
    }
    r->st->nrejected++;
    return 0;
}

int cdt_refine(cdt_mesh *m, const cdt_refine_params *prm, cdt_refine_stats *st)
{
    refiner r;
    r.m = m;
    r.prm = prm;
    r.st = st;
    double th = prm->min_angle_deg * (3.14159265358979323846 / 180.0);
    r.sin2 = prm->min_angle_deg > 0 ? sin(th) * sin(th) : 0.0;
    /* isosceles triangle on the shortest edge with apex angle a bit above the bound */
    r.offh = prm->min_angle_deg > 0 ? 0.5 / tan(0.5 * th) * 0.98 : 0.0;
    double lens = prm->min_angle_deg > 0 ? th : 20.0 * (3.14159265358979323846 / 180.0);
    r.cos1 = cos(lens);
    r.cos2 = cos(2 * lens);
    r.segq = (rq){NULL, 0, 0, 0, 3};
    r.triq = (rq){NULL, 0, 0, 0, 5};
    int rc = 0;
    for (int t = 0; t < m->nt && !rc; t++) {
        if (m->reg[t] != CDT_REG_DOMAIN) continue;
        for (int i = 0; i < 3 && !rc; i++)
            if (m->S[3 * t + i] >= 0) rc = check_seg(&r, 3 * t + i, 0);
        if (!rc) rc = push_tri(&r, t, 0);
    }
    while (!rc) {
        if (st->nsteiner >= prm->max_steiner) {
            if (r.segq.head < r.segq.n || r.triq.head < r.triq.n) st->capped = 1;
            break;
        }
        if (r.segq.head < r.segq.n) {
            int *it = r.segq.v + r.segq.head * 3;
            int a = it[0], b = it[1], f = it[2];
            r.segq.head++;
            rc = split_segment(&r, a, b, f);
        } else if (r.triq.head < r.triq.n) {
            int it[5];
            for (int i = 0; i < 5; i++) it[i] = r.triq.v[r.triq.head * 5 + i];
            r.triq.head++;
            rc = refine_triangle(&r, it);
        } else {
            break;
        }
    }
    free(r.segq.v);
    free(r.triq.v);
    return rc;
}
