/* Tests for opt/cholmod_solver and opt/csc: Laplacian systems solved to
 * 1e-10 relative residual, analysis reused for an unchanged pattern and
 * redone for a new one, relaxed supernodes, clear errors; factorizations
 * in two threads at once give the sequential answer and leave OpenMP's
 * process-wide max-active-levels as it was; the solver's own analysis and
 * kept solve workspaces give bit for bit the solutions of plain CHOLMOD
 * calls (with cholmod_factorize; with opt/supernodal_numeric, the same
 * to rounding). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#include <signal.h>

#include "base/interrupt.h"
#include "opt/block_symbolic.h"
#include "opt/cholmod_solver.h"
#include "opt/cholmod_view.h"
#include "opt/csc.h"
#include "rng.h"

/* Grid Laplacian of an m by m grid with Dirichlet boundary (5-point), plus
 * shift on the diagonal; extra != 0 adds one long-range coupling. */
static void grid_laplacian(opt_csc *A, int m, double shift, int extra)
{
    int n = m * m, cap = 5 * n + 2, nt = 0;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V);
    for (int y = 0; y < m; y++)
        for (int x = 0; x < m; x++) {
            int i = y * m + x;
            I[nt] = i;
            J[nt] = i;
            V[nt++] = 4 + shift;
            if (x + 1 < m) {
                I[nt] = i;
                J[nt] = i + 1;
                V[nt++] = -1;
            }
            if (y + 1 < m) {
                I[nt] = i + m;
                J[nt] = i;
                V[nt++] = -1;
            } /* lower triangle on purpose */
        }
    if (extra) {
        I[nt] = 0;
        J[nt] = n - 1;
        V[nt++] = -0.5;
        I[nt] = 0;
        J[nt] = 0;
        V[nt++] = 0.5;
    }
    assert_int_equal(opt_csc_from_triplets(A, n, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
}

/* p = a uniformly random permutation of 0..n-1 (Fisher-Yates). */
static void random_permutation(int *p, int n, rng *r)
{
    for (int i = 0; i < n; i++) p[i] = i;
    for (int i = n - 1; i > 0; i--) {
        int j = (int)rng_uniform(r, 0, i + 1);
        if (j > i) j = i;
        int t = p[i];
        p[i] = p[j];
        p[j] = t;
    }
}

static double rel_residual(const opt_csc *A, const double *x, const double *b)
{
    double *y = malloc(A->n * sizeof *y), num = 0, den = 0;
    opt_csc_symv(A, x, y);
    for (int i = 0; i < A->n; i++) {
        num += (y[i] - b[i]) * (y[i] - b[i]);
        den += b[i] * b[i];
    }
    free(y);
    return sqrt(num / den);
}

static void triplets_sum_duplicates(void **state)
{
    (void)state;
    int I[5] = {0, 1, 0, 2, 1}, J[5] = {0, 0, 1, 2, 0};
    double V[5] = {1, 2, 3, 4, 5};
    opt_csc A;
    assert_int_equal(opt_csc_from_triplets(&A, 3, 5, I, J, V, NULL), SCAF_OK);
    assert_int_equal(A.nnz, 3);
    assert_int_equal(A.colptr[1], 1);
    assert_int_equal(A.rowidx[1], 0); /* (1,0),(0,1),(1,0) all land at (0,1) */
    assert_true(A.val[1] == 10);
    opt_csc_free(&A);
    int bad[1] = {3};
    scaf_error e;
    assert_int_equal(opt_csc_from_triplets(&A, 3, 1, bad, J, V, &e), SCAF_ERR_USAGE);
}

static void solves_and_reuses_analysis(void **state)
{
    (void)state;
    const opt_ordering ords[3] = {OPT_ORDER_AMD, OPT_ORDER_METIS, OPT_ORDER_CHOLMOD_DEFAULT};
    rng r = {31};
    for (int o = 0; o < 3; o++) {
        opt_csc A;
        grid_laplacian(&A, 40, 0.0, 0);
        int n = A.n;
        double *b = malloc(2 * n * sizeof *b), *x = malloc(2 * n * sizeof *x);
        for (int i = 0; i < 2 * n; i++) b[i] = rng_uniform(&r, -1, 1);
        scaf_error e;
        opt_chol *c = opt_chol_create(ords[o], &e);
        assert_non_null(c);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_ERR_USAGE);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 2, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        assert_true(rel_residual(&A, x + n, b + n) < 1e-10);
        /* New values, same pattern: no new analysis. */
        for (int k = 0; k < A.nnz; k++) A.val[k] *= 1.5;
        for (int col = 0; col < n; col++) A.val[A.colptr[col + 1] - 1] += 0.25;
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        opt_chol_stats st = opt_chol_get_stats(c);
        assert_int_equal(st.analyses, 1);
        assert_int_equal(st.factorizations, 2);
        assert_true(st.nnz_L >= A.nnz);
        /* Reuse the permutation explicitly (cholmod_analyze_p). */
        int *perm = malloc(n * sizeof *perm);
        memcpy(perm, opt_chol_permutation(c), n * sizeof *perm);
        assert_int_equal(opt_chol_analyze_given(c, &A, perm, &e), SCAF_OK);
        assert_memory_equal(perm, opt_chol_permutation(c), n * sizeof *perm);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        assert_int_equal(opt_chol_get_stats(c).analyses, 2);
        free(perm);
        /* A different pattern: analyzed again automatically. */
        opt_csc B;
        grid_laplacian(&B, 40, 0.0, 1);
        assert_int_equal(opt_chol_factor(c, &B, &e), SCAF_OK);
        assert_int_equal(opt_chol_get_stats(c).analyses, 3);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&B, x, b) < 1e-10);
        opt_csc_free(&B);
        opt_chol_destroy(c);
        opt_csc_free(&A);
        free(b);
        free(x);
    }
}

