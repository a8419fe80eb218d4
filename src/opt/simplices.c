/* opt/simplices: a "simplex soup" with rest shapes — what the optimizer sees.
 *
 * The gradient operator of a rest simplex r_0..r_d is built from the inverse
 * of its edge matrix R = [r_1 - r_0, ..., r_d - r_0]: G[k] = row k-1 of
 * R^-1 for k >= 1 and G[0] = -sum of those rows, so that
 * J = [x_1 - x_0, ...] R^-1. Degenerate or non-finite rest shapes are
 * refused by the builders with the simplex index in the message.
 */
#include "opt/simplices.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

scaf_status opt_simplices_alloc(opt_simplices *s, int d, int n, scaf_error *err)
{
    memset(s, 0, sizeof *s);
    if ((d != 2 && d != 3) || n < 0)
        return err_set(err, SCAF_ERR_USAGE, "simplex set: dimension %d / count %d invalid", d, n);
    size_t nn = n > 0 ? (size_t)n : 1;
    s->idx = malloc(nn * (size_t)(d + 1) * sizeof *s->idx);
    s->grad = malloc(nn * (size_t)((d + 1) * d) * sizeof *s->grad);
    s->vol = malloc(nn * sizeof *s->vol);
    s->weight = malloc(nn * sizeof *s->weight);
    if (!s->idx || !s->grad || !s->vol || !s->weight) {
        opt_simplices_free(s);
        return err_nomem(err, "simplex set");
    }
    s->d = d;
    s->n = n;
    return SCAF_OK;
}

void opt_simplices_free(opt_simplices *s)
{
    if (!s) return;
    free(s->idx);
    free(s->grad);
    free(s->vol);
    free(s->weight);
    memset(s, 0, sizeof *s);
}

scaf_status opt_simplices_permute(opt_simplices *S, const int *order, scaf_error *err)
{
    int d = S->d, nc = d + 1;
    opt_simplices T = {0};
    scaf_status st = opt_simplices_alloc(&T, d, S->n, err);
    if (st != SCAF_OK) return st;
    for (int k = 0; k < S->n; k++) {
        size_t o = (size_t)order[k];
        memcpy(T.idx + (size_t)k * nc, S->idx + o * nc, (size_t)nc * sizeof *T.idx);
        memcpy(T.grad + (size_t)k * nc * d, S->grad + o * nc * d, (size_t)nc * d * sizeof *T.grad);
        T.vol[k] = S->vol[o];
        T.weight[k] = S->weight[o];
    }
    opt_simplices_free(S);
    *S = T;
    return SCAF_OK;
}

static int last_vertex(const opt_simplices *S, int s)
{
    const int *ix = S->idx + (size_t)s * (S->d + 1);
    int top = ix[0];
    for (int i = 1; i <= S->d; i++)
        if (ix[i] > top) top = ix[i];
    return top;
}

scaf_status opt_simplices_order_by_last_vertex(const opt_simplices *S, int nv, int *order,
                                               scaf_error *err)
{
    int *start = calloc((size_t)nv + 1, sizeof *start);
    if (!start) return err_nomem(err, "simplex order");
    for (int s = 0; s < S->n; s++) start[last_vertex(S, s) + 1]++;
    for (int v = 0; v < nv; v++) start[v + 1] += start[v];
    for (int s = 0; s < S->n; s++) order[start[last_vertex(S, s)]++] = s;
    free(start);
    return SCAF_OK;
}

void opt_flatten_triangle(const double p0[3], const double p1[3], const double p2[3], double q[6])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = p1[k] - p0[k];
        e2[k] = p2[k] - p0[k];
    }
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    double x = l1 > 0 ? (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1 : 0.0;
    double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    /* |e1 x e2| / |e1| is the height: exact positive y without cancellation. */
    double y = l1 > 0 ? sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / l1 : 0.0;
    q[0] = 0;
    q[1] = 0;
    q[2] = l1;
    q[3] = 0;
    q[4] = x;
    q[5] = y;
}

