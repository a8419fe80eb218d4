/* End-to-end: `scaf tet` writes a checked tetrahedral scaffold around a
 * closed surface, `scaf check FILE.mesh` verifies every tet, finds a tet
 * flipped by hand, and surfaces TetGen cannot mesh are refused with exit 4
 * and no file, the cause in words (open, no volume: the same words in
 * tet, inflate, flow and untangle). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support/cli_capture.h"
#include "support/support.h"

static char out[8192];

static void scaffold_and_check(void **state)
{
    (void)state;
    char surf[1024], tets[1024];
    test_tmp_path("tet_cli_ico.obj", surf, sizeof surf);
    test_tmp_path("tet_cli_ico.mesh", tets, sizeof tets);
    assert_int_equal(test_run("'%s' gen icosphere -s 3 -o '%s'", SCAF_BINARY, surf), 0);
    assert_int_equal(
        test_run("'%s' tet '%s' -o '%s' --box-cells 4 --quiet", SCAF_BINARY, surf, tets), 0);
    assert_int_equal(test_capture(out, sizeof out, "'%s' check --json '%s'", SCAF_BINARY, tets), 0);
    long long nt = test_json_field(out, "tets");
    assert_true(nt > 0);
    assert_int_equal(test_json_field(out, "positive"), nt);
    assert_int_equal(test_json_field(out, "valid"), 1);
    /* flip the first tet: swap its first two indices in the file */
    char *text = test_slurp(tets);
    assert_non_null(text);
    char *sec = strstr(text, "Tetrahedra\n");
    assert_non_null(sec);
    char *line = strchr(sec + strlen("Tetrahedra\n"), '\n') + 1;
    int a, b, c, d, ref, used;
    assert_int_equal(sscanf(line, "%d %d %d %d %d%n", &a, &b, &c, &d, &ref, &used), 5);
    char swapped[128];
    int n = snprintf(swapped, sizeof swapped, "%d %d %d %d %d", b, a, c, d, ref);
    assert_int_equal(n, used); /* same length: written in place */
    memcpy(line, swapped, (size_t)n);
    FILE *f = fopen(tets, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    free(text);
    assert_int_equal(test_capture(out, sizeof out, "'%s' check --json '%s'", SCAF_BINARY, tets), 1);
    assert_int_equal(test_json_field(out, "inverted"), 1);
    assert_int_equal(test_json_field(out, "first_bad"), 0);
    assert_int_equal(test_json_field(out, "valid"), 0);
}

