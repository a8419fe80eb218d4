/* Tests for opt/supernodal_lu: on M-matrices (random positive weights,
 * not symmetric, on grids whose separators make supernodes of tens of
 * columns, and on a complete graph whose one supernode goes through the
 * blocked diagonal factorization) the solves leave residuals at rounding;
 * a singular matrix, one that needs pivots, an asymmetric pattern and a
 * missing diagonal are refused with the right status. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/supernodal_lu.h"
#include "rng.h"

/* A square matrix built entry by entry (dense, small n), then stored as
 * CSC with the entries that are not zero or that the pattern marks. */
typedef struct dense {
    int n;
    double *a;           /* column-major */
    unsigned char *mark; /* the pattern */
} dense;

static void dense_make(dense *D, int n)
{
    D->n = n;
    D->a = calloc((size_t)n * n, sizeof *D->a);
    D->mark = calloc((size_t)n * n, 1);
    assert_non_null(D->a);
    assert_non_null(D->mark);
}

static void dense_free(dense *D)
{
    free(D->a);
    free(D->mark);
}

static void set(dense *D, int i, int j, double v)
{
    D->a[(size_t)j * D->n + i] = v;
    D->mark[(size_t)j * D->n + i] = 1;
}

typedef struct csc {
    int *p, *i;
    double *x;
} csc;

static void to_csc(const dense *D, csc *A)
{
    int n = D->n, nz = 0;
    for (size_t k = 0; k < (size_t)n * n; k++) nz += D->mark[k];
    A->p = malloc(((size_t)n + 1) * sizeof *A->p);
    A->i = malloc(((size_t)nz + 1) * sizeof *A->i);
    A->x = malloc(((size_t)nz + 1) * sizeof *A->x);
    int at = 0;
    for (int j = 0; j < n; j++) {
        A->p[j] = at;
        for (int i = 0; i < n; i++)
            if (D->mark[(size_t)j * n + i]) {
                A->i[at] = i;
                A->x[at++] = D->a[(size_t)j * n + i];
            }
    }
    A->p[n] = at;
}

static void csc_free(csc *A)
{
    free(A->p);
    free(A->i);
    free(A->x);
}

/* An M-matrix on graph edges (i, j) both ways with random weights in
 * [0.1, 2), each direction its own: off-diagonal -w, diagonal the row's
 * sum plus `extra` on the rows `anchored` says (1 in k), like the
 * mean-value system's rows next to the fixed boundary. */
static void m_matrix(dense *D, const int *edges, int ne, rng *r, int anchored)
{
    int n = D->n;
    for (int e = 0; e < ne; e++) {
        int a = edges[2 * e], b = edges[2 * e + 1];
        set(D, a, b, -rng_uniform(r, 0.1, 2.0));
        set(D, b, a, -rng_uniform(r, 0.1, 2.0));
    }
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int j = 0; j < n; j++)
            if (j != i) s -= D->a[(size_t)j * n + i];
        set(D, i, i, s + (anchored > 0 && i % anchored == 0 ? rng_uniform(r, 0.5, 1.5) : 0.0));
    }
}

/* Edges of an m x m grid with diagonals (8 neighbours). */
static int grid_edges(int m, int *edges)
{
    int ne = 0;
    for (int y = 0; y < m; y++)
        for (int x = 0; x < m; x++) {
            int v = y * m + x;
            if (x + 1 < m) edges[2 * ne] = v, edges[2 * ne++ + 1] = v + 1;
            if (y + 1 < m) edges[2 * ne] = v, edges[2 * ne++ + 1] = v + m;
            if (x + 1 < m && y + 1 < m) edges[2 * ne] = v, edges[2 * ne++ + 1] = v + m + 1;
            if (x > 0 && y + 1 < m) edges[2 * ne] = v, edges[2 * ne++ + 1] = v + m - 1;
        }
    return ne;
}

/* max |b - A x| / (max|A| max|x| + max|b|) over rows. */
static double relative_residual(const dense *D, const double *x, const double *b)
{
    int n = D->n;
    double amax = 0, xmax = 0, bmax = 0, rmax = 0;
    for (int i = 0; i < n; i++) {
        double r = b[i];
        for (int j = 0; j < n; j++) {
            double a = D->a[(size_t)j * n + i];
            r -= a * x[j];
            amax = fmax(amax, fabs(a));
        }
        rmax = fmax(rmax, fabs(r));
        xmax = fmax(xmax, fabs(x[i]));
        bmax = fmax(bmax, fabs(b[i]));
    }
    return rmax / (amax * xmax + bmax);
}

/* Factor D, solve for two random right-hand sides (one in place), and
 * check the residuals. */
