/* Tests for geom/tet_box_mesh and geom/tetgen_call: closed surfaces in a
 * box tetrahedralized by TetGen with every tet positive, every surface
 * triangle kept, inside/outside labels whose volumes add up to the
 * surface's enclosed volume and the box; refusals naming the reason (open,
 * non-manifold, self-intersecting, outside the box), TetGen's own `throw`
 * turned into an error; the shared closed meshes when present. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/tet_box_mesh.h"
#include "geom/tet_orient.h"
#include "geom/tetgen_call.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "support/support.h"

static double tet_volume(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = d[k] - a[k];
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0])) /
        6;
}

/* Volume enclosed by a closed outward surface (divergence theorem). */
static double enclosed_volume(int nf, const int *F, const double *V)
{
    static const double o[3] = {0, 0, 0};
    double vol = 0;
    for (int f = 0; f < nf; f++)
        vol += tet_volume(o, V + 3 * F[3 * f], V + 3 * F[3 * f + 1], V + 3 * F[3 * f + 2]);
    return vol;
}

/* The properties every successful build promises, checked here
 * independently of the module's own checks. */
static void check_mesh(const tet_box_mesh *tm, int nv, const double *V, int nf, const int *F,
                       const double lo[3], const double hi[3])
{
    assert_true(tm->nt > 0);
    assert_int_equal(tm->nsurface, nv);
    assert_memory_equal(tm->V, V, sizeof(double) * 3 * (size_t)nv);
    tet_orient_report r;
    assert_int_equal(tet_orient_check(tm->nv, tm->V, tm->nt, tm->T, &r, NULL), SCAF_OK);
    assert_int_equal(r.positive, tm->nt);
    double vin = 0, vout = 0;
    int ninside = 0;
    for (int t = 0; t < tm->nt; t++) {
        const int *q = tm->T + 4 * t;
        double v =
            tet_volume(tm->V + 3 * q[0], tm->V + 3 * q[1], tm->V + 3 * q[2], tm->V + 3 * q[3]);
        if (tm->inside[t]) vin += v, ninside++;
        else vout += v;
    }
    assert_int_equal(ninside, tm->ninside);
    double vs = enclosed_volume(nf, F, V);
    double vbox = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    assert_true(fabs(vin - vs) <= 1e-9 * vbox);
    assert_true(fabs(vin + vout - vbox) <= 1e-9 * vbox);
    /* every surface triangle is a face of a tet (all four faces listed) */
    for (int f = 0; f < nf; f++) {
        int hits = 0;
        for (int t = 0; t < tm->nt; t++) {
            int shared = 0;
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 4; l++) shared += F[3 * f + k] == tm->T[4 * t + l];
            hits += shared == 3;
        }
        assert_int_equal(hits, 2);
    }
}

static void sample_in_box(const char *name, int size, double scale, int cells)
{
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_sample_make(name, size, &m, &e), SCAF_OK);
    double lo[3], hi[3];
    tet_box_around(m.nv, m.V, scale, lo, hi);
    tet_box_mesh tm;
    err_clear(&e);
    scaf_status s = tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, cells, &tm, &e);
    if (s) print_error("%s: %s\n", name, e.message);
    assert_int_equal(s, SCAF_OK);
    assert_int_equal(tm.nbox_faces, 12 * cells * cells);
    assert_int_equal(tm.nbox, 6 * cells * cells + 2);
    check_mesh(&tm, m.nv, m.V, m.nf, m.F, lo, hi);
    tet_box_mesh_free(&tm);
    mesh_free(&m);
}

static void closed_samples(void **state)
{
    (void)state;
    sample_in_box("tetrahedron", 0, 3, 1);
    sample_in_box("icosphere", 3, 3, 4);
    sample_in_box("cubesphere", 4, 2, 8);
}

/* A hollow ball: the unit icosphere and one of radius 0.5 facing inward.
 * The cavity is outside, so the inside volume is the shell's. */
static void nested_shells(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, &e), SCAF_OK);
    int nv = 2 * m.nv, nf = 2 * m.nf;
    double *V = malloc(sizeof(double) * 3 * (size_t)nv);
    int *F = malloc(sizeof(int) * 3 * (size_t)nf);
    memcpy(V, m.V, sizeof(double) * 3 * (size_t)m.nv);
    memcpy(F, m.F, sizeof(int) * 3 * (size_t)m.nf);
    for (int i = 0; i < 3 * m.nv; i++) V[3 * m.nv + i] = 0.5 * m.V[i];
    for (int f = 0; f < m.nf; f++) {
        F[3 * (m.nf + f)] = m.nv + m.F[3 * f];
        F[3 * (m.nf + f) + 1] = m.nv + m.F[3 * f + 2];
        F[3 * (m.nf + f) + 2] = m.nv + m.F[3 * f + 1];
    }
    double lo[3], hi[3];
    tet_box_around(nv, V, 3, lo, hi);
    tet_box_mesh tm;
    assert_int_equal(tet_box_mesh_build(nv, V, nf, F, lo, hi, 4, &tm, &e), SCAF_OK);
    check_mesh(&tm, nv, V, nf, F, lo, hi);
    assert_true(enclosed_volume(nf, F, V) < 0.9 * enclosed_volume(m.nf, m.F, m.V));
    tet_box_mesh_free(&tm);
    free(V);
    free(F);
    mesh_free(&m);
}

