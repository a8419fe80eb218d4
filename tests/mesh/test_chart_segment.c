/* Tests for mesh/chart_segment: labels and connectivity of the automatic
 * charts, determinism, creases followed, and the chart count following
 * the total curvature (procedural meshes only: fast, also under ASan). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "base/half_edges.h"
#include "base/union_find.h"
#include "mesh/chart_segment.h"
#include "mesh/samples.h"

static void sample(const char *name, int size, mesh *m)
{
    scaf_error e;
    err_clear(&e);
    assert_int_equal(mesh_sample_make(name, size, m, &e), SCAF_OK);
}

/* The surface of the cube [0,n]^3 cut into n x n squares per side, two
 * triangles each, welded, counter-clockwise seen from outside. */
static void make_box(int n, mesh *m)
{
    int side = n + 1, *id = malloc(sizeof(int) * (size_t)side * side * side);
    assert_non_null(id);
    int nv = 0;
    for (int i = 0; i < side * side * side; i++) {
        int x = i % side, y = i / side % side, z = i / (side * side);
        int surface = x == 0 || y == 0 || z == 0 || x == n || y == n || z == n;
        id[i] = surface ? nv++ : -1;
    }
    scaf_error e;
    assert_int_equal(mesh_alloc(m, nv, 12 * n * n, 0, &e), SCAF_OK);
    for (int i = 0; i < side * side * side; i++)
        if (id[i] >= 0) {
            m->V[3 * id[i]] = i % side;
            m->V[3 * id[i] + 1] = i / side % side;
            m->V[3 * id[i] + 2] = i / (side * side);
        }
    int f = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int top = 0; top < 2; top++)
            for (int a = 0; a < n; a++)
                for (int b = 0; b < n; b++) {
                    int corner[4];
                    for (int q = 0; q < 4; q++) {
                        int p[3], u = a + (q == 1 || q == 2), v = b + (q >= 2);
                        p[axis] = top ? n : 0;
                        p[(axis + 1) % 3] = u;
                        p[(axis + 2) % 3] = v;
                        corner[q] = id[p[0] + side * (p[1] + side * p[2])];
                    }
                    /* (u, v) turns counter-clockwise about +axis: keep it on
                     * the top side, reverse it on the bottom side */
                    int t[2][3] = {{corner[0], corner[1], corner[2]},
                                   {corner[0], corner[2], corner[3]}};
                    for (int k = 0; k < 2; k++) {
                        m->F[3 * f] = t[k][0];
                        m->F[3 * f + 1] = top ? t[k][1] : t[k][2];
                        m->F[3 * f + 2] = top ? t[k][2] : t[k][1];
                        f++;
                    }
                }
    free(id);
}

/* Segment m; checks that every face has a chart in [0, n), every chart
 * is used and edge-connected; returns n. */
static int segment_checked(const mesh *m, const chart_segment_options *o, int *chart)
{
    scaf_error e;
    err_clear(&e);
    int n = -1;
    assert_int_equal(chart_segment(m->nv, m->V, m->nf, m->F, o, chart, &n, &e), SCAF_OK);
    assert_true(n >= 1);
    int *used = calloc((size_t)n, sizeof(int)), *parent = malloc(sizeof(int) * (size_t)m->nf);
    int *order = malloc(sizeof(int) * 3 * (size_t)m->nf);
    assert_non_null(used);
    assert_non_null(parent);
    assert_non_null(order);
    for (int f = 0; f < m->nf; f++) {
        assert_in_range(chart[f], 0, n - 1);
        used[chart[f]]++;
    }
    for (int c = 0; c < n; c++) assert_true(used[c] > 0);
    /* faces of one chart sharing an edge: one set per chart */
    int count = 0;
    assert_int_equal(half_edges_sort(m->nv, m->nf, m->F, NULL, order, &count, &e), SCAF_OK);
    uf_init(parent, m->nf);
    for (int i = 1; i < count; i++) {
        int g = order[i - 1], h = order[i];
        if (half_edges_same_edge(m->F, g, h) && chart[g / 3] == chart[h / 3])
            uf_union(parent, g / 3, h / 3);
    }
    int sets = 0;
    for (int f = 0; f < m->nf; f++) sets += uf_find(parent, f) == f;
    assert_int_equal(sets, n);
    free(used);
    free(parent);
    free(order);
    return n;
}

static void test_every_face_labelled_and_connected(void **state)
{
    (void)state;
    const char *names[] = {"hemisphere", "holes", "icosphere", "cubesphere", "spiral"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        mesh m;
        sample(names[i], 0, &m);
        int *chart = malloc(sizeof(int) * (size_t)m.nf);
        assert_non_null(chart);
        segment_checked(&m, NULL, chart);
        free(chart);
        mesh_free(&m);
    }
}

