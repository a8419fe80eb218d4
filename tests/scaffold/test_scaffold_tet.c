/* Tests for scaffold/scaffold_tet (the 3D scaffold provider) and the
 * volume loop's setup (scaffold/scaf_loop: scaf_loop_init_volume):
 *   - the first refresh builds tets around an icosphere: the box's 386
 *     vertices (8 x 8 squares per side) fixed, the others free, every tet
 *     positive, eps = l^3 / (6 sqrt 6) with l the shortest surface edge,
 *     quality summary in (0, 1];
 *   - with the improvement pass off, a later refresh keeps the tets as
 *     they are; with it on, every tet is still positive and the box and
 *     surface vertices are where they were;
 *   - an open surface is refused (SCAF_ERR_MESH), bad arguments
 *     (SCAF_ERR_USAGE), and the volume loop refuses a provider that is not
 *     3D over its vertices or a floor that is not > 0. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/tet_orient.h"
#include "mesh/samples.h"
#include "scaffold/scaf_loop.h"
#include "scaffold/scaffold_tet.h"

static void assert_positive(const scaffold_view *v, const double *X)
{
    int n = v->nmesh + v->nextra;
    double *P = malloc(sizeof(double) * 3 * (size_t)n);
    memcpy(P, X, sizeof(double) * 3 * (size_t)v->nmesh);
    memcpy(P + 3 * (size_t)v->nmesh, v->extra, sizeof(double) * 3 * (size_t)v->nextra);
    tet_orient_report r;
    assert_int_equal(tet_orient_check(n, P, v->n, v->simplices, &r, NULL), SCAF_OK);
    assert_int_equal(r.positive, r.tets);
    free(P);
}

static void builds_and_keeps(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, NULL), SCAF_OK);
    scaffold_provider *p = scaffold_tet_create(m.nv, m.nf, m.F, 3.0, 8, NULL);
    assert_non_null(p);
    scaffold_view v;
    p->ops->view(p, &v);
    assert_int_equal(v.n, 0); /* nothing before the first refresh */
    assert_int_equal(p->ops->refresh(p, m.V, NULL, NULL), SCAF_OK);
    p->ops->view(p, &v);
    assert_int_equal(v.d, 3);
    assert_int_equal(v.nmesh, m.nv);
    assert_true(v.n > 0 && v.nextra >= 386);
    for (int i = 0; i < v.nextra; i++) assert_int_equal(v.extra_fixed[i], i < 386);
    assert_positive(&v, m.V);
    double l = INFINITY;
    for (int f = 0; f < m.nf; f++)
        for (int e = 0; e < 3; e++) {
            const double *a = m.V + 3 * m.F[3 * f + e], *b = m.V + 3 * m.F[3 * f + (e + 1) % 3];
            double d = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                            (a[2] - b[2]) * (a[2] - b[2]));
            if (d < l) l = d;
        }
    assert_true(fabs(v.eps - l * l * l / (6 * sqrt(6.0))) <= 1e-15 * v.eps);
    double qmin, qp5;
    assert_int_equal(scaffold_tet_quality_stats(&v, m.V, &qmin, &qp5, NULL), SCAF_OK);
    assert_true(qmin > 0 && qmin <= qp5 && qp5 <= 1.0);
    const signed char *in = scaffold_tet_inside(p);
    int inside = 0;
    for (int t = 0; t < v.n; t++) inside += in[t] == 1;
    assert_true(inside > 0 && inside < v.n);
    /* off: the same tets again */
    int n0 = v.n;
    int *T0 = malloc(sizeof(int) * 4 * (size_t)n0);
    memcpy(T0, v.simplices, sizeof(int) * 4 * (size_t)n0);
    scaffold_tet_set_improve(p, 0, NULL);
    assert_int_equal(p->ops->refresh(p, m.V, NULL, NULL), SCAF_OK);
    p->ops->view(p, &v);
    assert_int_equal(v.n, n0);
    assert_memory_equal(v.simplices, T0, sizeof(int) * 4 * (size_t)n0);
    assert_int_equal(scaffold_tet_improve_stats(p)->tries, 0);
    /* on: improved, still positive, the box where it was */
    double *box = malloc(sizeof(double) * 3 * 386);
    memcpy(box, v.extra, sizeof(double) * 3 * 386);
    scaffold_tet_set_improve(p, 1, NULL);
    assert_int_equal(p->ops->refresh(p, m.V, NULL, NULL), SCAF_OK);
    p->ops->view(p, &v);
    assert_positive(&v, m.V);
    assert_memory_equal(v.extra, box, sizeof(double) * 3 * 386);
    assert_true(scaffold_tet_improve_stats(p)->tries > 0);
    double qmin2, qp52;
    assert_int_equal(scaffold_tet_quality_stats(&v, m.V, &qmin2, &qp52, NULL), SCAF_OK);
    assert_true(qmin2 >= qmin);
    free(box);
    free(T0);
    scaffold_provider_destroy(p);
    mesh_free(&m);
}

static void refusals(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_sample_make("hemisphere", 3, &m, NULL), SCAF_OK);
    assert_null(scaffold_tet_create(m.nv, m.nf, m.F, 1.0, 8, &e));
    assert_int_equal(e.code, SCAF_ERR_USAGE);
    assert_null(scaffold_tet_create(m.nv, m.nf, m.F, 3.0, 0, &e));
    scaffold_provider *p = scaffold_tet_create(m.nv, m.nf, m.F, 3.0, 8, NULL);
    assert_non_null(p);
    err_clear(&e);
    assert_int_equal(p->ops->refresh(p, m.V, NULL, &e), SCAF_ERR_MESH);
    scaffold_view v;
    p->ops->view(p, &v);
    assert_int_equal(v.n, 0);
    /* the volume loop: wrong vertex count, floor <= 0 (the provider is
     * taken in both cases) */
    scaf_loop L;
    assert_int_equal(scaf_loop_init_volume(&L, m.nv + 1, m.V, p, 1.0, NULL, &e), SCAF_ERR_USAGE);
    p = scaffold_tet_create(m.nv, m.nf, m.F, 3.0, 8, NULL);
    assert_int_equal(scaf_loop_init_volume(&L, m.nv, m.V, p, 0.0, NULL, &e), SCAF_ERR_USAGE);
    p = scaffold_tet_create(m.nv, m.nf, m.F, 3.0, 8, NULL);
    assert_int_equal(scaf_loop_init_volume(&L, m.nv, m.V, p, NAN, NULL, &e), SCAF_ERR_USAGE);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(builds_and_keeps),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
