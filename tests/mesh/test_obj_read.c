/* Tests for the OBJ reader: every face form, polygons, comments, CRLF,
 * exact numbers, UV policy and gzip input. */
#include <math.h>
#include <zlib.h>

#include "mesh_test_util.h"

static void plain_triangles(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    parse_ok("# a comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n", MESH_FORMAT_OBJ,
             &m, &info);
    assert_int_equal(m.nv, 4);
    assert_int_equal(m.nf, 2);
    assert_int_equal(m.nuv, 0);
    assert_null(m.FT);
    const int F[6] = {0, 1, 2, 1, 3, 2};
    assert_memory_equal(m.F, F, sizeof F);
    assert_true(m.V[9] == 1.0 && m.V[10] == 1.0 && m.V[11] == 0.0);
    assert_int_equal(info.format, MESH_FORMAT_OBJ);
    assert_int_equal(info.polygons_triangulated, 0);
    mesh_free(&m);
}

static void every_index_form(void **state)
{
    (void)state;
    const char *head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
    const char *faces[] = {"f 1 2 3\n",
                           "f 1/1 2/2 3/3\n",
                           "f 1//1 2//1 3//1\n",
                           "f 1/1/1 2/2/1 3/3/1\n",
                           "f -3/-3 -2/-2 -1/-1\n",
                           "f -3//-1 -2//-1 -1//-1\n",
                           "f 1/1/ 2/2/ 3/3/\n"};
    const int has_uv[] = {0, 1, 0, 1, 1, 0, 1};
    for (size_t i = 0; i < sizeof faces / sizeof *faces; i++) {
        char text[256];
        snprintf(text, sizeof text, "%s%s", head, faces[i]);
        mesh m;
        mesh_read_info info;
        parse_ok(text, MESH_FORMAT_OBJ, &m, &info);
        assert_int_equal(m.nf, 1);
        assert_int_equal(m.F[0], 0);
        assert_int_equal(m.F[1], 1);
        assert_int_equal(m.F[2], 2);
        assert_int_equal(info.normals_ignored, 1);
        assert_int_equal(mesh_has_uv(&m), has_uv[i]);
        if (has_uv[i]) {
            assert_int_equal(m.nuv, 3);
            assert_int_equal(m.FT[0], 0);
            assert_int_equal(m.FT[1], 1);
            assert_int_equal(m.FT[2], 2);
            assert_true(m.UV[2] == 1.0 && m.UV[3] == 0.0);
        }
        mesh_free(&m);
    }
}

static void relative_indices_follow_the_file(void **state)
{
    (void)state;
    mesh m;
    /* -1 means the last vertex read so far, not the last of the file. */
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n", MESH_FORMAT_OBJ, &m,
             NULL);
    assert_int_equal(m.nf, 2);
    const int F[6] = {0, 1, 2, 0, 1, 3};
    assert_memory_equal(m.F, F, sizeof F);
    mesh_free(&m);
}

static void polygons_are_fanned(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    parse_ok("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\nf 1 2 4 5\nf 1 2 3\n",
             MESH_FORMAT_OBJ, &m, &info);
    assert_int_equal(m.nf, 3 + 2 + 1);
    assert_int_equal(info.polygons_triangulated, 2);
    char w[256];
    assert_int_equal(mesh_read_warnings(&info, w, sizeof w), 1);
    assert_string_equal(w, "2 polygons with more than 3 corners fan-triangulated");
    const int F[18] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 1, 3, 0, 3, 4, 0, 1, 2};
    assert_memory_equal(m.F, F, sizeof F);
    mesh_free(&m);
}

static void ignored_statements_crlf_blanks(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    const char *text = "\xEF\xBB\xBF# exported\r\nmtllib x.mtl\r\no thing\r\ng group one\r\ns "
                       "off\r\n"
                       "usemtl mat\r\n\r\n   \r\n\tv 0 0 0 1.0\r\nv 1 0 0 0.5 0.5 0.5   \r\nv 0 1 "
                       "0\t\r\n"
                       "vp 0.5\r\nl 1 2\r\np 1\r\nf 1 2 3   # trailing comment\r\n";
    parse_ok(text, MESH_FORMAT_OBJ, &m, &info);
    assert_int_equal(m.nv, 3);
    assert_int_equal(m.nf, 1);
    assert_true(m.V[3] == 1.0 && m.V[6] == 0.0 && m.V[7] == 1.0);
    mesh_free(&m);
}

static void no_final_newline(void **state)
{
    (void)state;
    mesh m;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3", MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0.25\nf 1 2 3\nv 0 0 7", MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nv, 4);
    assert_true(m.V[11] == 7.0);
    mesh_free(&m);
}