/* A given permutation that is not postordered (random): the analysis
 * combines it with the etree's postorder; the factor solves, re-analyzing
 * with the resulting permutation reproduces it with the same fill and
 * flops, and a repeated index is reported, not trusted. */
static void given_random_permutation(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 30, 0.1, 1);
    int n = A.n;
    rng r = {7};
    int *perm = malloc(n * sizeof *perm), *seen = calloc(n, sizeof *seen);
    double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x);
    random_permutation(perm, n, &r);
    for (int i = 0; i < n; i++) b[i] = rng_uniform(&r, -1, 1);
    scaf_error e;
    for (int relax = 1; relax <= 4; relax += 3) {
        opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
        assert_non_null(c);
        opt_chol_set_relax(c, relax);
        assert_int_equal(opt_chol_analyze_given(c, &A, perm, &e), SCAF_OK);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        opt_chol_stats s1 = opt_chol_get_stats(c);
        memset(seen, 0, n * sizeof *seen);
        const int *lp = opt_chol_permutation(c);
        for (int i = 0; i < n; i++) {
            assert_true(lp[i] >= 0 && lp[i] < n);
            assert_int_equal(seen[lp[i]]++, 0);
        }
        int *post = malloc(n * sizeof *post);
        memcpy(post, lp, n * sizeof *post);
        assert_int_equal(opt_chol_analyze_given(c, &A, post, &e), SCAF_OK);
        assert_memory_equal(post, opt_chol_permutation(c), n * sizeof *post);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        opt_chol_stats s2 = opt_chol_get_stats(c);
        assert_true(s2.nnz_L == s1.nnz_L);
        assert_true(s2.flops == s1.flops);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        post[1] = post[0]; /* not a permutation */
        assert_int_not_equal(opt_chol_analyze_given(c, &A, post, &e), SCAF_OK);
        free(post);
        opt_chol_destroy(c);
    }
    opt_csc_free(&A);
    free(perm);
    free(seen);
    free(b);
    free(x);
}

/* The solution of plain CHOLMOD calls (cholmod_analyze_p with perm,
 * cholmod_factorize of the upper-stored A, cholmod_solve). */
static void plain_cholmod_solve(const opt_csc *A, const int *perm, int nrhs, const double *b,
                                double *x)
{
    cholmod_common cm;
    assert_true(cholmod_start(&cm));
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    cm.final_ll = 1;
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    cm.postorder = 1;
    cholmod_sparse S = opt_csc_cholmod_view(A);
    cholmod_factor *L = cholmod_analyze_p(&S, (int *)perm, NULL, 0, &cm);
    assert_non_null(L);
    assert_true(cholmod_factorize(&S, L, &cm));
    cholmod_dense B;
    memset(&B, 0, sizeof B);
    B.nrow = B.d = (size_t)A->n;
    B.ncol = (size_t)nrhs;
    B.nzmax = B.nrow * B.ncol;
    B.x = (void *)b;
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *X = cholmod_solve(CHOLMOD_A, L, &B, &cm);
    assert_non_null(X);
    memcpy(x, X->x, B.nzmax * sizeof *x);
    cholmod_free_dense(&X, &cm);
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
}

/* The solver analyses with its own passes (analyze_given_fast) and keeps
 * its solve workspaces: the solutions must be those of plain CHOLMOD bit
 * for bit, also after new values on the same pattern and with 1, 3, then
 * 1 right-hand sides. */
/* With cholmod_factorize: bit for bit; with opt/supernodal_numeric (its
 * own solve too): to rounding. */
