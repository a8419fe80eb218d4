/* app/uv_png: layout picture as PNG (see uv_png.h).
 *
 * Frame, fill, outline, encode: the geometry work is app/uv_raster, the
 * file app/png_write. Boundary edges are found by sorting the undirected
 * UV edge keys: an edge seen once bounds a chart (or a hole).
 */
#include "app/uv_png.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "app/picture_legend.h"
#include "app/png_write.h"
#include "app/uv_raster.h"
#include "base/sort_u64.h"
#include "geom/coord_scale.h"

uv_png_options uv_png_options_default(void)
{
    uv_png_options o = {1024, 0, 0.0, 1, 0, NULL, 0.0, 0};
    return o;
}

static scaf_status outline(uv_raster *r, const uv_raster_frame *fr, const double *uv, int nf,
                           const int *F, scaf_error *err)
{
    size_t ne = 3 * (size_t)nf;
    if (ne > INT32_MAX) return err_nomem(err, "picture outline");
    uint64_t *k = malloc(sizeof *k * (ne ? ne : 1));
    if (!k) return err_nomem(err, "picture outline");
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            uint32_t a = (uint32_t)F[3 * f + j], b = (uint32_t)F[3 * f + (j + 1) % 3];
            k[3 * (size_t)f + j] = a < b ? ((uint64_t)a << 32 | b) : ((uint64_t)b << 32 | a);
        }
    sort_u64(k, (int)ne);
    for (size_t i = 0; i < ne;) {
        size_t e = i + 1;
        while (e < ne && k[e] == k[i]) e++;
        if (e - i == 1)
            uv_raster_line(r, fr, uv + 2 * (size_t)(k[i] >> 32),
                           uv + 2 * (size_t)(k[i] & 0xffffffffu), 0x303030u);
        i = e;
    }
    free(k);
    return SCAF_OK;
}

scaf_status uv_png_write(const char *path, int nuv, const double *uv, int nf, const int *F,
                         const unsigned *colour, int nv, const double *V, const int *F3,
                         const uv_png_options *o, scaf_error *err)
{
    uv_raster r;
    scaf_status st = uv_png_render(path, nuv, uv, nf, F, colour, nv, V, F3, o, &r, err);
    if (st != SCAF_OK) return st;
    st = png_write_rgba(path, r.width, r.height, r.rgba, err);
    uv_raster_free(&r);
    return st;
}

scaf_status uv_png_render(const char *name, int nuv, const double *uv, int nf, const int *F,
                          const unsigned *colour, int nv, const double *V, const int *F3,
                          const uv_png_options *o, uv_raster *r, scaf_error *err)
{
    const char *path = name;
    r->rgba = NULL;
    r->width = r->height = 0;
    uv_png_options d = uv_png_options_default();
    if (!o) o = &d;
    if (o->size < UV_PNG_MIN_SIZE || o->size > UV_PNG_MAX_SIZE)
        return err_set(err, SCAF_ERR_USAGE, "%s: picture size %d is outside %d..%d pixels", path,
                       o->size, UV_PNG_MIN_SIZE, UV_PNG_MAX_SIZE);
    if (o->checker > 0.0 && (!V || !F3 || nv < 1))
        return err_set(err, SCAF_ERR_USAGE, "%s: the checker needs the 3D positions", path);
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int t = F[3 * f + j], v = F3 ? F3[3 * f + j] : 0;
            if (t < 0 || t >= nuv || (o->checker > 0.0 && (v < 0 || v >= nv)))
                return err_set(err, SCAF_ERR_USAGE, "%s: triangle %d has an index out of range",
                               path, f);
        }
    double lo[2] = {0.0, 0.0}, hi[2] = {1.0, 1.0};
    int margin = 0;
    if (!o->unit_square) {
        lo[0] = lo[1] = INFINITY;
        hi[0] = hi[1] = -INFINITY;
        for (int f = 0; f < nf; f++)
            for (int j = 0; j < 3; j++) {
                const double *p = uv + 2 * (size_t)F[3 * f + j];
                for (int c = 0; c < 2; c++) {
                    if (p[c] < lo[c]) lo[c] = p[c];
                    if (p[c] > hi[c]) hi[c] = p[c];
                }
            }
        if (!(hi[0] >= lo[0] && hi[1] >= lo[1])) lo[0] = lo[1] = 0.0, hi[0] = hi[1] = 1.0;
        margin = o->size / 64; /* room for the outline */
    }
    int W, H;
    uv_raster_frame fr = uv_raster_fit(lo, hi, o->size, margin, &W, &H);
    int strip = picture_legend_strip_height(W, o->energy_legend, o->unit_square ? o->padding : 0.0);
    if (!o->unit_square && strip > 0 && H + strip > o->size && o->size - strip >= 8) {
        /* a fitted picture keeps its longer side: the layout makes room */
        fr = uv_raster_fit(lo, hi, o->size - strip, margin, &W, &H);
        if (W < o->size) W = o->size; /* the strip's width (the bar) */
        strip = picture_legend_strip_height(W, o->energy_legend, 0.0);
    }
    uv_raster_mesh m = {nf, uv, F, colour, NULL, NULL, 0.0};
    double *Vs = NULL;
    if (o->checker > 0.0) {
        /* at unit scale (geom/coord_scale, exact): the pattern does not
         * depend on the mesh's units, and its period cannot overflow */
        Vs = malloc(sizeof(double) * 3 * (size_t)nv);
        if (!Vs) return err_nomem(err, "checker positions");
        coord_scale_apply(Vs, V, 3, nv, 3 * (size_t)nf, F3,
                          coord_scale_exponent(V, 3, 3 * (size_t)nf, F3));
        double blo[3] = {INFINITY, INFINITY, INFINITY}, bhi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < 3 * (size_t)nf; i++)
            for (int c = 0; c < 3; c++) {
                double x = Vs[3 * (size_t)F3[i] + c];
                if (x < blo[c]) blo[c] = x;
                if (x > bhi[c]) bhi[c] = x;
            }
        double diag =
            sqrt((bhi[0] - blo[0]) * (bhi[0] - blo[0]) + (bhi[1] - blo[1]) * (bhi[1] - blo[1]) +
                 (bhi[2] - blo[2]) * (bhi[2] - blo[2]));
        if (diag > 0.0 && isfinite(diag)) {
            m.xyz = Vs;
            m.F3 = F3;
            m.checker = diag / o->checker;
        }
    }
    scaf_status st = uv_raster_new(r, W, H + strip, err);
    if (st != SCAF_OK) {
        free(Vs);
        err_prefix(err, "%s", path);
        return st;
    }
    uv_raster_fill(r, &fr, &m);
    free(Vs);
    if (o->outline && (st = outline(r, &fr, uv, nf, F, err)) != SCAF_OK) {
        err_prefix(err, "%s", path);
        uv_raster_free(r);
        return st;
    }
    if (o->unit_square && o->frame) picture_legend_frame(r->rgba, W, H + strip, 4, 0, 0, W, H);
    if (o->chart &&
        (st = picture_legend_chart_numbers(r, &fr, uv, nf, F, o->chart, err)) != SCAF_OK) {
        err_prefix(err, "%s", path);
        uv_raster_free(r);
        return st;
    }
    if (strip > 0)
        picture_legend_strip(r->rgba, W, H + strip, 4, H, o->energy_legend,
                             o->unit_square ? o->padding * fr.scale : 0.0);
    return SCAF_OK;
}
