/* Tests for mesh/samples: each sample has the topology its documentation
 * promises (counts derived by hand from the construction), outward / CCW
 * orientation, valid UVs, and is deterministic. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/dented_sphere.h"
#include "mesh/samples.h"
#include "mesh/topology.h"
#include "mesh/uv_charts.h"
#include "support/loop_area.h"

static void make(const char *name, int size, mesh *m)
{
    scaf_error e;
    err_clear(&e);
    scaf_status s = mesh_sample_make(name, size, m, &e);
    if (s) print_error("%s: %s\n", name, e.message);
    assert_int_equal(s, SCAF_OK);
}

static void topo(const mesh *m, mesh_topology *t, mesh_charts *c)
{
    scaf_error e;
    assert_int_equal(mesh_topology_compute(m, t, &e), SCAF_OK);
    assert_int_equal(mesh_charts_compute(m, c, &e), SCAF_OK);
    /* every sample is clean */
    assert_true(t->manifold);
    assert_int_equal(t->misoriented_edges, 0);
    assert_int_equal(t->degenerate_faces, 0);
    assert_int_equal(t->duplicate_faces, 0);
    assert_int_equal(t->unreferenced_vertices, 0);
    assert_int_equal(t->components, 1);
}

/* Signed volume (closed meshes: > 0 when outward). */
static double volume(const mesh *m)
{
    double vol = 0;
    for (int f = 0; f < m->nf; f++) {
        const double *a = m->V + 3 * m->F[3 * f], *b = m->V + 3 * m->F[3 * f + 1],
                     *c = m->V + 3 * m->F[3 * f + 2];
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) /
            6;
    }
    return vol;
}

/* Sample `name` at `size` with its topology and charts (see make, topo);
 * the sample is named in the test output so a failure names its case. */
static void open_sample(const char *name, int size, mesh *m, mesh_topology *t, mesh_charts *c)
{
    print_message("    %s size %d\n", name, size);
    make(name, size, m);
    topo(m, t, c);
}

static void close_sample(mesh *m, mesh_topology *t, mesh_charts *c)
{
    mesh_charts_free(c);
    mesh_topology_free(t);
    mesh_free(m);
}

static void triangle_and_tetrahedron(void **state)
{
    (void)state;
    mesh m;
    mesh_topology t;
    mesh_charts c;
    open_sample("triangle", 0, &m, &t, &c);
    assert_int_equal(t.vertices, 3);
    assert_int_equal(t.faces, 1);
    assert_int_equal(t.boundary_loops, 1);
    assert_true(t.has_uv);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_DISK);
    close_sample(&m, &t, &c);

    open_sample("tetrahedron", 0, &m, &t, &c);
    assert_int_equal(t.faces, 4);
    assert_int_equal(t.euler_characteristic, 2);
    assert_int_equal(t.boundary_loops, 0);
    assert_true(volume(&m) > 0);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_CLOSED);
    close_sample(&m, &t, &c);
}

static void grid(void **state)
{
    (void)state;
    for (int n = 1; n <= 9; n += 4) {
        mesh m;
        mesh_topology t;
        mesh_charts c;
        open_sample("grid", n, &m, &t, &c);
        assert_int_equal(t.vertices, (n + 1) * (n + 1));
        assert_int_equal(t.faces, 2 * n * n);
        assert_int_equal(t.boundary_loops, 1);
        assert_int_equal(t.boundary_edges, 4 * n);
        assert_int_equal(t.euler_characteristic, 1);
        assert_int_equal(t.uv_charts, 1);
        assert_int_equal(t.seam_edges, 0);
        assert_int_equal(mesh_chart_check(&c, 0, 0, NULL), SCAF_OK);
        assert_true(test_loop_area_xy(&m, &t.cx, 0) > 0.999); /* unit square, CCW */
        close_sample(&m, &t, &c);
    }
}

static void hemisphere(void **state)
{
    (void)state;
    for (int n = 1; n <= 13; n += 6) {
        mesh m;
        mesh_topology t;
        mesh_charts c;
        open_sample("hemisphere", n, &m, &t, &c);
        assert_int_equal(t.vertices, 1 + 3 * n * (n + 1));
        assert_int_equal(t.faces, 6 * n * n);
        assert_int_equal(t.boundary_loops, 1);
        assert_int_equal(t.boundary_edges, 6 * n);
        assert_int_equal(t.euler_characteristic, 1);
        assert_int_equal(t.genus_sum, 0);
        assert_false(t.has_uv);
        assert_int_equal(t.uv_charts, 1);
        assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_DISK);
        assert_true(test_loop_area_xy(&m, &t.cx, 0) > 0); /* seen from +z: CCW */
        /* outward: each face normal points away from the centre */
        for (int f = 0; f < m.nf; f++) {
            const double *a = m.V + 3 * m.F[3 * f], *b = m.V + 3 * m.F[3 * f + 1],
                         *p = m.V + 3 * m.F[3 * f + 2];
            double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                   w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
            double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                             u[0] * w[1] - u[1] * w[0]};
            assert_true(nrm[0] * (a[0] + b[0] + p[0]) + nrm[1] * (a[1] + b[1] + p[1]) +
                            nrm[2] * (a[2] + b[2] + p[2]) >
                        0);
        }
        close_sample(&m, &t, &c);
    }
}

