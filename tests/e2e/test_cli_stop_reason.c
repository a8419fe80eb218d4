/* `scaf param` and `scaf atlas` say why they stopped: a "stop reason:"
 * line on stderr (unless --quiet) and "stop_reason" in the --report JSON
 * (the atlas also per phase), for the cap, the tolerance and a zero step
 * with --tolerance 0 (the run asked for 1000 iterations and ended earlier:
 * it must say so). `scaf atlas --resolution R` alone pads 4 texels of R. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "support/support.h"

/* Run `scaf param` on IN with ARGS; the report and stderr must both give
 * REASON. */
static void param_says(const char *in, const char *args, const char *reason)
{
    char rep[512], log[512], want[128];
    test_tmp_path("e2e_stop_report.json", rep, sizeof rep);
    test_tmp_path("e2e_stop_stderr.txt", log, sizeof log);
    char out[512];
    test_tmp_path("e2e_stop_out.obj", out, sizeof out);
    assert_int_equal(
        test_run("%s param %s -o %s %s --report %s 2> %s", SCAF_BINARY, in, out, args, rep, log),
        0);
    char *r = test_slurp(rep), *e = test_slurp(log);
    assert_non_null(r);
    assert_non_null(e);
    snprintf(want, sizeof want, "\"stop_reason\": \"%s\"", reason);
    if (!strstr(r, want)) print_error("report lacks %s:\n%s\n", want, r);
    assert_non_null(strstr(r, want));
    snprintf(want, sizeof want, "stop reason: %s (", reason);
    if (!strstr(e, want)) print_error("stderr lacks %s:\n%s\n", want, e);
    assert_non_null(strstr(e, want));
    free(r);
    free(e);
}

static void param_reasons(void **state)
{
    (void)state;
    char in[512];
    test_tmp_path("e2e_stop_hemisphere.obj", in, sizeof in);
    assert_int_equal(test_run("%s gen hemisphere --size 4 -o %s", SCAF_BINARY, in), 0);
    param_says(in, "--iterations 2", "iteration_limit");
    param_says(in, "--tolerance 1e-2 --solver slim", "converged");
    param_says(in, "--tolerance 1e-2", "converged");
    param_says(in, "--iterations 1000 --tolerance 0", "zero_step");
    /* --quiet: no line, the report still has it */
    char log[512];
    test_tmp_path("e2e_stop_quiet.txt", log, sizeof log);
    assert_int_equal(test_run("%s param %s -o %s.out.obj --quiet 2> %s", SCAF_BINARY, in, in, log),
                     0);
    char *e = test_slurp(log);
    assert_non_null(e);
    assert_null(strstr(e, "stop reason"));
    free(e);
}

static void atlas_reasons(void **state)
{
    (void)state;
    char in[512], out[512], rep[512], log[512];
    test_tmp_path("e2e_stop_cube.obj", in, sizeof in);
    test_tmp_path("e2e_stop_atlas.obj", out, sizeof out);
    test_tmp_path("e2e_stop_atlas.json", rep, sizeof rep);
    test_tmp_path("e2e_stop_atlas.txt", log, sizeof log);
    assert_int_equal(test_run("%s gen cubesphere --size 3 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s atlas %s -o %s --iterations 1 --compact-iterations 0 "
                              "--resolution 2048 --report %s 2> %s",
                              SCAF_BINARY, in, out, rep, log),
                     0);
    char *r = test_slurp(rep), *e = test_slurp(log);
    assert_non_null(r);
    assert_non_null(e);
    assert_non_null(strstr(r, "\"stop_reason\": \"iteration_limit\""));
    assert_non_null(strstr(r,
                           "\"phase_stop_reasons\": {\"settle\": \"iteration_limit\", \"compact\": "
                           "\"not_run\"}"));
    assert_non_null(strstr(e, "stop reason: iteration_limit ("));
    /* --resolution alone: the default 4 texels of it */
    assert_non_null(strstr(r, "\"padding\": 0.001953125"));
    assert_non_null(strstr(r, "\"resolution\": 2048"));
    free(r);
    free(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_reasons),
        cmocka_unit_test(atlas_reasons),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
