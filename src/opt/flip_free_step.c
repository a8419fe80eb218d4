/* opt/flip_free_step: the largest step before a simplex inverts.
 *
 * The quadratic uses the cancellation-free root formula. The general
 * routine splits (0, inf) at the positive critical points of p (roots of
 * p'), so p is monotone on every piece; the first piece whose end has
 * p <= 0 brackets the root, found by bisection kept on the positive side
 * (so the result is never past the true root by more than rounding).
 */
#include "opt/flip_free_step.h"

#include <math.h>
#include <stddef.h>

#include "base/parallel.h"
#include "opt/vector_clones.h"

static double eval(int deg, const double *c, double t)
{
    double v = c[deg];
    for (int k = deg - 1; k >= 0; k--) v = v * t + c[k];
    return v;
}

/* Positive roots of a + b t + q t^2 (any coefficients), sorted; returns count. */
static int positive_quadratic_roots(double a, double b, double q, double r[2])
{
    int n = 0;
    if (q == 0.0) {
        if (b != 0.0) {
            double t = -a / b;
            if (t > 0) r[n++] = t;
        }
        return n;
    }
    double disc = b * b - 4.0 * q * a;
    if (disc < 0) return 0;
    double sq = sqrt(disc);
    double h = -0.5 * (b + (b >= 0 ? sq : -sq));
    double t1 = h != 0.0 ? h / q : 0.0, t2 = h != 0.0 ? a / h : 0.0;
    if (t1 > t2) {
        double tmp = t1;
        t1 = t2;
        t2 = tmp;
    }
    if (t1 > 0) r[n++] = t1;
    if (t2 > 0 && t2 != t1) r[n++] = t2;
    return n;
}

static double bisect(int deg, const double *c, double lo, double hi)
{
    /* Invariant: p(lo) > 0, p(hi) <= 0. */
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (eval(deg, c, mid) > 0) lo = mid;
        else hi = mid;
    }
    return lo;
}

double opt_first_positive_root(int deg, const double *c)
{
    while (deg > 0 && c[deg] == 0.0) deg--;
    if (deg == 0) return INFINITY;
    /* No sign change possible when every coefficient is non-negative. */
    int any_neg = 0;
    for (int k = 1; k <= deg; k++) any_neg |= c[k] < 0;
    if (!any_neg) return INFINITY;
    if (deg == 1) return -c[0] / c[1];
    double crit[2];
    int nc = positive_quadratic_roots(c[1], 2.0 * c[2], deg == 3 ? 3.0 * c[3] : 0.0, crit);
    double lo = 0.0;
    for (int k = 0; k < nc; k++) {
        if (eval(deg, c, crit[k]) <= 0) return bisect(deg, c, lo, crit[k]);
        lo = crit[k];
    }
    if (c[deg] > 0) return INFINITY; /* p grows to +inf after the last critical point */
    /* Cauchy bound: every root is below 1 + max |c_k / c_deg|. */
    double m = 0;
    for (int k = 0; k < deg; k++) m = fmax(m, fabs(c[k] / c[deg]));
    double hi = 1.0 + m;
    if (hi <= lo) hi = 2.0 * lo + 1.0;
    while (eval(deg, c, hi) > 0 && isfinite(hi)) hi *= 2.0;
    return bisect(deg, c, lo, hi);
}

double opt_max_step_triangle(const double *x0, const double *x1, const double *x2, const double *d0,
                             const double *d1, const double *d2)
{
    double e1x = x1[0] - x0[0], e1y = x1[1] - x0[1], e2x = x2[0] - x0[0], e2y = x2[1] - x0[1];
    double f1x = d1[0] - d0[0], f1y = d1[1] - d0[1], f2x = d2[0] - d0[0], f2y = d2[1] - d0[1];
    double c = e1x * e2y - e1y * e2x;
    double b = e1x * f2y - e1y * f2x + f1x * e2y - f1y * e2x;
    double a = f1x * f2y - f1y * f2x;
    if (!(c > 0)) return 0.0;              /* already degenerate or inverted: no step is safe */
    if (a >= 0 && b >= 0) return INFINITY; /* fast path: area never decreases */
    double coef[3] = {c, b, a};
    double r[2];
    int n = positive_quadratic_roots(c, b, a, r);
    if (n == 0) return INFINITY;
    double t = r[0];
    /* Keep the returned t on the positive side of the root. */
    if (eval(2, coef, t) <= 0) t = bisect(2, coef, 0.0, t);
    return t;
}

