/* End-to-end: `--init mvc` of `scaf param` and `scaf atlas` runs and its
 * output passes `scaf check` and carries "mvc" in the report; an unknown
 * init name is refused with exit 2 and leaves no output file. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "support/support.h"

static void param_init_mvc(void **state)
{
    (void)state;
    char in[512], out[512], rep[512];
    test_tmp_path("e2e_init_holes.obj", in, sizeof in);
    test_tmp_path("e2e_init_param_out.obj", out, sizeof out);
    test_tmp_path("e2e_init_param.json", rep, sizeof rep);
    remove(out);
    assert_int_equal(test_run("%s gen holes --size 4 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s param %s -o %s --init mvc --iterations 3 --quiet --verify --report %s",
                              SCAF_BINARY, in, out, rep),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"mvc\""));
    free(json);
    remove(out);
    assert_int_equal(test_run("%s param %s -o %s --init meanvalue --quiet 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_false(test_exists(out));
}

static void atlas_init_mvc(void **state)
{
    (void)state;
    char in[512], out[512], rep[512];
    test_tmp_path("e2e_init_cube.obj", in, sizeof in);
    test_tmp_path("e2e_init_atlas_out.obj", out, sizeof out);
    test_tmp_path("e2e_init_atlas.json", rep, sizeof rep);
    remove(out);
    assert_int_equal(test_run("%s gen cubesphere --size 3 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s atlas %s -o %s --init mvc --iterations 2 --compact-iterations 2 --quiet --report %s",
                              SCAF_BINARY, in, out, rep),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"mvc\""));
    free(json);
    remove(out);
    assert_int_equal(test_run("%s atlas %s -o %s --init MVC --quiet 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_false(test_exists(out));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_init_mvc),
        cmocka_unit_test(atlas_init_mvc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
