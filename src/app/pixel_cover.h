/* app/pixel_cover: which pixel centres a 2D triangle covers, for the
 * rasterizers (app/uv_raster, app/surface_render).
 *
 * Pixel (i, j) has its centre at (i + 0.5, j + 0.5). A centre strictly
 * inside the triangle is covered; one on an edge is covered only when the
 * edge owns it (direction d = b - a owns when d.y > 0, or d.y == 0 and
 * d.x < 0: antisymmetric, so of two triangles sharing an edge with
 * bitwise the same endpoints exactly one covers it). Sides are decided by
 * the exact orient2d: no crack, no double cover along shared edges.
 */
#ifndef SCAF_APP_PIXEL_COVER_H
#define SCAF_APP_PIXEL_COVER_H

typedef struct pixel_cover {
    double p[3][2];     /* the corners, counter-clockwise (orient2d > 0) */
    int own[3];         /* edge p[k] -> p[k+1] owns its centres */
    double area2;       /* twice the signed area (floating point) */
    int i0, i1, j0, j1; /* pixel range of the bounding box, clamped */
} pixel_cover;

/* Set up the counter-clockwise triangle p over a width by height picture:
 * 0 when no pixel centre can be covered (outside the picture). */
int pixel_cover_init(pixel_cover *c, const double p[3][2], int width, int height);

/* Whether pixel (i, j) is covered. */
int pixel_cover_has(const pixel_cover *c, int i, int j);

/* Barycentric weights of the centre of pixel (i, j) (w[k] for p[k]),
 * plain floating point: for shading, not for decisions. */
void pixel_cover_weights(const pixel_cover *c, int i, int j, double w[3]);

#endif /* SCAF_APP_PIXEL_COVER_H */
