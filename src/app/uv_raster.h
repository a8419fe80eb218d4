/* app/uv_raster: UV triangles drawn into an RGBA pixel buffer.
 *
 * A frame maps UV to pixel coordinates (y down). Each triangle is filled
 * with its own colour at every pixel whose centre it covers; coverage is
 * decided with the exact orient2d predicate and a half-open ownership
 * rule for centres on an edge or vertex, so a pixel centre inside a
 * triangulated region is filled by exactly one of its triangles (no
 * cracks, no double cover along shared edges). Optionally a solid 3D
 * checkerboard modulates the fill: the pixel's 3D point (barycentric in
 * its triangle) picks light or dark by the parity of floor(x/s) +
 * floor(y/s) + floor(z/s), so stretched squares show the distortion.
 * Only allocation can fail.
 */
#ifndef SCAF_APP_UV_RASTER_H
#define SCAF_APP_UV_RASTER_H

#include "base/error.h"

typedef struct uv_raster {
    int width, height;
    unsigned char *rgba; /* height rows of width pixels, R G B A, top row first */
} uv_raster;

/* UV (u, v) -> pixel (x, y) = (ox + (u - u0) * scale, oy + (v1 - v) * scale);
 * pixel (i, j) has its centre at (i + 0.5, j + 0.5). */
typedef struct uv_raster_frame {
    double u0, v1, scale, ox, oy;
} uv_raster_frame;

typedef struct uv_raster_mesh {
    int nf;
    const double *uv;       /* UV positions, 2 per vertex */
    const int *F;           /* nf by 3 UV vertex indices per triangle */
    const unsigned *colour; /* nf fill colours 0xRRGGBB */
    const double *xyz;      /* NULL, or 3D positions, 3 per vertex: checker */
    const int *F3;          /* nf by 3 indices into xyz (with xyz) */
    double checker;         /* checker cube edge in 3D units (> 0 with xyz) */
} uv_raster_mesh;

/* A width by height buffer, all transparent white (255, 255, 255, 0).
 * SCAF_ERR_NOMEM when it cannot be allocated; *r is then empty. */
scaf_status uv_raster_new(uv_raster *r, int width, int height, scaf_error *err);

void uv_raster_free(uv_raster *r);

/* The frame that fits the UV box [lo, hi] into at most long_side pixels
 * on its longer side, margin pixels on each side included; *width and
 * *height are the picture size (>= 1). A flat box counts as size 1. */
uv_raster_frame uv_raster_fit(const double lo[2], const double hi[2], int long_side, int margin,
                              int *width, int *height);

/* Fill the triangles (opaque; degenerate ones are skipped, clockwise ones
 * are drawn like counter-clockwise ones). */
void uv_raster_fill(uv_raster *r, const uv_raster_frame *fr, const uv_raster_mesh *m);

/* A 1-pixel line from a to b (UV), opaque colour rgb. */
void uv_raster_line(uv_raster *r, const uv_raster_frame *fr, const double a[2], const double b[2],
                    unsigned rgb);

/* The dark checker square's colour for a fill colour. */
unsigned uv_raster_checker_dark(unsigned rgb);

#endif /* SCAF_APP_UV_RASTER_H */