static double det3(const double *a, const double *b, const double *c)
{
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
        a[2] * (b[0] * c[1] - b[1] * c[0]);
}

double opt_max_step_tet(const double *x0, const double *x1, const double *x2, const double *x3,
                        const double *d0, const double *d1, const double *d2, const double *d3)
{
    double e[3][3], f[3][3];
    const double *xs[3] = {x1, x2, x3}, *ds[3] = {d1, d2, d3};
    for (int k = 0; k < 3; k++)
        for (int r = 0; r < 3; r++) {
            e[k][r] = xs[k][r] - x0[r];
            f[k][r] = ds[k][r] - d0[r];
        }
    double c[4];
    c[0] = det3(e[0], e[1], e[2]);
    if (!(c[0] > 0)) return 0.0;
    c[1] = det3(f[0], e[1], e[2]) + det3(e[0], f[1], e[2]) + det3(e[0], e[1], f[2]);
    c[2] = det3(e[0], f[1], f[2]) + det3(f[0], e[1], f[2]) + det3(f[0], f[1], e[2]);
    c[3] = det3(f[0], f[1], f[2]);
    return opt_first_positive_root(3, c);
}

/* opt_max_step_triangle for the running minimum: a root t above `best`
 * (by more than the bisection can move it: it only brings t down to the
 * last double before the sign change, a few ulps) cannot lower the
 * minimum, so its bisection (about 50 polynomial evaluations from 0, the
 * bulk of the cost) is skipped and t returned as is. */
static double max_step_triangle_below(const double *x0, const double *x1, const double *x2,
                                      const double *d0, const double *d1, const double *d2,
                                      double best)
{
    double e1x = x1[0] - x0[0], e1y = x1[1] - x0[1], e2x = x2[0] - x0[0], e2y = x2[1] - x0[1];
    double f1x = d1[0] - d0[0], f1y = d1[1] - d0[1], f2x = d2[0] - d0[0], f2y = d2[1] - d0[1];
    double c = e1x * e2y - e1y * e2x;
    double b = e1x * f2y - e1y * f2x + f1x * e2y - f1y * e2x;
    double a = f1x * f2y - f1y * f2x;
    if (!(c > 0)) return 0.0;
    if (a >= 0 && b >= 0) return INFINITY;
    double coef[3] = {c, b, a};
    double r[2];
    int n = positive_quadratic_roots(c, b, a, r);
    if (n == 0) return INFINITY;
    double t = r[0];
    if (t > best * (1.0 + 1e-9)) return t;
    if (eval(2, coef, t) <= 0) t = bisect(2, coef, 0.0, t);
    return t;
}

/* Triangles per batch of the lane filter (a loop the compiler vectorizes,
 * as in opt/sd2_lanes). */
#define STEP_LANES 64

/* The minimum over triangles [lo, hi), max_step_triangle_below's result
 * bit for bit. A batch's quadratics and their smallest positive roots are
 * computed in vector lanes with the very operations of
 * positive_quadratic_roots; a triangle goes through the one-at-a-time
 * routine only when its lane root could lower the running minimum or its
 * case is not the plain one (c <= 0, a or h zero, not finite), which after
 * the first few batches is rare. The lanes beat the routine's branches
 * (aphrodite: 1.0-1.2 -> 0.53-0.59 ms a pass): half the triangles shrink
 * along a SLIM direction, in no order a branch predictor can follow. */