/* opt_chol_factor_rhs: the solve of that right-hand side (forward sweep
 * done in the factorization) gives the bits of factor + solve; another
 * right-hand side (address), or the same one solved again, takes the whole
 * solve. */
static void factor_with_rhs(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 40, 0.1, 1);
    int n = A.n;
    double *b = malloc(n * sizeof *b), *b2 = malloc(n * sizeof *b2), *x = malloc(n * sizeof *x),
           *y = malloc(n * sizeof *y);
    rng r = {5};
    for (int i = 0; i < n; i++) {
        b[i] = rng_uniform(&r, -1, 1);
        b2[i] = b[i];
    }
    b2[n / 2] += 1.0;
    scaf_error e;
    opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
    assert_non_null(c);
    assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
    assert_int_equal(opt_chol_solve(c, 1, b, y, &e), SCAF_OK);
    assert_int_equal(opt_chol_factor_rhs(c, &A, b, &e), SCAF_OK);
    assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
    assert_memory_equal(x, y, n * sizeof *x);
    assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK); /* again: whole solve */
    assert_memory_equal(x, y, n * sizeof *x);
    assert_int_equal(opt_chol_solve(c, 1, b2, y, &e), SCAF_OK);
    assert_int_equal(opt_chol_factor_rhs(c, &A, b, &e), SCAF_OK);
    assert_int_equal(opt_chol_solve(c, 1, b2, x, &e), SCAF_OK); /* not b: whole solve */
    assert_memory_equal(x, y, n * sizeof *x);
    assert_int_equal(opt_chol_get_stats(c).analyses, 1);
    opt_chol_destroy(c);
    free(b);
    free(b2);
    free(x);
    free(y);
    opt_csc_free(&A);
}

static void same_bits_as_plain_cholmod(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 40, 0.1, 1);
    int n = A.n;
    int *perm = malloc(n * sizeof *perm);
    double *b = malloc(3 * n * sizeof *b), *x = malloc(3 * n * sizeof *x),
           *y = malloc(3 * n * sizeof *y);
    for (int numeric = 0; numeric < 2; numeric++) {
        rng r = {11};
        random_permutation(perm, n, &r);
        for (int i = 0; i < 3 * n; i++) b[i] = rng_uniform(&r, -1, 1);
        scaf_error e;
        opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
        assert_non_null(c);
        opt_chol_set_numeric(c, numeric ? OPT_NUMERIC_SUPERNODAL : OPT_NUMERIC_CHOLMOD);
        assert_int_equal(opt_chol_analyze_given(c, &A, perm, &e), SCAF_OK);
        static const int nrhs[3] = {1, 3, 1};
        for (int round = 0; round < 3; round++) {
            if (round > 0) /* new values, same pattern: factorization only */
                for (int q = 0; q < A.nnz; q++) A.val[q] *= 1.0 + 0.01 * rng_uniform(&r, 0, 1);
            assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
            assert_int_equal(opt_chol_solve(c, nrhs[round], b, x, &e), SCAF_OK);
            plain_cholmod_solve(&A, perm, nrhs[round], b, y);
            size_t m = (size_t)nrhs[round] * n;
            if (!numeric) {
                assert_memory_equal(x, y, m * sizeof *x);
            } else {
                double diff = 0, big = 0;
                for (size_t i = 0; i < m; i++) {
                    diff = fmax(diff, fabs(x[i] - y[i]));
                    big = fmax(big, fabs(y[i]));
                }
                assert_true(diff <= 1e-13 * big);
            }
        }
        assert_int_equal(opt_chol_get_stats(c).analyses, 1);
        opt_chol_destroy(c);
    }
    opt_csc_free(&A);
    free(perm);
    free(b);
    free(x);
    free(y);
}

/* kron(grid Laplacian, M) with M 2x2 SPD: interleaved 2-blocks, like the
 * SLIM systems. Ordering the vertex graph must still solve exactly and
 * keep each vertex's two unknowns together. */
