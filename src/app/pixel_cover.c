/* app/pixel_cover: triangle coverage of pixel centres (see pixel_cover.h). */
#include "app/pixel_cover.h"

#include <math.h>
#include <string.h>

#include "geom/predicates.h"

/* First and last pixel index whose centre lies in [lo, hi], clamped to [0, n). */
static int span(double lo, double hi, int n, int *first, int *last)
{
    double a = ceil(lo - 0.5), b = floor(hi - 0.5);
    if (!(a <= b) || b < 0.0 || a > n - 1) return 0;
    *first = a < 0.0 ? 0 : (int)a;
    *last = b > n - 1 ? n - 1 : (int)b;
    return 1;
}

static int owns(const double a[2], const double b[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    return dy > 0.0 || (dy == 0.0 && dx < 0.0);
}

int pixel_cover_init(pixel_cover *c, const double p[3][2], int width, int height)
{
    memcpy(c->p, p, sizeof c->p);
    double lo[2] = {p[0][0], p[0][1]}, hi[2] = {p[0][0], p[0][1]};
    for (int k = 1; k < 3; k++)
        for (int d = 0; d < 2; d++) {
            if (p[k][d] < lo[d]) lo[d] = p[k][d];
            if (p[k][d] > hi[d]) hi[d] = p[k][d];
        }
    if (!span(lo[0], hi[0], width, &c->i0, &c->i1) || !span(lo[1], hi[1], height, &c->j0, &c->j1))
        return 0;
    for (int k = 0; k < 3; k++) c->own[k] = owns(p[k], p[(k + 1) % 3]);
    c->area2 =
        (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    return 1;
}

int pixel_cover_has(const pixel_cover *c, int i, int j)
{
    double q[2] = {i + 0.5, j + 0.5};
    for (int k = 0; k < 3; k++) {
        double s = orient2d(c->p[k], c->p[(k + 1) % 3], q);
        if (!(s > 0.0 || (s == 0.0 && c->own[k]))) return 0;
    }
    return 1;
}

void pixel_cover_weights(const pixel_cover *c, int i, int j, double w[3])
{
    double q[2] = {i + 0.5, j + 0.5};
    for (int k = 0; k < 3; k++) {
        const double *a = c->p[(k + 1) % 3], *b = c->p[(k + 2) % 3];
        w[k] = ((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])) / c->area2;
    }
}
