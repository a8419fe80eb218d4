/* scaffold/tet_ops: edge removal, 2-3 flips, smoothing, contraction and
 * edge splits on a tet_scaffold (see the header). Each operation proposes
 * new tets in floating point (quality), then confirms every one of them
 * with the exact orientation test before tet_scaffold_replace applies it:
 * new tets that are all positive and share the cavity's boundary tile the
 * cavity exactly, so the mesh stays a valid triangulation of the same
 * region. */
#include "scaffold/tet_ops.h"

#include <limits.h>
#include <math.h>
#include <string.h>

#include "geom/tet_orient.h"
#include "geom/tet_quality.h"

#define MAX_RING 12   /* longest edge ring removed or split */
#define MAX_STAR 64   /* most tets around a vertex moved or removed */
#define MIN_GAIN 1e-9 /* an operation must raise the worst quality by this */

#define PT(s, v) ((s)->P + 3 * (size_t)(v))

int tet_ops_exhausted(const tet_ops *c)
{
    return c->status != SCAF_OK || (c->max_tries > 0 && c->st->tries >= c->max_tries);
}

static double quality4(const tet_scaffold *s, const int *q)
{
    return tet_quality(PT(s, q[0]), PT(s, q[1]), PT(s, q[2]), PT(s, q[3]));
}

static int positive4(const tet_scaffold *s, const int *q)
{
    return tet_orientation(PT(s, q[0]), PT(s, q[1]), PT(s, q[2]), PT(s, q[3])) > 0;
}

static int all_positive(const tet_scaffold *s, const int *tets, int n)
{
    for (int i = 0; i < n; i++)
        if (!positive4(s, tets + 4 * i)) return 0;
    return 1;
}

static double min_quality(const tet_scaffold *s, const int *tets, int n)
{
    double m = INFINITY;
    for (int i = 0; i < n; i++) {
        double q = quality4(s, tets + 4 * i);
        if (q < m) m = q;
    }
    return m;
}

/* The worst quality of the tets when it is above `bound`, else -inf as
 * soon as one tet is at or below it (tet `first` looked at first: the
 * likeliest to fail). */
static double min_quality_above(const tet_scaffold *s, const int *tets, int n, int first,
                                double bound)
{
    double m = quality4(s, tets + 4 * first);
    if (!(m > bound)) return -INFINITY;
    for (int i = 0; i < n; i++) {
        if (i == first) continue;
        double q = quality4(s, tets + 4 * i);
        if (!(q > bound)) return -INFINITY;
        if (q < m) m = q;
    }
    return m;
}

static int local_index(const int *q, int v)
{
    for (int k = 0; k < 4; k++)
        if (q[k] == v) return k;
    return -1;
}

/* The corners k, l completing (i, j) so that (i, j, k, l) is an even
 * permutation: then tet (q[i], q[j], q[k], q[l]) has q's orientation. */
static void complete_even(int i, int j, int *k, int *l)
{
    int r[2], n = 0;
    for (int x = 0; x < 4; x++)
        if (x != i && x != j) r[n++] = x;
    int p[4] = {i, j, r[0], r[1]}, inv = 0;
    for (int a = 0; a < 4; a++)
        for (int b = a + 1; b < 4; b++) inv += p[a] > p[b];
    if (inv & 1) *k = r[1], *l = r[0];
    else *k = r[0], *l = r[1];
}

/* Replace, then refresh the quality cache of the new tets. */
static int apply(tet_ops *c, int nold, const int *old, int nnew, const int *newT)
{
    int ids[MAX_STAR];
    scaf_status st = tet_scaffold_reserve(c->s, nnew, 0, c->err);
    if (st == SCAF_OK) st = tet_scaffold_replace(c->s, nold, old, nnew, newT, ids, c->err);
    if (st) {
        c->status = st;
        return 0;
    }
    for (int i = 0; i < nnew; i++) c->s->q[ids[i]] = quality4(c->s, newT + 4 * i);
    return 1;
}

/* ---- edge rings ---- */

/* The tets around the edge (a, b) between corners i and j of tet t, in
 * order: ring[k] = (a, b, w[k], w[k + 1 mod m]) positively oriented. 0 when
 * the edge is on the hull, on a protected face, between regions, or its
 * ring has more than MAX_RING tets. */
