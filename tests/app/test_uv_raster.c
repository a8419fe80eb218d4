/* Tests for app/uv_raster, app/png_write and app/uv_png.
 *
 * Coverage: triangles drawn one at a time into separate buffers; every
 * pixel centre strictly inside the triangulated region must be covered by
 * exactly one triangle (no crack, no double cover), centres outside by
 * none, including centres lying exactly on shared edges and vertices
 * (dyadic coordinates make those cases exact) and a jittered grid at an
 * awkward scale. PNG: a two-chart layout written, read back with libpng
 * and checked for size, palette colours, transparent background. Checker:
 * along a row and a column of a chart stretched 3x in x, the shade
 * follows the parity of the 3D cells computed here independently.
 * Failures: unwritable paths give SCAF_ERR_IO naming the path and leave no
 * file or temporary behind; a bad size is refused. */
#include <dirent.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <cmocka.h>

#include "app/atlas_report.h"
#include "app/png_write.h"
#include "app/uv_png.h"
#include "app/uv_raster.h"
#include "support/png_read.h"
#include "support/support.h"

/* Draw each triangle alone and add up, per pixel, how many covered it. */
static int *coverage(int W, int H, const uv_raster_frame *fr, const double *uv, int nf,
                     const int *F)
{
    int *count = calloc((size_t)W * H, sizeof(int));
    assert_non_null(count);
    unsigned col = 0x123456u;
    for (int f = 0; f < nf; f++) {
        uv_raster r;
        assert_int_equal(uv_raster_new(&r, W, H, NULL), SCAF_OK);
        uv_raster_mesh m = {1, uv, F + 3 * f, &col, NULL, NULL, 0.0};
        uv_raster_fill(&r, fr, &m);
        for (int k = 0; k < W * H; k++) count[k] += r.rgba[4 * k + 3] == 255;
        uv_raster_free(&r);
    }
    return count;
}

static void fan_covers_each_centre_once(void **state)
{
    (void)state;
    /* frame: pixel x = u, pixel y = 32 - v (exact). The square
     * [2, 29.5] x [2.5, 30] in pixels, fan around (16.5, 16.5), which is
     * itself a pixel centre; the diagonals run through pixel centres. */
    const int W = 32, H = 32;
    uv_raster_frame fr = {0.0, 32.0, 1.0, 0.0, 0.0};
    double px[9][2] = {{16.5, 16.5}, {2, 2.5},   {16.5, 2.5}, {29.5, 2.5}, {29.5, 16.5},
                       {29.5, 30},   {16.5, 30}, {2, 30},     {2, 16.5}};
    double uv[18];
    for (int i = 0; i < 9; i++) uv[2 * i] = px[i][0], uv[2 * i + 1] = 32.0 - px[i][1];
    int F[24];
    for (int k = 0; k < 8; k++) {
        F[3 * k] = 0;
        F[3 * k + 1] = 1 + k;
        F[3 * k + 2] = 1 + (k + 1) % 8;
        if (k % 2) { /* mixed orientations are drawn alike */
            F[3 * k + 1] = 1 + (k + 1) % 8;
            F[3 * k + 2] = 1 + k;
        }
    }
    int *count = coverage(W, H, &fr, uv, 8, F);
    int inside = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double x = i + 0.5, y = j + 0.5;
            int strictly_in = x > 2 && x < 29.5 && y > 2.5 && y < 30;
            int out = x < 2 || x > 29.5 || y < 2.5 || y > 30;
            if (strictly_in) {
                inside++;
                if (count[j * W + i] != 1)
                    fail_msg("pixel (%d, %d) covered %d times", i, j, count[j * W + i]);
            }
            if (out) assert_int_equal(count[j * W + i], 0);
        }
    assert_int_equal(inside, 27 * 27); /* the square has 27 x 27 centres strictly inside */
    free(count);
}

