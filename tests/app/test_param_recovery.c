/* Tests for the recovery of a SCAF run from a failed factorization,
 * through the path users run (the scaf_param API).
 *
 * With the scaffold's weight vanishing next to the mesh's (lambda_ratio
 * 1e-30) the free scaffold vertices are numerically unconstrained: CHOLMOD
 * finds the SLIM proxy not positive definite (counted process-wide by
 * opt_chol_not_posdef_total), and the loop solves again with mu diag(A)
 * added. The run must still succeed, lower the energy and give a bijective
 * map (exact checker). With the default weight the count does not move, so
 * it is the vanishing weight that triggers the path. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "geom/bijectivity.h"
#include "mesh/samples.h"
#include "opt/cholmod_solver.h"
#include "scaf/scaf.h"

enum { ITERATIONS = 3 };

/* ITERATIONS iterations on a flat grid; returns how many factorizations
 * were found not positive definite meanwhile. */
static long run(double lambda_ratio)
{
    mesh m;
    assert_int_equal(mesh_sample_make("grid", 6, &m, NULL), SCAF_OK);
    scaf_options_t o = scaf_options_default();
    o.lambda_ratio = lambda_ratio;
    o.tolerance = 0.0;
    scaf_param_t *p = scaf_param_new(&o);
    assert_non_null(p);
    long before = opt_chol_not_posdef_total();
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    double e0 = scaf_param_energy(p);
    assert_int_equal(scaf_param_run(p, ITERATIONS, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_param_iterations(p), ITERATIONS);
    assert_true(scaf_param_energy(p) < e0);
    int nuv = scaf_param_uv_count(p);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_non_null(UV);
    assert_non_null(FT);
    scaf_param_get_uv(p, UV, FT);
    bij_report r;
    assert_int_equal(bij_check(nuv, UV, m.nf, FT, NULL, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    long found = opt_chol_not_posdef_total() - before;
    free(UV);
    free(FT);
    scaf_param_destroy(p);
    mesh_free(&m);
    return found;
}

static void vanishing_scaffold_weight_is_recovered(void **state)
{
    (void)state;
    assert_true(run(1e-30) >= 1);
}

static void default_weight_factors_directly(void **state)
{
    (void)state;
    assert_int_equal(run(scaf_options_default().lambda_ratio), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(vanishing_scaffold_weight_is_recovered),
        cmocka_unit_test(default_weight_factors_directly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
