/* Tests for opt/supernodal_plan on CHOLMOD's symbolic factors of 2D block
 * grids: for 1 to 8 bins the bins and the part above the cut hold every
 * supernode once, ascending within a bin, each bin a union of whole
 * subtrees of the supernodal elimination tree (a parent is in the same bin
 * or above the cut; above the cut, parents stay above); every entry of A
 * is placed exactly once, at its row and column in its supernode's block;
 * an entry outside L's structure gives no plan; the kept scatter of a
 * leading part is reused under the same pattern name and rebuilt under
 * another. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <stdlib.h>

#include <cholmod.h>

#include "opt/cholmod_view.h"
#include "opt/csc.h"
#include "opt/supernodal_plan.h"

/* m x m vertices, 2 unknowns each, 8-neighbour stencil (upper CSC). */
static void block_grid(opt_csc *A, int m)
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
                            if (u == v && b < a) continue;
                            int r = 2 * v + a, c = 2 * u + b;
                            I[nt] = r < c ? r : c;
                            J[nt] = r < c ? c : r;
                            V[nt++] = u == v ? (a == b ? 20.0 : 0.3) : -1.0;
                        }
                }
        }
    assert_int_equal(opt_csc_from_triplets(A, 2 * nv, nt, I, J, V, NULL), SCAF_OK);
    free(I);
    free(J);
    free(V);
}

static cholmod_factor *analyse(cholmod_common *cm, const opt_csc *A, int natural)
{
    cm->nmethods = 1;
    cm->method[0].ordering = natural ? CHOLMOD_NATURAL : CHOLMOD_AMD;
    cm->postorder = !natural;
    cholmod_sparse S = opt_csc_cholmod_view(A);
    cholmod_factor *L = cholmod_analyze(&S, cm);
    assert_non_null(L);
    assert_true(cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, L, cm));
    return L;
}

/* The parent supernode of sn (-1 for a root). */
static int parent_of(const opt_snum *P, int sn)
{
    int below = P->pi[sn] + P->super[sn + 1] - P->super[sn];
    return below < P->pi[sn + 1] ? P->col2super[P->s[below]] : -1;
}

static void bins_are_whole_subtrees(void **state)
{
    (void)state;
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    opt_csc A;
    block_grid(&A, 60);
    cholmod_factor *L = analyse(&cm, &A, 0);
    int cut_seen = 0;
    for (int B = 1; B <= 8; B *= 2) {
        opt_snum *P = opt_snum_create(L, &A, B);
        assert_non_null(P);
        int ns = P->nsuper, T = P->bins, top = P->bptr[T > 1 ? T : 0];
        opt_snum_shape sh = opt_snum_get_shape(P);
        assert_int_equal(sh.supernodes, ns);
        assert_int_equal(sh.in_bins + sh.above, ns);
        assert_true(T >= 1 && T <= B);
        cut_seen |= T > 1;
        int *bin = malloc(ns * sizeof *bin);
        for (int i = 0; i < ns; i++) bin[i] = -2;
        for (int k = 0; k < T && T > 1; k++)
            for (int i = P->bptr[k]; i < P->bptr[k + 1]; i++) {
                assert_int_equal(bin[P->order[i]], -2);
                bin[P->order[i]] = k;
                if (i > P->bptr[k]) assert_true(P->order[i] > P->order[i - 1]);
            }
        for (int i = top; i < ns; i++) {
            assert_int_equal(bin[P->order[i]], -2);
            bin[P->order[i]] = -1; /* above the cut */
        }
        for (int sn = 0; sn < ns; sn++) {
            assert_true(bin[sn] != -2);
            int p = parent_of(P, sn);
            if (p >= 0) assert_true(bin[p] == bin[sn] || bin[p] == -1);
        }
        /* every entry of A once, at its place */
        int *hit = calloc(A.nnz, sizeof *hit), *pinv = malloc(A.n * sizeof *pinv);
        const int *perm = L->Perm;
        for (int k = 0; k < A.n; k++) pinv[perm[k]] = k;
        for (int sn = 0; sn < ns; sn++) {
            int nsrow = P->pi[sn + 1] - P->pi[sn];
            for (int q = P->aptr[sn]; q < P->aptr[sn + 1]; q++) {
                int e = P->asrc[q], c = 0;
                while (A.colptr[c + 1] <= e) c++;
                int a = pinv[A.rowidx[e]], b = pinv[c];
                int lo = a < b ? a : b, hi = a < b ? b : a;
                assert_int_equal(lo - P->super[sn], P->adst[q] / nsrow);
                assert_int_equal(P->s[P->pi[sn] + P->adst[q] % nsrow], hi);
                hit[e]++;
            }
        }
        for (int e = 0; e < A.nnz; e++) assert_int_equal(hit[e], 1);
        free(hit);
        free(pinv);
        free(bin);
        opt_snum_destroy(P);
    }
    assert_true(cut_seen); /* the grid is large enough to be cut */
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
    opt_csc_free(&A);
}