static void jittered_grid_has_no_cracks(void **state)
{
    (void)state;
    /* n x n grid cells on [0, 1]^2, interior vertices jittered, drawn at a
     * scale that puts vertices at arbitrary sub-pixel positions. */
    enum { n = 7 };
    double uv[2 * (n + 1) * (n + 1)];
    uint32_t s = 12345u;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double du = 0.0, dv = 0.0;
            if (i > 0 && i < n && j > 0 && j < n) {
                s = s * 1664525u + 1013904223u;
                du = ((s >> 8) / 16777216.0 - 0.5) * 0.6 / n;
                s = s * 1664525u + 1013904223u;
                dv = ((s >> 8) / 16777216.0 - 0.5) * 0.6 / n;
            }
            uv[2 * (j * (n + 1) + i)] = (double)i / n + du;
            uv[2 * (j * (n + 1) + i) + 1] = (double)j / n + dv;
        }
    int F[6 * n * n], nf = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            int even[6] = {a, b, c, a, c, d}, odd[6] = {a, b, d, b, c, d}; /* both diagonals */
            const int *t = (i + j) % 2 ? odd : even;
            memcpy(F + 3 * nf, t, sizeof(int) * 6);
            nf += 2;
        }
    const int W = 61, H = 61;
    double scale = 57.3;
    uv_raster_frame fr = {0.0, 1.0, scale, 1.7, 1.9};
    int *count = coverage(W, H, &fr, uv, nf, F);
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double u = (i + 0.5 - 1.7) / scale, v = 1.0 - (j + 0.5 - 1.9) / scale;
            /* a margin of 1e-9 keeps clear of rounding in this inverse map */
            if (u > 1e-9 && u < 1 - 1e-9 && v > 1e-9 && v < 1 - 1e-9) {
                if (count[j * W + i] != 1)
                    fail_msg("pixel (%d, %d) covered %d times", i, j, count[j * W + i]);
            } else if (u < -1e-9 || u > 1 + 1e-9 || v < -1e-9 || v > 1 + 1e-9) {
                assert_int_equal(count[j * W + i], 0);
            }
        }
    free(count);
}

/* Two charts in the unit square: quads [0.1, 0.4]^2 and [0.6, 0.9] x [0.1, 0.4]. */
static const double two_uv[16] = {0.1, 0.1, 0.4, 0.1, 0.4, 0.4, 0.1, 0.4,
                                  0.6, 0.1, 0.9, 0.1, 0.9, 0.4, 0.6, 0.4};
static const int two_F[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};

static void png_two_charts_read_back(void **state)
{
    (void)state;
    char path[512];
    test_tmp_path("raster_two_charts.png", path, sizeof path);
    remove(path);
    unsigned col[4] = {atlas_chart_colour(0), atlas_chart_colour(0), atlas_chart_colour(1),
                       atlas_chart_colour(1)};
    assert_int_not_equal(col[0], col[2]);
    uv_png_options o = uv_png_options_default();
    o.size = 100;
    o.unit_square = 1;
    scaf_error err;
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_OK);
    int w = 0, h = 0, a;
    unsigned char *buf = test_png_read(path, &w, &h);
    assert_non_null(buf);
    assert_int_equal(w, 100);
    assert_int_equal(h, 100);
    /* unit square = picture: u = 0.25 -> x = 25, v = 0.25 -> y = 75 */
    unsigned c0 = test_png_pixel(buf, w, 25, 75, &a);
    assert_int_equal(a, 255);
    assert_int_equal(c0, col[0]);
    unsigned c1 = test_png_pixel(buf, w, 75, 75, &a);
    assert_int_equal(a, 255);
    assert_int_equal(c1, col[2]);
    assert_int_not_equal(c0, c1);
    /* background: between the charts, above them, in the corners */
    int bg[4][2] = {{50, 75}, {25, 25}, {0, 0}, {99, 99}};
    for (int k = 0; k < 4; k++) {
        test_png_pixel(buf, w, bg[k][0], bg[k][1], &a);
        assert_int_equal(a, 0);
    }
    /* every centre strictly inside chart 0, away from the outline (2 px), has its colour */
    for (int j = 62; j <= 87; j++)
        for (int i = 12; i <= 37; i++) {
            assert_int_equal(test_png_pixel(buf, w, i, j, &a), col[0]);
            assert_int_equal(a, 255);
        }
    /* the outline: a dark pixel on the left boundary of chart 0 (u = 0.1 -> x = 10) */
    unsigned e = test_png_pixel(buf, w, 10, 75, &a);
    assert_int_equal(a, 255);
    assert_true(((e >> 16) & 255) < 0x60 && ((e >> 8) & 255) < 0x60 && (e & 255) < 0x60);
    free(buf);

    /* a fitted picture keeps the aspect ratio: 0.8 by 0.3 -> 100 by about 38 */
    o.unit_square = 0;
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_OK);
    buf = test_png_read(path, &w, &h);
    assert_non_null(buf);
    assert_int_equal(w, 100);
    assert_true(h >= 36 && h <= 40);
    free(buf);
}

