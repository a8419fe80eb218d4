/* app/uv_png: a PNG picture of a UV layout, one colour per triangle.
 *
 * Draws the triangles (app/uv_raster) with the caller's colours, outlines
 * the chart boundaries (UV edges used by one triangle) in dark grey, and
 * optionally modulates the fill with a solid 3D checkerboard whose
 * squares are the 3D bounding-box diagonal / checker, so stretched or
 * sheared squares show the distortion. Outside the charts the picture is
 * transparent white.
 *
 * The legend (app/picture_legend), on request: with energy_legend the
 * colours are app/distortion_scale's and a strip below the layout holds
 * the colour bar with its energy ticks; with unit_square the square's
 * border is drawn and, with padding > 0, the strip shows a bar as long as
 * the padding at the picture's scale; with chart, each chart's number is
 * written on its largest triangle (when it fits in the chart's box). Written atomically (app/png_write); fails with
 * SCAF_ERR_USAGE (bad size), SCAF_ERR_NOMEM or SCAF_ERR_IO (path and
 * reason), and then no file is left.
 */
#ifndef SCAF_APP_UV_PNG_H
#define SCAF_APP_UV_PNG_H

#include "app/uv_raster.h"
#include "base/error.h"

#define UV_PNG_MIN_SIZE 16
#define UV_PNG_MAX_SIZE 16384

typedef struct uv_png_options {
    int size;          /* pixels of the longer side, UV_PNG_MIN_SIZE..UV_PNG_MAX_SIZE */
    int unit_square;   /* 1: the picture is the unit UV square (a texture);
                         0: it fits the layout with a small margin */
    double checker;    /* squares across the 3D bounding-box diagonal; 0 = none */
    int outline;       /* 1: draw the chart boundaries */
    int energy_legend; /* 1: the colours are distortion_scale's: add its colour bar */
    const int *chart;  /* NULL, or the chart of every triangle: their numbers drawn */
    double padding;    /* > 0 with unit_square: the padding's length in the legend */
    int frame;         /* 1 with unit_square: the square's border drawn */
} uv_png_options;

/* The defaults: 1024 pixels, fitted, no checker, outlines, no legend. */
uv_png_options uv_png_options_default(void);

/* path       output file
 * nuv, uv    nuv by 2 UV positions
 * nf, F      nf by 3 UV indices per triangle
 * colour     nf fill colours 0xRRGGBB
 * nv, V      nv by 3 3D positions, or 0 / NULL (needed for the checker)
 * F3         nf by 3 indices into V (same triangles as F), or NULL
 * o          options (NULL: defaults) */
scaf_status uv_png_write(const char *path, int nuv, const double *uv, int nf, const int *F,
                         const unsigned *colour, int nv, const double *V, const int *F3,
                         const uv_png_options *o, scaf_error *err);

/* The same picture into *r (the caller frees it with uv_raster_free)
 * instead of a file, for pictures made of several panels; name (the
 * file's) only prefixes messages. Same errors but SCAF_ERR_IO. */
scaf_status uv_png_render(const char *name, int nuv, const double *uv, int nf, const int *F,
                          const unsigned *colour, int nv, const double *V, const int *F3,
                          const uv_png_options *o, uv_raster *r, scaf_error *err);

#endif /* SCAF_APP_UV_PNG_H */