static int edge_ring(const tet_scaffold *s, int t, int i, int j, int *pa, int *pb, int *ring,
                     int *w)
{
    int a = s->T[4 * t + i], b = s->T[4 * t + j], cur = t, m = 0;
    *pa = a, *pb = b;
    for (;;) {
        const int *q = s->T + 4 * cur;
        int k, l;
        complete_even(local_index(q, a), local_index(q, b), &k, &l);
        if (m == MAX_RING || (m > 0 && q[k] != w[m])) return 0;
        if ((s->protect[cur] >> k) & 1) return 0;
        ring[m] = cur, w[m] = q[k];
        if (m + 1 < MAX_RING) w[m + 1] = q[l];
        m++;
        int n = s->nbr[4 * cur + k]; /* across the face (a, b, q[l]) */
        if (n < 0) return 0;
        cur = n / 4;
        if (s->region[cur] != s->region[t]) return 0;
        if (cur == t) return q[l] == w[0] ? m : 0;
    }
}

int tet_ops_edge_removal(tet_ops *c, int t, int i, int j)
{
    tet_scaffold *s = c->s;
    int a, b, ring[MAX_RING], w[MAX_RING];
    int m = edge_ring(s, t, i, j, &a, &b, ring, w);
    if (m < 3) return 0;
    c->st->tries++;
    double old_min = INFINITY;
    for (int k = 0; k < m; k++)
        if (s->q[ring[k]] < old_min) old_min = s->q[ring[k]];
    /* best triangulation of the ring polygon w[0..m-1], each triangle
     * coned to b and to a, maximizing the worst tet (dynamic programming
     * over polygon intervals) */
    double best[MAX_RING][MAX_RING];
    int choice[MAX_RING][MAX_RING];
    for (int len = 2; len < m; len++)
        for (int i0 = 0; i0 + len < m; i0++) {
            int k0 = i0 + len;
            best[i0][k0] = -INFINITY;
            for (int j0 = i0 + 1; j0 < k0; j0++) {
                double q1 = tet_quality(PT(s, w[i0]), PT(s, w[j0]), PT(s, w[k0]), PT(s, b));
                double q2 = tet_quality(PT(s, w[i0]), PT(s, w[k0]), PT(s, w[j0]), PT(s, a));
                double v = q1 < q2 ? q1 : q2;
                if (j0 - i0 >= 2 && best[i0][j0] < v) v = best[i0][j0];
                if (k0 - j0 >= 2 && best[j0][k0] < v) v = best[j0][k0];
                if (v > best[i0][k0]) best[i0][k0] = v, choice[i0][k0] = j0;
            }
        }
    if (!(best[0][m - 1] > old_min + MIN_GAIN)) return 0;
    int newT[4 * 2 * (MAX_RING - 2)], nnew = 0;
    int stack[2 * MAX_RING], top = 0;
    stack[top++] = 0, stack[top++] = m - 1;
    while (top > 0) {
        int k0 = stack[--top], i0 = stack[--top];
        if (k0 - i0 < 2) continue;
        int j0 = choice[i0][k0];
        int t1[4] = {w[i0], w[j0], w[k0], b}, t2[4] = {w[i0], w[k0], w[j0], a};
        memcpy(newT + 4 * nnew++, t1, sizeof t1);
        memcpy(newT + 4 * nnew++, t2, sizeof t2);
        stack[top++] = i0, stack[top++] = j0;
        stack[top++] = j0, stack[top++] = k0;
    }
    if (!all_positive(s, newT, nnew)) return 0;
    if (!apply(c, m, ring, nnew, newT)) return 0;
    if (m == 3) c->st->flip32++;
    else c->st->edge_removal++;
    return 1;
}

/* The tet u across face f of tet t and the two apexes (t's corner d off
 * the face, u's corner e), when the face may go: not on the hull, not
 * protected, between tets of one region. */
static int face_pair(const tet_scaffold *s, int t, int f, int *u, int *d, int *e)
{
    int n = s->nbr[4 * t + f];
    if (n < 0 || (s->protect[t] >> f) & 1 || s->region[n / 4] != s->region[t]) return 0;
    *u = n / 4, *d = s->T[4 * t + f], *e = s->T[n];
    return 1;
}

