/* Tests for opt/surface_arap_term, spokes-and-rims ARAP toward a target:
 *   - zero at the target and at a rigid motion of it (after the rotation
 *     fit), positive elsewhere, and the fit never raises the energy;
 *   - the slope against central differences (exact for the quadratic at
 *     fixed rotations, up to rounding);
 *   - the SLIM block is the energy itself: A x - b = half the gradient
 *     along any direction, also with a fixed vertex (its couplings on the
 *     right-hand side); the Newton fill doubles A and gives -gradient;
 *   - a zero-area target face is refused naming it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/samples.h"
#include "opt/surface_arap_term.h"

static double rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffff) / 65535.0 - 0.5;
}

/* an icosphere, target = the sphere stretched along x */
static void sphere(mesh *m, double **target)
{
    assert_int_equal(mesh_sample_make("icosphere", 2, m, NULL), SCAF_OK);
    *target = malloc(sizeof(double) * 3 * (size_t)m->nv);
    for (int v = 0; v < m->nv; v++)
        for (int k = 0; k < 3; k++) (*target)[3 * v + k] = m->V[3 * v + k] * (k == 0 ? 1.5 : 1.0);
}

static void zero_at_rigid_motion(void **state)
{
    (void)state;
    mesh m;
    double *T;
    sphere(&m, &T);
    opt_surface_arap s;
    assert_int_equal(opt_surface_arap_init(&s, m.nv, m.nf, m.F, T, 1.0, NULL), SCAF_OK);
    assert_true(fabs(opt_surface_arap_energy(&s, T)) < 1e-12);
    /* rotate by 0.7 about z and translate */
    double *X = malloc(sizeof(double) * 3 * (size_t)m.nv);
    double c = cos(0.7), sn = sin(0.7);
    for (int v = 0; v < m.nv; v++) {
        const double *t = T + 3 * v;
        X[3 * v] = c * t[0] - sn * t[1] + 3.0;
        X[3 * v + 1] = sn * t[0] + c * t[1] - 1.0;
        X[3 * v + 2] = t[2] + 0.5;
    }
    assert_true(opt_surface_arap_energy(&s, X) > 0.1); /* identity rotations */
    opt_surface_arap_fit(&s, X);
    assert_true(fabs(opt_surface_arap_energy(&s, X)) < 1e-10);
    /* the input sphere (not the target's shape): positive; the fit lowers it */
    double before = opt_surface_arap_energy(&s, m.V);
    opt_surface_arap_fit(&s, m.V);
    double after = opt_surface_arap_energy(&s, m.V);
    assert_true(after > 1e-3 && after <= before);
    free(X);
    free(T);
    opt_surface_arap_free(&s);
    mesh_free(&m);
}

/* y = A x for the symmetric matrix stored as its upper CSC */
static void sym_mul(const opt_csc *A, const double *x, double *y)
{
    memset(y, 0, sizeof(double) * (size_t)A->n);
    for (int j = 0; j < A->n; j++)
        for (int p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int i = A->rowidx[p];
            y[i] += A->val[p] * x[j];
            if (i != j) y[j] += A->val[p] * x[i];
        }
}

