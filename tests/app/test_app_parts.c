/* Tests for the app helpers of `scaf param`: UV fan splitting, the SVG
 * picture, the JSON report and atomic files. */
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

#include "app/param_report.h"
#include "app/uv_fans.h"
#include "app/distortion_scale.h"
#include "app/uv_svg.h"
#include "support/support.h"

static int count(const char *s, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(s, needle); p; p = strstr(p + 1, needle)) n++;
    return n;
}

static void bowtie_vertex_is_split(void **state)
{
    (void)state;
    /* two triangles meeting only at UV index 0: two fans */
    int FT[] = {0, 1, 2, 0, 3, 4};
    int out[6], nuv, *orig;
    assert_int_equal(uv_split_fans(2, FT, 5, out, &nuv, &orig, NULL), SCAF_OK);
    assert_int_equal(nuv, 6);
    assert_int_equal(out[0], 0);
    assert_int_equal(out[3], 5);
    assert_int_equal(orig[5], 0);
    for (int k = 1; k < 3; k++) assert_int_equal(out[k], FT[k]);
    for (int k = 4; k < 6; k++) assert_int_equal(out[k], FT[k]);
    free(orig);
}

static void shared_edge_keeps_indices(void **state)
{
    (void)state;
    /* a fan of three triangles around 0, and a separate quad */
    int FT[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 5, 6, 7, 5, 7, 8};
    int out[15], nuv;
    assert_int_equal(uv_split_fans(5, FT, 9, out, &nuv, NULL, NULL), SCAF_OK);
    assert_int_equal(nuv, 9);
    assert_memory_equal(out, FT, sizeof FT);
}

/* A side with both ends at one vt (a face with a repeated vt) joins no
 * faces: two such faces around vt 0 are two fans. */
static void degenerate_side_joins_nothing(void **state)
{
    (void)state;
    int FT[] = {0, 0, 1, 0, 0, 2};
    int out[6], nuv, *orig;
    assert_int_equal(uv_split_fans(2, FT, 3, out, &nuv, &orig, NULL), SCAF_OK);
    assert_int_equal(nuv, 4);
    assert_memory_equal(out, FT, 3 * sizeof(int));
    assert_int_equal(out[3], 3);
    assert_int_equal(out[4], 3);
    assert_int_equal(out[5], 2);
    assert_int_equal(orig[3], 0);
    free(orig);
}

static void svg_colours_grow_with_energy(void **state)
{
    (void)state;
    unsigned c4 = uv_svg_colour(4.0), c8 = uv_svg_colour(8.0), c64 = uv_svg_colour(64.0),
             cinf = uv_svg_colour(INFINITY);
    assert_int_not_equal(c4, c64);
    /* blue fades, red grows */
    assert_true((c4 & 0xff) > (c64 & 0xff));
    assert_true((c64 >> 16) > (c4 >> 16));
    assert_true((c8 & 0xff) <= (c4 & 0xff));
    /* the blue channel falls monotonically from isometry to the top */
    unsigned prev = 256;
    for (double e = 4.0; e < 100.0; e *= 1.1) {
        unsigned b = uv_svg_colour(e) & 0xff;
        assert_true(b <= prev);
        prev = b;
    }
    assert_int_equal(cinf, c64);
    assert_int_equal(uv_svg_colour(1.0), c4); /* below isometry: clamp */
    /* red rises monotonically too, and the scale spreads typical optimized
     * energies: 10% over an isometry is a quarter of the way up the bar */
    unsigned prev_red = 0;
    for (double e = 4.0; e < 100.0; e *= 1.05) {
        unsigned red = uv_svg_colour(e) >> 16;
        assert_true(red >= prev_red);
        prev_red = red;
    }
    assert_true(distortion_scale_t(4.4) > 0.25);
    assert_true(distortion_scale_t(5.0) > 0.35);
    assert_true(distortion_scale_t(16.0) == 1.0);
    for (double t = 0.05; t <= 1.0; t += 0.05)
        assert_true(fabs(distortion_scale_t(distortion_scale_energy(t)) - t) < 1e-12);
}

