/* app/surface_render: software rasterizer of triangle surfaces (see
 * surface_render.h).
 *
 * Check, frame, draw: every panel is checked first (indices, finite
 * coordinates), then the camera basis and the one frame shared by the
 * panels are computed, then each panel's faces are drawn into its own
 * columns of the picture with its own z-buffer. Pixel positions of a
 * vertex are computed once per corner with one formula, so the two faces
 * of an edge see bitwise the same endpoints and app/pixel_cover gives
 * each pixel centre on the edge to exactly one of them.
 */
#include "app/surface_render.h"

#include "app/picture_legend.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/pixel_cover.h"
#include "app/png_write.h"
#include "geom/predicates.h"

#define PI 3.14159265358979323846

static const double ambient = 0.25, diffuse = 0.75;
static const unsigned char front_rgb[3] = {158, 184, 224}; /* outside: grey blue */
static const unsigned char back_rgb[3] = {230, 128, 77};   /* inside: orange */

surface_render_options surface_render_options_default(void)
{
    surface_render_options o = {512, 512, 30.0, 25.0};
    return o;
}

/* The camera: orthonormal right, up, toward-viewer axes, the light, and
 * the map from (right, up) coordinates to pixels of one panel. */
typedef struct camera {
    double right[3], up[3], view[3], light[3];
    double cx, cy, scale, ox, oy; /* pixel = (ox + (x - cx) s, oy - (y - cy) s) */
} camera;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize3(double a[3])
{
    double l = sqrt(dot3(a, a));
    if (l > 0.0)
        for (int k = 0; k < 3; k++) a[k] /= l;
}

static void camera_axes(const surface_render_options *o, camera *c)
{
    double a = o->azimuth * PI / 180.0, e = o->elevation * PI / 180.0;
    c->view[0] = cos(e) * sin(a);
    c->view[1] = sin(e);
    c->view[2] = cos(e) * cos(a);
    double y[3] = {0.0, 1.0, 0.0};
    cross3(y, c->view, c->right);
    normalize3(c->right);
    cross3(c->view, c->right, c->up);
    for (int k = 0; k < 3; k++)
        c->light[k] = -0.4 * c->right[k] + 0.6 * c->up[k] + 0.7 * c->view[k];
    normalize3(c->light);
}

static scaf_status check_options(const surface_render_options *o, int n, scaf_error *err)
{
    if (n < 1 || n > SURFACE_RENDER_MAX_PANELS)
        return err_set(err, SCAF_ERR_USAGE, "picture: %d panels, expected 1..%d", n,
                       SURFACE_RENDER_MAX_PANELS);
    if (o->width < SURFACE_RENDER_MIN_SIZE || o->width > SURFACE_RENDER_MAX_SIZE ||
        o->height < SURFACE_RENDER_MIN_SIZE || o->height > SURFACE_RENDER_MAX_SIZE)
        return err_set(err, SCAF_ERR_USAGE, "picture: panel size %d x %d is outside %d..%d pixels",
                       o->width, o->height, SURFACE_RENDER_MIN_SIZE, SURFACE_RENDER_MAX_SIZE);
    if (!isfinite(o->azimuth) || !(fabs(o->elevation) < 90.0))
        return err_set(err, SCAF_ERR_USAGE,
                       "picture: camera azimuth %g, elevation %g (elevation must be in (-90, 90))",
                       o->azimuth, o->elevation);
    return SCAF_OK;
}

static scaf_status check_surface(const surface_view *s, int panel, scaf_error *err)
{
    if (s->nv < 0 || s->nf < 0 || (s->nf > 0 && (!s->F || !s->V)))
        return err_set(err, SCAF_ERR_USAGE, "picture panel %d: %d vertices, %d faces", panel + 1,
                       s->nv, s->nf);
    for (int f = 0; f < s->nf; f++)
        for (int k = 0; k < 3; k++) {
            int v = s->F[3 * (size_t)f + k];
            if (v < 0 || v >= s->nv)
                return err_set(err, SCAF_ERR_MESH,
                               "picture panel %d: face %d references vertex %d but there are %d",
                               panel + 1, f, v, s->nv);
            const double *p = s->V + 3 * (size_t)v;
            if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
                return err_set(err, SCAF_ERR_MESH,
                               "picture panel %d: vertex %d has a non-finite coordinate", panel + 1,
                               v);
        }
    if (s->nlines < 0 || (s->nlines > 0 && !s->lines))
        return err_set(err, SCAF_ERR_USAGE, "picture panel %d: %d lines", panel + 1, s->nlines);
    for (int i = 0; i < 2 * s->nlines; i++)
        if (s->lines[i] < 0 || s->lines[i] >= s->nv)
            return err_set(err, SCAF_ERR_MESH,
                           "picture panel %d: line %d references vertex %d but there are %d",
                           panel + 1, i / 2, s->lines[i], s->nv);
    return SCAF_OK;
}