static void refusals(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    tet_box_mesh tm;
    double lo[3], hi[3];
    assert_int_equal(mesh_sample_make("icosphere", 2, &m, &e), SCAF_OK);
    tet_box_around(m.nv, m.V, 3, lo, hi);
    /* open: one face removed */
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf - 1, m.F, lo, hi, 2, &tm, &e),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "open"));
    assert_null(tm.T);
    /* non-manifold: a face repeated (its edges get three faces... and it duplicates) */
    int *F2 = malloc(sizeof(int) * 3 * (size_t)(m.nf + 1));
    memcpy(F2, m.F, sizeof(int) * 3 * (size_t)m.nf);
    memcpy(F2 + 3 * m.nf, m.F, sizeof(int) * 3);
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf + 1, F2, lo, hi, 2, &tm, &e),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "not manifold"));
    free(F2);
    /* self-intersecting: a vertex pushed through the opposite side */
    double saved[3];
    memcpy(saved, m.V, sizeof saved);
    for (int k = 0; k < 3; k++) m.V[k] *= -1.5;
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, 2, &tm, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "intersects itself"));
    memcpy(m.V, saved, sizeof saved);
    /* a box not containing the surface */
    double small_hi[3] = {0.5, 0.5, 0.5};
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, small_hi, 2, &tm, &e),
                     SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "not strictly inside the box"));
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, 0, &tm, &e), SCAF_ERR_USAGE);
    /* restored: meshes */
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, 2, &tm, &e), SCAF_OK);
    tet_box_mesh_free(&tm);
    mesh_free(&m);
}

/* TetGen's own refusal (throw int), without the checks in front of it:
 * two tetrahedra crossing each other. */
static void tetgen_throw_is_an_error(void **state)
{
    (void)state;
    double P[] = {0,   0,   0,  2, 0,   0,   0,   2, 0,   0,   0,   2,
                  0.5, 0.5, -1, 3, 0.5, 0.5, 0.5, 3, 0.5, 0.5, 0.5, 3};
    int T[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2, 4, 6, 5, 4, 5, 7, 5, 6, 7, 4, 7, 6};
    tetgen_result r;
    scaf_error e;
    err_clear(&e);
    scaf_status s = tetgen_call(8, P, 8, T, 0, NULL, &r, &e);
    assert_int_equal(s, SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "TetGen"));
    assert_null(r.T);
    print_message("    TetGen says: %s\n", e.message);
    /* and a good input goes through */
    assert_int_equal(tetgen_call(4, P, 4, T, 0, NULL, &r, &e), SCAF_OK);
    assert_int_equal(r.np, 4);
    assert_int_equal(r.nt, 1);
    tetgen_result_free(&r);
    assert_int_equal(tetgen_call(3, P, 4, T, 0, NULL, &r, &e), SCAF_ERR_USAGE);
}

static void shared_closed_meshes(void **state)
{
    (void)state;
    char buf[4096];
    const char *path = test_data_path("closed/bunny.obj", buf, sizeof buf);
    if (!path) skip();
    mesh m;
    mesh_read_info info;
    scaf_error e;
    assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
    double lo[3], hi[3];
    tet_box_around(m.nv, m.V, 3, lo, hi);
    tet_box_mesh tm;
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, 8, &tm, &e), SCAF_OK);
    check_mesh(&tm, m.nv, m.V, m.nf, m.F, lo, hi);
    print_message("    bunny: %d vertices, %d tets (%d inside)\n", tm.nv, tm.nt, tm.ninside);
    tet_box_mesh_free(&tm);
    mesh_free(&m);

    path = test_data_path("closed/leg-intersect.off", buf, sizeof buf);
    if (!path) return;
    assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
    tet_box_around(m.nv, m.V, 3, lo, hi);
    assert_int_equal(tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, 8, &tm, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "intersects itself: 239 pairs"));
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_samples),
        cmocka_unit_test(nested_shells),
        cmocka_unit_test(refusals),
        cmocka_unit_test(tetgen_throw_is_an_error),
        cmocka_unit_test(shared_closed_meshes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
