/* Tests for opt/block_solver against dense Cholesky answers: 2D vertex
 * systems with a fixed part (a grid) and a changing part, solved to 1e-9
 * of the dense solution over rounds whose changing part grows past the
 * reuse threshold (the fixed part's order kept from the first round, a
 * permutation of its unknowns); a slightly indefinite system is refused
 * without retries and, with them, solved as A + mu diag(A) with the first
 * mu that works (1e-7), the right-hand side shifted by mu diag(A) x for
 * positions and left alone for steps; a solve without a factorization is
 * a usage error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/block_solver.h"
#include "rng.h"

/* Upper CSC of the 2D vertex system with edges (ea[e], eb[e]): each edge a
 * -M block, each vertex (degree + 1) M, M = [2 .5; .5 1]. */
static void block_laplacian(opt_csc *A, int nvtx, int ne, const int *ea, const int *eb)
{
    const double M[4] = {2, 0.5, 0.5, 1};
    int cap = 4 * (ne + nvtx), nt = 0;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V), *deg = calloc(nvtx, sizeof *deg);
    for (int e = 0; e < ne; e++) {
        deg[ea[e]] += 1;
        deg[eb[e]] += 1;
    }
    for (int pass = 0; pass < 2; pass++)
        for (int e = 0; e < (pass ? ne : nvtx); e++) {
            int u = pass ? ea[e] : e, v = pass ? eb[e] : e;
            double w = pass ? -1.0 : deg[e] + 1.0;
            if (u > v) {
                int t = u;
                u = v;
                v = t;
            }
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) {
                    if (2 * u + a > 2 * v + b) continue;
                    I[nt] = 2 * u + a;
                    J[nt] = 2 * v + b;
                    V[nt++] = w * M[2 * a + b];
                }
        }
    assert_int_equal(opt_csc_from_triplets(A, 2 * nvtx, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
    free(deg);
}

/* x = A^-1 b by a dense Cholesky factorization of A (+ mu diag(A)). */
static void dense_solve(const opt_csc *A, double mu, const double *b, double *x)
{
    int n = A->n;
    double *D = calloc((size_t)n * n, sizeof *D);
    for (int c = 0; c < n; c++)
        for (int e = A->colptr[c]; e < A->colptr[c + 1]; e++) {
            int r = A->rowidx[e];
            D[(size_t)c * n + r] = D[(size_t)r * n + c] = A->val[e] * (r == c ? 1.0 + mu : 1.0);
        }
    for (int j = 0; j < n; j++) { /* lower Cholesky in place */
        double s = D[(size_t)j * n + j];
        for (int k = 0; k < j; k++) s -= D[(size_t)j * n + k] * D[(size_t)j * n + k];
        assert_true(s > 0.0);
        D[(size_t)j * n + j] = sqrt(s);
        for (int i = j + 1; i < n; i++) {
            double t = D[(size_t)i * n + j];
            for (int k = 0; k < j; k++) t -= D[(size_t)i * n + k] * D[(size_t)j * n + k];
            D[(size_t)i * n + j] = t / D[(size_t)j * n + j];
        }
    }
    for (int i = 0; i < n; i++) {
        double t = b[i];
        for (int k = 0; k < i; k++) t -= D[(size_t)i * n + k] * x[k];
        x[i] = t / D[(size_t)i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        double t = x[i];
        for (int k = i + 1; k < n; k++) t -= D[(size_t)k * n + i] * x[k];
        x[i] = t / D[(size_t)i * n + i];
    }
    free(D);
}

static double max_rel_diff(const double *x, const double *y, int n)
{
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; i++) {
        num = fmax(num, fabs(x[i] - y[i]));
        den = fmax(den, fabs(y[i]));
    }
    return num / den;
}

/* The system of round k: an m x m grid of fixed vertices, then nvar
 * changing vertices in a chain, each also tied to a random grid vertex. */
static void round_system(opt_csc *A, int m, int nvar, rng *r)
{
    int nfv = m * m, nvtx = nfv + nvar, cap = 2 * nfv + 2 * nvar, ne = 0;
    int *ea = malloc(cap * sizeof *ea), *eb = malloc(cap * sizeof *eb);
    for (int y = 0; y < m; y++)
        for (int x = 0; x < m; x++) {
            int i = y * m + x;
            if (x + 1 < m) ea[ne] = i, eb[ne++] = i + 1;
            if (y + 1 < m) ea[ne] = i, eb[ne++] = i + m;
        }
    for (int k = 0; k < nvar; k++) {
        ea[ne] = nfv + k;
        eb[ne++] = (int)rng_uniform(r, 0, nfv - 1);
        if (k > 0) ea[ne] = nfv + k - 1, eb[ne++] = nfv + k;
    }
    block_laplacian(A, nvtx, ne, ea, eb);
    free(ea);
    free(eb);
}

static void solves_like_dense_over_changing_patterns(void **state)
{
    (void)state;
    const int m = 8, nfixed = 2 * m * m;
    rng r = {17};
    scaf_error e;
    opt_block_solver *s = opt_block_solver_create(2, nfixed, &e);
    assert_non_null(s);
    assert_null(opt_block_solver_fixed_ordering(s));
    int *first = malloc(nfixed * sizeof *first);
    const int nvars[5] = {6, 11, 300, 9, 9}; /* 300: past the threshold, AMD afresh */
    for (int k = 0; k < 5; k++) {
        opt_proxy_system sys;
        memset(&sys, 0, sizeof sys);
        sys.d = 2;
        round_system(&sys.A, m, nvars[k], &r);
        sys.nfree = sys.A.n / 2;
        int n = sys.A.n;
        double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x),
               *ref = malloc(n * sizeof *ref);
        for (int i = 0; i < n; i++) b[i] = rng_uniform(&r, -1, 1);
        dense_solve(&sys.A, 0.0, b, ref);
        assert_int_equal(opt_block_solver_update(s, &sys, &e), SCAF_OK);
        const int *fo = opt_block_solver_fixed_ordering(s);
        assert_non_null(fo);
        if (k == 0) {
            memcpy(first, fo, nfixed * sizeof *first);
            unsigned char *seen = calloc(nfixed, 1);
            for (int i = 0; i < nfixed; i++) {
                assert_true(fo[i] >= 0 && fo[i] < nfixed && !seen[fo[i]]);
                seen[fo[i]] = 1;
            }
            free(seen);
        } else {
            assert_memory_equal(first, fo, nfixed * sizeof *first);
        }
        opt_block_retry retry = {1, 0, NULL, NULL};
        assert_int_equal(opt_block_solver_factor(s, &sys, b, &retry, &e), SCAF_OK);
        assert_int_equal(opt_block_solver_solve(s, x, &e), SCAF_OK);
        assert_true(max_rel_diff(x, ref, n) < 1e-9);
        /* values of the same pattern refilled: factor again, no update */
        for (int i = 0; i < sys.A.nnz; i++) sys.A.val[i] *= 2.0;
        assert_int_equal(opt_block_solver_factor(s, &sys, b, &retry, &e), SCAF_OK);
        assert_int_equal(opt_block_solver_solve(s, x, &e), SCAF_OK);
        for (int i = 0; i < n; i++) x[i] *= 2.0;
        assert_true(max_rel_diff(x, ref, n) < 1e-9);
        free(b);
        free(x);
        free(ref);
        opt_csc_free(&sys.A);
    }
    opt_block_solver_times t = opt_block_solver_get_times(s);
    assert_true(t.analysis > 0.0 && t.factor > 0.0 && t.solve >= 0.0);
    free(first);
    opt_block_solver_destroy(s);
}

