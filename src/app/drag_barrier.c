/* app/drag_barrier: the padding as a barrier term (see drag_barrier.h). */
#include "app/drag_barrier.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort_u64.h"
#include "geom/chart_gap.h"
#include "opt/proxy_block.h"

scaf_status drag_barrier_init(drag_barrier *b, const atlas *a, scaf_error *err)
{
    memset(b, 0, sizeof *b);
    b->at = a;
    b->on = 1;
    b->band = DRAG_BARRIER_BAND;
    b->weight = DRAG_BARRIER_WEIGHT;
    b->reach_ratio = DRAG_BARRIER_REACH;
    b->growth = DRAG_BARRIER_GROWTH;
    b->rejects_seen = a->padding_rejects; /* (the atlas's own run counted too) */
    b->walls_left = DRAG_BARRIER_WALL_STEPS;
    b->act.d = 2;
    unsigned char *is = calloc((size_t)(a->nw ? a->nw : 1), 1);
    b->bv = malloc(sizeof(int) * (size_t)(a->nw ? a->nw : 1));
    if (!is || !b->bv) {
        free(is);
        drag_barrier_free(b);
        return err_nomem(err, "padding barrier");
    }
    for (int s = 0; s < a->nseg; s++)
        for (int k = 0; k < 2; k++) is[a->seg[3 * s + k]] = 1;
    for (int v = 0; v < a->nw; v++)
        if (is[v]) b->bv[b->nbv++] = v;
    free(is);
    return SCAF_OK;
}

void drag_barrier_enable(drag_barrier *b, int on) { b->on = on; }

void drag_barrier_free(drag_barrier *b)
{
    free(b->pe);
    free(b->act.idx);
    free(b->act_of);
    free(b->bv);
    memset(b, 0, sizeof *b);
}

/* ---- the barrier's pieces --------------------------------------------------- */

/* Squared distance from p to the segment ab, and its gradient g (6: p, a,
 * b). The nearest point is a, b or interior; s is C1 across the cases. */
static double pe_dist2(const double *p, const double *a, const double *b, double g[6])
{
    double ex = b[0] - a[0], ey = b[1] - a[1], wx = p[0] - a[0], wy = p[1] - a[1];
    double l2 = ex * ex + ey * ey, we = wx * ex + wy * ey;
    memset(g, 0, 6 * sizeof *g);
    if (!(l2 > 0.0) || we <= 0.0) {
        g[0] = 2.0 * wx, g[1] = 2.0 * wy, g[2] = -2.0 * wx, g[3] = -2.0 * wy;
        return wx * wx + wy * wy;
    }
    if (we >= l2) {
        double vx = p[0] - b[0], vy = p[1] - b[1];
        g[0] = 2.0 * vx, g[1] = 2.0 * vy, g[4] = -2.0 * vx, g[5] = -2.0 * vy;
        return vx * vx + vy * vy;
    }
    double c = ex * wy - ey * wx, f = 2.0 * c / l2, h = c * c / (l2 * l2);
    g[0] = -f * ey;
    g[1] = f * ex;
    g[4] = f * wy - 2.0 * h * ex;
    g[5] = -f * wx - 2.0 * h * ey;
    g[2] = -g[0] - g[4];
    g[3] = -g[1] - g[5];
    return c * c / l2;
}

/* b(x) = -(x - 1)^2 ln x and its first two derivatives. */
static double barrier(double x, double *d1, double *d2)
{
    double lx = log(x), y = x - 1.0;
    if (d1) *d1 = -2.0 * y * lx - y * y / x;
    if (d2) *d2 = -2.0 * lx - 4.0 * y / x + y * y / (x * x);
    return -y * y * lx;
}

/* Candidate pair k at X: its barrier argument x, g = the gradient of x (6). */
static double pair_x(const drag_barrier *b, int k, const double *X, double g[6])
{
    const int *t = b->pe + 3 * (size_t)k;
    double s = pe_dist2(X + 2 * (size_t)t[0], X + 2 * (size_t)t[1], X + 2 * (size_t)t[2], g);
    for (int i = 0; i < 6; i++) g[i] /= b->zhat;
    return (s - b->p2) / b->zhat;
}

