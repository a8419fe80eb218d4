/* app/uv_svg: a picture of a UV layout as plain SVG text.
 *
 * Draws the triangles of a UV map, each filled by a colour for its
 * distortion (symmetric Dirichlet energy, app/distortion_scale: dark blue
 * at an isometry, E = 4, through green and yellow to red at E = 16 and
 * above, with the colour bar below), with thin edges, and
 * optionally the scaffold triangles in grey outline underneath. The view
 * fits the drawn geometry. Written atomically (app/atomic_file).
 */
#ifndef SCAF_APP_UV_SVG_H
#define SCAF_APP_UV_SVG_H

#include <stdio.h>

#include "base/error.h"

typedef struct uv_svg_scaffold {
    int ntri;
    const int *T;        /* ntri by 3 ids: < nuv index uv, else extra */
    const double *extra; /* (max id - nuv + 1) by 2 scaffold-only positions */
} uv_svg_scaffold;

/* path      output file
 * nuv, uv   nuv by 2 positions
 * nf, F     nf by 3 UV indices per triangle
 * energy    nf per-triangle symmetric Dirichlet energies, or NULL (flat fill)
 * scaffold  NULL, or the scaffold to draw
 * title     text shown in the picture (may be NULL) */
scaf_status uv_svg_write(const char *path, int nuv, const double *uv, int nf, const int *F,
                         const double *energy, const uv_svg_scaffold *scaffold, const char *title,
                         scaf_error *err);

/* The colour bar of the distortion scale (app/distortion_scale) as an SVG
 * group id="legend": "E", 64 rects (class "scale", data-energy the
 * energy at their middle) from x to x + width at y, 14 units high, and a
 * tick with its label (class "tick") at every distortion_scale_ticks
 * value. uv_svg_write draws it below a layout shaded by energy. */
void uv_svg_colour_bar(FILE *o, double x, double y, double width);

/* The fill colour of an energy value, as 0xRRGGBB (exposed for tests). */
unsigned uv_svg_colour(double energy);

#endif /* SCAF_APP_UV_SVG_H */
