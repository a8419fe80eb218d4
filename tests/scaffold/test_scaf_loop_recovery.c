/* Tests for the SCAF loop's recovery from a failed factorization.
 *
 * With the scaffold's weight vanishing next to the mesh's (lambda_ratio
 * 1e-30) the free scaffold vertices are numerically unconstrained: CHOLMOD
 * finds the SLIM proxy not positive definite (counted by the solver's
 * not_posdef), and the loop solves again with mu diag(A) added. Every
 * iteration must still succeed, lower the energy and leave the map
 * bijective (exact checker). With the default weight the path is not
 * taken, so it is the vanishing weight that triggers it. */
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
#include "scaffold/scaf_loop.h"

enum { ITERATIONS = 3 };

/* ITERATIONS steps on a flat grid started stretched by 2 along x; returns
 * the solver's count of factorizations found not positive definite. */
static int run(double lambda_ratio)
{
    mesh m;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(mesh_sample_make("grid", 6, &m, &err), SCAF_OK);
    double *uv = malloc(sizeof(double) * 2 * (size_t)m.nv);
    assert_non_null(uv);
    for (int i = 0; i < m.nv; i++) {
        uv[2 * i] = 2.0 * m.V[3 * i];
        uv[2 * i + 1] = m.V[3 * i + 1];
    }
    scaf_options_t o = scaf_options_default();
    o.lambda_ratio = lambda_ratio;
    scaf_loop L;
    assert_int_equal(scaf_loop_init(&L, m.nv, m.V, m.nf, m.F, uv, &o, &err), SCAF_OK);
    double e0 = scaf_loop_energy(&L);
    for (int k = 0; k < ITERATIONS; k++) {
        scaf_iteration_info_t info;
        assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
        assert_true(info.energy <= info.energy_before);
        bij_report r;
        assert_int_equal(bij_check(L.nv, L.uv, L.nf, L.F, NULL, NULL, &r, &err), SCAF_OK);
        assert_true(r.bijective);
    }
    assert_true(scaf_loop_energy(&L) < e0);
    int not_posdef = opt_chol_get_stats(L.chol).not_posdef;
    scaf_loop_free(&L);
    free(uv);
    mesh_free(&m);
    return not_posdef;
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
