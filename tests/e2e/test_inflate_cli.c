/* End-to-end: `scaf inflate` grows an icosphere inside its box, writes the
 * input's connectivity at new positions that `scaf check` finds free of
 * self-intersections, the final tets that `scaf check` finds positive and
 * a report with one entry per iteration and a --png picture; the same
 * run twice writes the same bytes; an open, a non-manifold and a self-intersecting surface are
 * refused (exit 4) and bad command lines (exit 2), nothing written;
 * interrupted, nothing is left (exit 8). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "support/cli_capture.h"
#include "support/support.h"

static char out[65536];

static int count(const char *text, const char *what)
{
    int n = 0;
    for (const char *p = text; (p = strstr(p, what)); p++) n++;
    return n;
}

static void grows_and_writes(void **state)
{
    (void)state;
    char in[1024], res[1024], res2[1024], tets[1024], rep[1024];
    test_tmp_path("inflate_cli_ico.obj", in, sizeof in);
    test_tmp_path("inflate_cli_big.obj", res, sizeof res);
    test_tmp_path("inflate_cli_big2.obj", res2, sizeof res2);
    test_tmp_path("inflate_cli_big.mesh", tets, sizeof tets);
    test_tmp_path("inflate_cli_big.json", rep, sizeof rep);
    assert_int_equal(test_run("'%s' gen icosphere -s 3 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(test_capture(out, sizeof out,
                                  "'%s' inflate '%s' -o '%s' --scale 3 --iterations 8 --tets '%s' "
                                  "--report '%s' 2>&1",
                                  SCAF_BINARY, in, res, tets, rep),
                     0);
    assert_int_equal(count(out, "scaf inflate: iteration "), 8);
    assert_int_equal(test_run("'%s' check '%s' >/dev/null", SCAF_BINARY, res), 0);
    assert_int_equal(test_run("'%s' check '%s' >/dev/null", SCAF_BINARY, tets), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_int_equal(test_json_field(json, "iteration_count"), 8);
    assert_int_equal(count(json, "\"quality_p5\""), 8);
    free(json);
    mesh a, b;
    mesh_read_info info;
    assert_int_equal(mesh_read(in, &a, &info, NULL), SCAF_OK);
    assert_int_equal(mesh_read(res, &b, &info, NULL), SCAF_OK);
    assert_int_equal(a.nv, b.nv);
    assert_int_equal(a.nf, b.nf);
    assert_memory_equal(a.F, b.F, sizeof(int) * 3 * (size_t)a.nf);
    double ra = 0, rb = 0; /* grown: the first vertex went outward */
    for (int k = 0; k < 3; k++) ra += a.V[k] * a.V[k], rb += b.V[k] * b.V[k];
    assert_true(rb > 2.0 * ra);
    mesh_free(&a);
    mesh_free(&b);
    /* deterministic, also quiet */
    assert_int_equal(test_capture(out, sizeof out, "'%s' inflate '%s' -o '%s' -k 3 -n 8 -q 2>&1",
                                  SCAF_BINARY, in, res2),
                     0);
    assert_string_equal(out, "");
    /* --png: the input and the result side by side */
    char png[1024];
    test_tmp_path("inflate_cli_big.png", png, sizeof png);
    remove(png);
    assert_int_equal(test_run("'%s' inflate '%s' -o '%s' -k 3 -n 2 -q --png '%s' --png-size 64",
                              SCAF_BINARY, in, res2, png),
                     0);
    FILE *pf = fopen(png, "rb");
    assert_non_null(pf);
    unsigned char sig[8];
    assert_int_equal(fread(sig, 1, 8, pf), 8);
    fclose(pf);
    assert_memory_equal(sig, "\x89PNG\r\n\x1a\n", 8);
    assert_int_equal(test_run("'%s' inflate '%s' -o '%s' -k 3 -q --png-size 64 2>/dev/null",
                              SCAF_BINARY, in, res2),
                     2);
    assert_int_equal(test_run("'%s' inflate '%s' -o '%s' -k 3 -n 8 -q", SCAF_BINARY, in, res2), 0);
    char *x = test_slurp(res), *y = test_slurp(res2);
    assert_non_null(x);
    assert_non_null(y);
    assert_string_equal(x, y);
    free(x);
    free(y);
}