int tet_ops_flip23(tet_ops *c, int t, int f)
{
    tet_scaffold *s = c->s;
    int u, d, e, p[3];
    if (!face_pair(s, t, f, &u, &d, &e)) return 0;
    c->st->tries++;
    for (int k = 0; k < 3; k++) p[k] = s->T[4 * t + tet_face_corner[f][k]];
    /* p is seen from outside t, so (p0, p1, p2, e) is positive and the
     * three new tets turn around the edge d-e */
    int newT[12] = {d, e, p[0], p[1], d, e, p[1], p[2], d, e, p[2], p[0]};
    double old_min = s->q[t] < s->q[u] ? s->q[t] : s->q[u];
    if (!(min_quality(s, newT, 3) > old_min + MIN_GAIN)) return 0;
    if (!all_positive(s, newT, 3)) return 0;
    int old[2] = {t, u};
    if (!apply(c, 2, old, 3, newT)) return 0;
    c->st->flip23++;
    return 1;
}

/* ---- multi-face removal ---- */

#define MAX_SANDWICH 10 /* most faces removed at once */

/* The faces sandwiched between two apexes a and b: a triangulated polygon
 * w[0..m-1] (m = faces + 2), each of its faces g with the tets (g, a)
 * and (g, b); removing them leaves the m tets (a, b, w[i], w[i+1]) around
 * the new edge a-b. ta[i], tb[i]: the tets on the a and b sides of the
 * face holding the polygon edge (w[i], w[i+1]). */
typedef struct sandwich {
    int m, nold;
    int w[MAX_SANDWICH + 2], ta[MAX_SANDWICH + 2], tb[MAX_SANDWICH + 2];
    int old[2 * MAX_SANDWICH];
    double qold; /* worst of the old tets */
} sandwich;

/* The tet across the face of tet t made of u, v and apex (all corners of
 * t), when it is live, of the same region and the face is not protected;
 * its corner off that face goes to *x. -1 otherwise. */
static int across(const tet_scaffold *s, int t, int u, int v, int apex, int *x)
{
    const int *q = s->T + 4 * t;
    int f = 0;
    while (q[f] == u || q[f] == v || q[f] == apex) f++;
    int n = s->nbr[4 * t + f];
    if (n < 0 || (s->protect[t] >> f) & 1 || s->region[n / 4] != s->region[t]) return -1;
    *x = s->T[n]; /* the corner of the tet across, off the face */
    return n / 4;
}

/* Grow the sandwich of face f of tet t (a 2-3 flip's two tets) one face at
 * a time, across the polygon edge that leaves the best new tets, keeping
 * the best sandwich of two or more faces whose new tets beat its old
 * ones; apply it. */
int tet_ops_multi_face(tet_ops *c, int t, int f)
{
    tet_scaffold *s = c->s;
    int u, a, b;
    if (!face_pair(s, t, f, &u, &a, &b)) return 0;
    c->st->tries++;
    sandwich cur, best;
    cur.m = 3, cur.nold = 2, cur.old[0] = t, cur.old[1] = u;
    cur.qold = s->q[t] < s->q[u] ? s->q[t] : s->q[u];
    for (int k = 0; k < 3; k++)
        cur.w[k] = s->T[4 * t + tet_face_corner[f][k]], cur.ta[k] = t, cur.tb[k] = u;
    double best_q = -INFINITY;
    while (cur.nold < 2 * MAX_SANDWICH) {
        int pick = -1, pick_x = -1, pick_a = -1, pick_b = -1;
        double pick_q = -INFINITY;
        for (int i = 0; i < cur.m; i++) {
            int w0 = cur.w[i], w1 = cur.w[(i + 1) % cur.m], xa, xb;
            int na = across(s, cur.ta[i], w0, w1, a, &xa);
            int nb = na < 0 ? -1 : across(s, cur.tb[i], w0, w1, b, &xb);
            if (nb < 0 || xa != xb || xa == a || xa == b) continue;
            /* the sandwiched face (w0, w1, x), opposite a in na */
            if ((s->protect[na] >> local_index(s->T + 4 * na, a)) & 1) continue;
            int in_polygon = 0;
            for (int k = 0; k < cur.m; k++) in_polygon |= cur.w[k] == xa;
            if (in_polygon) continue;
            /* the new tets with (w0, w1) replaced by (w0, x), (x, w1) */
            int q1[4] = {a, b, w0, xa}, q2[4] = {a, b, xa, w1};
            double q = fmin(quality4(s, q1), quality4(s, q2));
            for (int k = 0; k < cur.m && q > pick_q; k++) {
                if (k == i) continue;
                int q3[4] = {a, b, cur.w[k], cur.w[(k + 1) % cur.m]};
                q = fmin(q, quality4(s, q3));
            }
            if (q > pick_q) pick_q = q, pick = i, pick_x = xa, pick_a = na, pick_b = nb;
        }
        if (pick < 0) break;
        /* insert x after w[pick] */
        for (int k = cur.m; k > pick + 1; k--)
            cur.w[k] = cur.w[k - 1], cur.ta[k] = cur.ta[k - 1], cur.tb[k] = cur.tb[k - 1];
        cur.w[pick + 1] = pick_x;
        cur.ta[pick] = cur.ta[pick + 1] = pick_a;
        cur.tb[pick] = cur.tb[pick + 1] = pick_b;
        cur.m++;
        cur.old[cur.nold++] = pick_a;
        cur.old[cur.nold++] = pick_b;
        cur.qold = fmin(cur.qold, fmin(s->q[pick_a], s->q[pick_b]));
        if (pick_q > cur.qold + MIN_GAIN && pick_q > best_q) best_q = pick_q, best = cur;
    }
    if (best_q == -INFINITY) return 0;
    int newT[4 * (MAX_SANDWICH + 2)];
    for (int i = 0; i < best.m; i++) {
        int q[4] = {a, b, best.w[i], best.w[(i + 1) % best.m]};
        memcpy(newT + 4 * i, q, sizeof q);
    }
    if (!all_positive(s, newT, best.m)) return 0;
    if (!apply(c, best.nold, best.old, best.m, newT)) return 0;
    c->st->multi_face++;
    return 1;
}

