/* Tests for mesh/obj_rewrite: the input OBJ again with new UVs. Every
 * line other than vt/f is kept in order byte for byte, faces keep their
 * vertex and normal tokens (polygons fanned like the reader), the new UVs
 * read back bitwise, CRLF/BOM/gzip inputs, in-place rewriting, and a file
 * that no longer matches the mesh is refused with nothing written. The
 * CLI (`scaf param`, `scaf atlas`) keeps normals through this path. */
#include <math.h>
#include <zlib.h>

#include "mesh/obj_rewrite.h"
#include "mesh_test_util.h"

static const char *const sample_obj = "# a test file\n"
                                      "mtllib ./thing.mtl\n"
                                      "o thing\n"
                                      "v 0 0 0\n"
                                      "v 1.000 0 0\n"
                                      "v 1 1 0.0\n"
                                      "v 0 1 0   # trailing comment\n"
                                      "v 2 0.5 0\n"
                                      "vt 0 0\n"
                                      "vt 1 0\n"
                                      "vt 1 1\n"
                                      "vt 0 1\n"
                                      "vt 0.5 0.5\n"
                                      "vn 0 0 1\n"
                                      "vn 0 0.1 0.99\n"
                                      "g part1\n"
                                      "usemtl red\n"
                                      "s 1\n"
                                      "f -5/1/1 -4/2/2 -3/3/1 -2/4/2\n"
                                      "\n"
                                      "usemtl blue\n"
                                      "s off\n"
                                      "f 2//1 5//2 3//1\n"
                                      "f 2/2 3/3 1/1\n"
                                      "# the end, no final newline";

/* The lines of text that are neither vt nor f, in order, each with its
 * line terminator (as written). */
static char **other_lines(const char *text, int *n)
{
    char **out = NULL;
    *n = 0;
    const char *p = text;
    while (*p) {
        const char *e = strchr(p, '\n');
        const char *next = e ? e + 1 : p + strlen(p);
        const char *k = p;
        while (*k == ' ' || *k == '\t') k++;
        int is_vt = k[0] == 'v' && k[1] == 't' && (k[2] == ' ' || k[2] == '\t');
        int is_f = k[0] == 'f' && (k[1] == ' ' || k[1] == '\t');
        if (!is_vt && !is_f) {
            out = realloc(out, sizeof *out * (size_t)(*n + 1));
            assert_non_null(out);
            out[*n] = strndup(p, (size_t)(next - p));
            (*n)++;
        }
        p = next;
    }
    return out;
}

static void free_lines(char **l, int n)
{
    for (int i = 0; i < n; i++) free(l[i]);
    free(l);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, strlen(text), f), strlen(text));
    assert_int_equal(fclose(f), 0);
}

/* New UVs: one per corner, distinct awkward values. */
static void give_new_uvs(mesh *m, double **UV, int **FT)
{
    *UV = malloc(sizeof(double) * 6 * (size_t)m->nf);
    *FT = malloc(sizeof(int) * 3 * (size_t)m->nf);
    assert_non_null(*UV);
    assert_non_null(*FT);
    for (int k = 0; k < 3 * m->nf; k++) {
        (*FT)[k] = k;
        (*UV)[2 * k] = 1.0 / (k + 3.0);
        (*UV)[2 * k + 1] = sqrt(k + 2.0) * 1e-7;
    }
}

/* A mesh read from path, with new UVs (o: the mesh to write). */
typedef struct with_uvs {
    mesh m, o;
    double *UV;
    int *FT;
} with_uvs;

static void read_with_new_uvs(const char *path, with_uvs *w)
{
    scaf_error err;
    assert_int_equal(mesh_read(path, &w->m, NULL, &err), SCAF_OK);
    give_new_uvs(&w->m, &w->UV, &w->FT);
    w->o = (mesh){w->m.nv, w->m.V, w->m.nf, w->m.F, 3 * w->m.nf, w->UV, w->FT};
}

