/* Tests for mesh/topology, mesh/uv_charts, mesh/edges: hand-made meshes
 * whose topology is known by construction. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/degenerate.h"
#include "mesh/edges.h"
#include "mesh/topology.h"
#include "mesh/uv_charts.h"
#include "support/count_checks.h"
#include "support/loop_area.h"

/* Build a mesh from literal arrays (UV/FT may be NULL). */
static void make(mesh *m, int nv, const double *V, int nf, const int *F, int nuv, const double *UV,
                 const int *FT)
{
    scaf_error e;
    assert_int_equal(mesh_alloc(m, nv, nf, nuv, &e), SCAF_OK);
    memcpy(m->V, V, sizeof(double) * 3 * (size_t)nv);
    memcpy(m->F, F, sizeof(int) * 3 * (size_t)nf);
    if (nuv) {
        memcpy(m->UV, UV, sizeof(double) * 2 * (size_t)nuv);
        memcpy(m->FT, FT, sizeof(int) * 3 * (size_t)nf);
    }
}

static void topo(const mesh *m, mesh_topology *t)
{
    scaf_error e;
    err_clear(&e);
    assert_int_equal(mesh_topology_compute(m, t, &e), SCAF_OK);
}

/* The charts of m, which must compute. */
static void charts(const mesh *m, mesh_charts *c)
{
    scaf_error e;
    err_clear(&e);
    assert_int_equal(mesh_charts_compute(m, c, &e), SCAF_OK);
}

/* mesh_chart_check of chart k returns `want`, with a message containing
 * `needle` when one is given. */
static void assert_chart_check(const mesh_charts *c, int k, int allow_holes, scaf_status want,
                               const char *needle)
{
    scaf_error e;
    err_clear(&e);
    scaf_status s = mesh_chart_check(c, k, allow_holes, &e);
    if (s != want)
        fail_msg("chart %d (holes %s): status %d, expected %d (%s)", k,
                 allow_holes ? "allowed" : "refused", (int)s, (int)want, e.message);
    if (needle && !strstr(e.message, needle))
        fail_msg("chart %d: message '%s' lacks '%s'", k, e.message, needle);
}

/* Everything a test built, in reverse order. */
static void free_all(mesh *m, mesh_topology *t, mesh_charts *c)
{
    mesh_charts_free(c);
    mesh_topology_free(t);
    mesh_free(m);
}

/* Each half-edge of an ordered loop must end where the next one starts. */
static void assert_loop_closed(const mesh *m, const tri_complex *cx, int l)
{
    assert_true(cx->loop_ordered[l]);
    int s = cx->loop_start[l], t = cx->loop_start[l + 1];
    for (int i = s; i < t; i++) {
        int h = cx->loop_he[i], hn = cx->loop_he[i + 1 < t ? i + 1 : s];
        assert_int_equal(he_to(m->F, h), m->F[hn]);
    }
}

static const double SQUARE_V[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

static void single_triangle(void **state)
{
    (void)state;
    mesh m;
    const int F[] = {0, 1, 2};
    make(&m, 3, SQUARE_V, 1, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    assert_true(t.manifold);
    EXPECT_COUNTS("single_triangle", HAS(t.vertices, 3), HAS(t.faces, 1), HAS(t.edges, 3),
                  HAS(t.boundary_edges, 3), HAS(t.components, 1), HAS(t.boundary_loops, 1),
                  HAS(t.euler_characteristic, 1), HAS(t.cx.group_genus[0], 0), HAS(t.genus_sum, 0),
                  HAS(t.non_manifold_edges + t.non_manifold_vertices + t.misoriented_edges, 0),
                  HAS(t.degenerate_faces + t.duplicate_faces + t.unreferenced_vertices, 0),
                  HAS(t.uv_charts, 1), HAS(t.cx.loop_start[1], 3));
    assert_loop_closed(&m, &t.cx, 0);
    assert_true(test_loop_area_xy(&m, &t.cx, 0) > 0); /* mesh on the left: CCW */
    mesh_topology_free(&t);
    mesh_free(&m);
}

static void two_triangles(void **state)
{
    (void)state;
    mesh m;
    const int F[] = {0, 1, 2, 0, 2, 3};
    make(&m, 4, SQUARE_V, 2, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("two_triangles", HAS(t.vertices, 4), HAS(t.edges, 5), HAS(t.boundary_edges, 4),
                  HAS(t.boundary_loops, 1), HAS(t.euler_characteristic, 1),
                  HAS(t.cx.loop_start[1], 4));
    assert_loop_closed(&m, &t.cx, 0);
    assert_true(test_loop_area_xy(&m, &t.cx, 0) > 0);

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(c.ncharts, 1);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_DISK);
    assert_chart_check(&c, 0, 0, SCAF_OK, NULL);
    assert_int_equal(c.loop_vt[0], -1);
    free_all(&m, &t, &c);
}

static const double TET_V[] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
static const int TET_F[] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};

static void closed_tetrahedron(void **state)
{
    (void)state;
    mesh m;
    make(&m, 4, TET_V, 4, TET_F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("closed_tetrahedron", HAS(t.edges, 6), HAS(t.boundary_edges, 0),
                  HAS(t.boundary_loops, 0), HAS(t.euler_characteristic, 2),
                  HAS(t.cx.group_genus[0], 0));
    assert_true(t.manifold);
    assert_true(t.orientable);
    assert_int_equal(t.misoriented_edges, 0);

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_CLOSED);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, "closed");
    free_all(&m, &t, &c);
}