static void test_deterministic(void **state)
{
    (void)state;
    mesh m;
    sample("cubesphere", 8, &m);
    int *a = malloc(sizeof(int) * (size_t)m.nf), *b = malloc(sizeof(int) * (size_t)m.nf);
    assert_non_null(a);
    assert_non_null(b);
    int na = segment_checked(&m, NULL, a), nb = segment_checked(&m, NULL, b);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, sizeof(int) * (size_t)m.nf);
    free(a);
    free(b);
    mesh_free(&m);
}

/* Six charts on a box: each one is a side (all its faces share a normal
 * axis and a side), so the seams lie on the creases. */
static void test_box_charts_follow_creases(void **state)
{
    (void)state;
    mesh m;
    make_box(6, &m);
    chart_segment_options o;
    chart_segment_defaults(&o);
    o.target_charts = 6;
    int *chart = malloc(sizeof(int) * (size_t)m.nf);
    assert_non_null(chart);
    assert_int_equal(segment_checked(&m, &o, chart), 6);
    /* faces were made side by side, 2 n^2 per side */
    int per_side = 2 * 6 * 6;
    for (int f = 0; f < m.nf; f++) assert_int_equal(chart[f], chart[f - f % per_side]);
    free(chart);
    mesh_free(&m);
}

/* A flat square needs one chart; a sphere few; two spheres twice as many
 * (the count follows the total curvature, components get their own). */
static void test_count_follows_curvature(void **state)
{
    (void)state;
    mesh grid, ball;
    sample("grid", 12, &grid);
    sample("icosphere", 8, &ball);
    int *chart = malloc(sizeof(int) * 2 * (size_t)ball.nf);
    assert_non_null(chart);
    assert_int_equal(segment_checked(&grid, NULL, chart), 1);
    int one = segment_checked(&ball, NULL, chart);
    assert_true(one >= 2 && one <= 6);
    /* the same sphere twice, the second shifted away */
    mesh two;
    scaf_error e;
    assert_int_equal(mesh_alloc(&two, 2 * ball.nv, 2 * ball.nf, 0, &e), SCAF_OK);
    for (int i = 0; i < 3 * ball.nv; i++) {
        two.V[i] = ball.V[i];
        two.V[3 * ball.nv + i] = ball.V[i] + (i % 3 == 0 ? 5.0 : 0.0);
    }
    for (int i = 0; i < 3 * ball.nf; i++) {
        two.F[i] = ball.F[i];
        two.F[3 * ball.nf + i] = ball.F[i] + ball.nv;
    }
    int both = segment_checked(&two, NULL, chart);
    assert_int_equal(both, 2 * one);
    for (int f = 0; f < ball.nf; f++) assert_true(chart[f] < one); /* no chart spans both */
    /* a smaller curvature budget per chart gives more charts */
    chart_segment_options o;
    chart_segment_defaults(&o);
    o.curvature_per_chart = CHART_SEGMENT_CURVATURE_PER_CHART / 3;
    assert_true(segment_checked(&ball, &o, chart) > one);
    free(chart);
    mesh_free(&two);
    mesh_free(&grid);
    mesh_free(&ball);
}

/* The same charts at any scale (areas of 1e200 would overflow). */
static void test_scale_free(void **state)
{
    (void)state;
    mesh m;
    sample("cubesphere", 6, &m);
    int *a = malloc(sizeof(int) * (size_t)m.nf), *b = malloc(sizeof(int) * (size_t)m.nf);
    assert_non_null(a);
    assert_non_null(b);
    int n = segment_checked(&m, NULL, a);
    const double scales[] = {1e200, 1e-200, 3.0};
    for (int i = 0; i < 3; i++) {
        mesh t;
        scaf_error e;
        assert_int_equal(mesh_alloc(&t, m.nv, m.nf, 0, &e), SCAF_OK);
        for (int j = 0; j < 3 * m.nv; j++) t.V[j] = m.V[j] * scales[i];
        memcpy(t.F, m.F, sizeof(int) * 3 * (size_t)m.nf);
        assert_int_equal(segment_checked(&t, NULL, b), n);
        if (i < 2) assert_memory_equal(a, b, sizeof(int) * (size_t)m.nf);
        mesh_free(&t);
    }
    free(a);
    free(b);
    mesh_free(&m);
}

static void test_bad_arguments(void **state)
{
    (void)state;
    double V[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    int F[3] = {0, 1, 3}, chart[1], n;
    scaf_error e;
    err_clear(&e);
    assert_int_equal(chart_segment(3, V, 1, F, NULL, chart, &n, &e), SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "face 0"));
    assert_int_equal(chart_segment(3, V, 1, F, NULL, chart, NULL, &e), SCAF_ERR_USAGE);
    F[2] = 2;
    assert_int_equal(chart_segment(3, V, 1, F, NULL, chart, &n, &e), SCAF_OK);
    assert_int_equal(n, 1);
    assert_int_equal(chart[0], 0);
    assert_int_equal(chart_segment(3, V, 0, F, NULL, chart, &n, &e), SCAF_OK);
    assert_int_equal(n, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_face_labelled_and_connected),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_box_charts_follow_creases),
        cmocka_unit_test(test_count_follows_curvature),
        cmocka_unit_test(test_scale_free),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
