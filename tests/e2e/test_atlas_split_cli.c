/* End-to-end tests of chart splitting in `scaf atlas` (app/atlas_charts):
 * a long thin chart (a spiral strip given one UV chart) is split by
 * --split-charts into more charts that pack better, still bijective by
 * `scaf check`; a curved disk above --max-distortion is split; a closed
 * mesh without vt gets automatic seams refined by default; bad values are
 * refused with the usage exit status. Generated meshes only. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "support/support.h"

/* The number after "key": in a JSON text (NAN when absent / null). */
static double json_num(const char *s, const char *key)
{
    char k[128];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(s, k);
    if (!p) return NAN;
    p += strlen(k);
    if (!strncmp(p, "null", 4)) return NAN;
    return strtod(p, NULL);
}

/* Sample `name` written as one UV chart (vt = the vertex's x, y: a
 * placeholder; vt index = vertex index). */
static void write_one_chart(const char *name, int size, const char *path)
{
    scaf_error e;
    err_clear(&e);
    mesh m;
    assert_int_equal(mesh_sample_make(name, size, &m, &e), SCAF_OK);
    if (!mesh_has_uv(&m)) {
        mesh w;
        assert_int_equal(mesh_alloc(&w, m.nv, m.nf, m.nv, &e), SCAF_OK);
        memcpy(w.V, m.V, sizeof(double) * 3 * (size_t)m.nv);
        memcpy(w.F, m.F, sizeof(int) * 3 * (size_t)m.nf);
        memcpy(w.FT, m.F, sizeof(int) * 3 * (size_t)m.nf);
        for (int v = 0; v < m.nv; v++) {
            w.UV[2 * v] = m.V[3 * v];
            w.UV[2 * v + 1] = m.V[3 * v + 1];
        }
        mesh_free(&m);
        m = w;
    }
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_OK);
    mesh_free(&m);
}

/* `scaf check --json` of out: must exit 0 (bijective); returns the text. */
static char *check_bijective(const char *out, const char *tag)
{
    char chk[512];
    test_tmp_path(tag, chk, sizeof chk);
    assert_int_equal(test_run("%s check --json %s > %s", SCAF_BINARY, out, chk), 0);
    char *c = test_slurp(chk);
    assert_non_null(c);
    assert_non_null(strstr(c, "\"bijective\": true"));
    return c;
}

static void long_thin_chart_is_split_and_packs_better(void **state)
{
    (void)state;
    char in[512], whole[512], split[512];
    test_tmp_path("e2e_split_spiral.obj", in, sizeof in);
    test_tmp_path("e2e_split_whole.obj", whole, sizeof whole);
    test_tmp_path("e2e_split_split.obj", split, sizeof split);
    write_one_chart("spiral", 160, in);
    assert_int_equal(test_run("%s atlas %s -o %s --quiet", SCAF_BINARY, in, whole), 0);
    assert_int_equal(test_run("%s atlas %s -o %s --quiet --split-charts", SCAF_BINARY, in, split),
                     0);
    char *a = check_bijective(whole, "e2e_split_whole.json");
    char *b = check_bijective(split, "e2e_split_split.json");
    assert_true(json_num(a, "charts") == 1.0);
    double charts = json_num(b, "charts");
    assert_true(charts >= 2.0 && charts <= 4.0); /* one split a round, three rounds */
    assert_true(json_num(b, "packing_efficiency") > json_num(a, "packing_efficiency"));
    assert_true(json_num(b, "mirrored_charts") == 0.0);
    free(a);
    free(b);
}

static void distorted_chart_is_split(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("e2e_split_hemi.obj", in, sizeof in);
    test_tmp_path("e2e_split_hemi_out.obj", out, sizeof out);
    write_one_chart("hemisphere", 10, in);
    /* a hemisphere settles well above 4.01: it must be cut */
    assert_int_equal(
        test_run("%s atlas %s -o %s --quiet --max-distortion 4.01", SCAF_BINARY, in, out), 0);
    char *c = check_bijective(out, "e2e_split_hemi.json");
    assert_true(json_num(c, "charts") >= 2.0);
    free(c);
}

static void bad_values_refused(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("e2e_split_bad.obj", in, sizeof in);
    test_tmp_path("e2e_split_bad_out.obj", out, sizeof out);
    write_one_chart("grid", 4, in);
    remove(out);
    assert_int_equal(
        test_run("%s atlas %s -o %s --max-distortion 3 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_int_equal(
        test_run("%s atlas %s -o %s --max-distortion x 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_false(test_exists(out));
}

/* A closed mesh without vt: automatic seams, split by default where a
 * chart distorts or packs badly; bijective, nothing mirrored. */
static void automatic_seams_refined_by_default(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("e2e_split_ball.obj", in, sizeof in);
    test_tmp_path("e2e_split_ball_out.obj", out, sizeof out);
    assert_int_equal(test_run("%s gen icosphere --size 6 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s atlas %s -o %s --quiet", SCAF_BINARY, in, out), 0);
    char *c = check_bijective(out, "e2e_split_ball.json");
    assert_true(json_num(c, "charts") >= 2.0);
    assert_true(json_num(c, "mirrored_charts") == 0.0);
    free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(long_thin_chart_is_split_and_packs_better),
        cmocka_unit_test(distorted_chart_is_split),
        cmocka_unit_test(bad_values_refused),
        cmocka_unit_test(automatic_seams_refined_by_default),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
