/* Tests for opt/handle_term, the soft positional constraints:
 *   - energy and slope: the closed form, the slope against a central
 *     difference (exact for a quadratic up to rounding);
 *   - its proxy is itself: solving its block alone puts every handle on
 *     its target (the block is w I, the right-hand side w t);
 *   - moving targets or the weight keeps the pattern (block version),
 *     other vertices or dofs rebuild it; fixed handles add nothing;
 *   - the weight is scale-free (w = ratio / n, whatever the area) and bad
 *     input is refused with h unchanged;
 *   - per-handle weight factors (opt_handle_term_set_scaled) scale energy,
 *     slope, proxy and Newton blocks handle by handle. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "opt/handle_term.h"

static void energy_and_slope(void **state)
{
    (void)state;
    double X[8] = {0, 0, 1, 0, 1, 1, 0, 1}, D[8] = {0.3, -0.2, 0, 0, 1, 2, -1, 0.5};
    int hv[3] = {0, 2, 2};
    double ht[6] = {1, 1, 2, 1, 1, 3};
    opt_handle_term h;
    opt_handle_term_init(&h, 2, 4);
    assert_int_equal(opt_handle_term_set(&h, 3, hv, ht, 0.5, NULL), SCAF_OK);
    opt_obj_term t = opt_handle_term_make(&h);
    double want = 0.5 * ((1 + 1) + (1 + 0) + (0 + 4));
    assert_true(fabs(t.ops->energy(&t, X) - want) < 1e-15);
    double e = 1.0, slope = 2.0;
    t.ops->energy_slope(&t, X, D, &e, &slope);
    assert_true(fabs(e - 1.0 - want) < 1e-15);
    const double eps = 1e-4;
    double Xp[8], Xm[8];
    for (int i = 0; i < 8; i++) Xp[i] = X[i] + eps * D[i], Xm[i] = X[i] - eps * D[i];
    double fd = (t.ops->energy(&t, Xp) - t.ops->energy(&t, Xm)) / (2 * eps);
    assert_true(fabs(slope - 2.0 - fd) < 1e-9);
    assert_true(fabs(opt_handle_term_max_error(&h, X) - 2.0) < 1e-15); /* vertex 2 to (1, 3) */
    assert_null(t.ops->max_step);
    assert_null(t.ops->valid);
    opt_obj_term_free(&t);
    opt_handle_term_free(&h);
}

/* Three handles on a unit square's corners 3, 0 and 2; vertex 2 fixed
 * (dof -1), so the pattern spans dofs 0..2. */
static const int three_dof[4] = {0, 1, -1, 2};
static const double three_X[8] = {0, 0, 1, 0, 1, 1, 0, 1};
static const double three_targets[6] = {5, 6, -1, 2, 9, 9};

static opt_obj_term three_handles(opt_handle_term *h)
{
    int hv[3] = {3, 0, 2};
    opt_handle_term_init(h, 2, 4);
    assert_int_equal(opt_handle_term_set(h, 3, hv, three_targets, 2.0, NULL), SCAF_OK);
    opt_obj_term t = opt_handle_term_make(h);
    assert_int_equal(t.ops->pattern(&t, three_dof, 3, NULL), SCAF_OK);
    return t;
}

/* The diagonal of a block (6 unknowns); off-diagonal entries must be 0. */
static void block_diagonal(const opt_csc *A, double diag[6])
{
    assert_int_equal(A->n, 6);
    for (int c = 0; c < 6; c++) diag[c] = 0.0;
    for (int c = 0; c < A->n; c++)
        for (int k = A->colptr[c]; k < A->colptr[c + 1]; k++) {
            if (A->rowidx[k] == c) diag[c] += A->val[k];
            else assert_true(A->val[k] == 0.0); /* w I: nothing off the diagonal */
        }
}

/* Block and right-hand side of the term alone; dof: identity except -1s. */
static void proxy_solves_to_targets(void **state)
{
    (void)state;
    const int *dof = three_dof;
    const double *X = three_X;
    opt_handle_term h;
    opt_obj_term t = three_handles(&h);
    double rhs[6] = {0};
    t.ops->fill(&t, dof, X, rhs);
    /* diagonal: w on the handles' unknowns (dofs 0 and 2), nothing on dof 1;
     * vertex 2 is fixed: skipped */
    double diag[6];
    block_diagonal(&t.blk.A, diag);
    assert_true(diag[0] == 2 && diag[1] == 2 && diag[4] == 2 && diag[5] == 2);
    assert_true(diag[2] == 0 && diag[3] == 0);
    /* x = b / w: the targets */
    assert_true(rhs[0] / diag[0] == -1 && rhs[1] / diag[1] == 2);
    assert_true(rhs[4] / diag[4] == 5 && rhs[5] / diag[5] == 6);
    opt_obj_term_free(&t);
    opt_handle_term_free(&h);
}

