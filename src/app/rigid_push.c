/* app/rigid_push: translate charts out of the way (see rigid_push.h). */
#include "app/rigid_push.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

scaf_status rigid_charts_init(rigid_charts *rc, const int *wchart, int nw, int ncharts,
                              const int *seg, int nseg, scaf_error *err)
{
    memset(rc, 0, sizeof *rc);
    rc->ncharts = ncharts;
    rc->nw = nw;
    rc->seg = seg;
    rc->nseg = nseg;
    rc->vstart = calloc((size_t)ncharts + 1, sizeof(int));
    rc->sstart = calloc((size_t)ncharts + 1, sizeof(int));
    rc->verts = malloc(sizeof(int) * (size_t)(nw ? nw : 1));
    rc->segs = malloc(sizeof(int) * (size_t)(nseg ? nseg : 1));
    if (!rc->vstart || !rc->sstart || !rc->verts || !rc->segs) {
        rigid_charts_free(rc);
        return err_nomem(err, "rigid motion charts");
    }
    /* counting sorts: chart by chart, in increasing order */
    for (int v = 0; v < nw; v++) rc->vstart[wchart[v] + 1]++;
    for (int s = 0; s < nseg; s++) rc->sstart[seg[3 * s + 2] + 1]++;
    for (int c = 0; c < ncharts; c++) {
        rc->vstart[c + 1] += rc->vstart[c];
        rc->sstart[c + 1] += rc->sstart[c];
    }
    int *vn = calloc((size_t)ncharts + 1, sizeof(int)),
        *sn = calloc((size_t)ncharts + 1, sizeof(int));
    if (!vn || !sn) {
        free(vn);
        free(sn);
        rigid_charts_free(rc);
        return err_nomem(err, "rigid motion charts");
    }
    for (int v = 0; v < nw; v++) rc->verts[rc->vstart[wchart[v]] + vn[wchart[v]]++] = v;
    for (int s = 0; s < nseg; s++) {
        int c = seg[3 * s + 2];
        rc->segs[rc->sstart[c] + sn[c]++] = s;
    }
    free(vn);
    free(sn);
    return SCAF_OK;
}

void rigid_charts_free(rigid_charts *rc)
{
    free(rc->vstart);
    free(rc->verts);
    free(rc->sstart);
    free(rc->segs);
    memset(rc, 0, sizeof *rc);
}

/* ---- where a moving point is near a segment ------------------------------- */

/* Open interval of s where c0 + s e (e unit) is closer than r to the
 * segment ab (the r-capsule around it): the hull of the two end disks
 * and the slab. 1 when not empty. */
static int point_capsule(const double c0[2], const double e[2], const double a[2],
                         const double b[2], double r, double *lo, double *hi)
{
    double l = INFINITY, h = -INFINITY;
    const double *ends[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        double w0 = c0[0] - ends[k][0], w1 = c0[1] - ends[k][1];
        double we = w0 * e[0] + w1 * e[1], disc = we * we - (w0 * w0 + w1 * w1 - r * r);
        if (disc > 0.0) {
            double q = sqrt(disc);
            l = fmin(l, -we - q);
            h = fmax(h, -we + q);
        }
    }
    double d0 = b[0] - a[0], d1 = b[1] - a[1], len = sqrt(d0 * d0 + d1 * d1);
    if (len > 0.0) {
        double u0 = d0 / len, u1 = d1 / len, w0 = c0[0] - a[0], w1 = c0[1] - a[1];
        double t0 = w0 * u0 + w1 * u1, tv = e[0] * u0 + e[1] * u1;
        double h0 = -w0 * u1 + w1 * u0, hv = -e[0] * u1 + e[1] * u0;
        double sl = -INFINITY, sh = INFINITY;
        /* 0 < t0 + s tv < len and -r < h0 + s hv < r */
        const double base[2] = {t0, h0}, rate[2] = {tv, hv}, low[2] = {0.0, -r}, up[2] = {len, r};
        int empty = 0;
        for (int k = 0; k < 2 && !empty; k++) {
            if (rate[k] == 0.0) {
                empty = !(base[k] > low[k] && base[k] < up[k]);
                continue;
            }
            double s1 = (low[k] - base[k]) / rate[k], s2 = (up[k] - base[k]) / rate[k];
            sl = fmax(sl, fmin(s1, s2));
            sh = fmin(sh, fmax(s1, s2));
        }
        if (!empty && sl < sh) {
            l = fmin(l, sl);
            h = fmax(h, sh);
        }
    }
    *lo = l;
    *hi = h;
    return l < h;
}

