/* Tests for opt/given_symbolic against CHOLMOD's own answer: for grid
 * Laplacians (with a long-range coupling) under random and identity
 * permutations, with and without the postorder and supernode
 * relaxation, the symbolic factor (Perm, ColCount, supernodes, row
 * patterns) is cholmod_analyze_p's entry for entry; a perm that is not a
 * permutation gives NULL with status OK (CHOLMOD then reports it). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <stdlib.h>

#include "opt/cholmod_view.h"
#include "opt/given_symbolic.h"
#include "rng.h"

/* m x m grid Laplacian (upper), plus (0, n - 1) when extra. */
static void grid(opt_csc *A, int m, int extra)
{
    int n = m * m, nt = 0, cap = 3 * n + 1;
    int *I = malloc(cap * sizeof *I), *J = malloc(cap * sizeof *J);
    double *V = malloc(cap * sizeof *V);
    for (int y = 0; y < m; y++)
        for (int x = 0; x < m; x++) {
            int i = y * m + x;
            I[nt] = i, J[nt] = i, V[nt++] = 5;
            if (x + 1 < m) I[nt] = i, J[nt] = i + 1, V[nt++] = -1;
            if (y + 1 < m) I[nt] = i, J[nt] = i + m, V[nt++] = -1;
        }
    if (extra) I[nt] = 0, J[nt] = n - 1, V[nt++] = -0.5;
    assert_int_equal(opt_csc_from_triplets(A, n, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
}

static void shuffle(int *p, int n, rng *r)
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

static void ints_equal(const void *a, const void *b, size_t n)
{
    assert_memory_equal(a, b, n * sizeof(int));
}

static void same_factor_as_cholmod(void **state)
{
    (void)state;
    rng r = {5};
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    for (int round = 0; round < 8; round++) {
        int m = 6 + 3 * round, n = m * m;
        opt_csc A;
        grid(&A, m, round & 1);
        int *perm = malloc(n * sizeof *perm);
        if (round % 4 == 3)
            for (int i = 0; i < n; i++) perm[i] = i;
        else shuffle(perm, n, &r);
        cm.postorder = round % 4 != 2;
        cm.nrelax[0] = round < 4 ? 4 : 16; /* relaxed supernodes in the later rounds */
        cholmod_sparse S = opt_csc_cholmod_view(&A);
        cholmod_factor *ref = cholmod_analyze_p(&S, perm, NULL, 0, &cm);
        assert_non_null(ref);
        cholmod_factor *L = opt_given_symbolic(&cm, n, A.colptr, A.rowidx, perm);
        assert_non_null(L);
        assert_true(L->is_super && ref->is_super);
        assert_int_equal(L->nsuper, ref->nsuper);
        ints_equal(L->Perm, ref->Perm, n);
        ints_equal(L->ColCount, ref->ColCount, n);
        ints_equal(L->super, ref->super, L->nsuper + 1);
        ints_equal(L->pi, ref->pi, L->nsuper + 1);
        ints_equal(L->px, ref->px, L->nsuper + 1);
        ints_equal(L->s, ref->s, ((int *)ref->pi)[ref->nsuper]);
        cholmod_free_factor(&L, &cm);
        cholmod_free_factor(&ref, &cm);
        free(perm);
        opt_csc_free(&A);
    }
    cholmod_finish(&cm);
}

static void not_a_permutation(void **state)
{
    (void)state;
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    opt_csc A;
    grid(&A, 4, 0);
    int perm[16];
    for (int i = 0; i < 16; i++) perm[i] = i;
    perm[3] = 5; /* 5 twice, 3 missing */
    cm.status = CHOLMOD_OK;
    assert_null(opt_given_symbolic(&cm, 16, A.colptr, A.rowidx, perm));
    assert_int_equal(cm.status, CHOLMOD_OK);
    perm[3] = 16; /* out of range */
    assert_null(opt_given_symbolic(&cm, 16, A.colptr, A.rowidx, perm));
    assert_int_equal(cm.status, CHOLMOD_OK);
    opt_csc_free(&A);
    cholmod_finish(&cm);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_factor_as_cholmod),
        cmocka_unit_test(not_a_permutation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