static void non_manifold_edge(void **state)
{
    (void)state;
    /* three triangles on edge 0-1 */
    const double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    const int F[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    mesh m;
    make(&m, 5, V, 3, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    assert_int_equal(t.non_manifold_edges, 1);
    assert_false(t.manifold);
    EXPECT_COUNTS("non_manifold_edge", HAS(t.cx.group_genus[0], -1), HAS(t.genus_sum, -1),
                  HAS(t.misoriented_edges, 1), /* 0->1 used by faces 0 and 2 */
                  HAS(t.edges, 7), HAS(t.euler_characteristic, 5 - 7 + 3));

    mesh_charts c;
    charts(&m, &c);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, "0-1 has 3 faces");
    free_all(&m, &t, &c);
}

static void non_manifold_vertex(void **state)
{
    (void)state;
    /* bowtie: two triangles touching at vertex 0 only */
    const double V[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0};
    const int F[] = {0, 1, 2, 0, 3, 4};
    mesh m;
    make(&m, 5, V, 2, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("non_manifold_vertex", HAS(t.non_manifold_vertices, 1),
                  HAS(t.non_manifold_edges, 0), HAS(t.components, 1), /* joined through vertex 0 */
                  HAS(t.boundary_loops, 1)); /* boundary graph joined at 0 too */
    assert_false(t.cx.loop_ordered[0]);      /* not a simple cycle */
    assert_int_equal(t.cx.loop_start[1], 6);
    assert_false(t.manifold);
    assert_int_equal(t.cx.group_genus[0], -1);

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_NON_MANIFOLD);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, "vertex 0");
    free_all(&m, &t, &c);
}

static void misoriented(void **state)
{
    (void)state;
    /* face 1 flipped: both faces traverse 2->0 */
    const int Fbad[] = {0, 1, 2, 0, 3, 2};
    mesh m;
    make(&m, 4, SQUARE_V, 2, Fbad, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    assert_int_equal(t.misoriented_edges, 1);
    assert_true(t.orientable); /* flipping face 1 repairs it */
    assert_true(t.manifold);
    assert_int_equal(t.cx.group_genus[0], 0);
    assert_false(t.cx.loop_ordered[0]);

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_MISORIENTED);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, "0-2");
    free_all(&m, &t, &c);
}

static void mobius_strip(void **state)
{
    (void)state;
    /* a strip of 5 quads, glued back with a half twist */
    enum { N = 5 };
    double V[2 * N * 3];
    int F[2 * N * 3];
    for (int i = 0; i < N; i++) {
        V[6 * i + 0] = i, V[6 * i + 1] = 0, V[6 * i + 2] = 0;
        V[6 * i + 3] = i, V[6 * i + 4] = 1, V[6 * i + 5] = 0;
    }
    for (int i = 0; i < N; i++) {
        int a = 2 * i, b = 2 * i + 1, c, d;
        if (i + 1 < N) c = 2 * i + 2, d = 2 * i + 3;
        else c = 1, d = 0; /* twist: bottom meets top */
        int q[6] = {a, c, d, a, d, b};
        memcpy(F + 6 * i, q, sizeof q);
    }
    mesh m;
    make(&m, 2 * N, V, 2 * N, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    assert_false(t.orientable);
    assert_true(t.manifold);
    EXPECT_COUNTS("mobius_strip", HAS(t.boundary_loops, 1), HAS(t.euler_characteristic, 0),
                  HAS(t.cx.group_genus[0], -1));
    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_NON_ORIENTABLE);
    free_all(&m, &t, &c);
}