/* The frame that fits the projections of every used vertex of every panel
 * into one panel with a margin. */
static void camera_frame(camera *c, int n, const surface_view *s, const surface_render_options *o)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int p = 0; p < n; p++)
        for (size_t i = 0; i < 3 * (size_t)s[p].nf; i++) {
            const double *x = s[p].V + 3 * (size_t)s[p].F[i];
            double q[2] = {dot3(x, c->right), dot3(x, c->up)};
            for (int d = 0; d < 2; d++) {
                if (q[d] < lo[d]) lo[d] = q[d];
                if (q[d] > hi[d]) hi[d] = q[d];
            }
        }
    double margin = (o->width < o->height ? o->width : o->height) / 25.0;
    double inner[2] = {o->width - 2.0 * margin, o->height - 2.0 * margin};
    c->scale = INFINITY;
    for (int d = 0; d < 2; d++) {
        double ext = hi[d] - lo[d];
        if (ext > 0.0 && inner[d] / ext < c->scale) c->scale = inner[d] / ext;
    }
    if (!(c->scale < INFINITY)) c->scale = 1.0; /* empty, or a single point */
    c->cx = lo[0] <= hi[0] ? 0.5 * (lo[0] + hi[0]) : 0.0;
    c->cy = lo[1] <= hi[1] ? 0.5 * (lo[1] + hi[1]) : 0.0;
    c->ox = 0.5 * o->width;
    c->oy = 0.5 * o->height;
}

/* The shaded colour of face f (x its three corners) and whether it draws:
 * 0 for a zero-area face or one seen edge-on. p receives the pixel
 * positions counter-clockwise on screen, z their depths (larger = nearer). */
static int face_setup(const camera *c, const double *x[3], double p[3][2], double z[3],
                      const unsigned char *front_base, unsigned char rgb[3])
{
    for (int k = 0; k < 3; k++) {
        p[k][0] = c->ox + (dot3(x[k], c->right) - c->cx) * c->scale;
        p[k][1] = c->oy - (dot3(x[k], c->up) - c->cy) * c->scale;
        z[k] = dot3(x[k], c->view);
    }
    double o = orient2d(p[0], p[1], p[2]);
    if (!(o != 0.0)) return 0;
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++) e1[k] = x[1][k] - x[0][k], e2[k] = x[2][k] - x[0][k];
    cross3(e1, e2, n);
    normalize3(n);
    /* pixel y points down: a face turned toward the viewer is clockwise on screen */
    int front = o < 0.0;
    const unsigned char *base = front ? front_base : back_rgb;
    double lit = dot3(n, c->light) * (front ? 1.0 : -1.0);
    double t = ambient + diffuse * (lit > 0.0 ? lit : 0.0);
    for (int k = 0; k < 3; k++) rgb[k] = (unsigned char)lround(base[k] * t);
    if (o < 0.0) {
        double tp[2] = {p[1][0], p[1][1]}, tz = z[1];
        p[1][0] = p[2][0], p[1][1] = p[2][1], z[1] = z[2];
        p[2][0] = tp[0], p[2][1] = tp[1], z[2] = tz;
    }
    return 1;
}

/* The lines of s (seams) over its drawn faces: sampled every half pixel,
 * a sample drawn (2 x 2 pixels, dark) where it is not behind the surface
 * by more than 2 pixels' worth of depth, so a line on the visible side
 * shows and one on the far side does not. */
static void draw_lines(const camera *c, const surface_view *s, const surface_render_options *o,
                       unsigned char *rgb, int stride, int x0, const double *zbuf)
{
    int W = o->width, H = o->height;
    double slack = 2.0 / c->scale;
    for (int e = 0; e < s->nlines; e++) {
        double p[2][2], z[2];
        for (int k = 0; k < 2; k++) {
            const double *x = s->V + 3 * (size_t)s->lines[2 * e + k];
            p[k][0] = c->ox + (dot3(x, c->right) - c->cx) * c->scale;
            p[k][1] = c->oy - (dot3(x, c->up) - c->cy) * c->scale;
            z[k] = dot3(x, c->view);
        }
        double len = hypot(p[1][0] - p[0][0], p[1][1] - p[0][1]);
        int n = (int)ceil(2.0 * len) + 1;
        for (int t = 0; t <= n; t++) {
            double a = (double)t / n;
            double px = p[0][0] + a * (p[1][0] - p[0][0]), py = p[0][1] + a * (p[1][1] - p[0][1]);
            double depth = z[0] + a * (z[1] - z[0]);
            int i0 = (int)floor(px - 0.5), j0 = (int)floor(py - 0.5);
            for (int j = j0; j <= j0 + 1; j++)
                for (int i = i0; i <= i0 + 1; i++) {
                    if (i < 0 || j < 0 || i >= W || j >= H) continue;
                    if (depth + slack < zbuf[(size_t)j * W + i]) continue;
                    unsigned char *q = rgb + 3 * ((size_t)j * stride + (size_t)(x0 + i));
                    q[0] = 30, q[1] = 30, q[2] = 30;
                }
        }
    }
}