static void block_ordering_solves(void **state)
{
    (void)state;
    opt_csc G;
    grid_laplacian(&G, 30, 0.1, 0);
    const double M[4] = {2, 0.5, 0.5, 1};
    int nt = 0, cap = 4 * G.nnz;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V);
    for (int c = 0; c < G.n; c++)
        for (int k = G.colptr[c]; k < G.colptr[c + 1]; k++)
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) {
                    int r = 2 * G.rowidx[k] + a, cc = 2 * c + b;
                    if (r > cc)
                        continue; /* upper part only (the diagonal block's lower entry is its mirror) */
                    I[nt] = r;
                    J[nt] = cc;
                    V[nt++] = G.val[k] * M[2 * a + b];
                }
    opt_csc A;
    assert_int_equal(opt_csc_from_triplets(&A, 2 * G.n, nt, I, J, V, NULL), SCAF_OK);
    rng r = {37};
    double *b = malloc(A.n * sizeof *b), *x = malloc(A.n * sizeof *x);
    for (int i = 0; i < A.n; i++) b[i] = rng_uniform(&r, -1, 1);
    const opt_ordering ords[2] = {OPT_ORDER_AMD, OPT_ORDER_METIS};
    for (int o = 0; o < 2; o++) {
        opt_chol *c = opt_chol_create(ords[o], NULL);
        opt_chol_set_block(c, 2);
        assert_int_equal(opt_chol_factor(c, &A, NULL), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, x, NULL), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-10);
        const int *p = opt_chol_permutation(c);
        for (int k = 0; k < G.n; k++) assert_int_equal(p[2 * k + 1], p[2 * k] + 1);
        opt_chol_destroy(c);
    }
    free(I);
    free(J);
    free(V);
    free(b);
    free(x);
    opt_csc_free(&A);
    opt_csc_free(&G);
}

/* Two coupled grid Laplacians in interleaved 2-blocks: unknown 2v is
 * vertex v's x, 2v+1 its y. The x part has every grid edge, the y part only
 * every other vertical one (so the last column of a group lacks row groups
 * the first has), and the two couple on the diagonal block (0.5). */
