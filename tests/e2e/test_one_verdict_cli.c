/* One verdict from the command line (issue 9, section 6): the defect
 * counts `scaf atlas --init input` quotes for input UVs that are not
 * bijective are the ones `scaf check --json` prints for the same file
 * (seams/spot.obj used to give 0 touchings / 1 nested loop in check and
 * 16 touchings / 0 nested loops in atlas). Skips without the shared data
 * or python3. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "support/support.h"

#ifndef SCAF_BINARY
#define SCAF_BINARY "scaf"
#endif

/* Python: print the nonzero defect counts of a check --json file as
 * "key n, key n" in the order of bij_report_defects. */
#define DEFECTS_OF_CHECK_JSON                                                                      \
    "python3 -c 'import json,sys\n"                                                                \
    "d = json.load(open(sys.argv[1]))\n"                                                           \
    "keys = [\"flipped\", \"degenerate\", \"mirrored_charts\", \"boundary_crossings\", "           \
    "\"boundary_touchings\",\n"                                                                    \
    "        \"boundary_foldbacks\", \"folded_edges\", \"nonmanifold_edges\", \"nested_loops\", "  \
    "\"corner_overlaps\"]\n"                                                                       \
    "print(\", \".join(\"%%s %%d\" %% (k, d[k]) for k in keys if d[k]), end=\"\")'"

static void spot_check_and_atlas_agree(void **state)
{
    (void)state;
    char in[1024], json[512], want[512], err[512], out[512];
    if (!test_data_path("seams/spot.obj", in, sizeof in)) skip();
    if (!test_have_program("python3")) skip();
    test_tmp_path("verdict_check.json", json, sizeof json);
    test_tmp_path("verdict_want.txt", want, sizeof want);
    test_tmp_path("verdict_err.txt", err, sizeof err);
    test_tmp_path("verdict_out.obj", out, sizeof out);
    assert_int_equal(test_run("%s check --json %s > %s", SCAF_BINARY, in, json), 1);
    assert_int_equal(test_run(DEFECTS_OF_CHECK_JSON " %s > %s", json, want), 0);
    assert_int_equal(test_run("%s atlas --init input %s -o %s -q 2> %s", SCAF_BINARY, in, out, err),
                     4);
    char *w = test_slurp(want), *e = test_slurp(err);
    assert_non_null(w);
    assert_non_null(e);
    char quoted[600];
    snprintf(quoted, sizeof quoted, "(as scaf check reports: %s)", w);
    assert_non_null(strstr(e, quoted));
    free(w);
    free(e);
    assert_false(test_exists(out));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spot_check_and_atlas_agree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