/* Draw surface s into the columns [x0, x0 + o->width) of the picture. */
static void draw_panel(const camera *c, const surface_view *s, const surface_render_options *o,
                       unsigned char *rgb, int stride, int x0, double *zbuf)
{
    int W = o->width, H = o->height;
    for (size_t i = 0; i < (size_t)W * H; i++) zbuf[i] = -INFINITY;
    for (int f = 0; f < s->nf; f++) {
        const double *x[3];
        for (int k = 0; k < 3; k++) x[k] = s->V + 3 * (size_t)s->F[3 * (size_t)f + k];
        double p[3][2], z[3];
        unsigned char col[3], base[3] = {front_rgb[0], front_rgb[1], front_rgb[2]};
        if (s->face_rgb) {
            unsigned u = s->face_rgb[f];
            base[0] = (unsigned char)(u >> 16), base[1] = (unsigned char)(u >> 8),
            base[2] = (unsigned char)u;
        }
        if (!face_setup(c, x, p, z, base, col)) continue;
        pixel_cover cov;
        if (!pixel_cover_init(&cov, (const double(*)[2])p, W, H)) continue;
        for (int j = cov.j0; j <= cov.j1; j++)
            for (int i = cov.i0; i <= cov.i1; i++) {
                if (!pixel_cover_has(&cov, i, j)) continue;
                double w[3];
                pixel_cover_weights(&cov, i, j, w);
                double depth = w[0] * z[0] + w[1] * z[1] + w[2] * z[2];
                double *zb = zbuf + (size_t)j * W + i;
                if (!(depth > *zb)) continue; /* the first of equal depths stays */
                *zb = depth;
                unsigned char *px = rgb + 3 * ((size_t)j * stride + (size_t)(x0 + i));
                px[0] = col[0], px[1] = col[1], px[2] = col[2];
            }
    }
    draw_lines(c, s, o, rgb, stride, x0, zbuf);
}

scaf_status surface_render_panels(int n, const surface_view *s, const surface_render_options *o,
                                  unsigned char **rgb, int *width, int *height, scaf_error *err)
{
    *rgb = NULL;
    surface_render_options d = surface_render_options_default();
    if (!o) o = &d;
    scaf_status st = check_options(o, n, err);
    for (int p = 0; p < n && st == SCAF_OK; p++) st = check_surface(&s[p], p, err);
    if (st != SCAF_OK) return st;
    camera c;
    camera_axes(o, &c);
    camera_frame(&c, n, s, o);
    int W = n * o->width, H = o->height;
    unsigned char *img = malloc(3 * (size_t)W * (size_t)H);
    double *zbuf = malloc(sizeof(double) * (size_t)o->width * (size_t)H);
    if (!img || !zbuf) {
        free(img);
        free(zbuf);
        return err_nomem(err, "picture buffer");
    }
    memset(img, 0xff, 3 * (size_t)W * (size_t)H); /* SURFACE_RENDER_BACKGROUND */
    for (int p = 0; p < n; p++) {
        draw_panel(&c, &s[p], o, img, W, p * o->width, zbuf);
        if (s[p].caption)
            picture_legend_caption(img, W, H, 3, p * o->width, picture_legend_scale(o->width),
                                   o->width, s[p].caption);
    }
    free(zbuf);
    *rgb = img;
    *width = W;
    *height = H;
    return SCAF_OK;
}

scaf_status surface_render(int nv, const double *V, int nf, const int *F,
                           const surface_render_options *o, unsigned char **rgb, scaf_error *err)
{
    surface_view s = {nv, V, nf, F, NULL, 0, NULL, NULL};
    int w, h;
    return surface_render_panels(1, &s, o, rgb, &w, &h, err);
}

scaf_status surface_render_png(const char *path, int n, const surface_view *s,
                               const surface_render_options *o, scaf_error *err)
{
    unsigned char *rgb;
    int w, h;
    scaf_status st = surface_render_panels(n, s, o, &rgb, &w, &h, err);
    if (st != SCAF_OK) {
        err_prefix(err, "%s", path);
        return st;
    }
    st = png_write_rgb(path, w, h, rgb, err);
    free(rgb);
    return st;
}