static void uneven_blocks(opt_csc *A, int m)
{
    opt_csc G;
    grid_laplacian(&G, m, 1.0, 0); /* diagonal 5: the 0.5 coupling keeps it definite */
    int cap = 3 * G.nnz, nt = 0;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V);
    for (int c = 0; c < G.n; c++)
        for (int k = G.colptr[c]; k < G.colptr[c + 1]; k++) {
            int r = G.rowidx[k];
            I[nt] = 2 * r;
            J[nt] = 2 * c;
            V[nt++] = G.val[k];
            if (r == c) {
                I[nt] = 2 * r;
                J[nt] = 2 * c + 1;
                V[nt++] = 0.5;
            }
            if (r == c || c - r != m || (c / m) % 2 == 0) {
                I[nt] = 2 * r + 1;
                J[nt] = 2 * c + 1;
                V[nt++] = G.val[k];
            }
        }
    assert_int_equal(opt_csc_from_triplets(A, 2 * G.n, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
    opt_csc_free(&G);
}

/* With blocks declared, the analysis runs on the vertex graph and is
 * expanded (opt/block_symbolic) whenever the permutation keeps blocks
 * together: computed, given by blocks, and on a pattern whose blocks are
 * not full; the solutions agree with plain CHOLMOD's to rounding. A
 * permutation that splits a block gets the scalar analysis. */
static void block_symbolic_analysis(void **state)
{
    (void)state;
    opt_csc A;
    uneven_blocks(&A, 24);
    int n = A.n, nb = n / 2;
    rng r = {53};
    int *vperm = malloc(nb * sizeof *vperm), *perm = malloc(n * sizeof *perm);
    double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    for (int i = 0; i < n; i++) b[i] = rng_uniform(&r, -1, 1);
    random_permutation(vperm, nb, &r);
    scaf_error e;
    for (int variant = 0; variant < 3; variant++) {
        /* 0: the solver's own ordering, 1: given by blocks, 2: split */
        for (int k = 0; k < nb; k++) {
            perm[2 * k] = 2 * vperm[k] + (variant == 2 && k % 7 == 3);
            perm[2 * k + 1] = 2 * vperm[k] + !(variant == 2 && k % 7 == 3);
        }
        opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
        assert_non_null(c);
        opt_chol_set_block(c, 2);
        opt_chol_set_relax(c, 4);
        assert_int_equal(opt_chol_analyze_given(c, &A, variant ? perm : NULL, &e), SCAF_OK);
        assert_int_equal(opt_chol_get_stats(c).block_analyses, variant == 2 ? 0 : 1);
        for (int round = 0; round < 2; round++) {
            assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
            assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
            assert_true(rel_residual(&A, x, b) < 1e-12);
            plain_cholmod_solve(&A, opt_chol_permutation(c), 1, b, y);
            double num = 0, den = 0;
            for (int i = 0; i < n; i++) {
                num += (x[i] - y[i]) * (x[i] - y[i]);
                den += y[i] * y[i];
            }
            assert_true(sqrt(num / den) < 1e-12);
            for (int q = 0; q < A.nnz; q++) A.val[q] *= 1.0 + 0.01 * rng_uniform(&r, 0, 1);
        }
        assert_int_equal(opt_chol_get_stats(c).analyses, 1);
        opt_chol_destroy(c);
    }
    opt_csc_free(&A);
    free(vperm);
    free(perm);
    free(b);
    free(x);
    free(y);
}

/* kron(Laplacian of a vertex graph + I, M) with M 2x2 SPD: the edges
 * (ea[e], eb[e]) between nvtx vertices, unknowns interleaved by vertex. */
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
                    if (2 * u + a > 2 * v + b) continue; /* upper */
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

/* A fixed part (two separate grids: two roots) in a fixed order and a
 * variable part whose size and couplings change every round: with the
 * fixed part declared, every analysis reuses the fixed part's (the split
 * counter) and every factorization after the first the placement of the
 * fixed part's entries (the kept counter), the solutions agree with plain
 * CHOLMOD's on the same permutation to rounding and, bit for bit, with a
 * solver that sees the pattern for the first time; a permutation whose
 * variable part is not in natural order gets the whole analysis; a new
 * entry of A in the fixed part (round 4) places its entries anew; the
 * analysis given A's vertex pattern (odd rounds) is the one that
 * compresses A itself. */
static void split_symbolic_analysis(void **state)
{
    (void)state;
    const int m = 14, nf = 2 * m * m;
    rng r = {71};
    int cap = 4 * nf + 400;
    int *ea = malloc(cap * sizeof *ea), *eb = malloc(cap * sizeof *eb);
    int *fperm = malloc(nf * sizeof *fperm);
    random_permutation(fperm, nf, &r);
    scaf_error e;
    opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
    assert_non_null(c);
    opt_chol_set_block(c, 2);
    opt_chol_set_relax(c, 4);
    opt_chol_set_fixed_part(c, 2 * nf);
    /* the last two fixed vertices of one grid in the order: an edge
     * between them falls in the factor's pattern already (their columns
     * end the grid's elimination), so only A's pattern tells it */
    int last = fperm[nf - 1], prev = nf - 2;
    while (fperm[prev] / (m * m) != last / (m * m)) prev--;
    prev = fperm[prev];
    for (int round = 0; round < 6; round++) {
        int ne = 0, nw = 20 + 7 * round, nv = nf + nw;
        if (round >= 4) ea[ne] = prev, eb[ne++] = last;
        for (int g = 0; g < 2; g++)
            for (int y = 0; y < m; y++)
                for (int x = 0; x < m; x++) {
                    int v = g * m * m + y * m + x;
                    if (x + 1 < m) ea[ne] = v, eb[ne++] = v + 1;
                    if (y + 1 < m) ea[ne] = v, eb[ne++] = v + m;
                }
        for (int j = 0; j < nw; j++) {
            int J = nf + j;
            if (j % 5 != 4) /* a few variable vertices touch no fixed one */
                for (int k = 0; k < 3; k++) {
                    int f = (int)rng_uniform(&r, 0, nf);
                    ea[ne] = f < nf ? f : nf - 1;
                    eb[ne++] = J;
                }
            if (j > 0) ea[ne] = J - 1, eb[ne++] = J;
        }
        opt_csc A;
        block_laplacian(&A, nv, ne, ea, eb);
        int n = A.n, *perm = malloc(n * sizeof *perm);
        double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        for (int k = 0; k < nv; k++) {
            int v = k < nf ? fperm[k] : (round == 3 ? nv - 1 - (k - nf) : k);
            perm[2 * k] = 2 * v;
            perm[2 * k + 1] = 2 * v + 1;
        }
        for (int i = 0; i < n; i++) b[i] = rng_uniform(&r, -1, 1);
        opt_chol_stats s0 = opt_chol_get_stats(c);
        /* odd rounds: A's vertex pattern handed in (what opt/proxy_system
         * keeps), which must give the same analysis, bit for bit */
        int *vcp = NULL, *vri = NULL;
        if (round % 2) assert_true(opt_block_graph(&A, 2, &vcp, &vri));
        assert_int_equal(opt_chol_analyze_vertices(c, &A, vcp, vri, perm, &e), SCAF_OK);
        free(vcp);
        free(vri);
        opt_chol_stats s1 = opt_chol_get_stats(c);
        assert_int_equal(s1.split_analyses - s0.split_analyses, round == 3 ? 0 : 1);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        int kept = opt_chol_get_stats(c).kept_scatters - s1.kept_scatters;
        if (round != 3) assert_int_equal(kept, round == 0 || round == 4 ? 0 : 1);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        assert_true(rel_residual(&A, x, b) < 1e-12);
        opt_chol *fresh = opt_chol_create(OPT_ORDER_AMD, &e);
        opt_chol_set_block(fresh, 2);
        opt_chol_set_relax(fresh, 4);
        opt_chol_set_fixed_part(fresh, 2 * nf);
        assert_int_equal(opt_chol_analyze_given(fresh, &A, perm, &e), SCAF_OK);
        assert_int_equal(opt_chol_factor(fresh, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_get_stats(fresh).kept_scatters, 0);
        assert_int_equal(opt_chol_solve(fresh, 1, b, y, &e), SCAF_OK);
        assert_memory_equal(x, y, n * sizeof *x);
        opt_chol_destroy(fresh);
        const int *lp = opt_chol_permutation(c);
        if (round != 3) /* the fixed unknowns first */
            for (int k = 0; k < 2 * nf; k++) assert_true(lp[k] < 2 * nf);
        plain_cholmod_solve(&A, lp, 1, b, y);
        double num = 0, den = 0;
        for (int i = 0; i < n; i++) {
            num += (x[i] - y[i]) * (x[i] - y[i]);
            den += y[i] * y[i];
        }
        assert_true(sqrt(num / den) < 1e-12);
        free(perm);
        free(b);
        free(x);
        free(y);
        opt_csc_free(&A);
    }
    opt_chol_destroy(c);
    free(ea);
    free(eb);
    free(fperm);
}

/* opt_chol_factor_vertices keeps and compares the pattern by vertices:
 * the same vertex pattern is not analysed again, a changed one is (and
 * its unchanged fixed part keeps its scatter), opt_chol_factor on the
 * same scalar A reuses that analysis, and every solve is the bits of a
 * fresh solver's. opt_csc_is_vertex_expansion tells a one-row change. */
static void factor_by_vertex_pattern(void **state)
{
    (void)state;
    const int m = 9, nf = m * m;
    scaf_error e;
    opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
    assert_non_null(c);
    opt_chol_set_block(c, 2);
    opt_chol_set_fixed_part(c, 2 * nf);
    int cap = 4 * nf + 64, *ea = malloc(cap * sizeof *ea), *eb = malloc(cap * sizeof *eb);
    rng r = {5};
    /* rounds 0, 1: one pattern; 2: another variable part; 3: round 2's A
     * through opt_chol_factor_rhs; 4: the fixed part changes */
    const int analysed[5] = {1, 0, 1, 0, 1}, kept[5] = {0, 0, 1, 0, 0};
    for (int round = 0; round < 5; round++) {
        int nw = round < 2 ? 6 : 9, nv = nf + nw, ne = 0;
        for (int y = 0; y < m; y++)
            for (int x = 0; x < m; x++) {
                int v = y * m + x;
                if (x + 1 < m) ea[ne] = v, eb[ne++] = v + 1;
                if (y + 1 < m) ea[ne] = v, eb[ne++] = v + m;
            }
        if (round == 4) ea[ne] = 0, eb[ne++] = nf - 1;
        for (int j = 0; j < nw; j++) {
            ea[ne] = (j * 7) % nf, eb[ne++] = nf + j;
            if (j > 0) ea[ne] = nf + j - 1, eb[ne++] = nf + j;
        }
        opt_csc A;
        block_laplacian(&A, nv, ne, ea, eb);
        int *vcp = NULL, *vri = NULL, n = A.n;
        assert_true(opt_block_graph(&A, 2, &vcp, &vri));
        assert_true(opt_csc_is_vertex_expansion(&A, 2, nv, vcp, vri));
        int *perm = malloc(n * sizeof *perm);
        for (int k = 0; k < n; k++) perm[k] = k;
        double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        for (int i = 0; i < n; i++) b[i] = rng_uniform(&r, -1, 1);
        opt_chol_stats s0 = opt_chol_get_stats(c);
        if (round == 3) assert_true(opt_chol_pattern_matches(c, &A));
        assert_int_equal(round == 3 ? opt_chol_factor_rhs(c, &A, b, &e)
                                    : opt_chol_factor_vertices(c, &A, vcp, vri, perm, b, &e),
                         SCAF_OK);
        opt_chol_stats s1 = opt_chol_get_stats(c);
        assert_int_equal(s1.analyses - s0.analyses, analysed[round]);
        assert_int_equal(s1.kept_scatters - s0.kept_scatters, kept[round]);
        assert_true(opt_chol_pattern_matches(c, &A));
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        opt_chol *fresh = opt_chol_create(OPT_ORDER_AMD, &e);
        opt_chol_set_block(fresh, 2);
        opt_chol_set_fixed_part(fresh, 2 * nf);
        assert_int_equal(opt_chol_analyze_given(fresh, &A, perm, &e), SCAF_OK);
        assert_int_equal(opt_chol_factor(fresh, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(fresh, 1, b, y, &e), SCAF_OK);
        assert_memory_equal(x, y, n * sizeof *x);
        opt_chol_destroy(fresh);
        /* one scalar row moved: not the expansion, nor the kept pattern */
        int last = A.nnz - 1, keep = A.rowidx[last - 1];
        A.rowidx[last - 1] = keep - 1;
        assert_false(opt_csc_is_vertex_expansion(&A, 2, nv, vcp, vri));
        assert_false(opt_chol_pattern_matches(c, &A));
        A.rowidx[last - 1] = keep;
        free(vcp);
        free(vri);
        free(perm);
        free(b);
        free(x);
        free(y);
        opt_csc_free(&A);
    }
    opt_chol_destroy(c);
    free(ea);
    free(eb);
}

/* libgomp, when loaded (through CHOLMOD): the solver must leave it as it
 * found it. */
extern int omp_get_max_active_levels(void) __attribute__((weak));
extern void omp_set_max_active_levels(int) __attribute__((weak));

/* Looser supernode amalgamation (more explicit zeros) still solves to the
 * same accuracy and agrees with the default relaxation; the OpenMP level
 * the solver lowers around CHOLMOD is restored. */
static void relaxed_supernodes_solve(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 60, 0.01, 1);
    rng r = {11};
    double *b = malloc(A.n * sizeof *b), *x0 = malloc(A.n * sizeof *x0),
           *x1 = malloc(A.n * sizeof *x1);
    for (int i = 0; i < A.n; i++) b[i] = rng_uniform(&r, -1, 1);
    int lv = omp_get_max_active_levels ? omp_get_max_active_levels() : -1;
    if (lv >= 0) omp_set_max_active_levels(3); /* a value the solver must not keep */
    for (int scale = 1; scale <= 8; scale *= 2) {
        opt_chol *c = opt_chol_create(OPT_ORDER_METIS, NULL);
        opt_chol_set_relax(c, scale);
        assert_int_equal(opt_chol_factor(c, &A, NULL), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, scale == 1 ? x0 : x1, NULL), SCAF_OK);
        assert_true(rel_residual(&A, scale == 1 ? x0 : x1, b) < 1e-10);
        if (scale > 1)
            for (int i = 0; i < A.n; i++)
                assert_true(fabs(x1[i] - x0[i]) <= 1e-8 * (1 + fabs(x0[i])));
        if (lv >= 0) assert_int_equal(omp_get_max_active_levels(), 3);
        opt_chol_destroy(c);
    }
    if (lv >= 0) omp_set_max_active_levels(lv);
    free(b);
    free(x0);
    free(x1);
    opt_csc_free(&A);
}

/* The layout check the assert()s use: built matrices pass, a column with
 * rows out of order or a row below the diagonal does not. */
static void upper_sorted_layout(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 4, 0.0, 1);
    assert_true(opt_csc_is_upper_sorted(&A));
    int c = 5, lo = A.colptr[c], hi = A.colptr[c + 1];
    assert_true(hi - lo >= 2);
    int t = A.rowidx[lo];
    A.rowidx[lo] = A.rowidx[lo + 1];
    A.rowidx[lo + 1] = t;
    assert_false(opt_csc_is_upper_sorted(&A));
    A.rowidx[lo + 1] = A.rowidx[lo];
    A.rowidx[lo] = t;
    assert_true(opt_csc_is_upper_sorted(&A));
    int keep = A.rowidx[hi - 1];
    A.rowidx[hi - 1] = c + 1; /* below the diagonal */
    assert_false(opt_csc_is_upper_sorted(&A));
    A.rowidx[hi - 1] = keep;
    A.colptr[A.n] = A.nnz + 1;
    assert_false(opt_csc_is_upper_sorted(&A));
    A.colptr[A.n] = A.nnz;
    opt_csc_free(&A);
}