/* ---- vertex stars ---- */

/* The tets holding vertex v (at most MAX_STAR; -1 beyond), and whether v
 * may move or go: a free scaffold-only vertex off the hull, its tets of
 * one region, no protected face through it. */
static int movable_star(tet_scaffold *s, int v, int *star)
{
    if (v < s->nmesh || v >= s->nv || s->fixed[v] || s->vtet[v] < 0) return -1;
    if (s->mark_now == INT_MAX) {
        memset(s->mark, 0, sizeof(int) * (size_t)s->cap_t);
        s->mark_now = 0;
    }
    int stamp = ++s->mark_now, n = 0, t0 = s->vtet[v];
    star[n++] = t0;
    s->mark[t0] = stamp;
    for (int h = 0; h < n; h++) {
        int t = star[h], lv = local_index(s->T + 4 * t, v);
        if (s->region[t] != s->region[t0]) return -1;
        for (int f = 0; f < 4; f++) {
            if (f == lv) continue;
            int nb = s->nbr[4 * t + f];
            if (nb < 0 || (s->protect[t] >> f) & 1) return -1;
            int u = nb / 4;
            if (s->mark[u] == stamp) continue;
            if (n == MAX_STAR) return -1;
            s->mark[u] = stamp;
            star[n++] = u;
        }
    }
    return n;
}

/* Move P[v] to raise the worst quality of the n tets `tets` (4 n corners,
 * each holding v), starting from qmin, their worst now. Candidates: along
 * the gradient of the worst tet's quality and along the sum of the unit
 * gradients of the near-worst ones (steps up to where the worst's linear
 * model meets another's, then halved), and the centroid of the
 * neighbours. A move is kept only when every tet stays positive (exact).
 * Returns the new worst quality (qmin when nothing moved). */