static void free_with_uvs(with_uvs *w)
{
    free(w->UV);
    free(w->FT);
    mesh_free(&w->m);
}

/* Rewrite `text` (stored in in_name) to out_name and check everything. */
static void rewrite_and_check(const char *in_name, const char *text, const char *out_name, int crlf)
{
    char in[512], out[512];
    test_tmp_path(in_name, in, sizeof in);
    test_tmp_path(out_name, out, sizeof out);
    write_text(in, text);
    with_uvs w;
    read_with_new_uvs(in, &w);
    const mesh m = w.m;
    const double *UV = w.UV;
    const int *FT = w.FT;
    scaf_error err;
    scaf_status st = obj_rewrite_uv(in, out, &w.o, &err);
    if (st) print_error("%s\n", err.message);
    assert_int_equal(st, SCAF_OK);

    /* the output reads back as the same mesh with the new UVs, bitwise */
    mesh b;
    assert_int_equal(mesh_read(out, &b, NULL, &err), SCAF_OK);
    assert_int_equal(b.nv, m.nv);
    assert_int_equal(b.nf, m.nf);
    assert_int_equal(b.nuv, 3 * m.nf);
    assert_memory_equal(b.V, m.V, sizeof(double) * 3 * (size_t)m.nv);
    assert_memory_equal(b.F, m.F, sizeof(int) * 3 * (size_t)m.nf);
    assert_memory_equal(b.FT, FT, sizeof(int) * 3 * (size_t)m.nf);
    assert_memory_equal(b.UV, UV, sizeof(double) * 6 * (size_t)m.nf);
    mesh_free(&b);

    /* every other line kept, in order, byte for byte (after the added
     * first comment line) */
    char *got = test_slurp(out);
    assert_non_null(got);
    int na, nb;
    const char *bom = "\xEF\xBB\xBF";
    const char *ta = strncmp(text, bom, 3) ? text : text + 3,
               *tb = strncmp(got, bom, 3) ? got : got + 3;
    assert_int_equal(ta == text, tb == got); /* a BOM is kept */
    char **la = other_lines(ta, &na), **lb = other_lines(tb, &nb);
    assert_int_equal(nb, na + 1);
    assert_non_null(strstr(lb[0], "scaf"));
    for (int i = 0; i < na; i++) assert_string_equal(lb[i + 1], la[i]);
    free_lines(la, na);
    free_lines(lb, nb);

    /* faces keep their normal tokens: the quad's fan and the v//n face */
    assert_non_null(strstr(got, crlf ? "f -5/1/1 -4/2/2 -3/3/1\r\n" : "f -5/1/1 -4/2/2 -3/3/1\n"));
    assert_non_null(strstr(got, crlf ? "f -5/4/1 -3/5/1 -2/6/2\r\n" : "f -5/4/1 -3/5/1 -2/6/2\n"));
    assert_non_null(strstr(got, "f 2/7/1 5/8/2 3/9/1"));
    assert_non_null(strstr(got, "f 2/10 3/11 1/12"));
    if (crlf) {
        /* every line break is CRLF */
        for (const char *q = strchr(got, '\n'); q; q = strchr(q + 1, '\n'))
            assert_int_equal(q[-1], '\r');
    }
    free(got);
    free_with_uvs(&w);
}

static void keeps_everything_but_uvs(void **state)
{
    (void)state;
    rewrite_and_check("rewrite_in.obj", sample_obj, "rewrite_out.obj", 0);
}

static void crlf_and_bom(void **state)
{
    (void)state;
    /* CRLF everywhere, and a BOM in front */
    size_t n = strlen(sample_obj);
    char *t = malloc(2 * n + 8);
    assert_non_null(t);
    size_t o = 0;
    memcpy(t, "\xEF\xBB\xBF", 3);
    o = 3;
    for (size_t i = 0; i < n; i++) {
        if (sample_obj[i] == '\n') t[o++] = '\r';
        t[o++] = sample_obj[i];
    }
    t[o] = '\0';
    rewrite_and_check("rewrite_crlf_in.obj", t, "rewrite_crlf_out.obj", 1);
    char out[512];
    test_tmp_path("rewrite_crlf_out.obj", out, sizeof out);
    char *got = test_slurp(out);
    assert_memory_equal(got, "\xEF\xBB\xBF", 3);
    free(got);
    free(t);
}