/* Parity of the 3D checker cell of point (x, y, z), cell size c. */
static int cell_parity(double x, double y, double z, double c)
{
    long long k = (long long)floor(x / c) + (long long)floor(y / c) + (long long)floor(z / c);
    return (int)(k & 1);
}

static double dist_to_grid(double x, double c)
{
    double t = x / c;
    return fabs(t - floor(t + 0.5)) * c;
}

static void checker_follows_3d_cells(void **state)
{
    (void)state;
    /* one chart, the unit UV square, whose 3D image is stretched 3x in x:
     * (u, v) -> (3u, v, 0.25). A 3D square of side c shows as c/3 in u and
     * c in v: the row changes shade 3x more often than the column. */
    const double uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const double V[12] = {0, 0, 0.25, 3, 0, 0.25, 3, 1, 0.25, 0, 1, 0.25};
    const int F[6] = {0, 1, 2, 0, 2, 3};
    const unsigned col[2] = {0xc0d0e0u, 0xc0d0e0u};
    const int S = 240;
    uv_raster r;
    assert_int_equal(uv_raster_new(&r, S, S, NULL), SCAF_OK);
    uv_raster_frame fr = {0.0, 1.0, (double)S, 0.0, 0.0};
    double c = 0.2;
    uv_raster_mesh m = {2, uv, F, col, V, F, c};
    uv_raster_fill(&r, &fr, &m);
    unsigned dark = 0;
    int row_changes = 0, col_changes = 0, prev = -1, checked = 0;
    for (int pass = 0; pass < 2; pass++) {
        prev = -1;
        for (int k = 0; k < S; k++) {
            int i = pass == 0 ? k : S / 2 + 7, j = pass == 0 ? S / 2 + 7 : k;
            double u = (i + 0.5) / S, v = 1.0 - (j + 0.5) / S;
            double x = 3 * u, y = v, z = 0.25;
            int a;
            unsigned got = test_png_pixel(r.rgba, S, i, j, &a);
            assert_int_equal(a, 255);
            int par = cell_parity(x, y, z, c);
            if (prev >= 0 && par != prev) {
                if (pass == 0) row_changes++;
                else col_changes++;
            }
            prev = par;
            if (dist_to_grid(x, c) < 1e-6 || dist_to_grid(y, c) < 1e-6)
                continue; /* on a cell face */
            checked++;
            if (par == 0) {
                assert_int_equal(got, col[0]);
            } else {
                assert_int_not_equal(got, col[0]);
                if (!dark) dark = got;
                assert_int_equal(got, dark); /* one dark shade */
            }
        }
    }
    assert_true(checked > 400);
    /* 3D extent 3 along the row, 1 along the column, cells of 0.2 */
    assert_int_equal(row_changes, 14);
    assert_int_equal(col_changes, 4);
    uv_raster_free(&r);
}

