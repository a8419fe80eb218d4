/* Tests for opt/supernodal_numeric: on CHOLMOD's own symbolic factors
 * (METIS and AMD orderings, relaxed supernodes), one, two and three
 * bins (the tree cut, the supernodes above the cut shared)
 * give cholmod_factorize's factor to rounding, the same bits at every
 * repetition and for one, two or three threads working a plan's bins,
 * and the plan's solves agree with
 * cholmod_solve to rounding; a matrix that is not positive
 * definite (a negative or zero diagonal) is reported at the column where
 * CHOLMOD reports it; and opt_chol solves with the factor. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include <cholmod.h>

#include "base/parallel.h"
#include "opt/cholmod_solver.h"
#include "opt/cholmod_view.h"
#include "opt/csc.h"
#include "opt/supernodal_numeric.h"
#include "opt/supernodal_solve.h"

/* 2D grid of m x m vertices, two unknowns per vertex coupled as in a SLIM
 * system (2x2 blocks), 8-neighbour stencil, diagonal shift. */
static void block_grid(opt_csc *A, int m, double shift)
{
    int nv = m * m, cap = 4 * 9 * nv, nt = 0;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V);
    for (int y = 0; y < m; y++)
        for (int x = 0; x < m; x++) {
            int v = y * m + x;
            for (int dy = 0; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    if (dy == 0 && dx < 0) continue;
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || xx >= m || yy >= m) continue;
                    int u = yy * m + xx;
                    for (int a = 0; a < 2; a++)
                        for (int b = 0; b < 2; b++) {
                            double w;
                            if (u == v) w = a == b ? 14.0 + shift + 0.01 * (v % 7) : 0.3;
                            else w = a == b ? -1.0 : -0.2 * (dx + 2);
                            if (u == v && b < a) continue;
                            I[nt] = 2 * v + a;
                            J[nt] = 2 * u + b;
                            V[nt++] = w;
                        }
                }
        }
    assert_int_equal(opt_csc_from_triplets(A, 2 * nv, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
}

typedef struct fixture {
    cholmod_common cm;
    opt_csc A;
    cholmod_factor *S;   /* symbolic */
    cholmod_factor *ref; /* cholmod_factorize's */
} fixture;

static void setup_fixture(fixture *f, int m, int ordering, int relax)
{
    cholmod_start(&f->cm);
    f->cm.print = 0;
    f->cm.supernodal = CHOLMOD_SUPERNODAL;
    f->cm.final_ll = 1;
    f->cm.nmethods = 1;
    f->cm.method[0].ordering = ordering;
    f->cm.postorder = 1;
    for (int k = 0; k < 3; k++) f->cm.nrelax[k] *= (size_t)relax;
    block_grid(&f->A, m, 0.0);
    cholmod_sparse Sv = opt_csc_cholmod_view(&f->A);
    f->S = cholmod_analyze(&Sv, &f->cm);
    assert_non_null(f->S);
    f->ref = cholmod_copy_factor(f->S, &f->cm);
    assert_true(cholmod_factorize(&Sv, f->ref, &f->cm));
    assert_int_equal(f->ref->minor, f->ref->n);
}

static void teardown_fixture(fixture *f)
{
    cholmod_free_factor(&f->S, &f->cm);
    cholmod_free_factor(&f->ref, &f->cm);
    cholmod_finish(&f->cm);
    opt_csc_free(&f->A);
}

/* Solve with the plan (two right-hand sides, in place) and compare with
 * cholmod_solve on CHOLMOD's factor. */
static void check_solve(fixture *f, opt_snum *P, const cholmod_factor *L)
{
    int n = f->A.n;
    cholmod_dense *B = cholmod_zeros((size_t)n, 2, CHOLMOD_REAL, &f->cm);
    double *b = B->x, *x = malloc(2 * (size_t)n * sizeof *x);
    for (int i = 0; i < 2 * n; i++) b[i] = x[i] = sin(0.7 * i) + (i % 5);
    opt_snum_solve(P, L, 2, x, x);
    cholmod_dense *Y = cholmod_solve(CHOLMOD_A, f->ref, B, &f->cm);
    const double *y = Y->x;
    double diff = 0, big = 0;
    for (int i = 0; i < 2 * n; i++) {
        diff = fmax(diff, fabs(x[i] - y[i]));
        big = fmax(big, fabs(y[i]));
    }
    assert_true(diff <= 1e-12 * big);
    cholmod_free_dense(&B, &f->cm);
    cholmod_free_dense(&Y, &f->cm);
    free(x);
}

/* A numeric copy of the symbolic factor, factored by a plan of B bins in
 * T threads (and, when positive definite, solved with); returns the
 * plan's result, the factor in *out. */
/* >= 0: the plan's diag_share_min for own_factor (0: every column block
 * of a shared diagonal block splits its rows between the threads, which
 * the default threshold leaves to larger factors than these grids). */
static double diag_share_min = -1;

static int own_factor_in(fixture *f, const opt_csc *A, int B, int T, cholmod_factor **out,
                         opt_snum_shape *shape)
{
    cholmod_factor *L = cholmod_copy_factor(f->S, &f->cm);
    assert_true(cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, L, &f->cm));
    par_set_threads(T);
    opt_snum *P = opt_snum_create(L, A, B);
    assert_non_null(P);
    if (diag_share_min >= 0) P->diag_share_min = diag_share_min;
    if (shape) *shape = opt_snum_get_shape(P);
    int r = opt_snum_factor(P, A, L);
    if (r < 0 && A == &f->A) check_solve(f, P, L);
    opt_snum_destroy(P);
    par_set_threads(1);
    *out = L;
    return r;
}