static void gzip_input_and_in_place(void **state)
{
    (void)state;
    char gz[512], path[512];
    test_tmp_path("rewrite_in.obj.gz", gz, sizeof gz);
    gzFile g = gzopen(gz, "wb");
    assert_non_null(g);
    assert_int_equal(gzwrite(g, sample_obj, (unsigned)strlen(sample_obj)), (int)strlen(sample_obj));
    assert_int_equal(gzclose(g), Z_OK);
    with_uvs w;
    read_with_new_uvs(gz, &w);
    const mesh m = w.m, o = w.o;
    const double *UV = w.UV;
    scaf_error err;
    test_tmp_path("rewrite_from_gz.obj", path, sizeof path);
    assert_int_equal(obj_rewrite_uv(gz, path, &o, &err), SCAF_OK);
    /* and in place: the output is its own input */
    assert_int_equal(obj_rewrite_uv(path, path, &o, &err), SCAF_OK);
    mesh b;
    assert_int_equal(mesh_read(path, &b, NULL, &err), SCAF_OK);
    assert_memory_equal(b.UV, UV, sizeof(double) * 6 * (size_t)m.nf);
    assert_memory_equal(b.F, m.F, sizeof(int) * 3 * (size_t)m.nf);
    char *got = test_slurp(path);
    assert_non_null(strstr(got, "mtllib ./thing.mtl\n"));
    /* one scaf comment line per rewrite */
    int comments = 0;
    for (const char *q = got; (q = strstr(q, "by scaf")); q++) comments++;
    assert_int_equal(comments, 2);
    free(got);
    mesh_free(&b);
    free_with_uvs(&w);
}

static void changed_file_is_refused(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("rewrite_changed_in.obj", in, sizeof in);
    test_tmp_path("rewrite_changed_out.obj", out, sizeof out);
    remove(out);
    write_text(in, sample_obj);
    with_uvs w;
    read_with_new_uvs(in, &w);
    mesh m = w.m, o = w.o;
    scaf_error err;
    /* a face of the mesh differs from the file */
    int keep = m.F[4];
    m.F[4] = (m.F[4] + 1) % m.nv;
    assert_int_equal(obj_rewrite_uv(in, out, &o, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "does not match"));
    assert_false(test_exists(out));
    m.F[4] = keep;
    /* one face fewer in the mesh than in the file */
    o.nf = m.nf - 1;
    assert_int_equal(obj_rewrite_uv(in, out, &o, &err), SCAF_ERR_MESH);
    assert_false(test_exists(out));
    /* a file with one more face than the mesh read from it */
    char *more = malloc(strlen(sample_obj) + 32);
    sprintf(more, "%s\nf 1 2 3\n", sample_obj);
    write_text(in, more);
    o.nf = m.nf;
    assert_int_equal(obj_rewrite_uv(in, out, &o, &err), SCAF_ERR_MESH);
    assert_false(test_exists(out));
    /* an unreadable input */
    test_tmp_path("no_such_input.obj", in, sizeof in);
    assert_int_equal(obj_rewrite_uv(in, out, &o, &err), SCAF_ERR_IO);
    assert_false(test_exists(out));
    free(more);
    free_with_uvs(&w);
}