static void png_checker_squares_from_diagonal(void **state)
{
    (void)state;
    /* uv_png: N squares across the 3D bounding-box diagonal. The same
     * stretched quad, written and read back; the diagonal of the 3D box
     * [0, 3] x [0, 1] x {0.25} is sqrt(10). */
    const double uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const double V[12] = {0, 0, 0.25, 3, 0, 0.25, 3, 1, 0.25, 0, 1, 0.25};
    const int F[6] = {0, 1, 2, 0, 2, 3};
    const unsigned col[2] = {0x80c0ffu, 0x80c0ffu};
    char path[512];
    test_tmp_path("raster_checker.png", path, sizeof path);
    uv_png_options o = uv_png_options_default();
    o.size = 300;
    o.unit_square = 1;
    o.outline = 0;
    o.checker = 25;
    scaf_error err;
    assert_int_equal(uv_png_write(path, 4, uv, 2, F, col, 4, V, F, &o, &err), SCAF_OK);
    int w, h;
    unsigned char *buf = test_png_read(path, &w, &h);
    assert_non_null(buf);
    assert_int_equal(w, 300);
    assert_int_equal(h, 300);
    double c = sqrt(10.0) / 25.0;
    int checked = 0, changes = 0, prev = -1;
    unsigned dark = 0;
    for (int i = 0; i < 300; i++) {
        int j = 101, a;
        double x = 3.0 * (i + 0.5) / 300, y = 1.0 - (j + 0.5) / 300;
        int par = cell_parity(x, y, 0.25, c);
        if (prev >= 0 && par != prev) changes++;
        prev = par;
        if (dist_to_grid(x, c) < 1e-6 || dist_to_grid(y, c) < 1e-6) continue;
        unsigned got = test_png_pixel(buf, w, i, j, &a);
        assert_int_equal(a, 255);
        checked++;
        if (!par) {
            assert_int_equal(got, col[0]);
        } else {
            assert_int_not_equal(got, col[0]);
            if (!dark) dark = got;
            assert_int_equal(got, dark);
        }
    }
    assert_true(checked > 250);
    assert_int_equal(changes, (int)floor(3.0 / c)); /* cell faces crossed in x in (0, 3) */
    free(buf);
}

/* Whether the tmp folder holds a file whose name starts with prefix. */
static int tmp_has_prefix(const char *prefix)
{
    char dir[512];
    test_tmp_path("", dir, sizeof dir);
    DIR *d = opendir(dir);
    assert_non_null(d);
    int found = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (!strncmp(e->d_name, prefix, strlen(prefix))) found = 1;
    closedir(d);
    return found;
}

static void write_failures_leave_nothing(void **state)
{
    (void)state;
    unsigned char px[16 * 16 * 4];
    memset(px, 200, sizeof px);
    char path[512];
    scaf_error err;
    /* a folder that does not exist */
    test_tmp_path("no_such_folder/x.png", path, sizeof path);
    err_clear(&err);
    assert_int_equal(png_write_rgba(path, 16, 16, px, &err), SCAF_ERR_IO);
    assert_non_null(strstr(err.message, path));
    assert_false(test_exists(path));
    /* the target is a folder: the temporary is written, the rename fails */
    test_tmp_path("png_target_is_dir", path, sizeof path);
    mkdir(path, 0755);
    err_clear(&err);
    assert_int_equal(png_write_rgba(path, 16, 16, px, &err), SCAF_ERR_IO);
    assert_non_null(strstr(err.message, path));
    assert_false(tmp_has_prefix(".png_target_is_dir.tmp"));
    /* uv_png: the same through the whole picture path, and a bad size */
    unsigned col[4] = {1, 2, 3, 4};
    uv_png_options o = uv_png_options_default();
    test_tmp_path("no_such_folder/y.png", path, sizeof path);
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_ERR_IO);
    assert_false(test_exists(path));
    test_tmp_path("raster_bad_size.png", path, sizeof path);
    remove(path);
    o.size = UV_PNG_MIN_SIZE - 1;
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_ERR_USAGE);
    o.size = UV_PNG_MAX_SIZE + 1;
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_ERR_USAGE);
    assert_false(test_exists(path));
    /* checker without 3D positions, index out of range */
    o = uv_png_options_default();
    o.checker = 10;
    assert_int_equal(uv_png_write(path, 8, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_ERR_USAGE);
    o.checker = 0;
    assert_int_equal(uv_png_write(path, 7, two_uv, 4, two_F, col, 0, NULL, NULL, &o, &err),
                     SCAF_ERR_USAGE);
    assert_false(test_exists(path));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fan_covers_each_centre_once),
        cmocka_unit_test(jittered_grid_has_no_cracks),
        cmocka_unit_test(png_two_charts_read_back),
        cmocka_unit_test(checker_follows_3d_cells),
        cmocka_unit_test(png_checker_squares_from_diagonal),
        cmocka_unit_test(write_failures_leave_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
