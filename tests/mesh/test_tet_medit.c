/* Tests for mesh/tet_medit: a bitwise write/read round trip with labels,
 * other tools' sections skipped, comments, and every kind of malformed
 * file refused with its line. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "mesh/tet_medit.h"
#include "support/support.h"

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void round_trip(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.1, 1e-300, -1.2345678901234567e300};
    int T[] = {0, 1, 2, 3, 1, 2, 3, 4};
    int L[] = {1, 2};
    char path[1024];
    test_tmp_path("medit_round_trip.mesh", path, sizeof path);
    scaf_error e;
    assert_int_equal(tet_medit_write(path, 5, V, 2, T, L, &e), SCAF_OK);
    tet_medit m;
    assert_int_equal(tet_medit_read(path, &m, &e), SCAF_OK);
    assert_int_equal(m.nv, 5);
    assert_int_equal(m.nt, 2);
    assert_memory_equal(m.V, V, sizeof V);
    assert_memory_equal(m.T, T, sizeof T);
    assert_memory_equal(m.label, L, sizeof L);
    tet_medit_free(&m);
    /* invalid arrays: nothing written */
    int bad[] = {0, 1, 2, 5};
    test_tmp_path("medit_not_written.mesh", path, sizeof path);
    remove(path);
    assert_int_equal(tet_medit_write(path, 5, V, 1, bad, NULL, &e), SCAF_ERR_MESH);
    assert_false(test_exists(path));
}

static void other_sections_and_comments(void **state)
{
    (void)state;
    char path[1024];
    test_tmp_path("medit_sections.mesh", path, sizeof path);
    write_text(path,
               "MeshVersionFormatted 2\n# a comment\nDimension\n3\nVertices\n4\n0 0 0 1\n1 0 0 1\n"
               "0 1 0 1\n0 0 1 1\nEdges\n1\n1 2 0\nTriangles\n1\n1 2 3 7\nCorners\n1\n1\n"
               "Tetrahedra\n1\n1 2 3 4 9 # trailing\nEnd\n");
    tet_medit m;
    scaf_error e;
    assert_int_equal(tet_medit_read(path, &m, &e), SCAF_OK);
    assert_int_equal(m.nt, 1);
    assert_int_equal(m.label[0], 9);
    assert_int_equal(m.T[3], 3);
    tet_medit_free(&m);
}

static void malformed(void **state)
{
    (void)state;
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"MeshVersionFormatted 1\nDimension 3\nVertices\n1\n0 0 0 0\nHexahedra\n0\nEnd\n",
         ":6: unsupported keyword 'Hexahedra'"},
        {"MeshVersionFormatted 1\nDimension 2\n", ":2: '2' is not the dimension"},
        {"Vertices\n2\n0 0 0 0\n1 1 x 0\nTetrahedra\n0\n", ":4: 'x' is not a finite number"},
        {"Vertices\n1\n0 0 0 0\nTetrahedra\n1\n1 1 1 2 0\n", ":6: '2' is not a vertex index"},
        {"Vertices\n1\n0 0 0 0\nTetrahedra\n1\n1 1 1\n", "end of file where"},
        {"Vertices\n1\n0 0 0 0\nEnd\n", "no Tetrahedra section"},
        {"Tetrahedra\n0\n", "Tetrahedra before Vertices"},
        {"Vertices\n1\n0 0 nan 0\n", "not a finite number"},
    };
    char path[1024];
    test_tmp_path("medit_bad.mesh", path, sizeof path);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        write_text(path, cases[i].text);
        tet_medit m;
        scaf_error e;
        err_clear(&e);
        assert_int_equal(tet_medit_read(path, &m, &e), SCAF_ERR_PARSE);
        if (!strstr(e.message, cases[i].message))
            fail_msg("case %zu: '%s' lacks '%s'", i, e.message, cases[i].message);
        assert_null(m.V);
    }
    tet_medit m;
    scaf_error e;
    assert_int_equal(tet_medit_read("/nonexistent/x.mesh", &m, &e), SCAF_ERR_IO);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_trip),
        cmocka_unit_test(other_sections_and_comments),
        cmocka_unit_test(malformed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