/* `scaf param` and `scaf atlas` keep the input's normals and materials. */
static void cli_keeps_normals(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("rewrite_cli_in.obj", in, sizeof in);
    test_tmp_path("rewrite_cli_out.obj", out, sizeof out);
    /* a 3 x 3 grid with a normal per vertex and a material */
    char text[8192];
    size_t o = 0;
    o += (size_t)snprintf(text + o, sizeof text - o, "mtllib grid.mtl\nusemtl a\n");
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            o += (size_t)snprintf(text + o, sizeof text - o, "v %d %d %g\nvn 0 %g 1\n", i, j,
                                  0.1 * i * j, 0.01 * j);
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            int a = 4 * j + i + 1, b = a + 1, c = a + 4, d = c + 1;
            o += (size_t)snprintf(text + o, sizeof text - o,
                                  "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a, a, b, b, d,
                                  d, a, a, d, d, c, c);
        }
    write_text(in, text);
    const char *cmds[] = {"param", "atlas"};
    for (int k = 0; k < 2; k++) {
        remove(out);
        assert_int_equal(test_run("%s %s %s -o %s --quiet", SCAF_BINARY, cmds[k], in, out), 0);
        char *got = test_slurp(out);
        assert_non_null(got);
        int na, nb;
        char **la = other_lines(text, &na), **lb = other_lines(got, &nb);
        assert_int_equal(nb, na + 1);
        for (int i = 0; i < na; i++) assert_string_equal(lb[i + 1], la[i]);
        free_lines(la, na);
        free_lines(lb, nb);
        /* every face corner carries its normal: "a/t/a" */
        int faces = 0;
        for (const char *q = got; (q = strstr(q, "\nf ")); q++) {
            int a, t, n;
            assert_int_equal(sscanf(q + 3, "%d/%d/%d", &a, &t, &n), 3);
            assert_int_equal(a, n);
            faces++;
        }
        assert_int_equal(faces, 18);
        free(got);
    }
}

/* A polygon is fanned, the commands say so (unless --quiet), and the
 * rewritten file has the fan's triangles. */
static void cli_reports_fanned_polygon(void **state)
{
    (void)state;
    char in[512], out[512], log[512];
    test_tmp_path("rewrite_quad_in.obj", in, sizeof in);
    test_tmp_path("rewrite_quad_out.obj", out, sizeof out);
    test_tmp_path("rewrite_quad.log", log, sizeof log);
    write_text(in, "v 0 0 0\nv 1 0 0\nv 1 1 0.2\nv 0 1 0\nf 1 2 3 4\n");
    const char *cmds[] = {"param", "atlas"};
    for (int k = 0; k < 2; k++) {
        remove(out);
        assert_int_equal(test_run("%s %s %s -o %s 2> %s", SCAF_BINARY, cmds[k], in, out, log), 0);
        char *text = test_slurp(log);
        assert_non_null(text);
        assert_non_null(strstr(text, "warning"));
        assert_non_null(strstr(text, "1 polygon with more than 3 corners fan-triangulated"));
        free(text);
        assert_int_equal(
            test_run("%s %s %s -o %s --quiet 2> %s", SCAF_BINARY, cmds[k], in, out, log), 0);
        text = test_slurp(log);
        assert_non_null(text);
        assert_null(strstr(text, "warning"));
        free(text);
        char *got = test_slurp(out);
        assert_non_null(got);
        /* the fan of the quad: (1 2 3), (1 3 4) by vertex */
        const int want[2][3] = {{1, 2, 3}, {1, 3, 4}};
        int faces = 0;
        for (const char *q = got; (q = strstr(q, "\nf ")); q++, faces++) {
            int v[3], t[3];
            assert_true(faces < 2);
            assert_int_equal(
                sscanf(q + 3, "%d/%d %d/%d %d/%d", &v[0], &t[0], &v[1], &t[1], &v[2], &t[2]), 6);
            for (int j = 0; j < 3; j++) assert_int_equal(v[j], want[faces][j]);
        }
        assert_int_equal(faces, 2);
        free(got);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(keeps_everything_but_uvs), cmocka_unit_test(crlf_and_bom),
        cmocka_unit_test(gzip_input_and_in_place),  cmocka_unit_test(changed_file_is_refused),
        cmocka_unit_test(cli_keeps_normals),        cmocka_unit_test(cli_reports_fanned_polygon),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
