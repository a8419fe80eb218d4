/* Tests for opt/ordering_reuse: extending a chart ordering to chart +
 * scaffold gives a permutation that keeps the chart's order, keeps each
 * vertex's unknowns together, puts every scaffold vertex after the chart
 * neighbours it touches, and solves the system exactly. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/cholmod_solver.h"
#include "opt/ordering_reuse.h"
#include "opt/proxy_system.h"
#include "opt/slim.h"
#include "polar_disk.h"
#include "rng.h"

static void extension_is_valid(void **state)
{
    (void)state;
    int rc = 6, seg = 16, rs = 3;
    polar_disk all;
    assert_int_equal(polar_disk_make(&all, rc + rs, seg, 0.0, 0), 0);
    int nvc = 1 + rc * seg, nfc = seg + 2 * seg * (rc - 1);
    /* Planar positions: the grid itself (CCW). Chart = first nfc faces. */
    double *X = malloc(2 * all.nv * sizeof *X);
    for (int v = 0; v < all.nv; v++) { X[2 * v] = all.V[3 * v]; X[2 * v + 1] = all.V[3 * v + 1]; }
    opt_simplices S;
    assert_int_equal(opt_simplices_from_current(&S, 2, all.nv, X, all.nf, all.F, 0.0, NULL), SCAF_OK);
    opt_simplices Sc = S, Ss = S;
    Sc.n = nfc;
    Ss.n = all.nf - nfc;
    Ss.idx += 3 * nfc; Ss.grad += 6 * nfc; Ss.vol += nfc; Ss.weight += nfc;
    unsigned char *fixed = calloc(all.nv, 1);
    for (int j = 0; j < seg; j++) fixed[all.loops[j]] = 1;
    int *dof = malloc(all.nv * sizeof *dof);
    int nfree = opt_dof_numbering(all.nv, fixed, dof);
    opt_term tc = {&Sc, OPT_ENERGY_SYMMETRIC_DIRICHLET}, ts = {&Ss, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_proxy_block bc = {0}, bs = {0};
    double *rhs = calloc(2 * nfree, sizeof *rhs);
    assert_int_equal(opt_proxy_block_pattern(&bc, &Sc, dof, nfree, NULL), SCAF_OK);
    assert_int_equal(opt_proxy_block_pattern(&bs, &Ss, dof, nfree, NULL), SCAF_OK);
    assert_int_equal(bc.nfree, nvc);
    opt_proxy_block_fill(&bc, &tc, dof, X, rhs);
    opt_proxy_block_fill(&bs, &ts, dof, X, rhs);
    opt_proxy_system sys = {0};
    const opt_proxy_block *bl[2] = {&bc, &bs};
    assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
    int n = sys.A.n;
    int *lead = malloc(bc.A.n * sizeof *lead), *perm = malloc(n * sizeof *perm);
    opt_chol *c = opt_chol_create(OPT_ORDER_METIS, NULL);
    opt_chol_set_block(c, 2);
    assert_int_equal(opt_chol_compute_ordering(c, &bc.A, lead, NULL), SCAF_OK);
    assert_int_equal(opt_ordering_extend(&sys.A, 2, bc.nfree, lead, perm, NULL), SCAF_OK);
    /* A permutation, pairs together. */
    int *seen = calloc(n, sizeof *seen), *where = malloc((n / 2) * sizeof *where);
    for (int k = 0; k < n; k++) { assert_true(perm[k] >= 0 && perm[k] < n); seen[perm[k]]++; }
    for (int k = 0; k < n; k++) assert_int_equal(seen[k], 1);
    for (int k = 0; k < n / 2; k++) {
        assert_int_equal(perm[2 * k] % 2, 0);
        assert_int_equal(perm[2 * k + 1], perm[2 * k] + 1);
        where[perm[2 * k] / 2] = k;
    }
    /* Chart vertices keep the lead ordering's relative order. */
    int last = -1;
    for (int k = 0; k < bc.A.n; k += 2) {
        int v = lead[k] / 2;
        assert_true(where[v] > last);
        last = where[v];
    }
    /* A scaffold vertex touching the chart comes after those chart neighbours. */
    for (int v = nvc; v < nfree; v++) {
        int maxpos = -1;
        for (int s = nfc; s < all.nf; s++) {
            int has = 0;
            for (int i = 0; i < 3; i++) has |= dof[all.F[3 * s + i]] == v;
            if (!has) continue;
            for (int i = 0; i < 3; i++) {
                int u = dof[all.F[3 * s + i]];
                if (u >= 0 && u < nvc && where[u] > maxpos) maxpos = where[u];
            }
        }
        if (maxpos >= 0) assert_true(where[v] > maxpos);
    }
    /* Solves exactly with it. */
    assert_int_equal(opt_chol_analyze_given(c, &sys.A, perm, NULL), SCAF_OK);
    assert_int_equal(opt_chol_factor(c, &sys.A, NULL), SCAF_OK);
    double *x = malloc(n * sizeof *x), *Ax = malloc(n * sizeof *Ax);
    assert_int_equal(opt_chol_solve(c, 1, rhs, x, NULL), SCAF_OK);
    opt_csc_symv(&sys.A, x, Ax);
    double num = 0, den = 0;
    for (int k = 0; k < n; k++) { num += (Ax[k] - rhs[k]) * (Ax[k] - rhs[k]); den += rhs[k] * rhs[k]; }
    assert_true(sqrt(num / den) < 1e-10);
    /* Bad sizes are refused. */
    assert_int_equal(opt_ordering_extend(&sys.A, 2, nfree + 1, lead, perm, NULL), SCAF_ERR_USAGE);
    free(x); free(Ax); free(seen); free(where); free(lead); free(perm); free(rhs); free(dof); free(fixed); free(X);
    opt_chol_destroy(c);
    opt_proxy_system_free(&sys);
    opt_proxy_block_free(&bc); opt_proxy_block_free(&bs);
    opt_simplices_free(&S);
    polar_disk_free(&all);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(extension_is_valid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
