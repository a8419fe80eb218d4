/* app/surface_render: pictures of closed triangle surfaces, drawn in
 * software (no GPU), flat shaded, for `--png` of the 3D commands.
 *
 * The camera is orthographic and fixed: it looks at the surface from the
 * direction (cos e sin a, sin e, cos e cos a) -- y is up, +z the front;
 * by default a = 30 degrees to the right and e = 25 degrees above: a 3/4
 * view from front-top -- and frames the projected vertices of all the
 * panels together, with a margin of 1/25 of the panel on each side, so
 * several surfaces drawn side by side (input, flowed, final) are seen
 * from the same place at the same scale.
 *
 * Shading: per face, one directional light coming from the viewer's
 * upper left (in camera coordinates (-0.4, 0.6, 0.7), normalized) plus
 * an ambient term: intensity = 0.25 + 0.75 max(0, n . l), n the face's
 * unit normal. A face seen from its back (the inside of a closed surface,
 * visible where the surface passes through itself) is drawn in a warm
 * colour, shaded with its reversed normal. The background is white, which
 * no shaded face reaches. Hidden faces are removed with a z-buffer; a
 * pixel whose centre lies on an edge shared by two faces belongs to
 * exactly one of them (exact orient2d and a half-open rule, as in
 * app/uv_raster), and of two faces at the same depth the first wins.
 * Deterministic: the same input gives the same bytes.
 */
#ifndef SCAF_APP_SURFACE_RENDER_H
#define SCAF_APP_SURFACE_RENDER_H

#include "base/error.h"

#define SURFACE_RENDER_MIN_SIZE 16
#define SURFACE_RENDER_MAX_SIZE 4096
#define SURFACE_RENDER_MAX_PANELS 8

#define SURFACE_RENDER_BACKGROUND 0xffffffu

typedef struct surface_render_options {
    int width, height; /* pixels of one panel, SURFACE_RENDER_MIN_SIZE..MAX_SIZE */
    double azimuth;    /* degrees about the vertical axis, from the front (+z) toward +x */
    double elevation;  /* degrees above the horizontal, in (-90, 90) */
} surface_render_options;

/* The defaults: 512 x 512 pixels, azimuth 30, elevation 25. */
surface_render_options surface_render_options_default(void);

/* One surface of a picture. */
typedef struct surface_view {
    int nv;
    const double *V; /* nv by 3 vertex positions (finite where referenced) */
    int nf;
    const int *F; /* nf by 3 vertex indices, 0-based */
    /* optional (zero / NULL: none), for pictures of seams and charts: */
    const unsigned *face_rgb; /* nf front colours 0xRRGGBB (NULL: grey blue) */
    int nlines;
    const int *lines;    /* nlines by 2 vertex indices: edges drawn dark over the
                         faces where they are not hidden (seams) */
    const char *caption; /* NULL, or a few words written at the top of the
                            panel (app/picture_legend) */
} surface_view;

/* n surfaces (1..SURFACE_RENDER_MAX_PANELS) side by side, left to right,
 * seen by the one camera that frames them all.
 *   o       options (NULL: defaults)
 *   rgb     output: *height rows of *width = n * o->width pixels, 3 bytes
 *           R G B each, top row first (caller frees)
 * Errors: SCAF_ERR_USAGE (panel size or count out of range, naming it),
 * SCAF_ERR_MESH (a face index out of range or a non-finite coordinate of
 * a used vertex: which one, in which panel), SCAF_ERR_NOMEM; *rgb is
 * then NULL. Zero-area faces and faces seen edge-on draw nothing. */
scaf_status surface_render_panels(int n, const surface_view *s, const surface_render_options *o,
                                  unsigned char **rgb, int *width, int *height, scaf_error *err);

/* One surface: surface_render_panels with n = 1 (the picture is
 * o->width by o->height). */
scaf_status surface_render(int nv, const double *V, int nf, const int *F,
                           const surface_render_options *o, unsigned char **rgb, scaf_error *err);

/* The panels written as a PNG file (app/png_write: whole or not at all);
 * SCAF_ERR_IO naming the path and the reason, or the errors above. */
scaf_status surface_render_png(const char *path, int n, const surface_view *s,
                               const surface_render_options *o, scaf_error *err);

#endif /* SCAF_APP_SURFACE_RENDER_H */