/* B bins in as many threads. */
static int own_factor(fixture *f, const opt_csc *A, int B, cholmod_factor **out,
                      opt_snum_shape *shape)
{
    return own_factor_in(f, A, B, B, out, shape);
}

static double max_rel_diff(const cholmod_factor *a, const cholmod_factor *b)
{
    const double *x = a->x, *y = b->x;
    double big = 0, diff = 0;
    for (size_t k = 0; k < a->xsize; k++) {
        if (fabs(y[k]) > big) big = fabs(y[k]);
        if (fabs(x[k] - y[k]) > diff) diff = fabs(x[k] - y[k]);
    }
    return diff / big;
}

static void check_against_cholmod(int m, int ordering, int relax)
{
    fixture f;
    setup_fixture(&f, m, ordering, relax);
    size_t bytes = f.ref->xsize * sizeof(double);
    cholmod_factor *L1;
    assert_int_equal(own_factor(&f, &f.A, 1, &L1, NULL), -1);
    assert_int_equal(L1->minor, L1->n);
    assert_int_equal(L1->xsize, f.ref->xsize);
    assert_true(max_rel_diff(L1, f.ref) < 1e-12);
    for (int T = 2; T <= 3; T++) {
        cholmod_factor *La, *Lb;
        opt_snum_shape sh;
        assert_int_equal(own_factor(&f, &f.A, T, &La, &sh), -1);
        assert_int_equal(sh.bins, T); /* the tree was cut */
        assert_true(sh.in_bins > 0 && sh.above > 0 && sh.in_bins + sh.above == sh.supernodes);
        assert_true(max_rel_diff(La, f.ref) < 1e-12);
        assert_int_equal(own_factor(&f, &f.A, T, &Lb, NULL), -1);
        assert_memory_equal(La->x, Lb->x, bytes); /* same bits every time */
        cholmod_free_factor(&La, &f.cm);
        cholmod_free_factor(&Lb, &f.cm);
    }
    cholmod_factor *L1b;
    assert_int_equal(own_factor(&f, &f.A, 1, &L1b, NULL), -1);
    assert_memory_equal(L1->x, L1b->x, bytes);
    cholmod_free_factor(&L1, &f.cm);
    cholmod_free_factor(&L1b, &f.cm);
    teardown_fixture(&f);
}

static void equals_cholmod_metis(void **state)
{
    (void)state;
    check_against_cholmod(40, CHOLMOD_METIS, 1);
}

static void equals_cholmod_amd_relaxed(void **state)
{
    (void)state;
    check_against_cholmod(30, CHOLMOD_AMD, 4);
}

/* A grid large enough for supernodes above the cut to be shared by the
 * threads (their columns split between them, their rows below too), and
 * again with every column block of their diagonal blocks split between
 * the threads: CHOLMOD's factor to rounding, the same bits twice. */