static double smooth_point(tet_scaffold *s, int v, const int *tets, int n, double qmin)
{
    double *p = PT(s, v);
    for (int iter = 0; iter < 4; iter++) {
        double orig[3] = {p[0], p[1], p[2]}, g[MAX_STAR][3], q[MAX_STAR];
        double centroid[3] = {0, 0, 0}, len = 0;
        int worst = 0;
        for (int i = 0; i < n; i++) {
            const int *c = tets + 4 * i;
            int lv = local_index(c, v);
            /* even permutations bringing corner lv first */
            static const int rot[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
            const int *r = rot[lv];
            q[i] = tet_quality_grad(p, PT(s, c[r[1]]), PT(s, c[r[2]]), PT(s, c[r[3]]), g[i]);
            if (q[i] < q[worst]) worst = i;
            for (int k = 1; k < 4; k++) {
                const double *o = PT(s, c[r[k]]);
                double dx = o[0] - p[0], dy = o[1] - p[1], dz = o[2] - p[2];
                len += sqrt(dx * dx + dy * dy + dz * dz);
                for (int x = 0; x < 3; x++) centroid[x] += o[x];
            }
        }
        len /= 3.0 * n;
        for (int x = 0; x < 3; x++) centroid[x] /= 3.0 * n;
        double dirs[2][3] = {{g[worst][0], g[worst][1], g[worst][2]}, {0, 0, 0}};
        for (int i = 0; i < n; i++) {
            double gn = sqrt(g[i][0] * g[i][0] + g[i][1] * g[i][1] + g[i][2] * g[i][2]);
            if (q[i] <= q[worst] + 0.01 && gn > 0)
                for (int x = 0; x < 3; x++) dirs[1][x] += g[i][x] / gn;
        }
        double best = qmin, bestp[3] = {orig[0], orig[1], orig[2]};
        for (int d = 0; d < 2; d++) {
            double *dir = dirs[d];
            double nd = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
            if (!(nd > 0)) continue;
            for (int x = 0; x < 3; x++) dir[x] /= nd;
            double rate = g[worst][0] * dir[0] + g[worst][1] * dir[1] + g[worst][2] * dir[2];
            double step = 0.5 * len;
            for (int i = 0; i < n && rate > 0; i++) {
                double ri = g[i][0] * dir[0] + g[i][1] * dir[1] + g[i][2] * dir[2];
                if (i != worst && ri < rate && q[i] > q[worst]) {
                    double meet = (q[i] - q[worst]) / (rate - ri);
                    if (meet < step) step = meet;
                }
            }
            /* halve until better than the best so far, then stop */
            for (int k = 0; k < 8; k++, step *= 0.5) {
                for (int x = 0; x < 3; x++) p[x] = orig[x] + step * dir[x];
                double m = min_quality_above(s, tets, n, worst, best);
                if (m > best) {
                    best = m, memcpy(bestp, p, sizeof bestp);
                    break;
                }
            }
        }
        memcpy(p, centroid, sizeof centroid);
        double m = min_quality_above(s, tets, n, worst, best);
        if (m > best) best = m, memcpy(bestp, p, sizeof bestp);
        memcpy(p, bestp, sizeof bestp);
        if (!(best > qmin + MIN_GAIN) || !all_positive(s, tets, n)) {
            memcpy(p, orig, sizeof orig);
            break;
        }
        qmin = best;
    }
    return qmin;
}

int tet_ops_smooth(tet_ops *c, int v)
{
    tet_scaffold *s = c->s;
    int star[MAX_STAR], n = movable_star(s, v, star);
    if (n <= 0) return 0;
    c->st->tries++;
    int tets[4 * MAX_STAR];
    double old_min = INFINITY;
    for (int i = 0; i < n; i++) {
        memcpy(tets + 4 * i, s->T + 4 * star[i], 4 * sizeof(int));
        if (s->q[star[i]] < old_min) old_min = s->q[star[i]];
    }
    double now = smooth_point(s, v, tets, n, old_min);
    if (!(now > old_min)) return 0;
    for (int i = 0; i < n; i++) s->q[star[i]] = quality4(s, tets + 4 * i);
    c->st->smooth++;
    return 1;
}

int tet_ops_contract(tet_ops *c, int v)
{
    tet_scaffold *s = c->s;
    int star[MAX_STAR], n = movable_star(s, v, star);
    if (n <= 0) return 0;
    c->st->tries++;
    double old_min = INFINITY;
    for (int i = 0; i < n; i++)
        if (s->q[star[i]] < old_min) old_min = s->q[star[i]];
    int best_u = -1, newT[4 * MAX_STAR], nnew = 0;
    double best = old_min + MIN_GAIN;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 4; k++) {
            int u = s->T[4 * star[i] + k], seen = 0;
            for (int i2 = 0; i2 < i && !seen; i2++) seen = local_index(s->T + 4 * star[i2], u) >= 0;
            for (int k2 = 0; k2 < k && !seen; k2++) seen = s->T[4 * star[i] + k2] == u;
            if (u == v || seen) continue;
            /* the tets of the star without u, v replaced by u */
            double m = INFINITY;
            for (int j = 0; j < n && m > best; j++) {
                int q[4];
                memcpy(q, s->T + 4 * star[j], sizeof q);
                if (local_index(q, u) >= 0) continue;
                q[local_index(q, v)] = u;
                double qq = quality4(s, q);
                if (qq < m) m = qq;
            }
            if (m > best) best = m, best_u = u;
        }
    if (best_u < 0) return 0;
    for (int j = 0; j < n; j++) {
        int *q = newT + 4 * nnew;
        memcpy(q, s->T + 4 * star[j], 4 * sizeof(int));
        if (local_index(q, best_u) >= 0) continue;
        q[local_index(q, v)] = best_u;
        nnew++;
    }
    if (!all_positive(s, newT, nnew)) return 0;
    if (!apply(c, n, star, nnew, newT)) return 0;
    tet_scaffold_remove_vertex(s, v);
    c->st->contract++;
    return 1;
}