/* Newton: Hessian 2w I on the handles' unknowns, rhs = -gradient (checked
 * against energy_slope along each unknown), and one full Newton step
 * lands on the targets (the term is quadratic). */
static void newton_fill_is_exact(void **state)
{
    (void)state;
    const int *dof = three_dof;
    const double *X = three_X, *ht = three_targets;
    opt_handle_term h;
    opt_obj_term t = three_handles(&h);
    assert_non_null(t.ops->hessian_fill);
    double rhs[6] = {0};
    assert_int_equal(t.ops->hessian_fill(&t, dof, X, 1, rhs, NULL), SCAF_OK);
    double diag[6];
    block_diagonal(&t.blk.A, diag);
    for (int v = 0; v < 4; v++)
        for (int a = 0; a < 2; a++) {
            if (dof[v] < 0) continue;
            double D[8] = {0}, e = 0, slope = 0;
            D[2 * v + a] = 1.0;
            t.ops->energy_slope(&t, X, D, &e, &slope);
            size_t c = 2 * (size_t)dof[v] + a;
            assert_true(fabs(rhs[c] + slope) < 1e-12); /* rhs = -dE/dx */
            if (diag[c] != 0.0)                        /* x + H^-1 (-g): the target */
                assert_true(fabs(X[2 * v + a] + rhs[c] / diag[c] -
                                 (v == 3       ? ht[a]
                                      : v == 0 ? ht[2 + a]
                                               : 0)) < 1e-12);
        }
    assert_true(diag[0] == 4 && diag[4] == 4 &&
                diag[2] == 0); /* 2w (w = 2, the proxy's diagonal) on handles only */
    opt_obj_term_free(&t);
    opt_handle_term_free(&h);
}

static void pattern_kept_while_vertices_stay(void **state)
{
    (void)state;
    int dof[4] = {0, 1, 2, 3};
    double X[8] = {0};
    int hv[2] = {1, 3}, hv2[2] = {1, 2};
    double ht[4] = {1, 1, 2, 2}, ht2[4] = {-1, 0, 7, 7};
    opt_handle_term h;
    opt_handle_term_init(&h, 2, 4);
    assert_int_equal(opt_handle_term_set(&h, 2, hv, ht, 1.0, NULL), SCAF_OK);
    opt_obj_term t = opt_handle_term_make(&h);
    assert_int_equal(t.ops->pattern(&t, dof, 4, NULL), SCAF_OK);
    unsigned v0 = t.blk.version;
    /* new targets and weight, more free dofs (the scaffold's): kept */
    assert_int_equal(opt_handle_term_set(&h, 2, hv, ht2, 3.0, NULL), SCAF_OK);
    assert_int_equal(t.ops->pattern(&t, dof, 9, NULL), SCAF_OK);
    assert_int_equal(t.blk.version, v0);
    double rhs[8] = {0};
    t.ops->fill(&t, dof, X, rhs);
    assert_true(rhs[2] == -3 && rhs[6] == 21);
    /* another vertex: rebuilt */
    assert_int_equal(opt_handle_term_set(&h, 2, hv2, ht2, 3.0, NULL), SCAF_OK);
    assert_int_equal(t.ops->pattern(&t, dof, 4, NULL), SCAF_OK);
    assert_true(t.blk.version != v0);
    unsigned v1 = t.blk.version;
    /* another numbering: rebuilt */
    int dof2[4] = {3, 2, 1, 0};
    assert_int_equal(t.ops->pattern(&t, dof2, 4, NULL), SCAF_OK);
    assert_true(t.blk.version != v1);
    opt_obj_term_free(&t);
    opt_handle_term_free(&h);
}