static void shared_supernodes_above_the_cut(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f, 110, CHOLMOD_METIS, 2);
    size_t bytes = f.ref->xsize * sizeof(double);
    for (int split = 0; split <= 1; split++)
        for (int T = 2; T <= 3; T++) {
            diag_share_min = split ? 0 : -1;
            cholmod_factor *L, *L2;
            opt_snum_shape sh;
            assert_int_equal(own_factor(&f, &f.A, T, &L, &sh), -1);
            assert_true(sh.above_parallel > 0);
            assert_true(max_rel_diff(L, f.ref) < 1e-12);
            assert_int_equal(own_factor(&f, &f.A, T, &L2, NULL), -1);
            assert_memory_equal(L->x, L2->x, bytes);
            cholmod_free_factor(&L, &f.cm);
            cholmod_free_factor(&L2, &f.cm);
        }
    diag_share_min = -1;
    teardown_fixture(&f);
}

/* A plan's bins (and the shares of the supernodes above the cut, their
 * diagonal blocks' rows split too) worked by one, two or three threads:
 * the same factor and the same solve, bit for bit, so the thread count
 * never changes a result. */
static void same_bits_for_any_thread_count(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f, 110, CHOLMOD_METIS, 2);
    int n = f.A.n;
    size_t bytes = f.ref->xsize * sizeof(double);
    double *b = malloc((size_t)n * sizeof *b), *x[3];
    for (int i = 0; i < n; i++) b[i] = sin(0.7 * i) + (i % 5);
    for (int split = 0; split <= 1; split++) {
        diag_share_min = split ? 0 : -1;
        cholmod_factor *L[3];
        for (int T = 1; T <= 3; T++) {
            opt_snum_shape sh;
            assert_int_equal(own_factor_in(&f, &f.A, OPT_SNUM_BINS, T, &L[T - 1], &sh), -1);
            assert_int_equal(sh.bins, OPT_SNUM_BINS);
            assert_true(sh.above_parallel > 0);
            x[T - 1] = malloc((size_t)n * sizeof *x[T - 1]);
            par_set_threads(T);
            opt_snum *P = opt_snum_create(L[T - 1], &f.A, OPT_SNUM_BINS);
            assert_non_null(P);
            assert_int_equal(opt_snum_factor_forward(P, &f.A, L[T - 1], b), -1);
            opt_snum_backward(P, L[T - 1], x[T - 1]);
            opt_snum_destroy(P);
            par_set_threads(1);
        }
        for (int T = 2; T <= 3; T++) {
            assert_memory_equal(L[0]->x, L[T - 1]->x, bytes);
            assert_memory_equal(x[0], x[T - 1], (size_t)n * sizeof *b);
        }
        for (int T = 1; T <= 3; T++) {
            cholmod_free_factor(&L[T - 1], &f.cm);
            free(x[T - 1]);
        }
    }
    diag_share_min = -1;
    free(b);
    teardown_fixture(&f);
}

/* Original unknown k's diagonal made bad: every thread count reports the
 * column (in the factor's order) where CHOLMOD's factorization stops. */
static void not_positive_definite_where_cholmod_says(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f, 40, CHOLMOD_METIS, 1);
    const int *perm = f.S->Perm;
    int n = f.A.n;
    for (int trial = 0; trial < 3; trial++) {
        int k = trial == 0 ? perm[n / 3] : trial == 1 ? perm[n - 1] : perm[5];
        opt_csc B = f.A;
        B.val = malloc(f.A.nnz * sizeof *B.val);
        memcpy(B.val, f.A.val, f.A.nnz * sizeof *B.val);
        int diag = f.A.colptr[k + 1] - 1; /* rows ascending: the diagonal is last */
        assert_int_equal(f.A.rowidx[diag], k);
        B.val[diag] = trial == 2 ? 0.0 : -1.0;
        cholmod_factor *C = cholmod_copy_factor(f.S, &f.cm);
        cholmod_sparse Bv = opt_csc_cholmod_view(&B);
        cholmod_factorize(&Bv, C, &f.cm);
        assert_true(C->minor < C->n);
        if (trial == 1) { /* the last column: deep in a wide supernode's diagonal block,
                             past its first column blocks (opt/supernodal_numeric) */
            const int *super = f.S->super;
            int sn = 0;
            while (super[sn + 1] <= (int)C->minor) sn++;
            assert_true((int)C->minor - super[sn] >= 32);
        }
        for (int run = 0; run < 6; run++) { /* 1-3 threads; the rows split or not */
            int T = 1 + run % 3;
            diag_share_min = run < 3 ? -1 : 0;
            cholmod_factor *L;
            int r = own_factor(&f, &B, T, &L, NULL);
            assert_int_equal(r, (int)C->minor);
            assert_int_equal(L->minor, C->minor);
            cholmod_free_factor(&L, &f.cm);
        }
        diag_share_min = -1;
        cholmod_free_factor(&C, &f.cm);
        free(B.val);
    }
    teardown_fixture(&f);
}

