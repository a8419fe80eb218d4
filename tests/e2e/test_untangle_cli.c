/* End-to-end: `scaf untangle` on the generated dented sphere (its cap
 * pushed through its bottom) with --verify (exact check after every
 * iteration), --report and --png: exit 0, `scaf check --3d` finds the
 * input intersecting and the output free, the output has the input's
 * faces, the report has a free verdict for every iteration and a final
 * distance well below the flowed one, the picture has three panels of
 * which only the input shows faces from inside. An already free input is
 * written unchanged with a message; refusals (open, genus 1, usage, too
 * few flow steps, unwritable picture, interrupted) write nothing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh_io.h"
#include "support/cli_capture.h"
#include "support/png_read.h"
#include "support/support.h"

static char out[65536];

static int count(const char *text, const char *what)
{
    int n = 0;
    for (const char *p = text; (p = strstr(p, what)); p++) n++;
    return n;
}

/* The number after "key": in a JSON text. */
static double json_number(const char *json, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    assert_non_null(p);
    return strtod(p + strlen(k), NULL);
}

static void dented(void **state)
{
    (void)state;
    char in[1024], res[1024], rep[1024], png[1024];
    test_tmp_path("untangle_dented.obj", in, sizeof in);
    test_tmp_path("untangle_dented_out.obj", res, sizeof res);
    test_tmp_path("untangle_dented.json", rep, sizeof rep);
    test_tmp_path("untangle_dented.png", png, sizeof png);
    remove(res);
    assert_int_equal(test_run("'%s' gen dented -s 4 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("'%s' check --3d '%s' >/dev/null", SCAF_BINARY, in), 1);
    assert_int_equal(test_capture(out, sizeof out,
                                  "'%s' untangle '%s' -o '%s' --verify --report '%s' --png '%s' "
                                  "--png-size 96 2>&1",
                                  SCAF_BINARY, in, res, rep, png),
                     0);
    assert_non_null(strstr(out, "flow step 1:"));
    assert_non_null(strstr(out, "iteration 1:"));
    assert_int_equal(test_run("'%s' check --3d '%s' >/dev/null", SCAF_BINARY, res), 0);
    mesh a, b;
    mesh_read_info info;
    assert_int_equal(mesh_read(in, &a, &info, NULL), SCAF_OK);
    assert_int_equal(mesh_read(res, &b, &info, NULL), SCAF_OK);
    assert_int_equal(a.nv, b.nv);
    assert_int_equal(a.nf, b.nf);
    assert_memory_equal(a.F, b.F, sizeof(int) * 3 * (size_t)a.nf);
    mesh_free(&a);
    mesh_free(&b);
    char *json = test_slurp(rep);
    assert_non_null(json);
    long long iterations = test_json_field(json, "iteration_count");
    assert_true(iterations >= 1);
    assert_true(test_json_field(json, "input_pairs") > 0);
    assert_true(test_json_field(json, "flow_steps") >= 1);
    assert_int_equal(test_json_field(json, "verified_every_iteration"), 1);
    const char *back = strstr(json, "\"iterations\": [");
    assert_non_null(back);
    assert_int_equal(count(back, "\"iteration\": "), (int)iterations);
    assert_int_equal(count(back, "\"pairs\": 0}"), (int)iterations);
    double flowed = json_number(json, "flowed_rms"), rms = json_number(json, "rms");
    assert_true(flowed > 0 && rms < 0.5 * flowed);
    free(json);
    int W, H, inside, drawn;
    unsigned char *rgba = test_png_read(png, &W, &H);
    assert_non_null(rgba);
    assert_int_equal(W, 3 * 96);
    assert_int_equal(H, 96);
    test_png_surface_pixels(rgba, W, H, 0, 96, &inside, &drawn);
    assert_true(drawn > 96 * 96 / 4 && inside > 0);
    for (int p = 1; p < 3; p++) {
        test_png_surface_pixels(rgba, W, H, 96 * p, 96, &inside, &drawn);
        assert_true(drawn > 96 * 96 / 4 && inside <= 2);
    }
    free(rgba);
    /* interrupted during the flow back: exit 8, nothing written */
    remove(res);
    remove(rep);
    assert_int_equal(test_capture(out, sizeof out,
                                  "SCAF_TEST_RAISE_SIGNAL_AT=9 '%s' untangle '%s' -o '%s' --report "
                                  "'%s' 2>&1",
                                  SCAF_BINARY, in, res, rep),
                     8);
    assert_non_null(strstr(out, "interrupted by SIGINT"));
    assert_false(test_exists(res));
    assert_false(test_exists(rep));
    /* too few flow steps: exit 6, nothing written */
    assert_int_equal(test_capture(out, sizeof out, "'%s' untangle '%s' -o '%s' --flow-steps 1 2>&1",
                                  SCAF_BINARY, in, res),
                     6);
    assert_non_null(strstr(out, "did not free"));
    assert_false(test_exists(res));
    /* an unwritable picture: exit 5, no OBJ either */
    char bad[1024];
    test_tmp_path("no_such_folder/untangle.png", bad, sizeof bad);
    assert_int_equal(
        test_run("'%s' untangle '%s' -o '%s' -q --png '%s' 2>/dev/null", SCAF_BINARY, in, res, bad),
        5);
    assert_false(test_exists(res));
}

static void already_free(void **state)
{
    (void)state;
    char in[1024], res[1024], rep[1024];
    test_tmp_path("untangle_ball.obj", in, sizeof in);
    test_tmp_path("untangle_ball_out.obj", res, sizeof res);
    test_tmp_path("untangle_ball.json", rep, sizeof rep);
    assert_int_equal(test_run("'%s' gen icosphere -s 3 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(test_capture(out, sizeof out, "'%s' untangle '%s' -o '%s' --report '%s' 2>&1",
                                  SCAF_BINARY, in, res, rep),
                     0);
    assert_non_null(strstr(out, "already free of self-intersections: written unchanged"));
    assert_int_equal(count(out, "iteration"), 0);
    mesh a, b;
    mesh_read_info info;
    assert_int_equal(mesh_read(in, &a, &info, NULL), SCAF_OK);
    assert_int_equal(mesh_read(res, &b, &info, NULL), SCAF_OK);
    assert_int_equal(a.nv, b.nv);
    assert_memory_equal(a.V, b.V, sizeof(double) * 3 * (size_t)a.nv);
    assert_memory_equal(a.F, b.F, sizeof(int) * 3 * (size_t)a.nf);
    mesh_free(&a);
    mesh_free(&b);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_int_equal(test_json_field(json, "already_free"), 1);
    assert_int_equal(test_json_field(json, "iterations"), 0);
    free(json);
}

static void refusals(void **state)
{
    (void)state;
    char in[1024], res[1024], tor[1024];
    test_tmp_path("untangle_open.obj", in, sizeof in);
    test_tmp_path("untangle_refused.obj", res, sizeof res);
    test_tmp_path("untangle_torus.obj", tor, sizeof tor);
    remove(res);
    assert_int_equal(test_run("'%s' gen hemisphere -s 3 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' untangle '%s' -o '%s' 2>&1", SCAF_BINARY, in, res), 4);
    assert_non_null(strstr(out, "open"));
    assert_false(test_exists(res));
    /* a torus of 8 x 8 quads */
    FILE *f = fopen(tor, "w");
    assert_non_null(f);
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            double u = 0.785398163397448 * i, v = 0.785398163397448 * j;
            fprintf(f, "v %.17g %.17g %.17g\n", (1 + 0.4 * cos(v)) * cos(u),
                    (1 + 0.4 * cos(v)) * sin(u), 0.4 * sin(v));
        }
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++)
            fprintf(f, "f %d %d %d %d\n", 1 + i * 8 + j, 1 + (i + 1) % 8 * 8 + j,
                    1 + (i + 1) % 8 * 8 + (j + 1) % 8, 1 + i * 8 + (j + 1) % 8);
    fclose(f);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' untangle '%s' -o '%s' 2>&1", SCAF_BINARY, tor, res), 4);
    assert_non_null(strstr(out, "genus 1"));
    assert_false(test_exists(res));
    const char *bad[] = {"",
                         "--iterations 0",
                         "--tolerance 1",
                         "--anchor -1",
                         "--delta 0",
                         "--flow-steps x",
                         "--png-size 64",
                         "--png p.png --png-size 9",
                         "--frobnicate"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        assert_int_equal(test_run("'%s' untangle '%s' %s %s %s 2>/dev/null", SCAF_BINARY, tor,
                                  k ? "-o" : "", k ? res : "", bad[k]),
                         2);
    assert_int_equal(test_run("'%s' untangle '%s' -o '%s.ply' 2>/dev/null", SCAF_BINARY, tor, res),
                     2);
    assert_int_equal(
        test_run("'%s' untangle '%s.missing' -o '%s' 2>/dev/null", SCAF_BINARY, tor, res), 3);
    assert_false(test_exists(res));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dented),
        cmocka_unit_test(already_free),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
