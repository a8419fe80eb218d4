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
#include "mesh/mesh_io.h"
#include "support/support.h"

typedef struct uvedge {
    int a, b, ccw, lo, hi;
} uvedge;

static int cmp_uvedge(const void *x, const void *y)
{
    const uvedge *p = x, *q = y;
    if (p->lo != q->lo)
        return p->lo < q->lo ? -1 : 1;
    return (p->hi > q->hi) - (p->hi < q->hi);
}

/* Chart boundary segments (chart on the left) of the vt triangulation, as
 * one pseudo-loop for the winding test, then the box. 0 when no UVs. */
static int uv_builder(const char *rel, cdt_builder *b)
{
    char path[4096];
    if (!test_data_path(rel, path, sizeof path))
        return -1;
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK)
        fail_msg("%s", err.message);
    if (!mesh_has_uv(&m)) {
        mesh_free(&m);
        return 0;
    }
    uvedge *e = malloc((size_t)m.nf * 3 * sizeof *e);
    int *map = malloc((size_t)m.nuv * sizeof(int));
    for (int f = 0; f < m.nf; f++) {
        const int *t = m.FT + 3 * f;
        double o = orient2d(m.UV + 2 * t[0], m.UV + 2 * t[1], m.UV + 2 * t[2]);
        for (int k = 0; k < 3; k++) {
            uvedge *q = e + 3 * f + k;
            q->a = t[k];
            q->b = t[(k + 1) % 3];
            q->ccw = o >= 0;
            q->lo = q->a < q->b ? q->a : q->b;
            q->hi = q->a < q->b ? q->b : q->a;
        }
    }
    qsort(e, (size_t)m.nf * 3, sizeof *e, cmp_uvedge);
    for (int i = 0; i < m.nuv; i++)
        map[i] = -1;
    cb_init(b);
    b->loop_start[0] = 0;
    b->nloops = 1;
    for (int i = 0; i < 3 * m.nf;) {
        int j = i;
        while (j < 3 * m.nf && e[j].lo == e[i].lo && e[j].hi == e[i].hi)
            j++;
        if (j - i == 1) {
            int ends[2] = {e[i].ccw ? e[i].a : e[i].b, e[i].ccw ? e[i].b : e[i].a};
            for (int k = 0; k < 2; k++)
                if (map[ends[k]] < 0)
                    map[ends[k]] = cb_point(b, m.UV[2 * ends[k]], m.UV[2 * ends[k] + 1]);
            cb_segment(b, map[ends[0]], map[ends[1]], 0, 1);
        }
        i = j;
    }
    b->loop_len[0] = b->ns;
    free(e);
    free(map);
    mesh_free(&m);
    cb_box(b, 3.0, NULL);
    return 1;
}

static void mesh_uv_scaffold(const char *rel)
{
    cdt_builder b;
    int r = uv_builder(rel, &b);
    if (r < 0)
        skip();
    assert_int_equal(r, 1);
    cdt_input in = cb_input(&b);
    cdt_options opt = cdt_default_options();
    cdt_output out;
    scaf_error err;
    if (cdt_triangulate(&in, &opt, &out, &err) != SCAF_OK)
        fail_msg("%s: %s", rel, err.message);
    cdt_check_stats st = cdt_check(&b, &opt, &out, INT32_MIN, 1);
    if (!st.ok)
        fail_msg("%s: %s", rel, st.why);
    assert_false(out.capped);
    assert_true(out.nsteiner > 0);
    print_message("    %s: %d chart edges, %d triangles, %d Steiner, min angle %.2f "
                  "(away from chart vertices %.2f)\n",
                  rel, b.ns - 4, out.ntriangles, out.nsteiner, st.min_angle_all,
                  st.min_angle_free);
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
    if (r < 0)
        skip();
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
