/* One checker, one verdict (issue 9, section 6): `scaf check` and
 * `scaf atlas --init input` judge the input UVs with the same function
 * (mesh_uv_verdict) on the same data, so the counts atlas quotes are the
 * ones check prints. On spot.obj they used to differ (check: 0 touchings,
 * 1 nested loop; atlas: 16 touchings, 0 nested loops) because atlas
 * judged its fan-split copy, where each pinch point became distinct UVs at
 * one point (touchings), with its own chart labels. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_verdict.h"
#include "support/support.h"

/* The atlas error with init_input on m, or NULL when atlas_init succeeds
 * (static buffer). */
static const char *atlas_init_input_error(const mesh *m)
{
    static scaf_error err;
    atlas_options o = atlas_options_default();
    o.init_input = 1;
    atlas a;
    err_clear(&err);
    scaf_status st = atlas_init(&a, m, &o, &err);
    if (st == SCAF_OK) {
        atlas_free(&a);
        return NULL;
    }
    return err.message;
}

/* atlas quotes exactly the counts of the check's verdict */
static void assert_same_counts(const mesh *m)
{
    bij_report r;
    scaf_error err;
    assert_int_equal(mesh_uv_verdict(m, &r, &err), SCAF_OK);
    assert_false(r.bijective);
    char defects[320], quoted[400];
    bij_report_defects(&r, defects, sizeof defects);
    snprintf(quoted, sizeof quoted, "(as scaf check reports: %s)", defects);
    const char *msg = atlas_init_input_error(m);
    assert_non_null(msg);
    assert_non_null(strstr(msg, quoted));
}

static void spot_counts_agree(void **state)
{
    (void)state;
    char path[1024];
    if (!test_data_path("seams/spot.obj", path, sizeof path)) skip();
    mesh m;
    mesh_read_info info;
    scaf_error err;
    assert_int_equal(mesh_read(path, &m, &info, &err), SCAF_OK);
    assert_same_counts(&m);
    mesh_free(&m);
}

/* Two UV triangles joined only at vt 0 (a pinch point: the faces around
 * it form two fans), in 3D a bent strip of two triangles sharing vertex 0. */
static void pinch_mesh(mesh *m, int flip_second)
{
    static double V[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0.5, -1, -1, 0.5};
    static double UV[10];
    static int F[6] = {0, 1, 2, 0, 3, 4}, FT[6];
    const double uv[10] = {0, 0, 1, 0, 1, 1, -1, 0, -1, -1};
    memcpy(UV, uv, sizeof uv);
    memcpy(FT, F, sizeof F);
    if (flip_second) {
        FT[4] = 4; /* the second UV triangle clockwise */
        FT[5] = 3;
    }
    *m = (mesh){5, V, 2, F, 5, UV, FT};
}

static void pinch_point_counts_agree(void **state)
{
    (void)state;
    mesh m;
    /* not bijective: the atlas quotes the check's counts */
    pinch_mesh(&m, 1);
    assert_same_counts(&m);
    /* bijective as given (check says so): the atlas does not contradict
     * it; it may refuse the start, saying the pinch point is why */
    pinch_mesh(&m, 0);
    bij_report r;
    scaf_error err;
    assert_int_equal(mesh_uv_verdict(&m, &r, &err), SCAF_OK);
    assert_true(r.bijective);
    const char *msg = atlas_init_input_error(&m);
    if (msg) {
        assert_null(strstr(msg, "not bijective"));
        assert_non_null(strstr(msg, "pinch point"));
    }
}

static void defects_text(void **state)
{
    (void)state;
    bij_report r;
    memset(&r, 0, sizeof r);
    char buf[64];
    bij_report_defects(&r, buf, sizeof buf);
    assert_string_equal(buf, "none");
    r.flipped = 177;
    r.nested_loops = 1;
    r.boundary_touchings = 16;
    bij_report_defects(&r, buf, sizeof buf);
    assert_string_equal(buf, "flipped 177, boundary_touchings 16, nested_loops 1");
    bij_report_defects(&r, buf, 12); /* truncated, still terminated */
    assert_true(strlen(buf) < 12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spot_counts_agree),
        cmocka_unit_test(pinch_point_counts_agree),
        cmocka_unit_test(defects_text),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