/* Offsets s where segment pq moved by s e is closer than r to segment xy. */
static int segment_interval(const double *p, const double *q, const double *x, const double *y,
                            const double e[2], double r, double *lo, double *hi)
{
    const double me[2] = {-e[0], -e[1]};
    double l = INFINITY, h = -INFINITY, a, b;
    if (point_capsule(p, e, x, y, r, &a, &b)) l = fmin(l, a), h = fmax(h, b);
    if (point_capsule(q, e, x, y, r, &a, &b)) l = fmin(l, a), h = fmax(h, b);
    if (point_capsule(x, me, p, q, r, &a, &b)) l = fmin(l, a), h = fmax(h, b);
    if (point_capsule(y, me, p, q, r, &a, &b)) l = fmin(l, a), h = fmax(h, b);
    *lo = l;
    *hi = h;
    return l < h;
}

/* ---- one chart --------------------------------------------------------------- */

typedef struct pusher {
    const rigid_charts *rc;
    double *X;
    const unsigned char *placed;
    double *ivl; /* interval pairs, scratch */
    size_t nivl, cap;
} pusher;

/* Crossing number of p with chart c's boundary (shifted by -off): 1 inside. */
static int inside_chart(const pusher *P, int c, const double p[2], const double off[2])
{
    const rigid_charts *rc = P->rc;
    int in = 0;
    for (int i = rc->sstart[c]; i < rc->sstart[c + 1]; i++) {
        const int *s = rc->seg + 3 * rc->segs[i];
        double ax = P->X[2 * s[0]] + off[0], ay = P->X[2 * s[0] + 1] + off[1];
        double bx = P->X[2 * s[1]] + off[0], by = P->X[2 * s[1] + 1] + off[1];
        if ((ay > p[1]) != (by > p[1]) && p[0] < ax + (p[1] - ay) * (bx - ax) / (by - ay)) in = !in;
    }
    return in;
}

/* B moved by s e: inside a placed chart, or a placed chart inside it. */
static int nested(const pusher *P, int B, const double e[2], double s, const int *cand, int nc)
{
    const rigid_charts *rc = P->rc;
    const double zero[2] = {0.0, 0.0}, off[2] = {s * e[0], s * e[1]}, back[2] = {-off[0], -off[1]};
    int vb = rc->verts[rc->vstart[B]];
    double pb[2] = {P->X[2 * vb] + off[0], P->X[2 * vb + 1] + off[1]};
    for (int k = 0; k < nc; k++) {
        int c = cand[k], vc = rc->verts[rc->vstart[c]];
        double pc[2] = {P->X[2 * vc] + back[0], P->X[2 * vc + 1] + back[1]};
        if (inside_chart(P, c, pb, zero) || inside_chart(P, B, pc, zero)) return 1;
    }
    return 0;
}

