/* End-to-end: `scaf check` on 3D surfaces without UVs (tools/check_surface):
 * a closed surface is checked for self-intersections by default, any
 * surface with --3d; exit 0 when intersection-free, 1 when not, 4 for an
 * open surface without --3d; the shared closed meshes when present. */
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

typedef struct result {
    int status;
    char out[8192];
} result;

static void run(const char *opts, const char *path, result *r)
{
    r->status = test_capture(r->out, sizeof r->out, "'%s' check %s '%s' 2>/dev/null", SCAF_BINARY,
                             opts, path);
    assert_true(r->status >= 0);
}

static long long field(const result *r, const char *key) { return test_json_field(r->out, key); }

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* An octahedron as OFF; push = 1 moves the top vertex through the face
 * (+x, +y, bottom), so the face (-x, -y, top) crosses it. */
static void write_octahedron(const char *path, int push)
{
    char text[1024];
    snprintf(text, sizeof text,
             "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n%s\n0 0 -1\n"
             "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n",
             push ? "0.2 0.2 -0.9" : "0 0 1");
    write_file(path, text);
}

static void closed_surfaces(void **state)
{
    (void)state;
    char path[1024];
    result r;
    test_tmp_path("check_octahedron.off", path, sizeof path);
    write_octahedron(path, 0);
    run("--json", path, &r);
    assert_int_equal(r.status, 0);
    assert_int_equal(field(&r, "intersection_free"), 1);
    assert_int_equal(field(&r, "closed"), 1);
    assert_int_equal(field(&r, "faces"), 8);
    run("", path, &r);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "intersection-free"));

    write_octahedron(path, 1);
    run("--json", path, &r);
    assert_int_equal(r.status, 1);
    assert_int_equal(field(&r, "intersection_free"), 0);
    assert_true(field(&r, "crossing_pairs") > 0);
    assert_non_null(strstr(r.out, "\"first_pairs\": [["));
    run("", path, &r);
    assert_int_equal(r.status, 1);
    assert_non_null(strstr(r.out, "SELF-INTERSECTING"));
}

static void open_surfaces(void **state)
{
    (void)state;
    char path[1024];
    result r;
    /* two crossing triangles, open: the UV check's "no UVs" unless --3d */
    test_tmp_path("check_open_crossing.obj", path, sizeof path);
    write_file(path,
               "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0.5 0.5 -1\nv 0.5 0.5 1\nv 3 3 0.5\nf 1 2 3\nf 4 5 "
               "6\n");
    run("--json", path, &r);
    assert_int_equal(r.status, 4);
    run("--json --3d", path, &r);
    assert_int_equal(r.status, 1);
    assert_int_equal(field(&r, "closed"), 0);
    assert_int_equal(field(&r, "intersecting_pairs"), 1);
    /* --3d on a mesh with vt checks the 3D surface too */
    write_file(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
    run("--json --self-intersections", path, &r);
    assert_int_equal(r.status, 0);
    assert_int_equal(field(&r, "intersection_free"), 1);
    run("--json", path, &r);
    assert_int_equal(field(&r, "bijective"), 1);
}

static void shared_closed_meshes(void **state)
{
    (void)state;
    char path[1024];
    result r;
    if (!test_data_path("closed/leg-intersect.off", path, sizeof path)) skip();
    run("--json", path, &r);
    assert_int_equal(r.status, 1);
    assert_int_equal(field(&r, "crossing_pairs"), 237); /* MANIFEST.md */
    assert_int_equal(field(&r, "intersecting_pairs"), 239);
    /* MANIFEST.md's self-isect pairs (pairs sharing no vertex position) */
    if (test_data_path("bad/cow.obj", path, sizeof path)) {
        run("--json", path, &r);
        assert_int_equal(r.status, 1);
        assert_int_equal(field(&r, "crossing_pairs"), 71);
        assert_int_equal(field(&r, "manifold"), 0);
    }
    if (test_data_path("disk/camelhead.off", path, sizeof path)) {
        run("--json --3d", path, &r);
        assert_int_equal(r.status, 1);
        assert_int_equal(field(&r, "crossing_pairs"), 3);
    }
    if (test_data_path("closed/leg-flow6.off", path, sizeof path)) {
        run("--json", path, &r);
        assert_int_equal(r.status, 0);
        assert_int_equal(field(&r, "intersecting_pairs"), 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_surfaces),
        cmocka_unit_test(open_surfaces),
        cmocka_unit_test(shared_closed_meshes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
