/* mesh/spiral_strip: the strip of Figure 4 and its spiral (see spiral_strip.h). */
#include "mesh/spiral_strip.h"

#include <math.h>

static const double PI = 3.14159265358979323846;

/* Angle step: n segments over n + 1 steps of the circle (one step open). */
static double step_angle(int n) { return 2.0 * PI / (n + 1); }

scaf_status spiral_strip_make(int n, mesh *m, scaf_error *err)
{
    if (n < 3) return err_set(err, SCAF_ERR_USAGE, "spiral strip: at least 3 segments, got %d", n);
    scaf_status st = mesh_alloc(m, 2 * (n + 1), 2 * n, 0, err);
    if (st != SCAF_OK) return st;
    double h = 0.5 * SPIRAL_STRIP_WIDTH;
    for (int j = 0; j <= n; j++) {
        double a = j * step_angle(n), c = cos(a), s = sin(a);
        double *in = m->V + 6 * (size_t)j, *out = in + 3;
        in[0] = (1.0 - h) * c, in[1] = (1.0 - h) * s, in[2] = 0.0;
        out[0] = (1.0 + h) * c, out[1] = (1.0 + h) * s, out[2] = 0.0;
    }
    for (int j = 0; j < n; j++) {
        int i0 = 2 * j, o0 = i0 + 1, i1 = i0 + 2, o1 = i0 + 3;
        int *f = m->F + 6 * (size_t)j;
        f[0] = i0, f[1] = o0, f[2] = o1;
        f[3] = i0, f[4] = o1, f[5] = i1;
    }
    return SCAF_OK;
}

/* The curl: the centre line keeps its start (station 0, tangent +y) and
 * its length, its curvature grows linearly from 1 (the circle) so that it
 * turns SPIRAL_STRIP_TURNS times in all. A curve of monotone curvature
 * never meets itself (Tait-Kneser: its osculating circles are nested), and
 * each curvature between the circle's and this one gives such a curve, so
 * the strip can wind up without touching itself: curl t in [0, 1] scales
 * c, from the circle itself (0) to the spiral (1). The tangent angle is
 * integrated exactly (it is quadratic in s), positions by the midpoint
 * rule on fine sub-steps. */
void spiral_strip_curl(int n, double t, double *T)
{
    const int sub = 400;
    double ds = step_angle(n), len = n * ds;
    double turning = 2.0 * PI * SPIRAL_STRIP_TURNS;
    double c = t * 2.0 * (turning - len) / (len * len); /* kappa(s) = 1 + c s */
    double h = 0.5 * SPIRAL_STRIP_WIDTH;
    double x = 1.0, y = 0.0;
    for (int j = 0; j <= n; j++) {
        double s0 = j * ds;
        double th = PI / 2.0 + s0 + 0.5 * c * s0 * s0; /* tangent angle */
        double nx = -sin(th), ny = cos(th);            /* left normal: inwards */
        T[4 * j] = x + h * nx, T[4 * j + 1] = y + h * ny;
        T[4 * j + 2] = x - h * nx, T[4 * j + 3] = y - h * ny;
        for (int k = 0; k < sub && j < n; k++) {
            double sm = s0 + (k + 0.5) * ds / sub, a = PI / 2.0 + sm + 0.5 * c * sm * sm;
            x += cos(a) * ds / sub;
            y += sin(a) * ds / sub;
        }
    }
}
