/* End-to-end tests of automatic seams (--seams) in `scaf param`, `scaf
 * atlas`: a closed sphere (genus 0), a torus (genus 1), several
 * components in one file and a plate with holes go through both commands
 * with exit 0, the output proved bijective by `scaf check` (exact), the
 * terminal saying which seams were used and how many charts; the report
 * lists the seams and the chart of every face; `--seams input` keeps the
 * old refusal of a closed chart, non-manifold input is refused naming the
 * edge with no output; a mesh whose vt cut it into disks keeps them by
 * default, and `--seams auto` / `extend` replace or extend them. */
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
#include "support/support.h"

/* A torus OBJ (nu x nv grid wrapped both ways), moved by dx, vertex
 * numbers from base + 1: for files with several components. */
static void write_torus(FILE *f, int nu, int nv, double dx, int base)
{
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 2 * 3.14159265358979 * i / nu, b = 2 * 3.14159265358979 * j / nv;
            fprintf(f, "v %.17g %.17g %.17g\n", dx + (2 + 0.7 * cos(b)) * cos(a),
                    (2 + 0.7 * cos(b)) * sin(a), 0.7 * sin(b));
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
            fprintf(f, "f %d %d %d\nf %d %d %d\n", base + a + 1, base + b + 1, base + c + 1,
                    base + a + 1, base + c + 1, base + d + 1);
        }
}

/* `scaf CMD IN -o OUT EXTRA` exits 0, says "seams: WANT", and OUT is
 * bijective by `scaf check`. The terminal text is left in *log (caller
 * frees). */
static void run_ok(const char *cmd, const char *in, const char *extra, const char *want, char **log)
{
    char out[512], err[512];
    test_tmp_path("e2e_seams_out.obj", out, sizeof out);
    test_tmp_path("e2e_seams_err.txt", err, sizeof err);
    remove(out);
    int rc = test_run("%s %s %s -o %s %s 2> %s", SCAF_BINARY, cmd, in, out, extra, err);
    char *text = test_slurp(err);
    assert_non_null(text);
    if (rc != 0) print_error("%s", text);
    assert_int_equal(rc, 0);
    if (!strstr(text, want)) print_error("no '%s' in: %s", want, text);
    assert_non_null(strstr(text, want));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    if (log) *log = text;
    else free(text);
}

/* The chart count "N chart(s)" on the seams line. */
static int charts_of(const char *log)
{
    const char *s = strstr(log, "seams: ");
    assert_non_null(s);
    const char *c = strstr(s, " chart(s)");
    assert_non_null(c);
    while (c > s && c[-1] >= '0' && c[-1] <= '9') c--;
    return atoi(c);
}

static void closed_sphere_and_torus(void **state)
{
    (void)state;
    char in[512];
    char *log;
    test_tmp_path("e2e_seams_ball.obj", in, sizeof in);
    assert_int_equal(test_run("%s gen icosphere --size 5 -o %s", SCAF_BINARY, in), 0);
    char png[512], extra[1100];
    test_tmp_path("e2e_seams_ball.png", png, sizeof png);
    remove(png);
    snprintf(extra, sizeof extra, "--iterations 30 --png-seams %s", png);
    run_ok("param", in, extra, "seams: auto", &log);
    assert_int_equal(charts_of(log), 1);
    free(log);
    /* the picture: two 512 x 512 panels */
    char *pic = test_slurp(png);
    assert_non_null(pic);
    assert_memory_equal(pic, "\x89PNG", 4);
    assert_memory_equal(pic + 16, "\0\0\x04\0\0\0\x02\0", 8); /* IHDR 1024 x 512 */
    free(pic);
    run_ok("atlas", in, "--iterations 20 --compact-iterations 5", "seams: auto", &log);
    assert_true(charts_of(log) >= 1);
    free(log);
    /* only the components: refused, naming the chart, no output */
    char out[512];
    test_tmp_path("e2e_seams_refused.obj", out, sizeof out);
    remove(out);
    assert_int_equal(
        test_run("%s param %s -o %s --seams input --quiet 2> /dev/null", SCAF_BINARY, in, out), 4);
    assert_false(test_exists(out));

    test_tmp_path("e2e_seams_torus.obj", in, sizeof in);
    FILE *f = fopen(in, "w");
    assert_non_null(f);
    write_torus(f, 30, 12, 0.0, 0);
    fclose(f);
    run_ok("param", in, "--iterations 30", "seams: auto", &log);
    assert_int_equal(charts_of(log), 1);
    free(log);
    run_ok("atlas", in, "--iterations 20 --compact-iterations 5", "seams: auto", NULL);
}