/* Wall (axis, hi) of vertex v at X: its barrier argument, *g its
 * derivative along the axis. */
static double wall_x(const drag_barrier *b, int v, int axis, int hi, const double *X, double *g)
{
    double x = X[2 * (size_t)v + axis];
    *g = (hi ? -1.0 : 1.0) / b->wall_width;
    return (hi ? b->wall_hi[axis] - x : x - b->wall_lo[axis]) / b->wall_width;
}

/* ---- ops -------------------------------------------------------------------- */

/* Energy, and with D its derivative along D (*slope); INFINITY outside. */
static double energy_along(const drag_barrier *b, const double *X, const double *D, double *slope)
{
    double e = 0.0, S = 0.0, g[6], d1;
    for (int k = 0; k < b->n; k++) {
        double x = pair_x(b, k, X, g);
        if (!(x > 0.0)) return INFINITY;
        if (!(x < 1.0)) continue;
        e += barrier(x, D ? &d1 : NULL, NULL);
        if (!D) continue;
        const int *v = b->pe + 3 * (size_t)k;
        for (int i = 0; i < 3; i++)
            S += d1 * (g[2 * i] * D[2 * (size_t)v[i]] + g[2 * i + 1] * D[2 * (size_t)v[i] + 1]);
    }
    for (int i = 0; b->walls && i < b->nbv; i++)
        for (int w = 0; w < 4; w++) {
            int v = b->bv[i], axis = w >> 1, hi = w & 1;
            double gw, x = wall_x(b, v, axis, hi, X, &gw);
            if (!(x > 0.0)) return INFINITY;
            if (!(x < 1.0)) continue;
            e += barrier(x, D ? &d1 : NULL, NULL);
            if (D) S += d1 * gw * D[2 * (size_t)v + axis];
        }
    if (slope) *slope = b->kappa * S;
    return b->kappa * e;
}

static double barrier_energy(const opt_obj_term *t, const double *X)
{
    return energy_along(t->self, X, NULL, NULL);
}

static void barrier_energy_slope(const opt_obj_term *t, const double *X, const double *D, double *e,
                                 double *slope)
{
    double s = 0.0, E = energy_along(t->self, X, D, &s);
    if (!isfinite(E)) {
        *e = INFINITY;
        return;
    }
    *e += E;
    *slope += s;
}

static scaf_status grow_active(drag_barrier *b, int need, scaf_error *err)
{
    if (need <= b->cap_act) return SCAF_OK;
    int cap = need + need / 2 + 16;
    int *q = realloc(b->act.idx, sizeof(int) * 3 * (size_t)cap);
    if (q) b->act.idx = q;
    int *r = q ? realloc(b->act_of, sizeof(int) * (size_t)cap) : NULL;
    if (!r) return err_nomem(err, "padding barrier");
    b->act_of = r;
    b->cap_act = cap;
    return SCAF_OK;
}

static void add_active(drag_barrier *b, int v0, int v1, int v2, int code)
{
    int *t = b->act.idx + 3 * (size_t)b->nact;
    t[0] = v0, t[1] = v1, t[2] = v2;
    b->act_of[b->nact++] = code;
}

/* The iteration's barrier at the loop's positions (banner): candidate
 * pairs, P, the walls, and the proxy's pairs and wall vertices. */
