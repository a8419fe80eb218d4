/* Every malformed input gets SCAF_ERR_PARSE with "NAME:LINE: reason" (or
 * SCAF_ERR_IO naming the path for unreadable files), never a crash. */
#include <zlib.h>

#include "mesh_test_util.h"

#define TRI "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

static const parse_case obj_index_cases[] = {
    {TRI "f 1 2 4\n", 4, "vertex index 4 out of range (the file has 3 vertices)"},
    {TRI "f 1 2 3\nf 1 2 99\nv 1 1 1\n", 5, "99"},
    {TRI "f 0 1 2\n", 4, "index 0"},
    {TRI "f -4 -2 -1\n", 4, "relative vertex index -4"},
    {TRI "f 1 2 99999999999\n", 4, "overflows"},
    {TRI "f 1 2 -99999999999999999999999\n", 4, "overflows"},
    {TRI "vt 0 0\nf 1/1 2/2 3/3\n", 5, "texture index 3 out of range (the file has 1 vt)"},
    {TRI "f 1/1 2/1 3/1\n", 4, "texture index 1 out of range (the file has 0 vt)"},
    {TRI "vt 0 0\nf 1/-2 2/-1 3/-1\n", 5, "relative texture index -2"},
    {TRI "vt 0 0\nf 1/1 2 3\n", 5, "mixes"},
};

static void obj_index_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_OBJ, obj_index_cases);
}

static const parse_case obj_face_shape_cases[] = {
    {TRI "f 1 2\n", 4, "2 corners"},
    {TRI "f\n", 4, "0 corners"},
    {TRI "f 1 2 1\n", 4, "vertex 1 more than once"},
    {TRI "v 1 1 0\nf 1 2 3 -3\n", 5, "vertex 2 more than once"},
    {TRI "f 1 2 3x\n", 4, "bad face corner '3x'"},
    {TRI "f 1/2/3/4 2 3\n", 4, "bad face corner"},
    {TRI "f 1/x 2 3\n", 4, "bad face corner"},
    {TRI "f 1//x 2//1 3//1\n", 4, "bad face corner"},
};

static void obj_face_shape_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_OBJ, obj_face_shape_cases);
}