VECTOR_CLONES static double max_step_triangles(const opt_simplices *S, const double *X,
                                               const double *D, size_t lo, size_t hi)
{
    double best = INFINITY;
    for (size_t s0 = lo; s0 < hi; s0 += STEP_LANES) {
        int m = hi - s0 < STEP_LANES ? (int)(hi - s0) : STEP_LANES;
        double cc[STEP_LANES], bb[STEP_LANES], aa[STEP_LANES], cand[STEP_LANES];
        for (int l = 0; l < STEP_LANES; l++) {
            if (l >= m) { /* a triangle that never shrinks */
                cc[l] = 1.0;
                bb[l] = aa[l] = 0.0;
                continue;
            }
            const int *ix = S->idx + 3 * (s0 + (size_t)l);
            const double *x0 = X + 2 * (size_t)ix[0], *x1 = X + 2 * (size_t)ix[1],
                         *x2 = X + 2 * (size_t)ix[2];
            const double *d0 = D + 2 * (size_t)ix[0], *d1 = D + 2 * (size_t)ix[1],
                         *d2 = D + 2 * (size_t)ix[2];
            double e1x = x1[0] - x0[0], e1y = x1[1] - x0[1], e2x = x2[0] - x0[0],
                   e2y = x2[1] - x0[1];
            double f1x = d1[0] - d0[0], f1y = d1[1] - d0[1], f2x = d2[0] - d0[0],
                   f2y = d2[1] - d0[1];
            cc[l] = e1x * e2y - e1y * e2x;
            bb[l] = e1x * f2y - e1y * f2x + f1x * e2y - f1y * e2x;
            aa[l] = f1x * f2y - f1y * f2x;
        }
        for (int l = 0; l < STEP_LANES; l++) {
            double c = cc[l], b = bb[l], a = aa[l];
            double disc = b * b - 4.0 * a * c;
            double sq = sqrt(disc > 0 ? disc : 0.0);
            double h = -0.5 * (b + (b >= 0 ? sq : -sq));
            double t1 = h / a, t2 = c / h;
            double r0 = t1 > t2 ? t2 : t1, r1 = t1 > t2 ? t1 : t2;
            double r1p = r1 > 0 ? r1 : INFINITY;
            double root = r0 > 0 ? r0 : r1p;
            int never = ((a >= 0) & (b >= 0)) | (disc < 0);
            int plain = (c > 0) & (a != 0) & (h != 0) & (root == root);
            double t = never ? INFINITY : root;
            cand[l] = plain ? t : 0.0;
        }
        for (int l = 0; l < m; l++) {
            if (!(cand[l] <= best * (1.0 + 1e-9))) continue; /* the routine skips it too */
            const int *ix = S->idx + 3 * (s0 + (size_t)l);
            double t = max_step_triangle_below(X + 2 * (size_t)ix[0], X + 2 * (size_t)ix[1],
                                               X + 2 * (size_t)ix[2], D + 2 * (size_t)ix[0],
                                               D + 2 * (size_t)ix[1], D + 2 * (size_t)ix[2], best);
            if (t < best) best = t;
        }
    }
    return best;
}

/* The minimum over simplices [lo, hi). */
static double max_step_range(const opt_simplices *S, const double *X, const double *D, size_t lo,
                             size_t hi)
{
    if (S->d == 2) return max_step_triangles(S, X, D, lo, hi);
    double best = INFINITY;
    int d = S->d;
    for (size_t s = lo; s < hi; s++) {
        const int *ix = S->idx + s * (d + 1);
        double t;
        if (d == 2)
            t = max_step_triangle_below(X + 2 * (size_t)ix[0], X + 2 * (size_t)ix[1],
                                        X + 2 * (size_t)ix[2], D + 2 * (size_t)ix[0],
                                        D + 2 * (size_t)ix[1], D + 2 * (size_t)ix[2], best);
        else
            t = opt_max_step_tet(X + 3 * (size_t)ix[0], X + 3 * (size_t)ix[1],
                                 X + 3 * (size_t)ix[2], X + 3 * (size_t)ix[3],
                                 D + 3 * (size_t)ix[0], D + 3 * (size_t)ix[1],
                                 D + 3 * (size_t)ix[2], D + 3 * (size_t)ix[3]);
        if (t < best) best = t;
    }
    return best;
}

/* Chunks in parallel (base/parallel). A chunk's minimum is exact (a
 * skipped bisection only concerns roots above the chunk's running
 * minimum), so the minimum of the chunks' is the serial one, bit for bit. */
typedef struct max_step_ctx {
    const opt_simplices *S;
    const double *X, *D;
} max_step_ctx;

static double max_step_chunk(const void *ctx, size_t lo, size_t hi)
{
    const max_step_ctx *c = ctx;
    return max_step_range(c->S, c->X, c->D, lo, hi);
}

double opt_max_step(const opt_simplices *S, const double *X, const double *D)
{
    max_step_ctx c = {S, X, D};
    return par_min((size_t)S->n, max_step_chunk, &c);
}
