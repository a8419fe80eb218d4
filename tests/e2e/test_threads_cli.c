/* End-to-end: `--threads N` of `scaf param` and `scaf atlas`
 * (tools/cli_threads). The same N gives the same bytes run after run
 * (scaf's own loops over simplices and the BLAS both run in N threads);
 * N = 1 and N = 2 both give bijective maps whose energies agree to
 * round-off (for atlas, the energy of the settled charts: the packing
 * after it is a discrete search, and the cube sphere's six charts of equal
 * area are sorted by values that differ in their last bits, so round-off
 * may pick another layout);
 * --threads wins over OPENBLAS_NUM_THREADS in both directions, so
 * --threads 1 writes what the one-thread program wrote before (with
 * OPENBLAS_NUM_THREADS=1 and no option); N < 1 or a non-number is a usage
 * error (exit 2) with no output. The samples are big enough that OpenBLAS
 * really splits the factorization's products between two threads (their
 * outputs with 1 and 2 threads differ on the development machine). */
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
    const char *cmd;    /* param / atlas */
    const char *caps;   /* iteration options */
    const char *energy; /* the report's energy compared between N = 1 and 2 */
} threads_case;

/* Run `ENV scaf CMD in -o TAG.obj CAPS EXTRA` and return the output's text. */
static char *run_out(const threads_case *c, const char *in, const char *tag, const char *env,
                     const char *extra)
{
    char out[512], name[256];
    snprintf(name, sizeof name, "e2e_threads_%s_%s.obj", c->name, tag);
    test_tmp_path(name, out, sizeof out);
    remove(out);
    assert_int_equal(test_run("%s %s %s %s -o %s %s %s --quiet", env, SCAF_BINARY, c->cmd, in, out,
                              c->caps, extra),
                     0);
    char *s = test_slurp(out);
    assert_non_null(s);
    remove(out);
    return s;
}

/* `scaf CMD in -o TAG.obj CAPS --threads N --report`: whether `scaf check`
 * calls the output bijective (exit 0), and the report's c->energy. */
static double checked_energy(const threads_case *c, const char *in, int threads)
{
    char out[512], rep[512], name[256];
    snprintf(name, sizeof name, "e2e_threads_%s_e%d.obj", c->name, threads);
    test_tmp_path(name, out, sizeof out);
    snprintf(name, sizeof name, "e2e_threads_%s_e%d.json", c->name, threads);
    test_tmp_path(name, rep, sizeof rep);
    assert_int_equal(test_run("OPENBLAS_NUM_THREADS=1 %s %s %s -o %s %s --threads %d --report %s "
                              "--quiet",
                              SCAF_BINARY, c->cmd, in, out, c->caps, threads, rep),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    char field[64];
    snprintf(field, sizeof field, "\"%s\":", c->energy);
    const char *key = strstr(json, field);
    assert_non_null(key);
    double e = strtod(key + strlen(field), NULL);
    free(json);
    remove(out);
    remove(rep);
    return e;
}

static void run_threads_case(const threads_case *c)
{
    char in[512], out[512], name[256];
    snprintf(name, sizeof name, "e2e_threads_%s_in.obj", c->name);
    test_tmp_path(name, in, sizeof in);
    assert_int_equal(test_run("%s gen %s -o %s", SCAF_BINARY, c->sample, in), 0);

    char *two_a = run_out(c, in, "2a", "OPENBLAS_NUM_THREADS=1", "--threads 2");
    char *two_b = run_out(c, in, "2b", "OPENBLAS_NUM_THREADS=1", "--threads 2");
    char *two_env = run_out(c, in, "2env", "OPENBLAS_NUM_THREADS=2", "");
    assert_string_equal(two_a, two_b);
    assert_string_equal(two_a, two_env);
    char *one_env = run_out(c, in, "1env", "OPENBLAS_NUM_THREADS=1", "");
    char *one = run_out(c, in, "1", "OPENBLAS_NUM_THREADS=2", "--threads 1");
    assert_string_equal(one, one_env);
    double e1 = checked_energy(c, in, 1), e2 = checked_energy(c, in, 2);
    assert_true(e1 > 0 && fabs(e1 - e2) <= 1e-9 * e1);
    free(two_a);
    free(two_b);
    free(two_env);
    free(one_env);
    free(one);

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
    threads_case c = {"param", "hemisphere --size 60", "param", "--iterations 4", "final_energy"};
    run_threads_case(&c);
}

static void atlas_threads(void **state)
{
    (void)state;
    threads_case c = {"atlas", "cubesphere --size 40", "atlas",
                      "--iterations 3 --compact-iterations 3", "settled_energy"};
    run_threads_case(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_threads),
        cmocka_unit_test(atlas_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