static void refusals(void **state)
{
    (void)state;
    char surf[1024], tets[1024];
    test_tmp_path("tet_cli_refused.mesh", tets, sizeof tets);
    remove(tets);
    /* open */
    test_tmp_path("tet_cli_open.obj", surf, sizeof surf);
    assert_int_equal(test_run("'%s' gen hemisphere -s 3 -o '%s'", SCAF_BINARY, surf), 0);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' tet '%s' -o '%s' 2>&1", SCAF_BINARY, surf, tets), 4);
    assert_non_null(strstr(out, "the surface is open"));
    assert_false(test_exists(tets));
    /* issue 29: a single triangle (open) and a triangle twice (closed, no
     * volume) said "tet_box_mesh: bad arguments (3 vertices, ...)"; every
     * 3D command now names the cause in the same words */
    static const char *const small[][2] = {
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the surface is open"},
        {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
         "the surface encloses no volume: 3 vertices and 2 faces"},
    };
    static const char *const cmds[] = {"tet", "inflate --scale 2", "flow --steps 2", "untangle"};
    for (int i = 0; i < 2; i++) {
        test_tmp_path("tet_cli_small.off", surf, sizeof surf);
        FILE *g = fopen(surf, "w");
        assert_non_null(g);
        fputs(small[i][0], g);
        fclose(g);
        for (int c = 0; c < 4; c++) {
            char o[1024];
            test_tmp_path(c == 0 ? "tet_cli_small.mesh" : "tet_cli_small.obj", o, sizeof o);
            remove(o);
            assert_int_equal(test_capture(out, sizeof out, "'%s' %.*s '%s' -o '%s' %s 2>&1",
                                          SCAF_BINARY, (int)strcspn(cmds[c], " "), cmds[c], surf, o,
                                          cmds[c] + strcspn(cmds[c], " ")),
                             4);
            if (!strstr(out, small[i][1])) print_error("%s: %s\n", cmds[c], out);
            assert_non_null(strstr(out, small[i][1]));
            assert_null(strstr(out, "bad arguments"));
            assert_false(test_exists(o));
        }
    }
    /* self-intersecting: an octahedron with its top pushed through a bottom face */
    test_tmp_path("tet_cli_pushed.off", surf, sizeof surf);
    FILE *f = fopen(surf, "w");
    assert_non_null(f);
    fputs("OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0.2 0.2 -0.9\n0 0 -1\n"
          "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n",
          f);
    fclose(f);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' tet '%s' -o '%s' 2>&1", SCAF_BINARY, surf, tets), 4);
    assert_non_null(strstr(out, "intersects itself"));
    assert_false(test_exists(tets));
    /* usage */
    assert_int_equal(test_run("'%s' tet '%s' 2>/dev/null", SCAF_BINARY, surf), 2);
    assert_int_equal(
        test_run("'%s' tet '%s' -o '%s' --box-scale 1 2>/dev/null", SCAF_BINARY, surf, tets), 2);
    assert_int_equal(
        test_run("'%s' tet '%s' -o '%s' --box-cells 65 2>/dev/null", SCAF_BINARY, surf, tets), 2);
    /* outputs: the shared checks before any work, nothing left on an interrupt */
    char *before = test_slurp(surf);
    assert_non_null(before);
    assert_int_equal(test_run("'%s' tet '%s' -o '%s' 2>/dev/null", SCAF_BINARY, surf, surf), 2);
    char *after = test_slurp(surf);
    assert_non_null(after);
    assert_string_equal(before, after); /* the input is never the output */
    free(before);
    free(after);
    char dir[1024];
    test_tmp_path("", dir, sizeof dir);
    assert_int_equal(test_run("'%s' tet '%s' -o '%s' 2>/dev/null", SCAF_BINARY, surf, dir), 5);
    remove(tets);
    test_tmp_path("tet_cli_ico2.obj", surf, sizeof surf);
    assert_int_equal(test_run("'%s' gen icosphere -s 2 -o '%s'", SCAF_BINARY, surf), 0);
    assert_int_equal(test_capture(out, sizeof out,
                                  "SCAF_TEST_RAISE_SIGNAL_AT=write '%s' tet '%s' -o '%s' 2>&1",
                                  SCAF_BINARY, surf, tets),
                     8);
    assert_false(test_exists(tets));
    /* a malformed .mesh */
    f = fopen(tets, "w");
    assert_non_null(f);
    fputs("Vertices\n1\n0 0 0 0\nTetrahedra\n1\n1 1 1 9 0\n", f);
    fclose(f);
    assert_int_equal(test_run("'%s' check '%s' 2>/dev/null", SCAF_BINARY, tets), 3);
}

static void shared_bunny(void **state)
{
    (void)state;
    char surf[1024], tets[1024];
    if (!test_data_path("closed/bunny.obj", surf, sizeof surf)) skip();
    test_tmp_path("tet_cli_bunny.mesh", tets, sizeof tets);
    assert_int_equal(
        test_capture(out, sizeof out, "'%s' tet '%s' -o '%s' 2>&1", SCAF_BINARY, surf, tets), 0);
    assert_non_null(strstr(out, "568 surface, 386 box"));
    assert_int_equal(test_capture(out, sizeof out, "'%s' check --json '%s'", SCAF_BINARY, tets), 0);
    assert_int_equal(test_json_field(out, "inverted") + test_json_field(out, "degenerate"), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scaffold_and_check),
        cmocka_unit_test(refusals),
        cmocka_unit_test(shared_bunny),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