static const parse_case obj_number_cases[] = {
    {"v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
    {"v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
    {"v 0 0 0\nv 1 0 -Infinity\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
    {"v 0 0 0\nv 1 0 1e999\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
    {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2, "missing value"},
    {"v 0 0 0\nv 1 0 abc\nv 0 1 0\nf 1 2 3\n", 2, "'abc' is not a number"},
    {"v 0 0 0\nv 1 0 1.5.5\nv 0 1 0\nf 1 2 3\n", 2, "not a number"},
    {"v 0 0 0\nv 1 0 1e\n", 2, "not a number"},
    {"v 0 0 0\nv 1 0 0x10\n", 2, "not a number"},
    {TRI "vt 0 nan\n", 4, "texture coordinate"},
};

static void obj_number_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_OBJ, obj_number_cases);
}

static const parse_case obj_garbage_cases[] = {
    {TRI "hello world\nf 1 2 3\n", 4, "unknown statement 'hello'"},
    {TRI "\x01\x02\x03\n", 4, "unknown statement"},
    {TRI, 3, "no faces"},
    {"", 1, "no faces"},
    {"# nothing\n\n", 2, "no faces"},
    /* issue 29: said "no faces (empty mesh)" */
    {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", 1, "lines end in CR alone"},
    {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3", 1, "lines end in CR alone"},
};

static void obj_garbage_and_empty(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_OBJ, obj_garbage_cases);
    /* Embedded NUL bytes are garbage, not the end of the text. */
    static const char nul[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\0\n";
    parse_fails_n(nul, sizeof nul - 1, MESH_FORMAT_OBJ, SCAF_ERR_PARSE, 5, "unknown statement");
}

static const parse_case off_cases[] = {
    {"", 1, "no OFF header"},
    {"PLY\n", 1, "not an OFF file"},
    {"4OFF\n3 1 0\n", 1, "4D"},
    {"nOFF\n2\n3 1 0\n", 2, "dimension 2"},
    {"OFF\n", 2, "missing vertex count"},
    {"OFF\n3 x 0\n", 2, "bad face count 'x'"},
    {"OFF\n-3 1 0\n", 2, "bad vertex count"},
    {"OFF\n1000000000000 1 0\n0 0 0\n", 2, "bad vertex count"},
    {"OFF\n2000000000 2000000000 0\n0 0 0\n", 2, "truncated"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n", 2, "truncated"},
    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# no more faces here\n", 8,
     "truncated file: 1 of 2 faces"},
    {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", 2, "no faces"},
    {"OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 4, "finite"},
    {"OFF\n3 1 0\n0 0 0\n10 0\n0 1 0\n3 0 1 2\n", 4, "has 2 coordinates"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6,
     "vertex index 3 out of range (the file has 3 vertices)"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6, "-1 out of range"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999999999999\n", 6, "out of range"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n", 6, "more than once"},
    {"OFF\n3 1 0\n0 0 0.5\n1 0 0.5\n0 1 0\n2 0 1\n", 6, "2 corners"},
    /* issue 29: the short lines of this file made it "only 24 bytes follow
     * (truncated file?)" */
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 6, "face has 2 corners (needs at least 3)"},
    {"OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r", 1, "lines end in CR alone"},
    {"OFF\n3 1 0\n0 0 0.5\n1 0 0.5\n0 1 0\n3 0 1\n", 6, "2 of its 3 indices"},
    {"OFF\n3 1 0\n0 0 0.5\n1 0 0.5\n0 1 0\n300 0 1 2\n", 6, "line is shorter"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2    \n", 6, "3 of its 4 indices"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 z\n", 6, "bad vertex index 'z'"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nx 0 1 2\n", 6, "bad corner count"},
};

static void off_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_OFF, off_cases);
}

#define PLY_HEAD(fmt, nv, nf)                                                                      \
    "ply\nformat " fmt " 1.0\nelement vertex " nv "\nproperty float x\nproperty float "            \
    "y\nproperty float z\n"                                                                        \
    "element face " nf "\nproperty list uchar int vertex_indices\nend_header\n"

static const parse_case ply_header_cases[] = {
    {"", 1, "truncated header"},
    {"plx\n", 1, "not a PLY file"},
    {"ply\nformat ascii 1.0\nelement vertex 3\n", 3, "no end_header"},
    {"ply\nformat binary_middle_endian 1.0\nend_header\n", 2,
     "unknown PLY format 'binary_middle_endian'"},
    {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\nend_header\n", 4,
     "unknown PLY type 'float128'"},
    {"ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n",
     4, "count type"},
    {"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float "
     "vertex_indices\nend_header\n",
     4, "integer type"},
    {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", 3, "before any element"},
    {"ply\nformat ascii 1.0\nelement vertex x\nend_header\n", 3, "bad element count"},
    {"ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", 3, "bad element count"},
    {"ply\nformat ascii 1.0\nbanana\nend_header\n", 3, "unknown header line"},
    {"ply\nend_header\n", 2, "no format"},
    {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n"
     "0 0\n1 0\n0 1\n",
     6, "lacks x, y or z"},
    {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
     "z\n"
     "end_header\n0 0 0\n1 0 0\n0 1 0\n",
     7, "no faces"},
    {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
     "z\n"
     "element face 1\nproperty list uchar int corners\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
     9, "lacks a 'vertex_indices'"},
};

static void ply_header_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_PLY, ply_header_cases);
}

static const parse_case ply_body_cases[] = {
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13,
     "vertex index 3 out of range (the file has 3 vertices)"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 13, "out of range"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1 0\n", 13, "more than once"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, "2 corners"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 11, "finite number"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", 11, "'x'"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", 14, "truncated"},
    {PLY_HEAD("ascii", "3", "2") "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 14, "truncated"},
    {PLY_HEAD("ascii", "4000000000", "1") "0 0 0\n", 9, "truncated"},
    {PLY_HEAD("ascii", "3", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n", 13, "integer"},
};

static void ply_body_errors(void **state)
{
    (void)state;
    PARSE_CASES_FAIL(MESH_FORMAT_PLY, ply_body_cases);
    /* Binary: a face whose list claims 200 corners in a short file; a huge element count. */
    char buf[512];
    size_t n = (size_t)snprintf(buf, sizeof buf, "%s", PLY_HEAD("binary_little_endian", "3", "1"));
    float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    memcpy(buf + n, v, sizeof v); /* host order: the test only checks the count error */
    n += sizeof v;
    buf[n++] = (char)200;
    memset(buf + n, 0, 12);
    n += 12;
    parse_fails_n(buf, n, MESH_FORMAT_PLY, SCAF_ERR_PARSE, 9, "truncated binary data: face 0");
    parse_fails(PLY_HEAD("binary_big_endian", "1000000000000", "1"), MESH_FORMAT_PLY, 9,
                "truncated");
}

/* issue 29: a gzip bomb (here 64 MiB of zeros behind one valid line,
 * 65 KB compressed) is refused after its first chunk, not inflated whole
 * before the parser looks at it (4 GB of zeros took 4.28 GB of memory). */
static void gzip_bomb_stops_at_the_first_chunk(void **state)
{
    (void)state;
    char path[512];
    test_tmp_path("read_errors_bomb.obj.gz", path, sizeof path);
    gzFile g = gzopen(path, "wb9");
    assert_non_null(g);
    assert_int_equal(gzputs(g, "v 0 0 0\n"), 8);
    char *zeros = calloc(1, 1 << 20);
    assert_non_null(zeros);
    for (int i = 0; i < 64; i++) assert_int_equal(gzwrite(g, zeros, 1 << 20), 1 << 20);
    free(zeros);
    assert_int_equal(gzclose(g), Z_OK);
    mesh m;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_ERR_PARSE);
    assert_non_null(strstr(err.message, ":2: a NUL byte in a text mesh file"));
    const char *after = strstr(err.message, "stopped decompressing after ");
    assert_non_null(after);
    double bytes = strtod(after + strlen("stopped decompressing after "), NULL);
    assert_true(bytes > 0 && bytes <= 2 << 20); /* one chunk, not 64 MiB */
    remove(path);
}

/* A bomb of valid text (no NUL byte) is stopped by its ratio, not
 * inflated whole: 64 MiB of one vertex line compress to about 64 KiB. */
static void gzip_text_bomb_stops_at_the_ratio(void **state)
{
    (void)state;
    char path[512];
    test_tmp_path("read_errors_text_bomb.obj.gz", path, sizeof path);
    gzFile g = gzopen(path, "wb9");
    assert_non_null(g);
    size_t line = 8, n = (1 << 20) / line;
    char *lines = malloc(n * line);
    assert_non_null(lines);
    for (size_t i = 0; i < n; i++) memcpy(lines + i * line, "v 0 0 0\n", line);
    for (int i = 0; i < 64; i++)
        assert_int_equal(gzwrite(g, lines, (unsigned)(n * line)), n * line);
    free(lines);
    assert_int_equal(gzclose(g), Z_OK);
    mesh m;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_ERR_PARSE);
    assert_non_null(strstr(err.message, "decompresses to more than 100 times"));
    assert_non_null(strstr(err.message, "gunzip"));
    const char *after = strstr(err.message, "stopped after ");
    assert_non_null(after);
    double bytes = strtod(after + strlen("stopped after "), NULL);
    assert_true(bytes > 16 << 20 && bytes <= 18 << 20); /* at the ratio, not 64 MiB */
    remove(path);
    /* an ordinary compressed mesh still reads (a few times smaller) */
    test_tmp_path("read_errors_fine.obj.gz", path, sizeof path);
    g = gzopen(path, "wb9");
    assert_non_null(g);
    for (int i = 0; i < 3; i++) gzprintf(g, "v %d %d 0\n", i == 1, i == 2);
    gzputs(g, "f 1 2 3\n");
    assert_int_equal(gzclose(g), Z_OK);
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    assert_int_equal(m.nf, 1);
    mesh_free(&m);
    remove(path);
}

static void unreadable_files(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    char path[512];
    test_tmp_path("does-not-exist.obj", path, sizeof path);
    assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_ERR_IO);
    assert_non_null(strstr(e.message, path));
    assert_null(m.V);
    test_tmp_path("", path, sizeof path);
    assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_ERR_IO);
    assert_non_null(strstr(e.message, "directory"));
    /* A truncated gzip stream is malformed input. */
    const char *text = TRI "f 1 2 3\n";
    char gz[512];
    test_tmp_path("errors_trunc.obj.gz", gz, sizeof gz);
    gzFile g = gzopen(gz, "wb");
    assert_non_null(g);
    for (int i = 0; i < 200; i++) gzwrite(g, text, (unsigned)strlen(text));
    assert_int_equal(gzclose(g), Z_OK);
    FILE *f = fopen(gz, "rb");
    assert_non_null(f);
    unsigned char b[4096];
    size_t k = fread(b, 1, sizeof b, f);
    fclose(f);
    assert_true(k > 20);
    write_tmp("errors_trunc.obj.gz", b, k - 10, gz, sizeof gz);
    assert_int_equal(mesh_read(gz, &m, NULL, &e), SCAF_ERR_PARSE);
    assert_non_null(strstr(e.message, "gzip"));
    assert_null(m.V);
}

/* A line number is counted the same way with CRLF and no final newline. */
static void line_numbers_with_crlf(void **state)
{
    (void)state;
    parse_fails("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf 1 2 7", MESH_FORMAT_OBJ, 5,
                "7 out of range");
    parse_fails("OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 5", MESH_FORMAT_OFF, 6,
                "5 out of range");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(obj_index_errors),
        cmocka_unit_test(obj_face_shape_errors),
        cmocka_unit_test(obj_number_errors),
        cmocka_unit_test(obj_garbage_and_empty),
        cmocka_unit_test(off_errors),
        cmocka_unit_test(ply_header_errors),
        cmocka_unit_test(ply_body_errors),
        cmocka_unit_test(unreadable_files),
        cmocka_unit_test(gzip_bomb_stops_at_the_first_chunk),
        cmocka_unit_test(gzip_text_bomb_stops_at_the_ratio),
        cmocka_unit_test(line_numbers_with_crlf),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