static void slope_and_fills(void **state)
{
    (void)state;
    mesh m;
    double *T;
    sphere(&m, &T);
    opt_surface_arap s;
    assert_int_equal(opt_surface_arap_init(&s, m.nv, m.nf, m.F, T, 2.0, NULL), SCAF_OK);
    int nv = m.nv;
    size_t n3 = 3 * (size_t)nv;
    double *X = malloc(sizeof(double) * n3), *D = malloc(sizeof(double) * n3);
    double *Xp = malloc(sizeof(double) * n3), *Xm = malloc(sizeof(double) * n3);
    unsigned seed = 7;
    for (size_t i = 0; i < n3; i++) {
        X[i] = 0.8 * m.V[i] + 0.05 * rnd(&seed);
        D[i] = rnd(&seed);
    }
    opt_obj_term t = opt_surface_arap_make(&s);
    for (int fixed0 = 0; fixed0 < 2; fixed0++) {
        int *dof = malloc(sizeof(int) * (size_t)nv);
        int nfree = 0;
        for (int v = 0; v < nv; v++) dof[v] = (fixed0 && v == 0) ? -1 : nfree++;
        if (fixed0)
            for (int k = 0; k < 3; k++) D[k] = 0.0; /* a fixed vertex does not move */
        assert_int_equal(t.ops->pattern(&t, dof, nfree, NULL), SCAF_OK);
        size_t nu = 3 * (size_t)nfree;
        double *rhs = calloc(nu, sizeof(double)), *x = malloc(sizeof(double) * nu),
               *d = malloc(sizeof(double) * nu), *y = malloc(sizeof(double) * nu);
        t.ops->fill(&t, dof, X, rhs); /* fits the rotations at X */
        assert_int_equal(t.blk.A.n, (int)nu);
        double e = 0.0, slope = 0.0;
        t.ops->energy_slope(&t, X, D, &e, &slope);
        assert_true(fabs(e - t.ops->energy(&t, X)) <= 1e-12 * fabs(e));
        const double h = 1e-5;
        for (size_t i = 0; i < n3; i++) Xp[i] = X[i] + h * D[i], Xm[i] = X[i] - h * D[i];
        double fd = (t.ops->energy(&t, Xp) - t.ops->energy(&t, Xm)) / (2 * h);
        assert_true(fabs(slope - fd) <= 1e-6 * (fabs(slope) + 1e-3));
        for (int v = 0; v < nv; v++)
            if (dof[v] >= 0)
                for (int k = 0; k < 3; k++) {
                    x[3 * dof[v] + k] = X[3 * v + k];
                    d[3 * dof[v] + k] = D[3 * v + k];
                }
        /* SLIM: (A x - b) . d = slope / 2 */
        sym_mul(&t.blk.A, x, y);
        double g = 0.0;
        for (size_t i = 0; i < nu; i++) g += (y[i] - rhs[i]) * d[i];
        assert_true(fabs(g - 0.5 * slope) <= 1e-9 * (fabs(slope) + 1.0));
        /* Newton: rhs = -gradient, A doubled */
        double *A1 = malloc(sizeof(double) * (size_t)t.blk.A.nnz);
        memcpy(A1, t.blk.A.val, sizeof(double) * (size_t)t.blk.A.nnz);
        memset(rhs, 0, sizeof(double) * nu);
        assert_int_equal(t.ops->hessian_fill(&t, dof, X, 1, rhs, NULL), SCAF_OK);
        double gn = 0.0;
        for (size_t i = 0; i < nu; i++) gn += rhs[i] * d[i];
        assert_true(fabs(gn + slope) <= 1e-9 * (fabs(slope) + 1.0));
        for (int p = 0; p < t.blk.A.nnz; p++)
            assert_true(fabs(t.blk.A.val[p] - 2.0 * A1[p]) <= 1e-12 * (fabs(A1[p]) + 1.0));
        free(A1);
        free(rhs);
        free(x);
        free(d);
        free(y);
        free(dof);
    }
    opt_obj_term_free(&t);
    free(X);
    free(D);
    free(Xp);
    free(Xm);
    free(T);
    opt_surface_arap_free(&s);
    mesh_free(&m);
}

static void zero_area_face_refused(void **state)
{
    (void)state;
    double V[12] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 1};
    int F[12] = {0, 1, 2, 0, 1, 3, 1, 2, 3, 0, 2, 3};
    opt_surface_arap s;
    scaf_error e;
    err_clear(&e);
    assert_int_equal(opt_surface_arap_init(&s, 4, 4, F, V, 1.0, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "face 0"));
    int bad[3] = {0, 1, 9};
    assert_int_equal(opt_surface_arap_init(&s, 4, 1, bad, V, 1.0, &e), SCAF_ERR_USAGE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zero_at_rigid_motion),
        cmocka_unit_test(slope_and_fills),
        cmocka_unit_test(zero_area_face_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