/* 4 x 4 vertex grid (3 x 3 cells) without its centre cell: an annulus. */
static void hole(void **state)
{
    (void)state;
    double V[16 * 3];
    int F[8 * 2 * 3], nf = 0;
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            double *p = V + 3 * (4 * j + i);
            p[0] = i, p[1] = j, p[2] = 0.1 * i * j;
        }
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            if (i == 1 && j == 1) continue;
            int a = 4 * j + i, b = a + 1, c = a + 5, d = a + 4;
            int q[6] = {a, b, c, a, c, d};
            memcpy(F + 3 * nf, q, sizeof q);
            nf += 2;
        }
    mesh m;
    make(&m, 16, V, nf, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("hole", HAS(t.boundary_loops, 2), HAS(t.euler_characteristic, 0),
                  HAS(t.cx.group_genus[0], 0));
    int outer = t.cx.loop_start[1] - t.cx.loop_start[0] == 12 ? 0 : 1;
    EXPECT_COUNTS("hole: loop lengths",
                  HAS(t.cx.loop_start[outer + 1] - t.cx.loop_start[outer], 12),
                  HAS(t.cx.loop_start[2 - outer] - t.cx.loop_start[1 - outer], 4));
    assert_loop_closed(&m, &t.cx, 0);
    assert_loop_closed(&m, &t.cx, 1);
    assert_true(test_loop_area_xy(&m, &t.cx, outer) > 0);     /* outer loop CCW */
    assert_true(test_loop_area_xy(&m, &t.cx, 1 - outer) < 0); /* hole CW: mesh on the left */

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(mesh_chart_classify(&c, 0), MESH_CHART_DISK_WITH_HOLES);
    assert_chart_check(&c, 0, 1, SCAF_OK, NULL);
    assert_chart_check(&c, 0, 0, SCAF_ERR_MESH, "1 holes");
    /* longest loop first */
    int first = c.chart_loops[0];
    assert_int_equal(c.cx.loop_start[first + 1] - c.cx.loop_start[first], 12);
    assert_true(c.loop_length[c.chart_loops[0]] > c.loop_length[c.chart_loops[1]]);
    free_all(&m, &t, &c);
}

static void seams(void **state)
{
    (void)state;
    const int F[] = {0, 1, 2, 0, 2, 3};
    const double UV[] = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};
    /* shared vt on the diagonal: one chart */
    const int FT1[] = {0, 1, 2, 0, 2, 3};
    /* face 1 uses its own copies of the diagonal's vt: a seam, two charts */
    const int FT2[] = {0, 1, 2, 4, 5, 3};
    mesh m;
    make(&m, 4, SQUARE_V, 2, F, 6, UV, FT1);
    mesh_topology t;
    topo(&m, &t);
    assert_true(t.has_uv);
    EXPECT_COUNTS("seams: shared diagonal vt", HAS(t.uv_charts, 1), HAS(t.seam_edges, 0));
    mesh_topology_free(&t);
    memcpy(m.FT, FT2, sizeof FT2);
    topo(&m, &t);
    EXPECT_COUNTS("seams: diagonal vt split", HAS(t.uv_charts, 2), HAS(t.seam_edges, 1),
                  HAS(t.components, 1));
    mesh_topology_free(&t);

    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(c.ncharts, 2);
    assert_true(c.uses_uv);
    for (int k = 0; k < 2; k++) {
        assert_chart_check(&c, k, 0, SCAF_OK, NULL);
        int l = c.chart_loops[c.chart_loop_start[k]];
        assert_int_equal(c.cx.loop_start[l + 1] - c.cx.loop_start[l], 3);
        for (int i = c.cx.loop_start[l]; i < c.cx.loop_start[l + 1]; i++) {
            /* vt and vertex of the same loop corner agree with some face */
            int h = c.cx.loop_he[i];
            assert_int_equal(c.loop_vt[i], m.FT[h]);
            assert_int_equal(c.loop_v[i], m.F[h]);
        }
    }
    EXPECT_COUNTS("seams: face groups", HAS(c.cx.face_group[0], 0), HAS(c.cx.face_group[1], 1));
    /* chart vertex lists: vt 0,1,2 and vt 3,4,5 */
    EXPECT_COUNTS("seams: chart vertex lists", HAS(c.chart_vertex_start[0], 0),
                  HAS(c.chart_vertex_start[1], 3), HAS(c.chart_vertex_start[2], 6));
    for (int i = 0; i < 6; i++) assert_int_equal(c.chart_vertices[i], i);
    mesh_charts_free(&c);
    mesh_free(&m);
}