/* Four vertices without couplings: vertex 0's block [1 1; 1 1 - 1e-8] is
 * indefinite (det -1e-8); the others are identities. */
static void indefinite_system(opt_proxy_system *sys)
{
    memset(sys, 0, sizeof *sys);
    int I[12], J[12], nt = 0;
    double V[12];
    for (int v = 0; v < 4; v++) {
        double a = 1, b = v == 0 ? 1 : 0, c = v == 0 ? 1 - 1e-8 : 1;
        I[nt] = 2 * v, J[nt] = 2 * v, V[nt++] = a;
        I[nt] = 2 * v, J[nt] = 2 * v + 1, V[nt++] = b;
        I[nt] = 2 * v + 1, J[nt] = 2 * v + 1, V[nt++] = c;
    }
    assert_int_equal(opt_csc_from_triplets(&sys->A, 8, nt, I, J, V, NULL), SCAF_OK);
    sys->d = 2;
    sys->nfree = 4;
}

static void regularizes_an_indefinite_system(void **state)
{
    (void)state;
    scaf_error e;
    const double b0[8] = {1, -1, 0.5, 2, -3, 1, 0.25, 4};
    /* positions X of 5 vertices; vertex 2 is fixed (dof -1) */
    const int dof[5] = {0, 1, -1, 2, 3};
    const double X[10] = {0.5, -0.25, 9, 9, 1, 2, -1, 0.75, 3, -2};
    for (int positions = 0; positions < 2; positions++) {
        opt_block_solver *s = opt_block_solver_create(2, 4, &e);
        assert_non_null(s);
        opt_proxy_system sys;
        indefinite_system(&sys);
        double b[8], x[8], ref[8], rb[8];
        memcpy(b, b0, sizeof b);
        assert_int_equal(opt_block_solver_update(s, &sys, &e), SCAF_OK);
        opt_block_retry none = {0, 0, NULL, NULL};
        assert_int_equal(opt_block_solver_factor(s, &sys, b, &none, &e), SCAF_ERR_NUMERIC);
        assert_int_equal(opt_block_solver_solve(s, x, &e), SCAF_ERR_USAGE);
        /* the reference: the system before the retries scale its diagonal */
        opt_proxy_system plain;
        indefinite_system(&plain);
        opt_block_retry retry = {1, 5, dof, positions ? X : NULL};
        assert_int_equal(opt_block_solver_factor(s, &sys, b, &retry, &e), SCAF_OK);
        assert_int_equal(opt_block_solver_solve(s, x, &e), SCAF_OK);
        double mu = 1e-10 * 1000.0; /* the second retry's: at 1e-10, det ~ 2 mu - 1e-8 < 0 */
        memcpy(rb, b0, sizeof rb);
        if (positions)
            for (int v = 0; v < 5; v++)
                for (int a = 0; dof[v] >= 0 && a < 2; a++) {
                    int c = 2 * dof[v] + a;
                    double dc = c == 1 ? 1 - 1e-8 : 1;
                    rb[c] += mu * dc * X[2 * v + a];
                }
        for (int i = 0; i < 8; i++) assert_true(b[i] == rb[i]); /* the rhs solved for */
        dense_solve(&plain.A, mu, rb, ref);
        assert_true(max_rel_diff(x, ref, 8) < 1e-6);
        opt_csc_free(&plain.A);
        opt_csc_free(&sys.A);
        opt_block_solver_destroy(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(solves_like_dense_over_changing_patterns),
        cmocka_unit_test(regularizes_an_indefinite_system),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
