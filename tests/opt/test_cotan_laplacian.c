/* Tests for opt/cotan_laplacian: known entries on a regular tetrahedron
 * and a flat grid (the 5-point stencil), symmetry, zero row sums (L of a
 * constant is zero), negative semidefiniteness, scale independence, the
 * barycentric mass, and a zero-area face refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "mesh/samples.h"
#include "opt/cotan_laplacian.h"

/* L_ij from the upper storage (0 when not stored). */
static double entry(const opt_csc *L, int i, int j)
{
    if (i > j) {
        int t = i;
        i = j;
        j = t;
    }
    for (int k = L->colptr[j]; k < L->colptr[j + 1]; k++)
        if (L->rowidx[k] == i) return L->val[k];
    return 0;
}

static const double tet_V[] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
static const int tet_F[] = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};

static void regular_tetrahedron(void **state)
{
    (void)state;
    opt_csc L;
    scaf_error e;
    assert_int_equal(opt_cotan_laplacian(4, tet_V, 4, tet_F, &L, &e), SCAF_OK);
    /* every angle 60 degrees: off-diagonal (2 cot 60) / 2 = 1/sqrt 3 */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            assert_float_equal(entry(&L, i, j), i == j ? -sqrt(3.0) : 1 / sqrt(3.0), 1e-15);
    double mass[4];
    double area = opt_mass_barycentric(4, tet_V, 4, tet_F, mass);
    /* edge 2 sqrt 2: four faces of area sqrt(3)/4 * 8 */
    assert_float_equal(area, 8 * sqrt(3.0), 1e-13);
    for (int v = 0; v < 4; v++) assert_float_equal(mass[v], area / 4, 1e-13);
    opt_csc_free(&L);
}

/* n x n unit squares, each cut along the same diagonal. */
static void flat_grid(void **state)
{
    (void)state;
    enum { n = 4, nv = (n + 1) * (n + 1), nf = 2 * n * n };
    double V[3 * nv];
    int F[3 * nf], f = 0;
    for (int y = 0; y <= n; y++)
        for (int x = 0; x <= n; x++) {
            int v = y * (n + 1) + x;
            V[3 * v] = x;
            V[3 * v + 1] = y;
            V[3 * v + 2] = 0;
        }
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int a = y * (n + 1) + x, b = a + 1, c = a + n + 2, d = a + n + 1;
            F[3 * f] = a;
            F[3 * f + 1] = b;
            F[3 * f + 2] = c;
            f++;
            F[3 * f] = a;
            F[3 * f + 1] = c;
            F[3 * f + 2] = d;
            f++;
        }
    opt_csc L;
    scaf_error e;
    assert_int_equal(opt_cotan_laplacian(nv, V, nf, F, &L, &e), SCAF_OK);
    /* interior vertex: the 5-point stencil (diagonal edges get cot 90 = 0) */
    int v = 2 * (n + 1) + 2;
    assert_float_equal(entry(&L, v, v), -4, 1e-14);
    assert_float_equal(entry(&L, v, v + 1), 1, 1e-14);
    assert_float_equal(entry(&L, v, v - 1), 1, 1e-14);
    assert_float_equal(entry(&L, v, v + n + 1), 1, 1e-14);
    assert_float_equal(entry(&L, v, v - n - 1), 1, 1e-14);
    assert_float_equal(entry(&L, v, v + n + 2), 0, 1e-14);
    /* L x = 0 for the constant and for the linear functions (flat, interior
     * rows: the cotangent Laplacian is exact on linear functions) */
    double x[nv], y[nv];
    for (int k = 0; k < nv; k++) x[k] = 3.5;
    opt_csc_symv(&L, x, y);
    for (int k = 0; k < nv; k++) assert_true(fabs(y[k]) < 1e-13);
    for (int k = 0; k < nv; k++) x[k] = 2 * V[3 * k] - V[3 * k + 1];
    opt_csc_symv(&L, x, y);
    for (int yy = 1; yy < n; yy++)
        for (int xx = 1; xx < n; xx++) assert_true(fabs(y[yy * (n + 1) + xx]) < 1e-13);
    double mass[nv];
    assert_float_equal(opt_mass_barycentric(nv, V, nf, F, mass), n * n, 1e-13);
    assert_float_equal(mass[v], 1, 1e-14); /* six triangles of area 1/2, a third each */
    opt_csc_free(&L);
}

/* On an irregular closed surface: symmetric storage, zero row sums,
 * x^T L x <= 0, the same L for a scaled copy. */
static void icosphere_properties(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, &e), SCAF_OK);
    opt_csc L, L2;
    assert_int_equal(opt_cotan_laplacian(m.nv, m.V, m.nf, m.F, &L, &e), SCAF_OK);
    assert_true(opt_csc_is_upper_sorted(&L));
    double *x = malloc(sizeof(double) * (size_t)m.nv), *y = malloc(sizeof(double) * (size_t)m.nv);
    for (int k = 0; k < m.nv; k++) x[k] = 1;
    opt_csc_symv(&L, x, y);
    for (int k = 0; k < m.nv; k++) assert_true(fabs(y[k]) < 1e-12);
    for (int trial = 0; trial < 3; trial++) {
        double q = 0;
        for (int k = 0; k < m.nv; k++)
            x[k] = sin(1.7 * k + trial) + m.V[3 * k + trial] * m.V[3 * k + trial];
        opt_csc_symv(&L, x, y);
        for (int k = 0; k < m.nv; k++) q += x[k] * y[k];
        assert_true(q < 0);
    }
    for (int k = 0; k < 3 * m.nv; k++) m.V[k] = 7 * m.V[k] + 1;
    assert_int_equal(opt_cotan_laplacian(m.nv, m.V, m.nf, m.F, &L2, &e), SCAF_OK);
    assert_int_equal(L2.nnz, L.nnz);
    for (int k = 0; k < L.nnz; k++)
        assert_true(fabs(L2.val[k] - L.val[k]) < 1e-12 * (1 + fabs(L.val[k])));
    free(x);
    free(y);
    opt_csc_free(&L);
    opt_csc_free(&L2);
    mesh_free(&m);
}

static void zero_area_face_refused(void **state)
{
    (void)state;
    double V[12];
    memcpy(V, tet_V, sizeof V);
    for (int d = 0; d < 3; d++) V[3 + d] = V[d]; /* vertex 1 onto vertex 0 */
    opt_csc L;
    scaf_error e;
    assert_int_equal(opt_cotan_laplacian(4, V, 4, tet_F, &L, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "face 0 has zero area"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(regular_tetrahedron),
        cmocka_unit_test(flat_grid),
        cmocka_unit_test(icosphere_properties),
        cmocka_unit_test(zero_area_face_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