/* The forward sweep run inside the factorization, then the backward one:
 * the same bits as the factorization followed by the whole solve, at 1, 2
 * and 3 threads (a tree cut, shared supernodes above it). */
static void forward_sweep_in_the_factorization(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f, 110, CHOLMOD_METIS, 2);
    int n = f.A.n;
    double *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x),
           *z = malloc((size_t)n * sizeof *z);
    for (int i = 0; i < n; i++) b[i] = sin(0.3 * i) + (i % 7);
    for (int T = 1; T <= 3; T++) {
        cholmod_factor *L = cholmod_copy_factor(f.S, &f.cm);
        assert_true(cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, L, &f.cm));
        par_set_threads(T);
        opt_snum *P = opt_snum_create(L, &f.A, T);
        assert_non_null(P);
        assert_int_equal(opt_snum_get_shape(P).bins, T);
        assert_int_equal(opt_snum_factor(P, &f.A, L), -1);
        opt_snum_solve(P, L, 1, b, x);
        for (int i = 0; i < n; i++) z[i] = -1.0;
        assert_int_equal(opt_snum_factor_forward(P, &f.A, L, b), -1);
        opt_snum_backward(P, L, z);
        assert_memory_equal(x, z, (size_t)n * sizeof *x);
        opt_snum_destroy(P);
        cholmod_free_factor(&L, &f.cm);
    }
    par_set_threads(1);
    free(b);
    free(x);
    free(z);
    teardown_fixture(&f);
}

/* Through opt_chol: solves to the residual of CHOLMOD's own factor, in one
 * and in two threads; a bad matrix is an error. */
static void opt_chol_solves_with_it(void **state)
{
    (void)state;
    opt_csc A;
    block_grid(&A, 50, 0.0);
    int n = A.n;
    double *b = malloc(n * sizeof *b), *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    for (int i = 0; i < n; i++) b[i] = cos(0.37 * i);
    scaf_error e;
    for (int T = 1; T <= 2; T++) {
        par_set_threads(T);
        opt_chol *c = opt_chol_create(OPT_ORDER_METIS, &e);
        opt_chol_set_block(c, 2);
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_OK);
        assert_int_equal(opt_chol_solve(c, 1, b, x, &e), SCAF_OK);
        opt_csc_symv(&A, x, y);
        double num = 0, den = 0;
        for (int i = 0; i < n; i++) {
            num += (y[i] - b[i]) * (y[i] - b[i]);
            den += b[i] * b[i];
        }
        assert_true(sqrt(num / den) < 1e-12);
        A.val[0] = -5.0; /* the first diagonal */
        assert_int_equal(opt_chol_factor(c, &A, &e), SCAF_ERR_NUMERIC);
        assert_non_null(strstr(e.message, "positive definite"));
        A.val[0] = 14.0;
        opt_chol_destroy(c);
    }
    par_set_threads(1);
    free(b);
    free(x);
    free(y);
    opt_csc_free(&A);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equals_cholmod_metis),
        cmocka_unit_test(equals_cholmod_amd_relaxed),
        cmocka_unit_test(shared_supernodes_above_the_cut),
        cmocka_unit_test(forward_sweep_in_the_factorization),
        cmocka_unit_test(same_bits_for_any_thread_count),
        cmocka_unit_test(not_positive_definite_where_cholmod_says),
        cmocka_unit_test(opt_chol_solves_with_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