static void indefinite_is_an_error(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 6, -8.0, 0); /* diagonal -4: negative definite */
    scaf_error e;
    opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
    long total = opt_chol_not_posdef_total();
    assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_ERR_NUMERIC);
    assert_non_null(strstr(e.message, "positive definite"));
    assert_int_equal(opt_chol_not_posdef_total(), total + 1);
    /* counted apart from the successful factorizations */
    assert_int_equal(opt_chol_get_stats(c).not_posdef, 1);
    assert_int_equal(opt_chol_get_stats(c).factorizations, 0);
    double b[36] = {0}, x[36];
    assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_ERR_USAGE);
    /* the same pattern made definite again factors, and is not counted */
    opt_csc_free(&A);
    grid_laplacian(&A, 6, 0.0, 0);
    assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
    assert_int_equal(opt_chol_get_stats(c).not_posdef, 1);
    assert_int_equal(opt_chol_get_stats(c).factorizations, 1);
    opt_chol_destroy(c);
    opt_csc_free(&A);
    opt_csc empty = {0};
    c = opt_chol_create(OPT_ORDER_AMD, &e);
    assert_int_equal(opt_chol_factor(c, &empty, &e), SCAF_ERR_USAGE);
    opt_chol_destroy(c);
}

/* ---- issue 29: a size the solver cannot index is a limit, said with the
 * numbers before any work (it was "CHOLMOD analysis failed: problem too
 * large", exit 6, after 43 s and 5.4 GB); the analysis stops at a pending
 * SIGINT / SIGTERM (base/interrupt) --------------------------------------- */
