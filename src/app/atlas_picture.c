/* app/atlas_picture: the surface beside its atlas (see the header). */
#include "app/atlas_picture.h"

#include <stdlib.h>
#include <string.h>

#include "app/picture_legend.h"
#include "app/png_write.h"
#include "app/uv_png.h"

scaf_status atlas_picture_png(const char *path, const surface_view views[2], int nuv,
                              const double *uv, int nf, const int *FT, const unsigned *colour,
                              int panel, scaf_error *err)
{
    if (panel < SURFACE_RENDER_MIN_SIZE || panel > SURFACE_RENDER_MAX_SIZE)
        return err_set(err, SCAF_ERR_USAGE, "%s: panel size %d is outside %d..%d pixels", path,
                       panel, SURFACE_RENDER_MIN_SIZE, SURFACE_RENDER_MAX_SIZE);
    surface_render_options so = surface_render_options_default();
    so.width = so.height = panel;
    unsigned char *rgb3 = NULL;
    int w3 = 0, h3 = 0;
    scaf_status st = surface_render_panels(2, views, &so, &rgb3, &w3, &h3, err);
    if (st != SCAF_OK) {
        err_prefix(err, "%s", path);
        return st;
    }
    uv_png_options uo = uv_png_options_default();
    uo.size = panel - 2 * (panel / 25); /* the 3D panels' margin */
    uo.unit_square = 1;
    uv_raster r;
    st = uv_png_render(path, nuv, uv, nf, FT, colour, 0, NULL, NULL, &uo, &r, err);
    if (st != SCAF_OK) {
        free(rgb3);
        return st;
    }
    int W = w3 + panel, H = h3;
    unsigned char *out = malloc((size_t)W * (size_t)H * 3);
    if (!out) {
        free(rgb3);
        uv_raster_free(&r);
        return err_nomem(err, "picture");
    }
    memset(out, 0xff, (size_t)W * (size_t)H * 3);
    for (int y = 0; y < h3; y++)
        memcpy(out + (size_t)y * W * 3, rgb3 + (size_t)y * w3 * 3, (size_t)w3 * 3);
    /* the atlas centred in the third panel, over white; its square framed
     * in light grey so the unit square's extent shows */
    int ox = w3 + (panel - r.width) / 2, oy = (H - r.height) / 2;
    for (int y = 0; y < r.height; y++)
        for (int x = 0; x < r.width; x++) {
            const unsigned char *p = r.rgba + ((size_t)y * r.width + x) * 4;
            unsigned char *q = out + ((size_t)(oy + y) * W + (size_t)(ox + x)) * 3;
            int frame = x == 0 || y == 0 || x == r.width - 1 || y == r.height - 1;
            for (int c = 0; c < 3; c++) {
                int under = frame ? 0xc0 : 0xff;
                q[c] = (unsigned char)((p[c] * p[3] + under * (255 - p[3]) + 127) / 255);
            }
        }
    uv_raster_free(&r);
    free(rgb3);
    picture_legend_caption(out, W, H, 3, w3, picture_legend_scale(panel), panel,
                           "atlas: unit square");
    st = png_write_rgb(path, W, H, out, err);
    free(out);
    return st;
}