static void svg_file_has_every_triangle(void **state)
{
    (void)state;
    double uv[] = {0, 0, 1, 0, 1, 1, 0, 1, 5, 5};
    int F[] = {0, 1, 2, 0, 2, 3};
    double E[] = {4.0, 40.0};
    int T[] = {1, 4, 2};
    uv_svg_scaffold sc = {1, T, uv + 8};
    char path[512];
    test_tmp_path("parts.svg", path, sizeof path);
    assert_int_equal(uv_svg_write(path, 4, uv, 2, F, E, &sc, "a <title> & more", NULL), SCAF_OK);
    char *s = test_slurp(path);
    assert_non_null(s);
    assert_int_equal(count(s, "<polygon"), 3);
    assert_non_null(strstr(s, "&lt;title&gt; &amp;"));
    assert_non_null(strstr(s, "</svg>"));
    free(s);
    /* a folder that does not exist: an error, and nothing written */
    char bad[600];
    snprintf(bad, sizeof bad, "%s/no-such-dir/x.svg", SCAF_TEST_TMPDIR);
    scaf_error err;
    assert_int_equal(uv_svg_write(bad, 4, uv, 2, F, E, NULL, NULL, &err), SCAF_ERR_IO);
    assert_non_null(strstr(err.message, "no-such-dir"));
}

static void report_is_json_with_phases(void **state)
{
    (void)state;
    scaf_iteration_info_t it[3];
    memset(it, 0, sizeof it);
    for (int i = 0; i < 3; i++) {
        it[i].iteration = i + 1;
        it[i].energy = 5.0 - i;
        it[i].seconds = 0.1 * (i + 1);
        it[i].phase_seconds[SCAF_PHASE_FACTORIZATION] = 0.05;
        it[i].total_before = 10;
        it[i].total_after = 9;
    }
    it[1].lambda = NAN; /* non-finite numbers become null */
    scaf_options_t o = scaf_options_default();
    param_report r = {"in \"quoted\".obj", "out.obj", &o, 10,  12, 1, 0.5, 7.0, 3.0, 3.25, "ok",
                      SCAF_STOP_TOLERANCE, 3,         it, NULL};
    char path[512];
    test_tmp_path("parts.json", path, sizeof path);
    assert_int_equal(param_report_write(path, &r, NULL), SCAF_OK);
    char *s = test_slurp(path);
    assert_non_null(s);
    assert_int_equal(count(s, "{"), count(s, "}"));
    assert_int_equal(count(s, "["), count(s, "]"));
    assert_non_null(strstr(s, "\"in \\\"quoted\\\".obj\""));
    assert_non_null(strstr(s, "\"lambda\": null"));
    assert_non_null(strstr(s, "\"median_seconds_per_iteration\": 0.20000000000000001"));
    assert_int_equal(count(s, "\"iteration\":"), 3);
    assert_non_null(strstr(s, "\"phase_fraction\""));
    assert_non_null(strstr(s, "\"stop_reason\": \"tolerance\""));
    assert_true(strncmp(s, "{\n  \"schema\": \"scaf-report/1\",\n  \"command\": \"param\"", 51) ==
                0);
    assert_non_null(strstr(s, "\"energy\": 3.25"));
    assert_null(strstr(s, "nan"));
    free(s);
    assert_true(fabs(param_report_median_seconds(it, 2) - 0.15) < 1e-15);
    assert_true(param_report_median_seconds(it, 0) == 0.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bowtie_vertex_is_split),
        cmocka_unit_test(shared_edge_keeps_indices),
        cmocka_unit_test(degenerate_side_joins_nothing),
        cmocka_unit_test(svg_colours_grow_with_energy),
        cmocka_unit_test(svg_file_has_every_triangle),
        cmocka_unit_test(report_is_json_with_phases),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
