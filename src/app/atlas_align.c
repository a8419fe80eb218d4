/* app/atlas_align: turns of charts and of the layout (see atlas_align.h). */
#include "app/atlas_align.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/min_box.h"
#include "geom/predicates.h"

/* Turn the vertices vs (nv ids) of uv by theta about their bounding-box
 * center into out. */
static void turn(const double *uv, const int *vs, int nv, double theta, double *out)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 2; k++) {
            double x = uv[2 * (size_t)vs[i] + k];
            lo[k] = fmin(lo[k], x);
            hi[k] = fmax(hi[k], x);
        }
    double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]), c = cos(theta), s = sin(theta);
    for (int i = 0; i < nv; i++) {
        const double *p = uv + 2 * (size_t)vs[i];
        double x = p[0] - cx, y = p[1] - cy;
        out[2 * (size_t)vs[i]] = cx + (c * x - s * y);
        out[2 * (size_t)vs[i] + 1] = cy + (s * x + c * y);
    }
}

/* Every face of fs (nfs ids) strictly positive at X, decided exactly. */
static int positive(const double *X, const int *F, const int *fs, int nfs)
{
    for (int i = 0; i < nfs; i++) {
        const int *t = F + 3 * (size_t)(fs ? fs[i] : i);
        if (!(orient2d(X + 2 * (size_t)t[0], X + 2 * (size_t)t[1], X + 2 * (size_t)t[2]) > 0.0))
            return 0;
    }
    return 1;
}

/* Gather the coordinates of vs (nv ids) into P and return the angle chosen
 * by pick (0: least-area rectangle, 1: smallest square); *side gets the
 * square's side for pick 1. -1 when out of memory. */
static int angle_of(const double *uv, const int *vs, int nv, int pick, double *theta, double *side)
{
    double *P = malloc(sizeof(double) * 2 * (size_t)(nv ? nv : 1));
    int *hull = malloc(sizeof(int) * (size_t)(nv + 1));
    if (!P || !hull) {
        free(P);
        free(hull);
        return -1;
    }
    for (int i = 0; i < nv; i++)
        memcpy(P + 2 * (size_t)i, uv + 2 * (size_t)vs[i], sizeof(double) * 2);
    int nh = min_box_hull(P, nv, hull);
    if (nh >= 0)
        *theta = pick ? min_box_square_angle(P, hull, nh, side) : min_box_area_angle(P, hull, nh);
    free(P);
    free(hull);
    return nh < 0 ? -1 : 0;
}

scaf_status atlas_align_charts(int nw, const double *uv, int nf, const int *F, const int *chart,
                               const int *wchart, int ncharts, double *out, int *turned,
                               scaf_error *err)
{
    memcpy(out, uv, sizeof(double) * 2 * (size_t)nw);
    if (turned) *turned = 0;
    size_t nc1 = (size_t)ncharts + 1;
    int *vstart = calloc(nc1 + 1, sizeof(int)), *fstart = calloc(nc1 + 1, sizeof(int));
    int *vs = malloc(sizeof(int) * (size_t)(nw ? nw : 1)),
        *fs = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    int *fill = malloc(sizeof(int) * nc1);
    scaf_status st = SCAF_OK;
    if (!vstart || !fstart || !vs || !fs || !fill) {
        st = err_nomem(err, "turning charts");
        goto done;
    }
    /* vertices and faces grouped by chart */
    for (int v = 0; v < nw; v++)
        if (wchart[v] >= 0) vstart[wchart[v] + 1]++;
    for (int f = 0; f < nf; f++) fstart[chart[f] + 1]++;
    for (int c = 0; c < ncharts; c++) vstart[c + 1] += vstart[c], fstart[c + 1] += fstart[c];
    memcpy(fill, vstart, sizeof(int) * (size_t)ncharts);
    for (int v = 0; v < nw; v++)
        if (wchart[v] >= 0) vs[fill[wchart[v]]++] = v;
    memcpy(fill, fstart, sizeof(int) * (size_t)ncharts);
    for (int f = 0; f < nf; f++) fs[fill[chart[f]]++] = f;
    for (int c = 0; c < ncharts; c++) {
        const int *cv = vs + vstart[c], *cf = fs + fstart[c];
        int ncv = vstart[c + 1] - vstart[c], ncf = fstart[c + 1] - fstart[c];
        double theta = 0.0;
        if (angle_of(uv, cv, ncv, 0, &theta, NULL) < 0) {
            st = err_nomem(err, "turning charts");
            goto done;
        }
        if (theta == 0.0) continue;
        turn(uv, cv, ncv, theta, out);
        if (positive(out, F, cf, ncf)) {
            if (turned) (*turned)++;
        } else {
            /* rounding flipped a triangle: this chart keeps its place */
            for (int i = 0; i < ncv; i++)
                memcpy(out + 2 * (size_t)cv[i], uv + 2 * (size_t)cv[i], sizeof(double) * 2);
        }
    }
done:
    free(vstart);
    free(fstart);
    free(vs);
    free(fs);
    free(fill);
    return st;
}

scaf_status atlas_turn_to_square(int nw, const double *uv, int nf, const int *F, double *out,
                                 int *turned, scaf_error *err)
{
    *turned = 0;
    memcpy(out, uv, sizeof(double) * 2 * (size_t)nw);
    int *all = malloc(sizeof(int) * (size_t)(nw ? nw : 1));
    if (!all) return err_nomem(err, "turning the layout");
    for (int v = 0; v < nw; v++) all[v] = v;
    double theta = 0.0, side = INFINITY, w0, h0;
    if (angle_of(uv, all, nw, 1, &theta, &side) < 0) {
        free(all);
        return err_nomem(err, "turning the layout");
    }
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < nw; v++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], uv[2 * (size_t)v + k]);
            hi[k] = fmax(hi[k], uv[2 * (size_t)v + k]);
        }
    w0 = hi[0] - lo[0];
    h0 = hi[1] - lo[1];
    /* turn only for a real gain (not rounding noise) */
    if (theta != 0.0 && side < (1.0 - 1e-9) * fmax(w0, h0)) {
        turn(uv, all, nw, theta, out);
        if (positive(out, F, NULL, nf)) *turned = 1;
        else memcpy(out, uv, sizeof(double) * 2 * (size_t)nw);
    }
    free(all);
    return SCAF_OK;
}