int tet_ops_split(tet_ops *c, int t, int i, int j)
{
    tet_scaffold *s = c->s;
    int a, b, ring[MAX_RING], w[MAX_RING];
    int m = edge_ring(s, t, i, j, &a, &b, ring, w);
    if (m < 3) return 0;
    c->st->tries++;
    if (tet_scaffold_reserve(s, 2 * m, 1, c->err)) {
        c->status = SCAF_ERR_NOMEM;
        return 0;
    }
    double old_min = INFINITY, mid[3];
    for (int k = 0; k < m; k++)
        if (s->q[ring[k]] < old_min) old_min = s->q[ring[k]];
    for (int x = 0; x < 3; x++) mid[x] = 0.5 * (PT(s, a)[x] + PT(s, b)[x]);
    int v = tet_scaffold_add_vertex(s, mid);
    int newT[4 * 2 * MAX_RING];
    for (int k = 0; k < m; k++) {
        int w0 = w[k], w1 = w[(k + 1) % m];
        int t1[4] = {a, v, w0, w1}, t2[4] = {v, b, w0, w1};
        memcpy(newT + 8 * k, t1, sizeof t1);
        memcpy(newT + 8 * k + 4, t2, sizeof t2);
    }
    double now = -INFINITY;
    if (all_positive(s, newT, 2 * m))
        now = smooth_point(s, v, newT, 2 * m, min_quality(s, newT, 2 * m));
    if (!(now > old_min + MIN_GAIN) || !apply(c, m, ring, 2 * m, newT)) {
        s->nv--; /* the vertex was appended last: take it back */
        return 0;
    }
    c->st->split++;
    return 1;
}

int tet_ops_improve_tet(tet_ops *c, int t, unsigned ops)
{
    tet_scaffold *s = c->s;
    static const int edge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    if (ops & TET_OP_EDGE_REMOVAL)
        for (int e = 0; e < 6 && !tet_ops_exhausted(c); e++)
            if (tet_ops_edge_removal(c, t, edge[e][0], edge[e][1])) return 1;
    if (ops & TET_OP_FLIP23)
        for (int f = 0; f < 4 && !tet_ops_exhausted(c); f++)
            if (tet_ops_flip23(c, t, f)) return 1;
    if (ops & TET_OP_MULTI_FACE)
        for (int f = 0; f < 4 && !tet_ops_exhausted(c); f++)
            if (tet_ops_multi_face(c, t, f)) return 1;
    int corner[4];
    memcpy(corner, s->T + 4 * t, sizeof corner);
    if (ops & TET_OP_SMOOTH)
        for (int k = 0; k < 4 && !tet_ops_exhausted(c); k++)
            if (tet_ops_smooth(c, corner[k])) return 1;
    if (ops & TET_OP_CONTRACT)
        for (int k = 0; k < 4 && !tet_ops_exhausted(c); k++)
            if (tet_ops_contract(c, corner[k])) return 1;
    if (ops & TET_OP_SPLIT) {
        /* the edges longest first: a surface edge cannot be split, the
         * next may */
        double len[6];
        int order[6];
        for (int e = 0; e < 6; e++) {
            const double *p = PT(s, corner[edge[e][0]]), *q = PT(s, corner[edge[e][1]]);
            len[e] = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                (p[2] - q[2]) * (p[2] - q[2]);
            int k = e;
            for (; k > 0 && len[order[k - 1]] < len[e]; k--) order[k] = order[k - 1];
            order[k] = e;
        }
        for (int k = 0; k < 6 && !tet_ops_exhausted(c); k++)
            if (tet_ops_split(c, t, edge[order[k]][0], edge[order[k]][1])) return 1;
    }
    return 0;
}
