/* app/uv_raster: triangle rasterizer (see uv_raster.h).
 *
 * Pixel positions of the vertices are computed once per corner with the
 * same formula, so two triangles sharing an edge see bitwise the same
 * endpoints, and app/pixel_cover gives each pixel centre on the edge to
 * exactly one of them. Barycentric weights
 * for the 3D checker are plain floating point: they only pick a shade.
 */
#include "app/uv_raster.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/pixel_cover.h"
#include "geom/predicates.h"

scaf_status uv_raster_new(uv_raster *r, int width, int height, scaf_error *err)
{
    r->width = r->height = 0;
    r->rgba = NULL;
    if (width < 1 || height < 1)
        return err_set(err, SCAF_ERR_USAGE, "picture size %d x %d", width, height);
    size_t n = (size_t)width * (size_t)height * 4;
    r->rgba = malloc(n);
    if (!r->rgba) return err_nomem(err, "picture buffer");
    for (size_t i = 0; i < n; i += 4) {
        r->rgba[i] = r->rgba[i + 1] = r->rgba[i + 2] = 255;
        r->rgba[i + 3] = 0;
    }
    r->width = width;
    r->height = height;
    return SCAF_OK;
}

void uv_raster_free(uv_raster *r)
{
    free(r->rgba);
    r->rgba = NULL;
    r->width = r->height = 0;
}

uv_raster_frame uv_raster_fit(const double lo[2], const double hi[2], int long_side, int margin,
                              int *width, int *height)
{
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    /* a flat, empty or non-finite box draws at scale long_side (no NaN sizes) */
    if (!(w > 0.0) || !isfinite(w)) w = 0.0;
    if (!(h > 0.0) || !isfinite(h)) h = 0.0;
    double ext = w > h ? w : h;
    if (!(ext > 0.0)) ext = 1.0;
    if (long_side < 1) long_side = 1;
    if (margin < 0 || 2 * margin >= long_side) margin = (long_side - 1) / 2;
    int inner = long_side - 2 * margin;
    uv_raster_frame fr = {lo[0], hi[1], inner / ext, margin, margin};
    int W = (int)ceil(w * fr.scale - 1e-9) + 2 * margin,
        H = (int)ceil(h * fr.scale - 1e-9) + 2 * margin;
    *width = W < 1 ? 1 : (W > long_side ? long_side : W);
    *height = H < 1 ? 1 : (H > long_side ? long_side : H);
    return fr;
}

unsigned uv_raster_checker_dark(unsigned rgb)
{
    unsigned out = 0;
    for (int k = 2; k >= 0; k--) out = (out << 8) | (((rgb >> (8 * k)) & 0xffu) * 3u / 5u);
    return out;
}

static void put(uv_raster *r, int i, int j, unsigned rgb)
{
    unsigned char *p = r->rgba + 4 * ((size_t)j * (size_t)r->width + (size_t)i);
    p[0] = (unsigned char)(rgb >> 16);
    p[1] = (unsigned char)(rgb >> 8);
    p[2] = (unsigned char)rgb;
    p[3] = 255;
}

static void to_pixel(const uv_raster_frame *fr, const double *uv, double p[2])
{
    p[0] = fr->ox + (uv[0] - fr->u0) * fr->scale;
    p[1] = fr->oy + (fr->v1 - uv[1]) * fr->scale;
}

void uv_raster_fill(uv_raster *r, const uv_raster_frame *fr, const uv_raster_mesh *m)
{
    int checker = m->xyz && m->F3 && m->checker > 0.0;
    for (int f = 0; f < m->nf; f++) {
        double p[3][2];
        const double *x[3] = {NULL, NULL, NULL};
        for (int k = 0; k < 3; k++) {
            to_pixel(fr, m->uv + 2 * (size_t)m->F[3 * f + k], p[k]);
            if (checker) x[k] = m->xyz + 3 * (size_t)m->F3[3 * f + k];
        }
        double o = orient2d(p[0], p[1], p[2]);
        if (!(o != 0.0)) continue; /* degenerate (or NaN) */
        if (o < 0.0) {
            /* make it counter-clockwise in pixel coordinates */
            double t[2] = {p[1][0], p[1][1]};
            p[1][0] = p[2][0], p[1][1] = p[2][1];
            p[2][0] = t[0], p[2][1] = t[1];
            const double *tx = x[1];
            x[1] = x[2];
            x[2] = tx;
        }
        pixel_cover cov;
        if (!pixel_cover_init(&cov, (const double(*)[2])p, r->width, r->height)) continue;
        unsigned light = m->colour[f], dark = uv_raster_checker_dark(light);
        for (int j = cov.j0; j <= cov.j1; j++)
            for (int i = cov.i0; i <= cov.i1; i++) {
                if (!pixel_cover_has(&cov, i, j)) continue;
                unsigned col = light;
                if (checker) {
                    int parity = 0;
                    double w[3];
                    pixel_cover_weights(&cov, i, j, w);
                    for (int d = 0; d < 3; d++) {
                        double X = w[0] * x[0][d] + w[1] * x[1][d] + w[2] * x[2][d];
                        /* fmod, not an integer cast: far from the origin floor() can overflow an int */
                        parity += fabs(fmod(floor(X / m->checker), 2.0)) == 1.0;
                    }
                    if (parity & 1) col = dark;
                }
                put(r, i, j, col);
            }
    }
}

void uv_raster_line(uv_raster *r, const uv_raster_frame *fr, const double a[2], const double b[2],
                    unsigned rgb)
{
    double p[2], q[2];
    to_pixel(fr, a, p);
    to_pixel(fr, b, q);
    double len = fmax(fabs(q[0] - p[0]), fabs(q[1] - p[1]));
    if (!isfinite(len)) return;
    /* half-pixel steps: every pixel the segment crosses gets at least one sample */
    int n = (int)fmin(ceil(2.0 * len), 4.0 * 16384.0) + 1;
    for (int s = 0; s <= n; s++) {
        double t = (double)s / n;
        double x = p[0] + (q[0] - p[0]) * t, y = p[1] + (q[1] - p[1]) * t;
        if (x < 0.0 || y < 0.0 || x >= r->width || y >= r->height) continue;
        put(r, (int)x, (int)y, rgb);
    }
}
