/* Tests for the OFF reader: variants, comments, CRLF, polygons, colours. */
#include <zlib.h>

#include "mesh_test_util.h"

static void plain_off(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    parse_ok("OFF\n4 2 5\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", MESH_FORMAT_OFF, &m,
             &info);
    assert_int_equal(m.nv, 4);
    assert_int_equal(m.nf, 2);
    const int F[6] = {0, 1, 2, 1, 3, 2};
    assert_memory_equal(m.F, F, sizeof F);
    assert_true(m.V[9] == 1.0 && m.V[10] == 1.0);
    assert_int_equal(info.format, MESH_FORMAT_OFF);
    assert_null(m.FT);
    mesh_free(&m);
}

static void comments_crlf_blank_lines(void **state)
{
    (void)state;
    mesh m;
    parse_ok("# leading comment\r\nOFF # trailing\r\n\r\n# counts next\r\n3 1 0\r\n0.5 0 0\r\n# "
             "mid\r\n"
             "1 0 0   \r\n\r\n0 1 0\r\n3 0 1 2\r\n",
             MESH_FORMAT_OFF, &m, NULL);
    assert_int_equal(m.nv, 3);
    assert_int_equal(m.nf, 1);
    assert_true(m.V[0] == 0.5);
    mesh_free(&m);
}

static void counts_on_header_line_and_no_edges(void **state)
{
    (void)state;
    mesh m;
    parse_ok("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2", MESH_FORMAT_OFF, &m, NULL);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
    parse_ok("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MESH_FORMAT_OFF, &m, NULL);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
}

static void variants_and_extra_values(void **state)
{
    (void)state;
    mesh m;
    /* Colour per vertex (COFF), normals (NOFF), both, texture (STOFF): extra values ignored. */
    parse_ok("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 1 0 "
             "0\n",
             MESH_FORMAT_OFF, &m, NULL);
    assert_int_equal(m.nf, 1);
    assert_true(m.V[3] == 1.0 && m.V[4] == 0.0 && m.V[5] == 0.0);
    mesh_free(&m);
    parse_ok("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", MESH_FORMAT_OFF, &m,
             NULL);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
    parse_ok("CNOFF\n3 1 0\n0 0 0 0 0 1 1 1 1\n1 0 0 0 0 1 1 1 1\n0 1 0 0 0 1 1 1 1\n3 0 1 2\n",
             MESH_FORMAT_OFF, &m, NULL);
    mesh_free(&m);
    parse_ok("STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n", MESH_FORMAT_OFF, &m, NULL);
    mesh_free(&m);
    parse_ok("nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MESH_FORMAT_OFF, &m, NULL);
    assert_int_equal(m.nv, 3);
    mesh_free(&m);
}

static void polygons_fanned_with_face_colour(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    parse_ok("OFF\n5 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4 0.1 0.2 0.3 1\n4 0 1 3 "
             "4\n",
             MESH_FORMAT_OFF, &m, &info);
    assert_int_equal(m.nf, 3 + 2);
    assert_int_equal(info.polygons_triangulated, 2);
    const int F[15] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 1, 3, 0, 3, 4};
    assert_memory_equal(m.F, F, sizeof F);
    mesh_free(&m);
}

static void format_from_extension_and_content(void **state)
{
    (void)state;
    const char *text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    char path[512];
    mesh m;
    scaf_error e;
    mesh_read_info info;
    write_tmp("off_read.OFF", text, strlen(text), path, sizeof path);
    assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
    assert_int_equal(info.format, MESH_FORMAT_OFF);
    mesh_free(&m);
    /* Unknown extension: recognized by content. */
    write_tmp("off_read.mesh", text, strlen(text), path, sizeof path);
    assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
    assert_int_equal(info.format, MESH_FORMAT_OFF);
    mesh_free(&m);
}

static void gzip_off(void **state)
{
    (void)state;
    const char *text = "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    char path[512];
    test_tmp_path("off_read.off.gz", path, sizeof path);
    gzFile g = gzopen(path, "wb");
    assert_non_null(g);
    assert_int_equal(gzwrite(g, text, (unsigned)strlen(text)), (int)strlen(text));
    assert_int_equal(gzclose(g), Z_OK);
    mesh m;
    scaf_error e;
    mesh_read_info info;
    assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
    assert_int_equal(info.format, MESH_FORMAT_OFF);
    assert_int_equal(m.nf, 1);
    assert_true(m.V[3] == 1.0);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plain_off),
        cmocka_unit_test(comments_crlf_blank_lines),
        cmocka_unit_test(counts_on_header_line_and_no_edges),
        cmocka_unit_test(variants_and_extra_values),
        cmocka_unit_test(polygons_fanned_with_face_colour),
        cmocka_unit_test(format_from_extension_and_content),
        cmocka_unit_test(gzip_off),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