static int by_low(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Smallest s >= 0 at which chart B moved by s e is >= r from every placed
 * chart and not nested with one; INFINITY out of memory. */
static double clear_along(pusher *P, int B, const double e[2], double r, int *cand)
{
    const rigid_charts *rc = P->rc;
    const double *X = P->X;
    double n[2] = {-e[1], e[0]};
    double bn0 = INFINITY, bn1 = -INFINITY, be0 = INFINITY;
    for (int i = rc->vstart[B]; i < rc->vstart[B + 1]; i++) {
        const double *p = X + 2 * rc->verts[i];
        double pn = p[0] * n[0] + p[1] * n[1], pe = p[0] * e[0] + p[1] * e[1];
        bn0 = fmin(bn0, pn), bn1 = fmax(bn1, pn), be0 = fmin(be0, pe);
    }
    int nc = 0;
    P->nivl = 0;
    for (int c = 0; c < rc->ncharts; c++) {
        if (!P->placed[c] || c == B) continue;
        double xn0 = INFINITY, xn1 = -INFINITY, xe1 = -INFINITY;
        for (int i = rc->vstart[c]; i < rc->vstart[c + 1]; i++) {
            const double *q = X + 2 * rc->verts[i];
            double qn = q[0] * n[0] + q[1] * n[1], qe = q[0] * e[0] + q[1] * e[1];
            xn0 = fmin(xn0, qn), xn1 = fmax(xn1, qn), xe1 = fmax(xe1, qe);
        }
        if (xn1 < bn0 - r || xn0 > bn1 + r || xe1 < be0 - r) continue; /* never met */
        cand[nc++] = c;
        for (int i = rc->sstart[B]; i < rc->sstart[B + 1]; i++) {
            const int *sb = rc->seg + 3 * rc->segs[i];
            const double *p = X + 2 * sb[0], *q = X + 2 * sb[1];
            double pn = p[0] * n[0] + p[1] * n[1], qn = q[0] * n[0] + q[1] * n[1];
            double lo_n = fmin(pn, qn), hi_n = fmax(pn, qn);
            double lo_e = fmin(p[0] * e[0] + p[1] * e[1], q[0] * e[0] + q[1] * e[1]);
            for (int j = rc->sstart[c]; j < rc->sstart[c + 1]; j++) {
                const int *sx = rc->seg + 3 * rc->segs[j];
                const double *x = X + 2 * sx[0], *y = X + 2 * sx[1];
                double xn = x[0] * n[0] + x[1] * n[1], yn = y[0] * n[0] + y[1] * n[1];
                if (fmax(xn, yn) < lo_n - r || fmin(xn, yn) > hi_n + r) continue;
                if (fmax(x[0] * e[0] + x[1] * e[1], y[0] * e[0] + y[1] * e[1]) < lo_e - r) continue;
                double lo, hi;
                if (!segment_interval(p, q, x, y, e, r, &lo, &hi) || !(hi > 0.0)) continue;
                if (P->nivl == P->cap) {
                    size_t cap = P->cap ? 2 * P->cap : 1024;
                    double *t = realloc(P->ivl, sizeof(double) * 2 * cap);
                    if (!t) return INFINITY;
                    P->ivl = t;
                    P->cap = cap;
                }
                P->ivl[2 * P->nivl] = lo;
                P->ivl[2 * P->nivl + 1] = hi;
                P->nivl++;
            }
        }
    }
    if (P->nivl > 1) qsort(P->ivl, P->nivl, sizeof(double) * 2, by_low); /* NULL when empty */
    double cur = 0.0;
    size_t k = 0;
    for (;;) {
        /* cur is clear of intervals starting at or after it: the ones before
         * either end at or before cur or contain it */
        int blocked = 0;
        for (; k < P->nivl && P->ivl[2 * k] < cur; k++)
            if (P->ivl[2 * k + 1] > cur) cur = P->ivl[2 * k + 1], blocked = 1;
        if (blocked) continue;
        if (!nested(P, B, e, cur, cand, nc)) return cur;
        if (k == P->nivl) return cur; /* beyond every interval: outside all */
        cur = P->ivl[2 * k + 1];      /* nested: leave through the next wall */
        k++;
    }
}

/* ---- all charts -------------------------------------------------------------- */

typedef struct order_item {
    int late; /* 0: placed first (the selection's other charts) */
    double dist;
    int chart;
} order_item;

static int by_dist(const void *a, const void *b)
{
    const order_item *x = a, *y = b;
    if (x->late != y->late) return x->late - y->late;
    if (x->dist != y->dist) return (x->dist > y->dist) - (x->dist < y->dist);
    return x->chart - y->chart;
}

scaf_status rigid_push(const rigid_charts *rc, double *X, const unsigned char *fixed,
                       const unsigned char *early, const double from[2], const double dir[2],
                       double r, unsigned char *moved, scaf_error *err)
{
    int nc = rc->ncharts;
    unsigned char *placed = malloc((size_t)nc + 1);
    order_item *order = malloc(sizeof *order * ((size_t)nc + 1));
    int *cand = malloc(sizeof(int) * ((size_t)nc + 1));
    double *cen = malloc(sizeof(double) * 2 * ((size_t)nc + 1));
    pusher P = {rc, X, placed, NULL, 0, 0};
    scaf_status st = SCAF_OK;
    if (!placed || !order || !cand || !cen) {
        st = err_nomem(err, "rigid motion");
        goto done;
    }
    if (moved) memset(moved, 0, (size_t)nc);
    int no = 0;
    for (int c = 0; c < nc; c++) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int i = rc->vstart[c]; i < rc->vstart[c + 1]; i++)
            for (int k = 0; k < 2; k++) {
                lo[k] = fmin(lo[k], X[2 * rc->verts[i] + k]);
                hi[k] = fmax(hi[k], X[2 * rc->verts[i] + k]);
            }
        cen[2 * c] = 0.5 * (lo[0] + hi[0]);
        cen[2 * c + 1] = 0.5 * (lo[1] + hi[1]);
        placed[c] = fixed[c] != 0;
        if (!fixed[c] && rc->vstart[c + 1] > rc->vstart[c]) {
            /* distance from the selection to the nearest side of the box */
            double dx = fmax(0.0, fmax(lo[0] - from[0], from[0] - hi[0]));
            double dy = fmax(0.0, fmax(lo[1] - from[1], from[1] - hi[1]));
            order[no].dist =
                hypot(dx, dy) + 1e-9 * hypot(cen[2 * c] - from[0], cen[2 * c + 1] - from[1]);
            order[no].late = !(early && early[c]);
            order[no++].chart = c;
        }
    }
    if (no > 1) qsort(order, (size_t)no, sizeof *order, by_dist);
    double drag[2] = {0.0, 0.0};
    if (dir && hypot(dir[0], dir[1]) > 0.0) {
        double l = hypot(dir[0], dir[1]);
        drag[0] = dir[0] / l, drag[1] = dir[1] / l;
    }
    for (int k = 0; k < no; k++) {
        int B = order[k].chart;
        double cand_dir[10][2];
        int nd = 0;
        double ax = cen[2 * B] - from[0], ay = cen[2 * B + 1] - from[1], al = hypot(ax, ay);
        if (al > 0.0) cand_dir[nd][0] = ax / al, cand_dir[nd++][1] = ay / al;
        if (drag[0] != 0.0 || drag[1] != 0.0)
            cand_dir[nd][0] = drag[0], cand_dir[nd++][1] = drag[1];
        static const double h = 0.70710678118654752440; /* sqrt(1/2) */
        static const double compass[8][2] = {{1, 0},  {h, h},   {0, 1},  {-h, h},
                                             {-1, 0}, {-h, -h}, {0, -1}, {h, -h}};
        for (int j = 0; j < 8; j++)
            cand_dir[nd][0] = compass[j][0], cand_dir[nd++][1] = compass[j][1];
        double best = INFINITY;
        int bi = -1;
        for (int j = 0; j < nd && best > 0.0; j++) {
            double s = clear_along(&P, B, cand_dir[j], r, cand);
            if (s < best) best = s, bi = j;
        }
        if (bi < 0) {
            st = err_nomem(err, "rigid motion");
            goto done;
        }
        if (best > 0.0) {
            for (int i = rc->vstart[B]; i < rc->vstart[B + 1]; i++) {
                X[2 * rc->verts[i]] += best * cand_dir[bi][0];
                X[2 * rc->verts[i] + 1] += best * cand_dir[bi][1];
            }
            if (moved) moved[B] = 1;
        }
        placed[B] = 1;
    }
done:
    free(P.ivl);
    free(placed);
    free(order);
    free(cand);
    free(cen);
    return st;
}