static void holes(void **state)
{
    (void)state;
    for (int n = 2; n <= 11; n += 3) {
        mesh m;
        mesh_topology t;
        mesh_charts c;
        open_sample("holes", n, &m, &t, &c);
        assert_int_equal(t.boundary_loops, 7);
        assert_int_equal(t.euler_characteristic, 2 - 7);
        assert_int_equal(t.genus_sum, 0);
        assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_DISK_WITH_HOLES);
        assert_int_equal(mesh_chart_check(&c, 0, 1, NULL), SCAF_OK);
        assert_int_equal(mesh_chart_check(&c, 0, 0, NULL), SCAF_ERR_MESH);
        /* the longest loop is the outer 3 x 2 rectangle, CCW; holes are CW */
        int outer = c.chart_loops[0];
        assert_int_equal(c.cx.loop_start[outer + 1] - c.cx.loop_start[outer], 2 * (3 * n + 2 * n));
        for (int l = 0; l < 7; l++) {
            double a = test_loop_area_xy(&m, &c.cx, l);
            if (l == outer) assert_true(a > 5.99 && a < 6.01);
            else assert_true(a < 0);
        }
        close_sample(&m, &t, &c);
    }
}

static void cubesphere(void **state)
{
    (void)state;
    for (int n = 1; n <= 7; n += 3) {
        mesh m;
        mesh_topology t;
        mesh_charts c;
        open_sample("cubesphere", n, &m, &t, &c);
        assert_int_equal(t.vertices, 6 * n * n + 2);
        assert_int_equal(t.faces, 12 * n * n);
        assert_int_equal(t.boundary_loops, 0);
        assert_int_equal(t.euler_characteristic, 2);
        assert_int_equal(t.genus_sum, 0);
        assert_true(volume(&m) > 0);
        assert_true(t.has_uv);
        assert_int_equal(t.uv_charts, 6);
        assert_int_equal(t.seam_edges, 12 * n);
        assert_int_equal(c.ncharts, 6);
        for (int k = 0; k < 6; k++) {
            assert_int_equal(mesh_chart_check(&c, k, 0, NULL), SCAF_OK);
            assert_int_equal(c.cx.group_face_start[k + 1] - c.cx.group_face_start[k], 2 * n * n);
            assert_int_equal(c.chart_vertex_start[k + 1] - c.chart_vertex_start[k],
                             (n + 1) * (n + 1));
            assert_int_equal(c.cx.group_euler[k], 1);
        }
        /* UVs: every triangle CCW, inside [0,1]^2, each chart in its own
         * atlas cell (cells of side 1/3), no two charts in one cell */
        int cell_of[6] = {-1, -1, -1, -1, -1, -1};
        for (int f = 0; f < m.nf; f++) {
            const double *a = m.UV + 2 * m.FT[3 * f], *b = m.UV + 2 * m.FT[3 * f + 1],
                         *p = m.UV + 2 * m.FT[3 * f + 2];
            assert_true((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) > 0);
            int chart = c.cx.face_group[f];
            for (int q = 0; q < 3; q++) {
                const double *uv = m.UV + 2 * m.FT[3 * f + q];
                assert_true(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1);
                int cell = (int)(uv[0] * 3) + 3 * (int)(uv[1] * 3);
                if (cell_of[chart] < 0) cell_of[chart] = cell;
                assert_int_equal(cell, cell_of[chart]);
            }
        }
        for (int i = 0; i < 6; i++)
            for (int j = 0; j < i; j++) assert_int_not_equal(cell_of[i], cell_of[j]);
        close_sample(&m, &t, &c);
    }
}