static scaf_status setup(drag_barrier *b, scaf_error *err)
{
    const atlas *a = b->at;
    const double *X = a->loop.uv;
    b->n = b->nact = 0;
    b->walls = 0;
    /* walls for the next DRAG_BARRIER_WALL_STEPS iterations once the
     * padding test rejected a step (banner) */
    if (a->padding_rejects != b->rejects_seen) b->walls_left = DRAG_BARRIER_WALL_STEPS;
    b->rejects_seen = a->padding_rejects;
    int walls = b->walls_left > 0;
    if (b->walls_left > 0) b->walls_left--;
    double need = atlas_padding_need(a, X);
    if (!b->on || !(need > 0.0)) return SCAF_OK;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < a->nw; v++)
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], X[2 * (size_t)v + c]);
            hi[c] = fmax(hi[c], X[2 * (size_t)v + c]);
        }
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    double reach = need * (1.0 + b->growth) * (1.0 + b->band) + b->reach_ratio * side;
    b->kappa = b->weight * a->loop.total_area / (a->nseg > 0 ? a->nseg : 1);
    /* candidates: vertex-segment pairs of different charts closer than
     * the reach, once each */
    int *sp = NULL;
    long nsp = 0;
    scaf_status st = chart_gap_close_pairs(X, a->seg, a->nseg, reach, &sp, &nsp, err);
    if (st != SCAF_OK) return st;
    /* (4 keys per pair, counted in an int) */
    uint64_t *key =
        nsp <= INT32_MAX / 4 ? malloc(sizeof(uint64_t) * 4 * (size_t)(nsp ? nsp : 1)) : NULL;
    if (!key) {
        free(sp);
        free(key);
        return err_nomem(err, "padding barrier pairs");
    }
    int nk = 0;
    uint64_t ns = (uint64_t)a->nseg;
    for (long i = 0; i < nsp; i++)
        for (int k = 0; k < 2; k++) {
            int s = sp[2 * i + k], o = sp[2 * i + 1 - k];
            if (a->seg[3 * o] == a->seg[3 * o + 1]) continue; /* a point chart's */
            for (int e = 0; e < 2; e++) key[nk++] = (uint64_t)a->seg[3 * s + e] * ns + (uint64_t)o;
        }
    free(sp);
    sort_u64(key, nk);
    int nu = 0;
    for (int i = 0; i < nk; i++)
        if (i == 0 || key[i] != key[i - 1]) key[nu++] = key[i];
    if (nu > b->cap) {
        int *q = realloc(b->pe, sizeof(int) * 3 * (size_t)nu);
        if (!q) {
            free(key);
            return err_nomem(err, "padding barrier pairs");
        }
        b->pe = q;
        b->cap = nu;
    }
    double gmin2 = INFINITY, g[6];
    for (int i = 0; i < nu; i++) {
        int v = (int)(key[i] / ns), o = (int)(key[i] % ns);
        int *t = b->pe + 3 * (size_t)b->n;
        t[0] = v, t[1] = a->seg[3 * o], t[2] = a->seg[3 * o + 1];
        double s = pe_dist2(X + 2 * (size_t)t[0], X + 2 * (size_t)t[1], X + 2 * (size_t)t[2], g);
        if (s >= reach * reach) continue;
        gmin2 = fmin(gmin2, s);
        b->n++;
    }
    free(key);
    /* the growth allowance, half the room the closest pair has */
    double gamma = fmin(b->growth, 0.5 * (sqrt(gmin2) / need - 1.0));
    if (!(gamma > 0.0)) { /* no room (rounding): the hook alone */
        b->n = 0;
        return SCAF_OK;
    }
    double P = need * (1.0 + gamma), dhat = P * (1.0 + b->band), S = side * (1.0 + gamma);
    b->p2 = P * P;
    b->zhat = dhat * dhat - b->p2;
    b->wall_width = dhat - P;
    for (int c = 0; c < 2; c++) {
        double slack = 0.5 * (S - (hi[c] - lo[c]));
        b->wall_lo[c] = lo[c] - slack;
        b->wall_hi[c] = hi[c] + slack;
    }
    b->walls = walls;
    /* the proxy's share: pairs closer than dhat, vertices near a wall */
    for (int k = 0; k < b->n; k++) {
        if (!(pair_x(b, k, X, g) < 1.0)) continue;
        st = grow_active(b, b->nact + 1, err);
        if (st != SCAF_OK) return st;
        const int *t = b->pe + 3 * (size_t)k;
        add_active(b, t[0], t[1], t[2], k);
    }
    for (int i = 0; b->walls && i < b->nbv; i++)
        for (int w = 0; w < 4; w++) {
            int v = b->bv[i];
            double gw;
            if (!(wall_x(b, v, w >> 1, w & 1, X, &gw) < 1.0)) continue;
            st = grow_active(b, b->nact + 1, err);
            if (st != SCAF_OK) return st;
            add_active(b, v, v, v, -1 - (4 * v + w));
        }
    return SCAF_OK;
}

