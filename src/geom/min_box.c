/* geom/min_box: convex hull and best-fitting rotations (see min_box.h). */
#include "geom/min_box.h"

#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"

#define HALF_PI 1.57079632679489661923

typedef struct hull_pt {
    double p[2];
    int i;
} hull_pt;

static int cmp_xy(const void *a, const void *b)
{
    const hull_pt *p = a, *q = b;
    if (p->p[0] != q->p[0]) return p->p[0] < q->p[0] ? -1 : 1;
    if (p->p[1] != q->p[1]) return p->p[1] < q->p[1] ? -1 : 1;
    return p->i - q->i;
}

int min_box_hull(const double *P, int n, int *hull)
{
    if (n <= 0) return 0;
    hull_pt *s = malloc(sizeof *s * (size_t)n);
    if (!s) return -1;
    for (int i = 0; i < n; i++) s[i] = (hull_pt){{P[2 * (size_t)i], P[2 * (size_t)i + 1]}, i};
    qsort(s, (size_t)n, sizeof *s, cmp_xy);
    /* drop duplicates of one point */
    int m = 0;
    for (int i = 0; i < n; i++)
        if (m == 0 || s[i].p[0] != s[m - 1].p[0] || s[i].p[1] != s[m - 1].p[1]) s[m++] = s[i];
    if (m < 3) {
        for (int i = 0; i < m; i++) hull[i] = s[i].i;
        free(s);
        return m;
    }
    int k = 0;
    for (int i = 0; i < m; i++) { /* lower chain */
        while (k >= 2 &&
               !(orient2d(P + 2 * (size_t)hull[k - 2], P + 2 * (size_t)hull[k - 1], s[i].p) > 0.0))
            k--;
        hull[k++] = s[i].i;
    }
    for (int i = m - 2, lo = k + 1; i >= 0; i--) { /* upper chain */
        while (k >= lo &&
               !(orient2d(P + 2 * (size_t)hull[k - 2], P + 2 * (size_t)hull[k - 1], s[i].p) > 0.0))
            k--;
        hull[k++] = s[i].i;
    }
    free(s);
    return k - 1; /* the first point closed the chain */
}

void min_box_extent(const double *P, const int *hull, int nh, double theta, double *w, double *h)
{
    double c = cos(theta), s = sin(theta);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < nh; i++) {
        const double *p = P + 2 * (size_t)hull[i];
        double x = c * p[0] - s * p[1], y = s * p[0] + c * p[1];
        x0 = fmin(x0, x), x1 = fmax(x1, x);
        y0 = fmin(y0, y), y1 = fmax(y1, y);
    }
    *w = nh > 0 ? x1 - x0 : 0.0;
    *h = nh > 0 ? y1 - y0 : 0.0;
}

/* The rotation in [0, pi/2) that makes hull edge i axis parallel. */
static double edge_angle(const double *P, const int *hull, int nh, int i)
{
    const double *a = P + 2 * (size_t)hull[i], *b = P + 2 * (size_t)hull[(i + 1) % nh];
    double t = fmod(-atan2(b[1] - a[1], b[0] - a[0]), HALF_PI);
    if (t < 0.0) t += HALF_PI;
    if (!(t < HALF_PI)) t = 0.0;
    return t;
}

double min_box_area_angle(const double *P, const int *hull, int nh)
{
    double best = 0.0, best_area = INFINITY;
    for (int i = 0; i < nh && nh >= 3; i++) {
        double t = edge_angle(P, hull, nh, i), w, h;
        min_box_extent(P, hull, nh, t, &w, &h);
        if (w * h < best_area) best_area = w * h, best = t;
    }
    return best;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The index of the hull point extreme in direction (dx, dy). */
static int extreme(const double *P, const int *hull, int nh, double dx, double dy)
{
    int k = 0;
    double best = -INFINITY;
    for (int i = 0; i < nh; i++) {
        const double *p = P + 2 * (size_t)hull[i];
        double v = dx * p[0] + dy * p[1];
        if (v > best) best = v, k = hull[i];
    }
    return k;
}

double min_box_square_angle(const double *P, const int *hull, int nh, double *side)
{
    double best = 0.0, best_side = INFINITY, w, h;
    if (nh < 3) {
        min_box_extent(P, hull, nh, 0.0, &w, &h);
        if (side) *side = fmax(w, h);
        return 0.0;
    }
    /* breakpoints, then per interval the angle where width = height */
    double *t = malloc(sizeof(double) * (size_t)(nh + 1));
    int nt = 0;
    if (t) {
        for (int i = 0; i < nh; i++) t[nt++] = edge_angle(P, hull, nh, i);
        qsort(t, (size_t)nt, sizeof(double), cmp_double);
        t[nt] = t[0] + HALF_PI;
    }
    /* candidates: 0, the breakpoints, breakpoints + 45 degrees, the
     * crossings; each evaluated directly */
    for (int i = -1; i < nt; i++) {
        double cand[3];
        int nc = 0;
        if (i < 0) {
            cand[nc++] = 0.0;
        } else {
            cand[nc++] = t[i];
            cand[nc++] = fmod(t[i] + 0.5 * HALF_PI, HALF_PI);
            double mid = 0.5 * (t[i] + t[i + 1]), c = cos(mid), s = sin(mid);
            /* at mid, x' = c x - s y and y' = s x + c y; the extreme
             * points of x' and y' stay the same over the interval */
            const double *xa = P + 2 * (size_t)extreme(P, hull, nh, c, -s),
                         *xb = P + 2 * (size_t)extreme(P, hull, nh, -c, s);
            const double *ya = P + 2 * (size_t)extreme(P, hull, nh, s, c),
                         *yb = P + 2 * (size_t)extreme(P, hull, nh, -s, -c);
            double ux = xa[0] - xb[0], uy = xa[1] - xb[1], vx = ya[0] - yb[0], vy = ya[1] - yb[1];
            /* w - h = cos(th) (ux - vy) - sin(th) (uy + vx) = 0 */
            double th = atan2(ux - vy, uy + vx);
            while (th < t[i]) th += 2.0 * HALF_PI;
            while (th > t[i + 1]) th -= 2.0 * HALF_PI;
            if (th >= t[i] && th <= t[i + 1]) cand[nc++] = fmod(th, HALF_PI);
        }
        for (int j = 0; j < nc; j++) {
            min_box_extent(P, hull, nh, cand[j], &w, &h);
            if (fmax(w, h) < best_side) best_side = fmax(w, h), best = cand[j];
        }
    }
    free(t);
    if (side) *side = best_side;
    return best;
}