static void icosphere(void **state)
{
    (void)state;
    for (int n = 1; n <= 9; n += 4) {
        mesh m;
        mesh_topology t;
        mesh_charts c;
        open_sample("icosphere", n, &m, &t, &c);
        assert_int_equal(t.vertices, 10 * n * n + 2);
        assert_int_equal(t.faces, 20 * n * n);
        assert_int_equal(t.boundary_loops, 0);
        assert_int_equal(t.euler_characteristic, 2);
        assert_int_equal(t.genus_sum, 0);
        assert_false(t.has_uv);
        /* outward, on the unit sphere, inscribed: volume below 4/3 pi */
        double vol = volume(&m);
        assert_true(vol > 0 && vol < 4.0 / 3.0 * 3.14159265358979323846);
        for (int i = 0; i < m.nv; i++) {
            const double *p = m.V + 3 * i;
            assert_true(fabs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1) < 1e-12);
        }
        close_sample(&m, &t, &c);
    }
}

/* The icosphere turned so that a corner is the top pole, with its cap
 * pushed down by the documented amount: same faces, the vertices outside
 * the cap only turned, the pole at 1 - depth, below the sphere. */
static void dented(void **state)
{
    (void)state;
    for (int n = 2; n <= 8; n += 3) {
        mesh m, ico;
        mesh_topology t;
        mesh_charts c;
        open_sample("dented", n, &m, &t, &c);
        make("icosphere", n, &ico);
        assert_int_equal(t.euler_characteristic, 2);
        assert_int_equal(t.genus_sum, 0);
        assert_int_equal(t.boundary_loops, 0);
        assert_int_equal(m.nv, ico.nv);
        assert_memory_equal(m.F, ico.F, sizeof(int) * 3 * (size_t)m.nf);
        int moved = 0, pole = 0;
        double g = (1 + sqrt(5.0)) / 2, turn = atan2(1, g);
        assert_true(fabs(turn - DENTED_SPHERE_TURN) < 1e-15);
        for (int v = 0; v < m.nv; v++) {
            const double *p = m.V + 3 * v, *o = ico.V + 3 * v;
            double q[3] = {cos(turn) * o[0] - sin(turn) * o[1], sin(turn) * o[0] + cos(turn) * o[1],
                           o[2]};
            double cap = cos(DENTED_SPHERE_CAP * 3.14159265358979323846 / 180);
            assert_true(fabs(p[0] - q[0]) < 1e-15 && p[2] == q[2]);
            if (q[1] <= cap) assert_true(fabs(p[1] - q[1]) < 1e-15);
            else assert_true(p[1] < q[1]), moved++;
            if (fabs(q[1] - 1.0) < 1e-15) {
                assert_true(fabs(p[1] - (1 - DENTED_SPHERE_DEPTH)) < 1e-12);
                pole++;
            }
            assert_true(fabs(q[1] - p[1] - dented_sphere_push_of(q)) < 1e-15);
        }
        assert_true(moved > 0);
        assert_int_equal(pole, 1);
        /* the pole lies below the sphere's bottom */
        double low = 0;
        for (int v = 0; v < m.nv; v++)
            if (m.V[3 * v + 1] < low) low = m.V[3 * v + 1];
        assert_true(low < -1.2);
        mesh_free(&ico);
        close_sample(&m, &t, &c);
    }
}

static void deterministic(void **state)
{
    (void)state;
    for (int i = 0; i < mesh_sample_count(); i++) {
        const mesh_sample_info *s = mesh_sample_get(i);
        mesh a, b;
        make(s->name, 0, &a);
        make(s->name, 0, &b);
        assert_int_equal(a.nv, b.nv);
        assert_int_equal(a.nf, b.nf);
        assert_memory_equal(a.V, b.V, sizeof(double) * 3 * (size_t)a.nv);
        assert_memory_equal(a.F, b.F, sizeof(int) * 3 * (size_t)a.nf);
        for (int k = 0; k < 3 * a.nv; k++) assert_true(a.V[k] == a.V[k]); /* no NaN */
        mesh_free(&a);
        mesh_free(&b);
    }
}

static void bad_names_and_sizes(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_sample_make("nope", 0, &m, &e), SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "hemisphere")); /* lists what exists */
    assert_int_equal(mesh_sample_make("hemisphere", -3, &m, &e), SCAF_ERR_USAGE);
    assert_int_equal(mesh_sample_make("cubesphere", 100000, &m, &e), SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "outside"));
    assert_null(mesh_sample_find("nope"));
    assert_null(mesh_sample_get(mesh_sample_count()));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(triangle_and_tetrahedron),
        cmocka_unit_test(grid),
        cmocka_unit_test(hemisphere),
        cmocka_unit_test(holes),
        cmocka_unit_test(cubesphere),
        cmocka_unit_test(icosphere),
        cmocka_unit_test(dented),
        cmocka_unit_test(deterministic),
        cmocka_unit_test(bad_names_and_sizes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