int opt_gradient_operator(int d, const double *rest, double *grad, double *vol)
{
    if (d == 2) {
        double a = rest[2] - rest[0], b = rest[4] - rest[0];
        double c = rest[3] - rest[1], e = rest[5] - rest[1];
        /* R = [[a, b], [c, e]] (columns are edges). */
        double det = a * e - b * c;
        *vol = 0.5 * det;
        if (!(det != 0.0) || !isfinite(det)) return 0;
        double inv[4] = {e / det, -b / det, -c / det, a / det};
        grad[2] = inv[0];
        grad[3] = inv[1];
        grad[4] = inv[2];
        grad[5] = inv[3];
        grad[0] = -inv[0] - inv[2];
        grad[1] = -inv[1] - inv[3];
        return 1;
    }
    double R[9];
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) R[3 * r + k] = rest[3 * (k + 1) + r] - rest[r];
    double C[9] = {R[4] * R[8] - R[5] * R[7], R[5] * R[6] - R[3] * R[8], R[3] * R[7] - R[4] * R[6],
                   R[2] * R[7] - R[1] * R[8], R[0] * R[8] - R[2] * R[6], R[1] * R[6] - R[0] * R[7],
                   R[1] * R[5] - R[2] * R[4], R[2] * R[3] - R[0] * R[5], R[0] * R[4] - R[1] * R[3]};
    double det = R[0] * C[0] + R[1] * C[1] + R[2] * C[2];
    *vol = det / 6.0;
    if (!(det != 0.0) || !isfinite(det)) return 0;
    /* inv = adj / det, adj = C^T: inv[k][r] = C[r][k] / det. */
    for (int k = 0; k < 3; k++)
        for (int b = 0; b < 3; b++) grad[3 * (k + 1) + b] = C[3 * b + k] / det;
    for (int b = 0; b < 3; b++) grad[b] = -(grad[3 + b] + grad[6 + b] + grad[9 + b]);
    return 1;
}

void opt_jacobian_general(const opt_simplices *S, int s, const double *X, double *J)
{
    int d = S->d;
    const int *ix = S->idx + (size_t)s * (d + 1);
    const double *G = S->grad + (size_t)s * (d + 1) * d;
    for (int k = 0; k < d * d; k++) J[k] = 0.0;
    for (int i = 0; i <= d; i++) {
        const double *x = X + (size_t)ix[i] * d;
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++) J[a * d + b] += x[a] * G[i * d + b];
    }
}

double opt_signed_volume(const opt_simplices *S, int s, const double *X)
{
    int d = S->d;
    const int *ix = S->idx + (size_t)s * (d + 1);
    const double *x0 = X + (size_t)ix[0] * d;
    if (d == 2) {
        const double *x1 = X + (size_t)ix[1] * 2, *x2 = X + (size_t)ix[2] * 2;
        return 0.5 * ((x1[0] - x0[0]) * (x2[1] - x0[1]) - (x1[1] - x0[1]) * (x2[0] - x0[0]));
    }
    double e[3][3];
    for (int k = 0; k < 3; k++)
        for (int r = 0; r < 3; r++) e[k][r] = X[(size_t)ix[k + 1] * 3 + r] - x0[r];
    double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
        e[1][0] * (e[0][1] * e[2][2] - e[0][2] * e[2][1]) +
        e[2][0] * (e[0][1] * e[1][2] - e[0][2] * e[1][1]);
    return det / 6.0;
}

static scaf_status check_indices(int d, int nv, int n, const int *S, scaf_error *err)
{
    for (int s = 0; s < n; s++)
        for (int i = 0; i <= d; i++) {
            int v = S[(size_t)s * (d + 1) + i];
            if (v < 0 || v >= nv)
                return err_set(err, SCAF_ERR_USAGE,
                               "simplex %d corner %d references vertex %d but there are %d", s, i,
                               v, nv);
        }
    return SCAF_OK;
}

scaf_status opt_simplices_from_surface(opt_simplices *out, int nv, const double *V, int nf,
                                       const int *F, scaf_error *err)
{
    scaf_status st = check_indices(2, nv, nf, F, err);
    if (st != SCAF_OK) return st;
    st = opt_simplices_alloc(out, 2, nf, err);
    if (st != SCAF_OK) return st;
    for (int f = 0; f < nf; f++) {
        const int *t = F + (size_t)f * 3;
        double q[6], vol;
        opt_flatten_triangle(V + (size_t)t[0] * 3, V + (size_t)t[1] * 3, V + (size_t)t[2] * 3, q);
        memcpy(out->idx + (size_t)f * 3, t, 3 * sizeof *t);
        if (!opt_gradient_operator(2, q, out->grad + (size_t)f * 6, &vol) || !(vol > 0)) {
            opt_simplices_free(out);
            return err_set(err, SCAF_ERR_MESH,
                           "triangle %d (vertices %d %d %d) has zero or non-finite 3D area", f,
                           t[0], t[1], t[2]);
        }
        out->vol[f] = vol;
        out->weight[f] = vol;
    }
    return SCAF_OK;
}