static void weight_and_errors(void **state)
{
    (void)state;
    /* scale-free: the ratio per handle, whatever the area */
    assert_true(opt_handle_weight(1e4, 1.0, 10) == 1e3);
    assert_true(fabs(opt_handle_weight(1e4, 1e-6, 10) - 1e3) < 1e-9);
    assert_true(opt_handle_weight(1e4, 1.0, 0) == 0.0);
    opt_handle_term h;
    opt_handle_term_init(&h, 2, 3);
    int ok[1] = {2}, bad[1] = {3};
    double t[2] = {1, 2}, nan_t[2] = {NAN, 0};
    assert_int_equal(opt_handle_term_set(&h, 1, ok, t, 1.0, NULL), SCAF_OK);
    scaf_error err;
    assert_int_equal(opt_handle_term_set(&h, 1, bad, t, 1.0, &err), SCAF_ERR_USAGE);
    assert_non_null(strstr(err.message, "vertex 3"));
    assert_int_equal(opt_handle_term_set(&h, 1, ok, nan_t, 1.0, &err), SCAF_ERR_USAGE);
    assert_int_equal(opt_handle_term_set(&h, 1, ok, t, -1.0, &err), SCAF_ERR_USAGE);
    assert_int_equal(opt_handle_term_set(&h, 1, ok, t, INFINITY, &err), SCAF_ERR_USAGE);
    assert_true(h.n == 1 && h.vertex[0] == 2 && h.target[1] == 2 && h.w == 1.0); /* unchanged */
    opt_handle_term_free(&h);
}

/* Handle i weighs w * scale[i]: the energy, the slope, the proxy and
 * Newton diagonals and right-hand sides of each handle scale alone. */
static void scaled_handles(void **state)
{
    (void)state;
    double X[8] = {0, 0, 1, 0, 1, 1, 0, 1}, D[8] = {0.3, -0.2, 0, 0, 1, 2, -1, 0.5};
    int hv[2] = {0, 2}, dof[4] = {0, 1, 2, 3};
    double ht[4] = {1, 1, 2, 1}, sc[2] = {0.25, 3.0};
    opt_handle_term h;
    opt_handle_term_init(&h, 2, 4);
    assert_int_equal(opt_handle_term_set_scaled(&h, 2, hv, ht, sc, 2.0, NULL), SCAF_OK);
    opt_obj_term t = opt_handle_term_make(&h);
    double want = 2.0 * (0.25 * (1 + 1) + 3.0 * (1 + 0));
    assert_true(fabs(t.ops->energy(&t, X) - want) < 1e-14);
    double e = 0.0, slope = 0.0;
    t.ops->energy_slope(&t, X, D, &e, &slope);
    const double eps = 1e-4;
    double Xp[8], Xm[8];
    for (int i = 0; i < 8; i++) Xp[i] = X[i] + eps * D[i], Xm[i] = X[i] - eps * D[i];
    double fd = (t.ops->energy(&t, Xp) - t.ops->energy(&t, Xm)) / (2 * eps);
    assert_true(fabs(slope - fd) < 1e-9);
    assert_int_equal(t.ops->pattern(&t, dof, 4, NULL), SCAF_OK);
    double rhs[8] = {0};
    t.ops->fill(&t, dof, X, rhs);
    assert_true(rhs[0] == 0.5 && rhs[1] == 0.5 && rhs[4] == 12.0 && rhs[5] == 6.0);
    double nrhs[8] = {0};
    assert_int_equal(t.ops->hessian_fill(&t, dof, X, 1, nrhs, NULL), SCAF_OK);
    assert_true(nrhs[0] == -2.0 * 0.5 * (0 - 1) && nrhs[4] == -2.0 * 6.0 * (1 - 2));
    /* a bad factor is refused, h unchanged */
    double bad[2] = {1.0, -1.0};
    scaf_error err;
    assert_int_equal(opt_handle_term_set_scaled(&h, 2, hv, ht, bad, 2.0, &err), SCAF_ERR_USAGE);
    assert_non_null(strstr(err.message, "handle 1"));
    assert_true(h.scale[1] == 3.0);
    /* no factors: all 1 again */
    assert_int_equal(opt_handle_term_set(&h, 2, hv, ht, 2.0, NULL), SCAF_OK);
    assert_true(fabs(t.ops->energy(&t, X) - 2.0 * 3.0) < 1e-14);
    opt_obj_term_free(&t);
    opt_handle_term_free(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(energy_and_slope),     cmocka_unit_test(proxy_solves_to_targets),
        cmocka_unit_test(newton_fill_is_exact), cmocka_unit_test(pattern_kept_while_vertices_stay),
        cmocka_unit_test(weight_and_errors),    cmocka_unit_test(scaled_handles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