/* Every number must equal what strtod makes of the same text. */
static void numbers_equal_strtod(void **state)
{
    (void)state;
    const char *nums[] = {"0.1",
                          "-0.0",
                          "1e-5",
                          "1E+22",
                          "123456789012345678",
                          "0.30000000000000004",
                          "1.7976931348623157e308",
                          "4.9e-324",
                          "2.2250738585072011e-308",
                          "9007199254740993",
                          "0.000000000000000000000000000001234567890123456789",
                          "+3.25",
                          "-.5",
                          "5.",
                          "1e23",
                          "8.589973e9",
                          "0.00817800034",
                          "-0.0496510006",
                          "12345678901234567890.5",
                          "1.00000000000000011102230246251565404236316680908203125",
                          "7.0e-10",
                          "3"};
    size_t k = sizeof nums / sizeof *nums;
    char text[4096];
    size_t o = 0;
    for (size_t i = 0; i < k; i++)
        o += (size_t)snprintf(text + o, sizeof text - o, "v %s 0 0\n", nums[i]);
    snprintf(text + o, sizeof text - o, "f 1 2 3\n");
    mesh m;
    parse_ok(text, MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nv, (int)k);
    for (size_t i = 0; i < k; i++) {
        double want = strtod(nums[i], NULL);
        assert_memory_equal(&m.V[3 * i], &want, sizeof want);
    }
    mesh_free(&m);
    /* And many random decimal strings of every length. */
    srand(12345);
    char *big = malloc(1 << 20);
    assert_non_null(big);
    char(*strs)[40] = malloc(3000 * sizeof *strs);
    assert_non_null(strs);
    o = 0;
    for (int i = 0; i < 3000; i++) {
        int digits = 1 + rand() % 24, point = rand() % (digits + 1), e = rand() % 70 - 35;
        char *s = strs[i];
        int n = 0;
        if (rand() & 1) s[n++] = '-';
        for (int d = 0; d < digits; d++) {
            if (d == point && d > 0) s[n++] = '.';
            s[n++] = (char)('0' + rand() % 10);
        }
        if (rand() % 3 == 0) n += snprintf(s + n, 40 - (size_t)n, "e%d", e);
        s[n] = '\0';
        o += (size_t)snprintf(big + o, (1 << 20) - o, "v %s 1 1\n", s);
    }
    snprintf(big + o, (1 << 20) - o, "f 1 2 3\n");
    parse_ok(big, MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nv, 3000);
    for (int i = 0; i < 3000; i++) {
        double want = strtod(strs[i], NULL);
        if (memcmp(&m.V[3 * i], &want, sizeof want) != 0)
            print_error("mismatch on '%s'\n", strs[i]);
        assert_memory_equal(&m.V[3 * i], &want, sizeof want);
    }
    mesh_free(&m);
    free(strs);
    free(big);
}

static void uv_seams_kept(void **state)
{
    (void)state;
    mesh m;
    /* Two triangles share the 3D edge 2-3 but use different vt on it. */
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 5 5\nvt 6 6\nvt 7 7\n"
             "f 1/1 2/2 3/3\nf 2/4 4/5 3/6\n",
             MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nuv, 6);
    const int FT[6] = {0, 1, 2, 3, 4, 5};
    assert_memory_equal(m.FT, FT, sizeof FT);
    mesh_free(&m);
}

static void vt_with_one_or_three_values(void **state)
{
    (void)state;
    mesh m;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nvt 1 0 0\nvt 0 1\nf 1/1 2/2 3/3\n",
             MESH_FORMAT_OBJ, &m, NULL);
    assert_true(m.UV[0] == 0.5 && m.UV[1] == 0.0);
    mesh_free(&m);
}

static void mixed_uv_faces_drop_uvs(void **state)
{
    (void)state;
    mesh m;
    mesh_read_info info;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 2 4 "
             "3\nf 4 3 2\n",
             MESH_FORMAT_OBJ, &m, &info);
    assert_int_equal(m.nf, 3);
    assert_int_equal(m.nuv, 0);
    assert_null(m.FT);
    assert_int_equal(info.faces_without_uv, 2);
    char w[256];
    assert_int_equal(mesh_read_warnings(&info, w, sizeof w), 1);
    assert_non_null(strstr(w, "2 faces without texture indices"));
    mesh_free(&m);
    /* vt lines that no face uses: no UVs, no warning. */
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n", MESH_FORMAT_OBJ, &m, &info);
    assert_int_equal(m.nuv, 0);
    assert_int_equal(info.faces_without_uv, 0);
    mesh_free(&m);
}

static void forward_references_allowed(void **state)
{
    (void)state;
    mesh m;
    parse_ok("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", MESH_FORMAT_OBJ, &m, NULL);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
}

static void gzip_and_plain_files_read_alike(void **state)
{
    (void)state;
    const char *text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
    char plain[512], gz[512];
    write_tmp("obj_read_plain.obj", text, strlen(text), plain, sizeof plain);
    test_tmp_path("obj_read_gz.obj.gz", gz, sizeof gz);
    gzFile g = gzopen(gz, "wb");
    assert_non_null(g);
    assert_int_equal(gzwrite(g, text, (unsigned)strlen(text)), (int)strlen(text));
    assert_int_equal(gzclose(g), Z_OK);
    mesh a, b;
    scaf_error e;
    assert_int_equal(mesh_read(plain, &a, NULL, &e), SCAF_OK);
    assert_int_equal(mesh_read(gz, &b, NULL, &e), SCAF_OK);
    assert_same_mesh(&a, &b);
    mesh_free(&a);
    mesh_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plain_triangles),
        cmocka_unit_test(every_index_form),
        cmocka_unit_test(relative_indices_follow_the_file),
        cmocka_unit_test(polygons_are_fanned),
        cmocka_unit_test(ignored_statements_crlf_blanks),
        cmocka_unit_test(no_final_newline),
        cmocka_unit_test(numbers_equal_strtod),
        cmocka_unit_test(uv_seams_kept),
        cmocka_unit_test(vt_with_one_or_three_values),
        cmocka_unit_test(mixed_uv_faces_drop_uvs),
        cmocka_unit_test(forward_references_allowed),
        cmocka_unit_test(gzip_and_plain_files_read_alike),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
