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

/* One command with --init mvc on a generated sample: it runs, the output
 * passes `scaf check`, the report names the start; a bad init name is a
 * usage error (exit 2) with no output. */
typedef struct init_case {
    const char *name;   /* file name stem */
    const char *sample; /* `scaf gen` arguments */
    const char *cmd;    /* param / atlas */
    const char *caps;   /* iteration options */
    const char *bad;    /* an init name that is refused */
} init_case;

static void run_init_case(const init_case *c)
{
    char in[512], out[512], rep[512], name[256];
    snprintf(name, sizeof name, "e2e_init_%s_in.obj", c->name);
    test_tmp_path(name, in, sizeof in);
    snprintf(name, sizeof name, "e2e_init_%s_out.obj", c->name);
    test_tmp_path(name, out, sizeof out);
    snprintf(name, sizeof name, "e2e_init_%s.json", c->name);
    test_tmp_path(name, rep, sizeof rep);
    remove(out);
    assert_int_equal(test_run("%s gen %s -o %s", SCAF_BINARY, c->sample, in), 0);
    assert_int_equal(test_run("%s %s %s -o %s --init mvc %s --quiet --report %s", SCAF_BINARY,
                              c->cmd, in, out, c->caps, rep),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"mvc\""));
    free(json);
    remove(out);
    assert_int_equal(test_run("%s %s %s -o %s --init %s --quiet 2> /dev/null", SCAF_BINARY, c->cmd,
                              in, out, c->bad),
                     2);
    assert_false(test_exists(out));
}

static void param_init_mvc(void **state)
{
    (void)state;
    init_case c = {"param", "holes --size 4", "param", "--iterations 3 --verify", "meanvalue"};
    run_init_case(&c);
}

static void atlas_init_mvc(void **state)
{
    (void)state;
    init_case c = {"atlas", "cubesphere --size 3", "atlas", "--iterations 2 --compact-iterations 2",
                   "MVC"};
    run_init_case(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_init_mvc),
        cmocka_unit_test(atlas_init_mvc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