static void uv_pinch_fails_check(void **state)
{
    (void)state;
    /* two faces sharing only vt 0 (but 3D edge 0-2): the charts touch at a
     * vt vertex, which the embedding cannot keep */
    const int F[] = {0, 1, 2, 0, 2, 3};
    const double UV[] = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0};
    const int FT[] = {0, 1, 2, 0, 4, 3};
    mesh m;
    make(&m, 4, SQUARE_V, 2, F, 5, UV, FT);
    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(c.ncharts, 2);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, "vt 0");
    mesh_charts_free(&c);
    mesh_free(&m);
}

static void faces_without_uv(void **state)
{
    (void)state;
    /* face 1 has no vt (-1, as the OBJ reader marks it): it is a chart of
     * its own, a seam borders it, and its chart fails the check */
    const int F[] = {0, 1, 2, 0, 2, 3};
    const double UV[] = {0, 0, 1, 0, 1, 1};
    const int FT[] = {0, 1, 2, -1, -1, -1};
    mesh m;
    make(&m, 4, SQUARE_V, 2, F, 3, UV, FT);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("faces_without_uv", HAS(t.uv_charts, 2), HAS(t.seam_edges, 1));
    mesh_topology_free(&t);
    mesh_charts c;
    charts(&m, &c);
    assert_int_equal(c.ncharts, 2);
    assert_chart_check(&c, 0, 0, SCAF_OK, NULL);
    assert_chart_check(&c, 1, 1, SCAF_ERR_MESH, "face 1");
    /* the loop accessor of the good chart */
    const int *v, *vt;
    int id;
    assert_int_equal(mesh_chart_loop(&c, 0, 0, &v, &vt, &id), 3);
    assert_int_equal(mesh_chart_loop(&c, 0, 1, &v, &vt, &id), 0);
    assert_int_equal(v[0], 0);
    assert_int_equal(vt[0], 0);
    assert_int_equal(v[1], 1);
    assert_int_equal(v[2], 2);
    mesh_charts_free(&c);
    mesh_free(&m);
}

static void degenerate_duplicate_unreferenced(void **state)
{
    (void)state;
    const double V[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0, 7, 7, 7};
    const int F[] = {
        0, 1, 2, /* fine */
        2, 1, 0, /* duplicate of face 0 (reversed) */
        0, 0, 3, /* repeated index */
        0, 1, 4, /* collinear: zero area */
    };
    mesh m;
    make(&m, 6, V, 4, F, 0, NULL, NULL);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("degenerate_duplicate_unreferenced", HAS(t.duplicate_faces, 1),
                  HAS(t.repeated_index_faces, 1), HAS(t.degenerate_faces, 2),
                  HAS(t.unreferenced_vertices, 1), /* vertex 5 */
                  HAS(t.vertices, 5));
    mesh_topology_free(&t);
    mesh_free(&m);
}

/* Many triangles meeting at one vertex / one edge: linear-time code paths
 * (a quadratic scan per vertex would take minutes here). */
static void huge_fans_are_handled(void **state)
{
    (void)state;
    enum { N = 50000 };
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_alloc(&m, 2 * N + 2, N, 0, &e), SCAF_OK);
    for (int i = 0; i < 3 * (2 * N + 2); i++) m.V[i] = (double)(i % 7) + i / 3;
    /* N separate triangles sharing vertex 0 only */
    for (int i = 0; i < N; i++) {
        m.F[3 * i] = 0;
        m.F[3 * i + 1] = 2 + 2 * i;
        m.F[3 * i + 2] = 3 + 2 * i;
    }
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("huge fan at one vertex", HAS(t.components, 1), HAS(t.non_manifold_vertices, 1),
                  HAS(t.boundary_loops, 1));
    assert_false(t.cx.loop_ordered[0]);
    assert_int_equal(t.boundary_edges, 3 * N);
    mesh_topology_free(&t);
    /* N triangles on the edge 0-1 */
    for (int i = 0; i < N; i++) {
        m.F[3 * i] = i % 2 ? 1 : 0;
        m.F[3 * i + 1] = i % 2 ? 0 : 1;
        m.F[3 * i + 2] = 2 + i;
    }
    topo(&m, &t);
    EXPECT_COUNTS("huge fan on one edge", HAS(t.non_manifold_edges, 1), HAS(t.misoriented_edges, 2),
                  HAS(t.non_manifold_vertices, 0), /* one fan through the edge */
                  HAS(t.unreferenced_vertices, N));
    mesh_topology_free(&t);
    mesh_charts c;
    assert_int_equal(mesh_charts_compute(&m, &c, &e), SCAF_OK);
    assert_chart_check(&c, 0, 1, SCAF_ERR_MESH, NULL);
    mesh_charts_free(&c);
    mesh_free(&m);
}