static scaf_status barrier_pattern(opt_obj_term *t, const int *dof, int nfree, scaf_error *err)
{
    drag_barrier *b = t->self;
    scaf_status st = setup(b, err);
    if (st != SCAF_OK) return st;
    b->act.n = b->nact;
    return opt_proxy_block_pattern(&t->blk, &b->act, dof, nfree, err);
}

/* Active entry k's Gauss-Newton matrix (6 by 6, times scale) and gradient
 * (6, over its three corners) at X. */
static void model(const drag_barrier *b, int k, const double *X, double scale, double K[36],
                  double grad[6])
{
    double g[6] = {0, 0, 0, 0, 0, 0}, x, d1, d2;
    int c = b->act_of[k];
    if (c >= 0) {
        x = pair_x(b, c, X, g);
    } else {
        int code = -1 - c, axis = (code & 3) >> 1;
        x = wall_x(b, code >> 2, axis, code & 1, X, &g[axis]);
    }
    barrier(x, &d1, &d2);
    double h = scale * b->kappa * d2, f = b->kappa * d1;
    for (int i = 0; i < 6; i++) {
        grad[i] = f * g[i];
        for (int j = 0; j < 6; j++) K[6 * i + j] = h * g[i] * g[j];
    }
}

/* SLIM's convention: half the model's Hessian, and half of H X - grad on
 * the right-hand side (the model's minimizer is the target). Newton: the
 * Hessian and -grad. */
static void fill_model(opt_obj_term *t, const int *dof, const double *X, int newton, double *rhs)
{
    const drag_barrier *b = t->self;
    if (t->blk.A.nnz > 0) memset(t->blk.A.val, 0, sizeof(double) * (size_t)t->blk.A.nnz);
    double K[36], grad[6];
    for (int k = 0; k < b->nact; k++) {
        model(b, k, X, newton ? 1.0 : 0.5, K, grad);
        opt_proxy_block_add_local(&t->blk, &b->act, k, dof, K);
        const int *v = b->act.idx + 3 * (size_t)k;
        for (int i = 0; i < 6; i++) {
            int r = dof[v[i / 2]];
            if (r < 0) continue;
            double add = -grad[i];
            if (!newton) {
                add *= 0.5;
                for (int j = 0; j < 6; j++) add += K[6 * i + j] * X[2 * (size_t)v[j / 2] + j % 2];
            }
            rhs[2 * (size_t)r + i % 2] += add;
        }
    }
}

static void barrier_fill(opt_obj_term *t, const int *dof, const double *X, double *rhs)
{
    fill_model(t, dof, X, 0, rhs);
}

static scaf_status barrier_hessian_fill(opt_obj_term *t, const int *dof, const double *X,
                                        int project, double *rhs, scaf_error *err)
{
    (void)project; /* the Gauss-Newton matrix is positive semi-definite */
    (void)err;
    fill_model(t, dof, X, 1, rhs);
    return SCAF_OK;
}

static const opt_obj_term_ops barrier_ops = {
    barrier_energy, barrier_energy_slope, barrier_pattern, barrier_fill, NULL,
    NULL,           barrier_hessian_fill};

opt_obj_term drag_barrier_make(drag_barrier *b)
{
    opt_obj_term t;
    memset(&t, 0, sizeof t);
    t.ops = &barrier_ops;
    t.self = b;
    return t;
}