static void several_components_and_report(void **state)
{
    (void)state;
    char in[512], out[512], rep[512], ball[512];
    test_tmp_path("e2e_seams_ball3.obj", ball, sizeof ball);
    assert_int_equal(test_run("%s gen icosphere --size 3 -o %s", SCAF_BINARY, ball), 0);
    mesh b;
    scaf_error e;
    assert_int_equal(mesh_read(ball, &b, NULL, &e), SCAF_OK);
    test_tmp_path("e2e_seams_three.obj", in, sizeof in);
    FILE *f = fopen(in, "w");
    assert_non_null(f);
    for (int i = 0; i < b.nv; i++)
        fprintf(f, "v %.17g %.17g %.17g\n", b.V[3 * i], b.V[3 * i + 1], b.V[3 * i + 2]);
    for (int i = 0; i < b.nf; i++)
        fprintf(f, "f %d %d %d\n", b.F[3 * i] + 1, b.F[3 * i + 1] + 1, b.F[3 * i + 2] + 1);
    write_torus(f, 20, 8, 5.0, b.nv);
    write_torus(f, 16, 8, 12.0, b.nv + 160);
    fclose(f);
    char *log;
    run_ok("param", in, "--iterations 20", "seams: auto", &log);
    assert_int_equal(charts_of(log), 3);
    free(log);
    test_tmp_path("e2e_seams_report.json", rep, sizeof rep);
    test_tmp_path("e2e_seams_three_out.obj", out, sizeof out);
    char extra[1100];
    snprintf(extra, sizeof extra, "--iterations 10 --compact-iterations 3 --report %s", rep);
    run_ok("atlas", in, extra, "seams: auto", &log);
    int nc = charts_of(log);
    assert_true(nc >= 3);
    free(log);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"seams\": {\"source\": \"auto\""));
    assert_non_null(strstr(json, "\"seam_edges\": [["));
    assert_non_null(strstr(json, "\"length_per_sqrt_area\": "));
    /* one chart per face */
    const char *fc = strstr(json, "\"face_chart\": [");
    assert_non_null(fc);
    int commas = 0;
    for (const char *p = fc; *p && *p != ']'; p++) commas += *p == ',';
    assert_int_equal(commas + 1, b.nf + 2 * 20 * 8 + 2 * 16 * 8);
    free(json);
    mesh_free(&b);
}

static void holes_need_no_cut(void **state)
{
    (void)state;
    char in[512];
    char *log;
    test_tmp_path("e2e_seams_holes.obj", in, sizeof in);
    assert_int_equal(test_run("%s gen holes --size 4 -o %s", SCAF_BINARY, in), 0);
    run_ok("param", in, "--iterations 20", "seams: input", &log);
    assert_non_null(strstr(log, " 0 seam edges"));
    free(log);
}

static void non_manifold_is_refused_naming_the_edge(void **state)
{
    (void)state;
    char in[512], out[512], err[512];
    test_tmp_path("e2e_seams_nm.obj", in, sizeof in);
    test_tmp_path("e2e_seams_nm_out.obj", out, sizeof out);
    test_tmp_path("e2e_seams_nm_err.txt", err, sizeof err);
    FILE *f = fopen(in, "w");
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n", f);
    fclose(f);
    const char *modes[] = {"", "--seams auto", "--seams extend"};
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 2; c++) {
            remove(out);
            assert_int_equal(test_run("%s %s %s -o %s %s 2> %s", SCAF_BINARY, c ? "atlas" : "param",
                                      in, out, modes[i], err),
                             4);
            assert_false(test_exists(out));
            char *text = test_slurp(err);
            assert_non_null(text);
            assert_non_null(strstr(text, "0-1 has 3 faces"));
            free(text);
        }
}

/* cubesphere's vt cut it into 6 disks: kept by default; auto ignores
 * them; extend keeps them (nothing to add). */
static void input_seams_are_kept(void **state)
{
    (void)state;
    char in[512];
    char *log;
    test_tmp_path("e2e_seams_cube.obj", in, sizeof in);
    assert_int_equal(test_run("%s gen cubesphere --size 4 -o %s", SCAF_BINARY, in), 0);
    run_ok("param", in, "--iterations 10", "seams: input", &log);
    assert_int_equal(charts_of(log), 6);
    free(log);
    run_ok("param", in, "--iterations 10 --seams extend", "seams: extend", &log);
    assert_int_equal(charts_of(log), 6);
    free(log);
    run_ok("param", in, "--iterations 10 --seams auto", "seams: auto", &log);
    assert_int_equal(charts_of(log), 1);
    free(log);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_sphere_and_torus),
        cmocka_unit_test(several_components_and_report),
        cmocka_unit_test(holes_need_no_cut),
        cmocka_unit_test(non_manifold_is_refused_naming_the_edge),
        cmocka_unit_test(input_seams_are_kept),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