static void too_large_is_a_limit_and_signals_stop_the_analysis(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    assert_int_equal(opt_chol_size_check(6e6, 2147483647.0, &e), SCAF_OK);
    assert_int_equal(opt_chol_size_check(6e6, 3e9, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message,
                           "too large for the solver: 6000000 unknowns and "
                           "3000000000 matrix entries"));
    assert_non_null(strstr(e.message, "2147483647"));
    assert_int_equal(opt_chol_size_check(3e9, 10.0, &e), SCAF_ERR_MESH);
    opt_csc A;
    grid_laplacian(&A, 6, 0.0, 0);
    opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
    interrupt_clear();
    interrupt_request(SIGTERM);
    assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_ERR_CANCELLED);
    assert_non_null(strstr(e.message, "interrupted by SIGTERM while analysing"));
    assert_int_equal(opt_chol_get_stats(c).analyses, 0);
    interrupt_clear();
    assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
    opt_chol_destroy(c);
    opt_csc_free(&A);
}

/* ---- two threads factoring at once ---------------------------------- */

extern int omp_get_max_active_levels(void) __attribute__((weak));

typedef struct factor_job {
    const opt_csc *A;
    const double *b;
    double *x;
    int rounds;
    int ok;
} factor_job;

static void *factor_rounds(void *arg)
{
    factor_job *j = arg;
    scaf_error e;
    j->ok = 1;
    for (int r = 0; r < j->rounds && j->ok; r++) {
        opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &e);
        if (!c || opt_chol_factor(c, j->A, &e) != SCAF_OK ||
            opt_chol_solve(c, 1, j->b, j->x, &e) != SCAF_OK)
            j->ok = 0;
        opt_chol_destroy(c);
    }
    return NULL;
}