static void refusals(void **state)
{
    (void)state;
    char in[1024], res[1024], nm[1024], si[1024];
    test_tmp_path("inflate_cli_open.obj", in, sizeof in);
    test_tmp_path("inflate_cli_refused.obj", res, sizeof res);
    remove(res);
    assert_int_equal(test_run("'%s' gen hemisphere -s 3 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' inflate '%s' -o '%s' -k 2 2>&1", SCAF_BINARY, in, res),
        4);
    assert_non_null(strstr(out, "the surface is open"));
    /* closed but not manifold: two tetrahedra sharing vertex 3 */
    test_tmp_path("inflate_cli_bowtie.off", nm, sizeof nm);
    FILE *f = fopen(nm, "w");
    assert_non_null(f);
    fputs("OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n2 1 1\n1 2 1\n2 2 2\n"
          "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n3 3 5 4\n3 3 4 6\n3 4 5 6\n3 5 3 6\n",
          f);
    fclose(f);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' inflate '%s' -o '%s' -k 2 2>&1", SCAF_BINARY, nm, res),
        4);
    assert_non_null(strstr(out, "not manifold"));
    /* an icosphere whose sides were pushed through each other */
    test_tmp_path("inflate_cli_pushed.obj", si, sizeof si);
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 5, &m, NULL), SCAF_OK);
    for (int v = 0; v < m.nv; v++) {
        double *p = m.V + 3 * v;
        if (*p > 0.5) *p -= 0.8;
        else if (*p < -0.5) *p += 0.8;
    }
    assert_int_equal(mesh_write_obj(si, &m, NULL), SCAF_OK);
    mesh_free(&m);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' inflate '%s' -o '%s' -k 2 2>&1", SCAF_BINARY, si, res),
        4);
    assert_non_null(strstr(out, "intersects itself"));
    assert_false(test_exists(res));
    /* usage */
    const char *bad[] = {"",
                         "-k 0",
                         "-k x",
                         "-k 2 -n 0",
                         "-k 2 -n x",
                         "-k 2 --box-scale 1",
                         "-k 2 --solver cg",
                         "-k 2 --frobnicate",
                         "-k"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        assert_int_equal(
            test_run("'%s' inflate '%s' -o '%s' %s 2>/dev/null", SCAF_BINARY, si, res, bad[k]), 2);
    assert_int_equal(test_run("'%s' inflate '%s' -k 2 2>/dev/null", SCAF_BINARY, si), 2);
    assert_int_equal(test_run("'%s' inflate '%s' -o '%s' -k 2 --report '%s' 2>/dev/null",
                              SCAF_BINARY, si, res, si),
                     2);
    assert_int_equal(
        test_run("'%s' inflate '%s.missing' -o '%s' -k 2 2>/dev/null", SCAF_BINARY, si, res), 3);
    assert_false(test_exists(res));
}

static void interrupted(void **state)
{
    (void)state;
    char in[1024], res[1024];
    test_tmp_path("inflate_cli_int.obj", in, sizeof in);
    test_tmp_path("inflate_cli_int_out.obj", res, sizeof res);
    remove(res);
    assert_int_equal(test_run("'%s' gen icosphere -s 3 -o '%s'", SCAF_BINARY, in), 0);
    assert_int_equal(test_capture(out, sizeof out,
                                  "SCAF_TEST_RAISE_SIGNAL_AT=2 '%s' inflate '%s' -o '%s' -k 2 -n 5 "
                                  "2>&1",
                                  SCAF_BINARY, in, res),
                     8);
    assert_int_equal(count(out, "scaf inflate: iteration "), 2);
    assert_false(test_exists(res));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grows_and_writes),
        cmocka_unit_test(refusals),
        cmocka_unit_test(interrupted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
