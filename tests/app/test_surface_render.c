/* Tests for app/surface_render.
 *
 * On the generated unit icosphere (closed, outward faces) drawn with the
 * default camera: two renders give the same bytes; every pixel whose
 * centre is well inside the sphere's silhouette (a disk about the panel
 * centre whose radius is bounded from the documented margin) shows the
 * surface, every pixel well outside it is background; the point whose
 * normal is the documented light direction is brighter than a point near
 * the lower-right rim, which faces away from the light. With its faces
 * reversed the sphere is seen from inside: the warm back colour (red >
 * blue). Panels share the camera: [S, S] is twice the single picture,
 * [S, 2S] shows the left sphere at a quarter of the right one's area.
 * The PNG reads back as the buffer. Bad panel sizes and counts, bad
 * indices and non-finite coordinates are refused with no buffer. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/surface_render.h"
#include "mesh/samples.h"
#include "support/png_read.h"
#include "support/support.h"

enum { S = 256 };

static void sphere(mesh *m)
{
    assert_int_equal(mesh_sample_make("icosphere", 8, m, NULL), SCAF_OK);
}

static surface_render_options opts(void)
{
    surface_render_options o = surface_render_options_default();
    o.width = o.height = S;
    return o;
}

static const unsigned char *px(const unsigned char *img, int W, int i, int j)
{
    return img + 3 * ((size_t)j * W + i);
}

static int is_background(const unsigned char *p)
{
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

static int brightness(const unsigned char *p) { return p[0] + p[1] + p[2]; }

static unsigned char *render(const mesh *m)
{
    surface_render_options o = opts();
    unsigned char *img = NULL;
    assert_int_equal(surface_render(m->nv, m->V, m->nf, m->F, &o, &img, NULL), SCAF_OK);
    assert_non_null(img);
    return img;
}

static void deterministic_and_covers_the_silhouette(void **state)
{
    (void)state;
    mesh m;
    sphere(&m);
    unsigned char *a = render(&m), *b = render(&m);
    assert_memory_equal(a, b, 3 * (size_t)S * S);
    /* the vertices' projections span at most the inner square (panel minus
     * the 1/25 margin on each side) and at least 0.98 of it (the icosphere's
     * vertices lie on the unit sphere, its faces inside it) */
    double inner = S - 2.0 * S / 25.0, r_min = 0.98 * inner / 2, r_max = inner / 2 / 0.98;
    int surface = 0;
    for (int j = 0; j < S; j++)
        for (int i = 0; i < S; i++) {
            double d = hypot(i + 0.5 - S / 2.0, j + 0.5 - S / 2.0);
            const unsigned char *p = px(a, S, i, j);
            if (d < 0.97 * r_min) assert_false(is_background(p));
            if (d > r_max + 1) assert_true(is_background(p));
            surface += !is_background(p);
        }
    assert_true(surface > 0.9 * 3.14159 * r_min * r_min);
    free(a);
    free(b);
    mesh_free(&m);
}

static void lit_side_is_brighter(void **state)
{
    (void)state;
    mesh m;
    sphere(&m);
    unsigned char *img = render(&m);
    double l[3] = {-0.4, 0.6, 0.7}, n = sqrt(0.16 + 0.36 + 0.49);
    double r = (S - 2.0 * S / 25.0) / 2;
    /* screen y points down: the lit point is at (l.x, -l.y) r from the centre */
    int li = (int)(S / 2.0 + l[0] / n * r), lj = (int)(S / 2.0 - l[1] / n * r);
    /* near the lower-right rim the normal is about (0.52, -0.79, 0.31): n . l < 0 */
    int di = (int)(S / 2.0 + 0.55 * 0.9 * r), dj = (int)(S / 2.0 + 0.83 * 0.9 * r);
    const unsigned char *lit = px(img, S, li, lj), *dark = px(img, S, di, dj);
    assert_false(is_background(lit));
    assert_false(is_background(dark));
    assert_true(brightness(lit) > brightness(dark) + 150);
    /* outside: the cool colour */
    assert_true(lit[2] > lit[0]);
    free(img);
    mesh_free(&m);
}

static void inside_out_shows_the_back_colour(void **state)
{
    (void)state;
    mesh m;
    sphere(&m);
    for (int f = 0; f < m.nf; f++) {
        int t = m.F[3 * f + 1];
        m.F[3 * f + 1] = m.F[3 * f + 2];
        m.F[3 * f + 2] = t;
    }
    unsigned char *img = render(&m);
    const unsigned char *c = px(img, S, S / 2, S / 2);
    assert_false(is_background(c));
    assert_true(c[0] > c[2]);
    free(img);
    mesh_free(&m);
}

static int count_surface(const unsigned char *img, int W, int x0, int w, int h)
{
    int n = 0;
    for (int j = 0; j < h; j++)
        for (int i = x0; i < x0 + w; i++) n += !is_background(px(img, W, i, j));
    return n;
}