static void concurrent_factorizations(void **state)
{
    (void)state;
    opt_csc A;
    grid_laplacian(&A, 60, 0.1, 1);
    int n = A.n;
    double *b = malloc(n * sizeof *b), *x0 = malloc(n * sizeof *x0);
    for (int i = 0; i < n; i++) b[i] = sin(0.1 * i);
    /* the sequential answer */
    factor_job seq = {&A, b, x0, 1, 0};
    factor_rounds(&seq);
    assert_true(seq.ok);
    int before = omp_get_max_active_levels ? omp_get_max_active_levels() : -1;
    enum { NT = 2 };
    factor_job jobs[NT];
    pthread_t t[NT];
    double *x[NT];
    for (int k = 0; k < NT; k++) {
        x[k] = malloc(n * sizeof *x[k]);
        jobs[k] = (factor_job){&A, b, x[k], 40, 0};
        assert_int_equal(pthread_create(&t[k], NULL, factor_rounds, &jobs[k]), 0);
    }
    for (int k = 0; k < NT; k++) {
        assert_int_equal(pthread_join(t[k], NULL), 0);
        assert_true(jobs[k].ok);
        assert_memory_equal(x[k], x0, n * sizeof *x0); /* bit for bit */
        free(x[k]);
    }
    /* the level is the calling thread's (OpenMP 5): untouched here */
    if (omp_get_max_active_levels) assert_int_equal(omp_get_max_active_levels(), before);
    free(b);
    free(x0);
    opt_csc_free(&A);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(triplets_sum_duplicates),
        cmocka_unit_test(solves_and_reuses_analysis),
        cmocka_unit_test(given_random_permutation),
        cmocka_unit_test(same_bits_as_plain_cholmod),
        cmocka_unit_test(factor_with_rhs),
        cmocka_unit_test(block_ordering_solves),
        cmocka_unit_test(relaxed_supernodes_solve),
        cmocka_unit_test(upper_sorted_layout),
        cmocka_unit_test(indefinite_is_an_error),
        cmocka_unit_test(concurrent_factorizations),
        cmocka_unit_test(block_symbolic_analysis),
        cmocka_unit_test(split_symbolic_analysis),
        cmocka_unit_test(factor_by_vertex_pattern),
        cmocka_unit_test(too_large_is_a_limit_and_signals_stop_the_analysis),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
