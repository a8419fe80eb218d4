/* Tests for mesh/uv_verdict: the verdict on the UVs as given, and on the
 * UVs a glTF reader gets back (32-bit floats of (u, 1 - v)). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "mesh/uv_verdict.h"

static const double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
static const int F[] = {0, 1, 3, 0, 3, 2};

static void float_rounding_keeps_a_fair_map(void **state)
{
    (void)state;
    double UV[] = {0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75};
    mesh m = {4, (double *)V, 2, (int *)F, 4, UV, (int *)F};
    bij_report r;
    assert_int_equal(mesh_uv_verdict(&m, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    assert_int_equal(mesh_uv_verdict_gltf(&m, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
}

/* a map bijective in doubles whose sliver collapses in floats */
static void float_rounding_can_flatten_a_sliver(void **state)
{
    (void)state;
    double UV[] = {0.5, 0.5, 0.5 + 1e-9, 0.5, 0.5, 0.5 + 1e-9, 0.5 + 1e-9, 0.5 + 1e-9};
    mesh m = {4, (double *)V, 2, (int *)F, 4, UV, (int *)F};
    bij_report r;
    assert_int_equal(mesh_uv_verdict(&m, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    assert_int_equal(mesh_uv_verdict_gltf(&m, &r, NULL), SCAF_OK);
    assert_false(r.bijective);
    assert_int_equal(r.degenerate, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(float_rounding_keeps_a_fair_map),
        cmocka_unit_test(float_rounding_can_flatten_a_sliver),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