static void panels_share_the_camera(void **state)
{
    (void)state;
    mesh m, big;
    sphere(&m);
    sphere(&big);
    for (int k = 0; k < 3 * big.nv; k++) big.V[k] *= 2.0;
    surface_render_options o = opts();
    surface_view same[2] = {{m.nv, m.V, m.nf, m.F, NULL, 0, NULL, NULL},
                            {m.nv, m.V, m.nf, m.F, NULL, 0, NULL, NULL}};
    unsigned char *img = NULL, *one = render(&m);
    int W = 0, H = 0;
    assert_int_equal(surface_render_panels(2, same, &o, &img, &W, &H, NULL), SCAF_OK);
    assert_int_equal(W, 2 * S);
    assert_int_equal(H, S);
    for (int j = 0; j < S; j++) {
        assert_memory_equal(px(img, W, 0, j), px(one, S, 0, j), 3 * S);
        assert_memory_equal(px(img, W, S, j), px(one, S, 0, j), 3 * S);
    }
    free(img);
    surface_view two[2] = {{m.nv, m.V, m.nf, m.F, NULL, 0, NULL, NULL},
                           {big.nv, big.V, big.nf, big.F, NULL, 0, NULL, NULL}};
    assert_int_equal(surface_render_panels(2, two, &o, &img, &W, &H, NULL), SCAF_OK);
    double small = count_surface(img, W, 0, S, S), large = count_surface(img, W, S, S, S);
    assert_true(large > 0.9 * count_surface(one, S, 0, S, S));
    assert_true(fabs(small / large - 0.25) < 0.02);
    free(img);
    free(one);
    mesh_free(&m);
    mesh_free(&big);
}

static void png_reads_back(void **state)
{
    (void)state;
    mesh m;
    sphere(&m);
    char path[512];
    test_tmp_path("surface_render.png", path, sizeof path);
    remove(path);
    surface_render_options o = opts();
    surface_view v = {m.nv, m.V, m.nf, m.F, NULL, 0, NULL, NULL};
    assert_int_equal(surface_render_png(path, 1, &v, &o, NULL), SCAF_OK);
    int w = 0, h = 0;
    unsigned char *rgba = test_png_read(path, &w, &h), *img = render(&m);
    assert_non_null(rgba);
    assert_int_equal(w, S);
    assert_int_equal(h, S);
    for (size_t i = 0; i < (size_t)S * S; i++) {
        assert_memory_equal(rgba + 4 * i, img + 3 * i, 3);
        assert_int_equal(rgba[4 * i + 3], 255);
    }
    free(rgba);
    free(img);
    scaf_error err;
    char bad[512];
    test_tmp_path("no_such_folder/surface.png", bad, sizeof bad);
    assert_int_equal(surface_render_png(bad, 1, &v, &o, &err), SCAF_ERR_IO);
    assert_non_null(strstr(err.message, bad));
    assert_false(test_exists(bad));
    mesh_free(&m);
}

static void refuses_bad_input(void **state)
{
    (void)state;
    mesh m;
    sphere(&m);
    surface_view v = {m.nv, m.V, m.nf, m.F, NULL, 0, NULL, NULL};
    unsigned char *img = (unsigned char *)&v; /* must come back NULL */
    int W, H;
    scaf_error err;
    int sizes[][2] = {{15, 100}, {100, 15}, {4097, 100}, {100, 4097}, {0, 0}, {-5, 100}};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        surface_render_options o = opts();
        o.width = sizes[k][0];
        o.height = sizes[k][1];
        assert_int_equal(surface_render_panels(1, &v, &o, &img, &W, &H, &err), SCAF_ERR_USAGE);
        assert_null(img);
        assert_non_null(strstr(err.message, "panel size"));
    }
    surface_render_options o = opts();
    assert_int_equal(surface_render_panels(0, &v, &o, &img, &W, &H, &err), SCAF_ERR_USAGE);
    assert_int_equal(
        surface_render_panels(SURFACE_RENDER_MAX_PANELS + 1, &v, &o, &img, &W, &H, &err),
        SCAF_ERR_USAGE);
    o.elevation = 90;
    assert_int_equal(surface_render_panels(1, &v, &o, &img, &W, &H, &err), SCAF_ERR_USAGE);
    o = opts();
    m.F[3 * 7 + 1] = m.nv;
    assert_int_equal(surface_render_panels(1, &v, &o, &img, &W, &H, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "face 7"));
    assert_null(img);
    m.F[3 * 7 + 1] = 0;
    m.V[3 * m.F[3 * 9] + 2] = NAN;
    assert_int_equal(surface_render_panels(1, &v, &o, &img, &W, &H, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "non-finite"));
    assert_null(img);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(deterministic_and_covers_the_silhouette),
        cmocka_unit_test(lit_side_is_brighter),
        cmocka_unit_test(inside_out_shows_the_back_colour),
        cmocka_unit_test(panels_share_the_camera),
        cmocka_unit_test(png_reads_back),
        cmocka_unit_test(refuses_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