/* Corners of a regular d-simplex of volume v, positively oriented. */
static void regular_simplex(int d, double v, double *rest)
{
    if (d == 2) {
        double a = sqrt(4.0 * v / sqrt(3.0));
        double q[6] = {0, 0, a, 0, 0.5 * a, 0.5 * sqrt(3.0) * a};
        memcpy(rest, q, sizeof q);
    } else {
        double a = cbrt(6.0 * sqrt(2.0) * v);
        double q[12] = {0,
                        0,
                        0,
                        a,
                        0,
                        0,
                        0.5 * a,
                        0.5 * sqrt(3.0) * a,
                        0,
                        0.5 * a,
                        sqrt(3.0) / 6.0 * a,
                        sqrt(2.0 / 3.0) * a};
        memcpy(rest, q, sizeof q);
    }
}

/* The 2D guard's rest shape for a triangle of area vol between
 * GUARD_LO * min_vol and GUARD_HI * min_vol, corners in rest (overwritten):
 * its metric (edge-vector dot products, rotation-free) blended from its
 * own (at GUARD_HI) towards the regular triangle's of area min_vol (at
 * GUARD_LO and below). A convex combination of positive definite metrics
 * is one, and its area is at least (1 - t) vol + t min_vol. The blend
 * makes the rest shape a continuous function of the current one: the
 * paper's switch to a regular shape at min_vol made the re-rested
 * scaffold's energy jump there, and where the map presses its boundary
 * against itself (ARAP on camel_b) the run then cycled between the
 * closing gap and the push-back instead of settling. The span straddles
 * min_vol: blending only below it let scaffold slivers keep sliver rest
 * shapes, which hold the boundary in place (ARAP on myles_knot1: no
 * convergence in 200 iterations, measured in bench/RESULTS-newton.md). */
#define GUARD_HI 2.0
#define GUARD_LO 0.25
static void guard_blend_2d(double vol, double min_vol, double *rest)
{
    double s = log(GUARD_HI * min_vol / vol) / log(GUARD_HI / GUARD_LO);
    double t = s >= 1 ? 1 : s * s * (3 - 2 * s); /* smooth in log(area) */
    double e1[2] = {rest[2] - rest[0], rest[3] - rest[1]};
    double e2[2] = {rest[4] - rest[0], rest[5] - rest[1]};
    double l2 = 4.0 * min_vol / sqrt(3.0); /* regular: |e|^2, e1.e2 = |e|^2 / 2 */
    double m11 = (1 - t) * (e1[0] * e1[0] + e1[1] * e1[1]) + t * l2;
    double m22 = (1 - t) * (e2[0] * e2[0] + e2[1] * e2[1]) + t * l2;
    double m12 = (1 - t) * (e1[0] * e2[0] + e1[1] * e2[1]) + t * 0.5 * l2;
    double a = sqrt(m11);
    double q[6] = {0, 0, a, 0, m12 / a, sqrt(m11 * m22 - m12 * m12) / a};
    memcpy(rest, q, sizeof q);
}

scaf_status opt_simplices_from_current(opt_simplices *out, int d, int nv, const double *X, int n,
                                       const int *S, double min_vol, scaf_error *err)
{
    if (d != 2 && d != 3)
        return err_set(err, SCAF_ERR_USAGE, "simplex set: dimension %d invalid", d);
    scaf_status st = check_indices(d, nv, n, S, err);
    if (st != SCAF_OK) return st;
    st = opt_simplices_alloc(out, d, n, err);
    if (st != SCAF_OK) return st;
    for (int s = 0; s < n; s++) {
        const int *t = S + (size_t)s * (d + 1);
        double rest[12], vol;
        for (int i = 0; i <= d; i++)
            for (int a = 0; a < d; a++) rest[i * d + a] = X[(size_t)t[i] * d + a];
        memcpy(out->idx + (size_t)s * (d + 1), t, (size_t)(d + 1) * sizeof *t);
        double *G = out->grad + (size_t)s * (d + 1) * d;
        int ok = opt_gradient_operator(d, rest, G, &vol);
        if (d == 2 && ok && vol > GUARD_LO * min_vol && vol < GUARD_HI * min_vol && min_vol > 0) {
            guard_blend_2d(vol, min_vol, rest);
            ok = opt_gradient_operator(d, rest, G, &vol);
            if (ok && vol > 0) {
                out->vol[s] = vol;
                out->weight[s] = 1.0;
                continue;
            }
        }
        if (!(ok && vol >= min_vol && vol > 0)) {
            if (!(min_vol > 0) || !isfinite(vol)) {
                opt_simplices_free(out);
                return err_set(err, SCAF_ERR_MESH,
                               "simplex %d has rest volume %g (degenerate or inverted)", s, vol);
            }
            regular_simplex(d, min_vol, rest);
            opt_gradient_operator(d, rest, G, &vol);
        }
        out->vol[s] = vol;
        out->weight[s] = 1.0;
    }
    return SCAF_OK;
}
