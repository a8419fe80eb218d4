/* End-to-end: `--threads N` and `--deterministic` of `scaf param`, `scaf
 * atlas`, `scaf deform` and `scaf inflate` (tools/cli_threads). With
 * --deterministic the output is the same bytes for N = 1, 2 and 3 and for
 * the default count (issue 29: the default is every core, and a file must
 * be able not to depend on the machine it was made on); without it, the
 * same N gives the same bytes run after run; the maps are bijective
 * (`scaf check`); N < 1 or a non-number is a usage error (exit 2) with no
 * output. The inputs are small (seconds under ASan) and the runs set
 * SCAF_MIN_CHUNK=64 (tools/main.c: loops cut into chunks of 64 simplices
 * instead of 4096), so every parallel path is taken: chunked sums,
 * parallel fills, a factorization tree cut into bins with shared
 * supernodes above the cut. On the code before (02ab067) param and atlas
 * gave three different files (and knew no --deterministic); with the
 * sums' chunks following the thread count again, or the deterministic
 * factorization's bins, all four commands do. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>

#include "support/support.h"

typedef struct threads_case {
    const char *name;   /* file name stem */
    const char *sample; /* `scaf gen` arguments */
    const char *cmd;    /* param / atlas / deform / inflate */
    const char *caps;   /* iteration options */
    int check;          /* `scaf check` the output (a UV map) */
} threads_case;

/* Run `ENV scaf CMD in -o TAG.obj CAPS EXTRA` and return the output's text. */
static char *run_out(const threads_case *c, const char *in, const char *tag, const char *env,
                     const char *extra)
{
    char out[512], name[256];
    snprintf(name, sizeof name, "e2e_threads_%s_%s.obj", c->name, tag);
    test_tmp_path(name, out, sizeof out);
    remove(out);
    assert_int_equal(test_run("SCAF_MIN_CHUNK=64 %s %s %s %s -o %s %s %s --quiet", env, SCAF_BINARY,
                              c->cmd, in, out, c->caps, extra),
                     0);
    if (c->check) assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *s = test_slurp(out);
    assert_non_null(s);
    remove(out);
    return s;
}

static void run_threads_case(const threads_case *c)
{
    char in[512], out[512], name[256];
    snprintf(name, sizeof name, "e2e_threads_%s_in.obj", c->name);
    test_tmp_path(name, in, sizeof in);
    assert_int_equal(test_run("%s gen %s -o %s", SCAF_BINARY, c->sample, in), 0);

    char *one = run_out(c, in, "1", "OPENBLAS_NUM_THREADS=1", "--threads 1 --deterministic");
    char *two = run_out(c, in, "2", "OPENBLAS_NUM_THREADS=1", "--threads 2 --deterministic");
    char *three = run_out(c, in, "3", "OPENBLAS_NUM_THREADS=1", "--threads 3 --deterministic");
    char *again = run_out(c, in, "3b", "OPENBLAS_NUM_THREADS=3", "--threads 3 --deterministic");
    char *dflt = run_out(c, in, "default", "env -u OPENBLAS_NUM_THREADS", "--deterministic");
    assert_true(strlen(one) > 100);
    assert_string_equal(one, two);
    assert_string_equal(one, three);
    assert_string_equal(one, again);
    assert_string_equal(one, dflt);
    /* without --deterministic: the same bytes for the same N */
    char *two_a = run_out(c, in, "2a", "OPENBLAS_NUM_THREADS=1", "--threads 2");
    char *two_b = run_out(c, in, "2b", "OPENBLAS_NUM_THREADS=2", "--threads 2");
    assert_string_equal(two_a, two_b);
    free(two_a);
    free(two_b);
    free(dflt);
    free(one);
    free(two);
    free(three);
    free(again);

    snprintf(name, sizeof name, "e2e_threads_%s_bad.obj", c->name);
    test_tmp_path(name, out, sizeof out);
    remove(out);
    static const char *const bad[] = {"0", "-1", "2x", ""};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_equal(test_run("%s %s %s -o %s %s --threads '%s' --quiet 2> /dev/null",
                                  SCAF_BINARY, c->cmd, in, out, c->caps, bad[k]),
                         2);
        assert_false(test_exists(out));
    }
    assert_int_equal(
        test_run("%s %s %s -o %s --threads 2> /dev/null", SCAF_BINARY, c->cmd, in, out), 2);
    assert_false(test_exists(out));
}

static void param_threads(void **state)
{
    (void)state;
    threads_case c = {"param", "hemisphere --size 16", "param", "--iterations 3", 1};
    run_threads_case(&c);
}

static void atlas_threads(void **state)
{
    (void)state;
    threads_case c = {"atlas", "cubesphere --size 8", "atlas",
                      "--iterations 2 --compact-iterations 2", 1};
    run_threads_case(&c);
}

/* A 31 x 31 grid pulled by three corner handles (the targets written here). */
static void deform_threads(void **state)
{
    (void)state;
    char targets[512], caps[700];
    test_tmp_path("e2e_threads_deform.targets.json", targets, sizeof targets);
    FILE *f = fopen(targets, "w");
    assert_non_null(f);
    fputs("{\"handles\": [{\"vertex\": 0, \"target\": [-0.2, 0.1]},\n"
          " {\"vertex\": 960, \"target\": [1.3, 0.8]},\n"
          " {\"vertex\": 30, \"target\": [1.1, -0.3]}]}\n",
          f);
    fclose(f);
    snprintf(caps, sizeof caps, "--targets %s --iterations 3", targets);
    threads_case c = {"deform", "grid --size 30", "deform", caps, 1};
    run_threads_case(&c);
    remove(targets);
}

static void inflate_threads(void **state)
{
    (void)state;
    threads_case c = {"inflate", "icosphere --size 5", "inflate", "--scale 1.5 --iterations 2", 0};
    run_threads_case(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_threads),
        cmocka_unit_test(atlas_threads),
        cmocka_unit_test(deform_threads),
        cmocka_unit_test(inflate_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