static void zero_area_is_exact(void **state)
{
    (void)state;
    /* tiny but not degenerate: a floating-point cross product underflows */
    const double a[3] = {0, 0, 0}, b[3] = {1e-200, 0, 0}, c[3] = {0, 1e-200, 0};
    assert_false(tri3_is_degenerate(a, b, c));
    /* one ulp off a line */
    const double d[3] = {1, 1, 1}, e[3] = {2, 2, 2}, f[3] = {3, 3, 3.0000000000000004};
    assert_false(tri3_is_degenerate(d, e, f));
    /* exactly on the line x = y = z, with inexact-looking decimals */
    const double g[3] = {0.1, 0.1, 0.1}, h[3] = {0.2, 0.2, 0.2}, k[3] = {0.7, 0.7, 0.7};
    assert_true(tri3_is_degenerate(g, h, k));
    /* coincident points */
    assert_true(tri3_is_degenerate(d, d, e));
}

static void index_out_of_range(void **state)
{
    (void)state;
    const int F[] = {0, 1, 9};
    mesh m;
    make(&m, 4, SQUARE_V, 1, F, 0, NULL, NULL);
    mesh_topology t;
    scaf_error e;
    assert_int_equal(mesh_topology_compute(&m, &t, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "vertex 9"));
    mesh_charts c;
    assert_int_equal(mesh_charts_compute(&m, &c, &e), SCAF_ERR_MESH);
    mesh_free(&m);
}

static void empty_mesh(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_alloc(&m, 0, 0, 0, &e), SCAF_OK);
    mesh_topology t;
    topo(&m, &t);
    EXPECT_COUNTS("empty_mesh", HAS(t.faces, 0), HAS(t.components, 0), HAS(t.boundary_loops, 0),
                  HAS(t.euler_characteristic, 0));
    mesh_topology_free(&t);
    mesh_charts c;
    assert_int_equal(mesh_charts_compute(&m, &c, &e), SCAF_OK);
    assert_int_equal(c.ncharts, 0);
    assert_chart_check(&c, 0, 1, SCAF_ERR_USAGE, NULL);
    mesh_charts_free(&c);
    mesh_free(&m);
}

static void edge_table_is_sorted_and_complete(void **state)
{
    (void)state;
    mesh_edges E;
    scaf_error e;
    assert_int_equal(mesh_edges_build(4, 4, TET_F, &E, &e), SCAF_OK);
    assert_int_equal(E.ne, 6);
    for (int k = 0; k < E.ne; k++) {
        assert_true(E.ev[2 * k] < E.ev[2 * k + 1]);
        if (k)
            assert_true(E.ev[2 * k - 2] < E.ev[2 * k] ||
                        (E.ev[2 * k - 2] == E.ev[2 * k] && E.ev[2 * k - 1] < E.ev[2 * k + 1]));
        assert_int_equal(mesh_edge_valence(&E, k), 2);
    }
    for (int h = 0; h < 12; h++) {
        int k = E.he_edge[h];
        int a = he_from(TET_F, h), b = he_to(TET_F, h);
        assert_int_equal(E.ev[2 * k], a < b ? a : b);
        assert_int_equal(E.ev[2 * k + 1], a < b ? b : a);
    }
    mesh_edges_free(&E);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(single_triangle),
        cmocka_unit_test(two_triangles),
        cmocka_unit_test(closed_tetrahedron),
        cmocka_unit_test(non_manifold_edge),
        cmocka_unit_test(non_manifold_vertex),
        cmocka_unit_test(misoriented),
        cmocka_unit_test(mobius_strip),
        cmocka_unit_test(hole),
        cmocka_unit_test(seams),
        cmocka_unit_test(uv_pinch_fails_check),
        cmocka_unit_test(faces_without_uv),
        cmocka_unit_test(degenerate_duplicate_unreferenced),
        cmocka_unit_test(huge_fans_are_handled),
        cmocka_unit_test(zero_area_is_exact),
        cmocka_unit_test(index_out_of_range),
        cmocka_unit_test(empty_mesh),
        cmocka_unit_test(edge_table_is_sorted_and_complete),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
