/* End-to-end tests for geom/cdt on the UV charts of the shared meshes.
 *
 * The UV boundary of a mesh with a bijective UV map (camel_b, blub, spot:
 * MANIFEST.md says their chart boundaries do not cross) is meshed inside a
 * 3x box and checked exactly with cdt_check: no triangle inside any chart
 * (winding number of its centroid with respect to all chart boundary
 * edges), constrained Delaunay, every chart edge present. A mesh whose UV
 * boundaries cross (myles_knot1_seamed: 12 crossing pairs in MANIFEST.md)
 * must be refused with SCAF_ERR_MESH. Skips when the data folder is absent.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/cdt_check.h"
#include "geom/cdt_uv_boundary.h"
#include "mesh/mesh_io.h"
#include "support/support.h"

/* The chart boundaries of a shared mesh's UVs and the box (see
 * cdt_uv_boundary.h): 1, or 0 when the mesh has no UVs, -1 when the file is
 * absent. */
static int uv_builder(const char *rel, cdt_builder *b)
{
    char path[4096];
    if (!test_data_path(rel, path, sizeof path)) return -1;
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) fail_msg("%s", err.message);
    if (!mesh_has_uv(&m)) {
        mesh_free(&m);
        return 0;
    }
    int ok = cb_uv_boundary(&m, b);
    mesh_free(&m);
    if (!ok) fail_msg("%s: out of memory", rel);
    return 1;
}

static void mesh_uv_scaffold(const char *rel)
{
    cdt_builder b;
    int r = uv_builder(rel, &b);
    if (r < 0) skip();
    assert_int_equal(r, 1);
    cdt_input in = cb_input(&b);
    cdt_options opt = cdt_default_options();
    cdt_output out;
    scaf_error err;
    if (cdt_triangulate(&in, &opt, &out, &err) != SCAF_OK) fail_msg("%s: %s", rel, err.message);
    cdt_check_stats st = cdt_check(&b, &opt, &out, INT32_MIN, 1);
    if (!st.ok) fail_msg("%s: %s", rel, st.why);
    assert_false(out.capped);
    assert_true(out.nsteiner > 0);
    print_message("    %s: %d chart edges, %d triangles, %d Steiner, min angle %.2f "
                  "(away from chart vertices %.2f)\n",
                  rel, b.ns - 4, out.ntriangles, out.nsteiner, st.min_angle_all, st.min_angle_free);
    cdt_output_free(&out);
    cb_free(&b);
}

static void camel_b(void **state)
{
    (void)state;
    mesh_uv_scaffold("disk/camel_b.obj");
}

static void blub(void **state)
{
    (void)state;
    mesh_uv_scaffold("seams/blub.obj");
}

static void spot(void **state)
{
    (void)state;
    mesh_uv_scaffold("seams/spot.obj");
}

static void knot_uv_boundary_crossings_are_refused(void **state)
{
    (void)state;
    cdt_builder b;
    int r = uv_builder("seams/myles_knot1_seamed.obj", &b);
    if (r < 0) skip();
    assert_int_equal(r, 1); /* the knot has UVs */
    cdt_input in = cb_input(&b);
    cdt_output out;
    scaf_error err;
    assert_int_equal(cdt_triangulate(&in, NULL, &out, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "crosses segment"));
    cb_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(camel_b),
        cmocka_unit_test(blub),
        cmocka_unit_test(spot),
        cmocka_unit_test(knot_uv_boundary_crossings_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