static void solves_to_rounding(const dense *D, rng *r)
{
    int n = D->n;
    csc A;
    to_csc(D, &A);
    scaf_error e;
    opt_lu *F = opt_lu_factor(n, A.p, A.i, A.x, &e);
    assert_non_null(F);
    assert_true(opt_lu_entries(F) >= (double)A.p[n]);
    double *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
    for (int rhs = 0; rhs < 2; rhs++) {
        for (int i = 0; i < n; i++) b[i] = rng_uniform(r, -1, 1);
        if (rhs == 0) {
            opt_lu_solve(F, b, x);
        } else { /* in place */
            memcpy(x, b, (size_t)n * sizeof *x);
            opt_lu_solve(F, x, x);
        }
        assert_true(relative_residual(D, x, b) < 1e-13);
    }
    free(b);
    free(x);
    opt_lu_free(F);
    csc_free(&A);
}

/* Grids: supernodes from one column up to the top separators (~2m). */
static void grid_m_matrices(void **state)
{
    (void)state;
    rng r = {11};
    const int sizes[3] = {3, 12, 30};
    for (int k = 0; k < 3; k++) {
        int m = sizes[k], n = m * m;
        int *edges = malloc((size_t)8 * n * sizeof *edges);
        int ne = grid_edges(m, edges);
        dense D;
        dense_make(&D, n);
        m_matrix(&D, edges, ne, &r, m + 1); /* a few anchored rows only */
        solves_to_rounding(&D, &r);
        dense_free(&D);
        free(edges);
    }
}

/* A complete graph: one supernode of n columns, factored by panels. */
static void dense_block(void **state)
{
    (void)state;
    rng r = {13};
    const int n = 150;
    int *edges = malloc((size_t)n * n * sizeof *edges), ne = 0;
    for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++) edges[2 * ne] = a, edges[2 * ne++ + 1] = b;
    dense D;
    dense_make(&D, n);
    m_matrix(&D, edges, ne, &r, 7);
    solves_to_rounding(&D, &r);
    dense_free(&D);
    free(edges);
}

static void one_unknown(void **state)
{
    (void)state;
    rng r = {17};
    dense D;
    dense_make(&D, 1);
    set(&D, 0, 0, 3.0);
    solves_to_rounding(&D, &r);
    dense_free(&D);
}

static void refused(const dense *D, scaf_status want)
{
    csc A;
    to_csc(D, &A);
    scaf_error e;
    err_clear(&e);
    opt_lu *F = opt_lu_factor(D->n, A.p, A.i, A.x, &e);
    assert_null(F);
    assert_int_equal(e.code, want);
    assert_true(strlen(e.message) > 0);
    csc_free(&A);
}

/* No anchored row: every row sums to zero, the last pivot vanishes. */
static void singular_is_refused(void **state)
{
    (void)state;
    rng r = {19};
    const int m = 8, n = m * m;
    int edges[2 * 4 * 64];
    int ne = grid_edges(m, edges);
    dense D;
    dense_make(&D, n);
    m_matrix(&D, edges, ne, &r, 0);
    refused(&D, SCAF_ERR_NUMERIC);
    dense_free(&D);
}

/* [[1, 2], [2, 1]]: the second pivot is -3 (a pivoting LU would swap). */
static void needs_pivots_is_refused(void **state)
{
    (void)state;
    dense D;
    dense_make(&D, 2);
    set(&D, 0, 0, 1.0);
    set(&D, 1, 0, 2.0);
    set(&D, 0, 1, 2.0);
    set(&D, 1, 1, 1.0);
    refused(&D, SCAF_ERR_NUMERIC);
    dense_free(&D);
}

static void bad_patterns_are_refused(void **state)
{
    (void)state;
    dense D;
    dense_make(&D, 3);
    set(&D, 0, 0, 2.0);
    set(&D, 1, 1, 2.0);
    set(&D, 2, 2, 2.0);
    set(&D, 0, 2, -1.0); /* (0, 2) without (2, 0) */
    refused(&D, SCAF_ERR_USAGE);
    dense_free(&D);
    dense_make(&D, 2);
    set(&D, 0, 0, 2.0);
    set(&D, 0, 1, -1.0);
    set(&D, 1, 0, -1.0); /* no (1, 1) */
    refused(&D, SCAF_ERR_USAGE);
    dense_free(&D);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grid_m_matrices),
        cmocka_unit_test(dense_block),
        cmocka_unit_test(one_unknown),
        cmocka_unit_test(singular_is_refused),
        cmocka_unit_test(needs_pivots_is_refused),
        cmocka_unit_test(bad_patterns_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
