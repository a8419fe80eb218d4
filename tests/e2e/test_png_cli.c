/* End-to-end tests of the PNG pictures of `scaf atlas` and `scaf param`.
 *
 * Atlas: a generated six-chart sample with --png --png-size 200 --png-plain
 * (the texture, no legend: tests/cli/test_picture_legend has those); the PNG
 * is read back with libpng: 200 x 200, transparent outside the charts,
 * and at a pixel deep inside each output triangle (found from the
 * written OBJ) the colour is one of the atlas palette colours, the same
 * for the triangles of one chart and different between charts. With
 * --checker the same pixels show both the chart colour and a darker
 * shade. Param: the picture's longer side is --png-size. Errors: a bad
 * --png-size, --checker without --png -> exit 2 and no output; an
 * unwritable PNG path -> exit 5 and no PNG. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas_report.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_charts.h"
#include "support/png_read.h"
#include "support/support.h"

/* Distance in pixels from point c to the line through a and b. */
static double line_dist(const double a[2], const double b[2], const double c[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    return fabs(dx * (c[1] - a[1]) - dy * (c[0] - a[0])) / sqrt(dx * dx + dy * dy);
}

/* Per face: the colour of a pixel whose centre lies inside the face at
 * least 2 pixels from its edges (so no outline), or -1 when there is none
 * near the centroid. Picture = unit square, S pixels. */
static long deep_pixel(const mesh *m, int f, const unsigned char *img, int S)
{
    double p[3][2], c[2] = {0, 0};
    for (int j = 0; j < 3; j++) {
        const double *t = m->UV + 2 * (size_t)m->FT[3 * f + j];
        p[j][0] = t[0] * S;
        p[j][1] = (1.0 - t[1]) * S;
        c[0] += p[j][0] / 3;
        c[1] += p[j][1] / 3;
    }
    double q[2] = {floor(c[0]) + 0.5, floor(c[1]) + 0.5};
    double area2 =
        (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    for (int j = 0; j < 3; j++) {
        const double *a = p[j], *b = p[(j + 1) % 3];
        double side = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
        if (side * area2 <= 0.0 || line_dist(a, b, q) < 2.0) return -1;
    }
    int i = (int)q[0], k = (int)q[1], alpha;
    if (i < 0 || k < 0 || i >= S || k >= S) return -1;
    unsigned col = test_png_pixel(img, S, i, k, &alpha);
    assert_int_equal(alpha, 255);
    return (long)col;
}

static void cli_atlas_png(void **state)
{
    (void)state;
    char in[512], out[512], png[512], chk[512];
    test_tmp_path("e2e_png_in.obj", in, sizeof in);
    test_tmp_path("e2e_png_out.obj", out, sizeof out);
    test_tmp_path("e2e_png_atlas.png", png, sizeof png);
    test_tmp_path("e2e_png_atlas_checker.png", chk, sizeof chk);
    remove(png);
    remove(chk);
    assert_int_equal(test_run("%s gen cubesphere --size 4 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s atlas %s -o %s --iterations 4 --compact-iterations 4 --quiet "
                              "--png %s "
                              "--png-size 200 --png-plain",
                              SCAF_BINARY, in, out, png),
                     0);
    assert_int_equal(test_run("%s atlas %s -o %s --iterations 4 --compact-iterations 4 --quiet "
                              "--png %s "
                              "--png-size 200 --png-plain --checker 12",
                              SCAF_BINARY, in, out, chk),
                     0);
    int w = 0, h = 0;
    unsigned char *img = test_png_read(png, &w, &h);
    assert_non_null(img);
    assert_int_equal(w, 200);
    assert_int_equal(h, 200);
    int cw = 0, ch = 0;
    unsigned char *cimg = test_png_read(chk, &cw, &ch);
    assert_non_null(cimg);
    assert_int_equal(cw, 200);
    assert_int_equal(ch, 200);

    mesh m;
    scaf_error err;
    assert_int_equal(mesh_read(out, &m, NULL, &err), SCAF_OK);
    int *lab = malloc(sizeof(int) * (size_t)m.nf), nc = 0;
    assert_non_null(lab);
    assert_int_equal(mesh_uv_chart_labels(&m, lab, &nc, &err), SCAF_OK);
    assert_int_equal(nc, 6);
    long colour_of[6] = {-1, -1, -1, -1, -1, -1};
    int sampled = 0, light = 0, dark = 0;
    for (int f = 0; f < m.nf; f++) {
        long c = deep_pixel(&m, f, img, 200);
        if (c < 0) continue;
        sampled++;
        int in_palette = 0;
        for (int k = 0; k < nc; k++) in_palette |= (unsigned)c == atlas_chart_colour(k);
        assert_true(in_palette);
        if (colour_of[lab[f]] < 0) colour_of[lab[f]] = c;
        assert_int_equal(colour_of[lab[f]], c); /* one colour per chart */
        long cc = deep_pixel(&m, f, cimg, 200);
        if (cc == c) light++;
        else {
            /* darker in every channel */
            for (int s = 0; s < 24; s += 8) assert_true(((cc >> s) & 255) < ((c >> s) & 255));
            dark++;
        }
    }
    for (int k = 0; k < nc; k++) assert_true(colour_of[k] >= 0); /* every chart sampled */
    assert_true(sampled >= 6);
    for (int a = 0; a < nc; a++)
        for (int b = a + 1; b < nc; b++)
            if (colour_of[a] >= 0 && colour_of[b] >= 0)
                assert_int_not_equal(colour_of[a], colour_of[b]);
    assert_true(light > 0 && dark > 0);
    /* outside the charts: the corners of the unit square hold no chart here, some pixel is transparent */
    int transparent = 0, alpha;
    for (int j = 0; j < 200; j++)
        for (int i = 0; i < 200; i++) {
            test_png_pixel(img, 200, i, j, &alpha);
            transparent += alpha == 0;
        }
    assert_true(transparent > 200 * 200 / 10);
    free(lab);
    mesh_free(&m);
    free(img);
    free(cimg);
}

static void cli_param_png(void **state)
{
    (void)state;
    char in[512], out[512], png[512];
    test_tmp_path("e2e_png_hemi.obj", in, sizeof in);
    test_tmp_path("e2e_png_hemi_out.obj", out, sizeof out);
    test_tmp_path("e2e_png_param.png", png, sizeof png);
    remove(png);
    assert_int_equal(test_run("%s gen hemisphere --size 6 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s param %s -o %s --iterations 5 --quiet --png %s --png-size 200 "
                              "--checker",
                              SCAF_BINARY, in, out, png),
                     0);
    int w = 0, h = 0, alpha;
    unsigned char *img = test_png_read(png, &w, &h);
    assert_non_null(img);
    assert_int_equal(w > h ? w : h, 200);
    assert_true(w >= 16 && h >= 16);
    /* the disk's middle is drawn, the picture corner is not */
    test_png_pixel(img, w, w / 2, h / 2, &alpha);
    assert_int_equal(alpha, 255);
    test_png_pixel(img, w, 0, 0, &alpha);
    assert_int_equal(alpha, 0);
    free(img);
}

static void cli_png_errors(void **state)
{
    (void)state;
    char in[512], out[512], png[512];
    test_tmp_path("e2e_png_err_in.obj", in, sizeof in);
    test_tmp_path("e2e_png_err_out.obj", out, sizeof out);
    test_tmp_path("e2e_png_err.png", png, sizeof png);
    remove(out);
    remove(png);
    assert_int_equal(test_run("%s gen cubesphere --size 2 -o %s", SCAF_BINARY, in), 0);
    const char *cmds[] = {"atlas", "param"};
    const char *bad[] = {"--png %s --png-size 15",  "--png %s --png-size 16385",
                         "--png %s --png-size abc", "--png %s --png-size",
                         "--png-size 100",          "--checker",
                         "--png %s --checker 0"};
    for (int c = 0; c < 2; c++)
        for (size_t b = 0; b < sizeof bad / sizeof *bad; b++) {
            char opts[1024], cmd[4096];
            snprintf(opts, sizeof opts, bad[b], png);
            snprintf(cmd, sizeof cmd, "%s %s %s -o %s --quiet %s 2> /dev/null", SCAF_BINARY,
                     cmds[c], in, out, opts);
            int rc = test_run("%s", cmd);
            if (rc != 2) fail_msg("exit %d, not 2: %s", rc, cmd);
            assert_false(test_exists(out));
            assert_false(test_exists(png));
        }
    /* the PNG's folder does not exist: exit 5, no PNG */
    test_tmp_path("no_such_folder/e2e.png", png, sizeof png);
    /* (param: the atlas has a fixed packing cost, slow under the sanitizers) */
    assert_int_equal(test_run("%s param %s -o %s --iterations 2 --quiet --png %s 2> /dev/null",
                              SCAF_BINARY, in, out, png),
                     5);
    assert_false(test_exists(png));
    assert_int_equal(test_run("%s atlas --help | grep -q -- --checker", SCAF_BINARY), 0);
    assert_int_equal(test_run("%s param --help | grep -q -- --png-size", SCAF_BINARY), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cli_atlas_png),
        cmocka_unit_test(cli_param_png),
        cmocka_unit_test(cli_png_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