static void entry_outside_the_factor(void **state)
{
    (void)state;
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    opt_csc A;
    block_grid(&A, 12);
    cholmod_factor *L = analyse(&cm, &A, 1); /* natural: vertex 0 to the last */
    /* A plus (0, n - 1): in natural order column 0's rows reach only
     * about 2 m unknowns down (a band), checked below */
    int n = A.n;
    int *tI = malloc((A.nnz + 1) * sizeof *tI), *tJ = malloc((A.nnz + 1) * sizeof *tJ);
    double *tV = malloc((A.nnz + 1) * sizeof *tV);
    int nt = 0;
    for (int c = 0; c < n; c++)
        for (int e = A.colptr[c]; e < A.colptr[c + 1]; e++)
            tI[nt] = A.rowidx[e], tJ[nt] = c, tV[nt++] = A.val[e];
    tI[nt] = 0, tJ[nt] = n - 1, tV[nt++] = -0.01;
    opt_csc A2;
    assert_int_equal(opt_csc_from_triplets(&A2, n, nt, tI, tJ, tV, NULL), SCAF_OK);
    const int *pi = L->pi, *s = L->s, *super = L->super;
    int sn0 = 0;
    while (super[sn0 + 1] <= 0) sn0++;
    int inside = 0;
    for (int q = pi[sn0]; q < pi[sn0 + 1]; q++) inside |= s[q] == n - 1;
    assert_false(inside);
    assert_null(opt_snum_create(L, &A2, 2));
    opt_snum *P = opt_snum_create(L, &A, 2);
    assert_non_null(P);
    opt_snum_destroy(P);
    free(tI);
    free(tJ);
    free(tV);
    opt_csc_free(&A2);
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
    opt_csc_free(&A);
}

static void kept_scatter_reused_by_pattern_name(void **state)
{
    (void)state;
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    opt_csc A;
    block_grid(&A, 16);
    cholmod_factor *L = analyse(&cm, &A, 1); /* natural: leading columns first */
    const int *super = L->super;
    int nfixed = super[L->nsuper / 2];
    assert_true(nfixed > 0 && nfixed < A.n);
    opt_snum_kept *kept = NULL;
    opt_snum *P = opt_snum_create_kept(L, &A, 2, nfixed, 7, &kept);
    assert_non_null(P);
    assert_non_null(kept);
    assert_int_equal(P->kept_reused, 0);
    assert_true(P->nks > 0);
    opt_snum_destroy(P);
    P = opt_snum_create_kept(L, &A, 2, nfixed, 7, &kept);
    assert_non_null(P);
    assert_int_equal(P->kept_reused, 1);
    opt_snum_destroy(P);
    P = opt_snum_create_kept(L, &A, 2, nfixed, 8, &kept); /* another pattern */
    assert_non_null(P);
    assert_int_equal(P->kept_reused, 0);
    opt_snum_destroy(P);
    opt_snum_kept_destroy(kept);
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
    opt_csc_free(&A);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bins_are_whole_subtrees),
        cmocka_unit_test(entry_outside_the_factor),
        cmocka_unit_test(kept_scatter_reused_by_pattern_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
