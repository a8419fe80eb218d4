/* Tests for opt/energy_exp_symmetric_dirichlet, the row added to
 * opt/energy_table to show that an energy is one file plus one row: it is
 * found by name through the public list, its value is exp(0.1 (SD - 2d))
 * of symmetric Dirichlet's, its gradient and Hessian match central
 * differences, its SLIM proxy has the exact gradient (2 W^T W (J - T) =
 * dE/dJ, positive weights), its projected Hessian is PSD, and a
 * parametrization with it is bijective (exact checker) and lowers the
 * worst triangle's symmetric Dirichlet density below that of the default
 * energy's map, the reason to choose it. (`scaf param --energy
 * exp-symmetric-dirichlet` is run by tests/e2e/test_energy_cli, which runs
 * every row.) */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "app/param.h"
#include "geom/bijectivity.h"
#include "mesh/samples.h"
#include "opt/energy.h"
#include "opt/isotropic_hessian.h"
#include "opt/rng.h"
#include "scaf/scaf.h"

static opt_energy exp_sd(void)
{
    scaf_energy e;
    assert_int_equal(scaf_energy_find("exp_symmetric_dirichlet", &e), SCAF_OK);
    scaf_energy alias;
    assert_int_equal(scaf_energy_find("esd", &alias), SCAF_OK);
    assert_int_equal(alias, e);
    return (opt_energy)e;
}

static void random_jacobian(rng *r, int d, double *J)
{
    do {
        for (int k = 0; k < d * d; k++) J[k] = rng_uniform(r, -1.2, 1.2);
        for (int k = 0; k < d; k++) J[k * d + k] += 1.0;
    } while (det_d(d, J) < 0.3 || det_d(d, J) > 3.0);
}

static void value_is_exp_of_symmetric_dirichlet(void **state)
{
    (void)state;
    opt_energy e = exp_sd();
    rng r = {31};
    for (int d = 2; d <= 3; d++) {
        double I[9] = {0};
        for (int k = 0; k < d; k++) I[k * d + k] = 1.0;
        assert_true(fabs(opt_density(e, d, I) - 1.0) < 1e-15);
        for (int t = 0; t < 200; t++) {
            double J[9];
            random_jacobian(&r, d, J);
            double sd = opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J);
            double want = exp(0.1 * (sd - 2.0 * d));
            assert_true(fabs(opt_density(e, d, J) - want) <= 1e-14 * want);
        }
    }
}

static void gradient_hessian_and_proxy(void **state)
{
    (void)state;
    opt_energy e = exp_sd();
    rng r = {37};
    for (int d = 2; d <= 3; d++)
        for (int t = 0; t < 100; t++) {
            int dd = d * d;
            double J[9], G[9], H[81], Hp[81], W[9], T[9];
            random_jacobian(&r, d, J);
            opt_density_grad(e, d, J, G);
            assert_true(opt_isotropic_hessian(e, d, J, 0, H) >= 0);
            double gs = 0, hs = 0;
            for (int k = 0; k < dd; k++) gs = fmax(gs, fabs(G[k]));
            for (int k = 0; k < dd * dd; k++) hs = fmax(hs, fabs(H[k]));
            for (int k = 0; k < dd; k++) {
                double h = 1e-6, keep = J[k], Gp[9], Gm[9];
                J[k] = keep + h;
                double ep = opt_density_grad(e, d, J, Gp);
                J[k] = keep - h;
                double em = opt_density_grad(e, d, J, Gm);
                J[k] = keep;
                assert_true(fabs((ep - em) / (2 * h) - G[k]) <= 1e-6 * (1 + gs));
                for (int m = 0; m < dd; m++)
                    assert_true(fabs((Gp[m] - Gm[m]) / (2 * h) - H[m * dd + k]) <= 1e-5 * (1 + hs));
            }
            /* SLIM: the proxy's gradient is exact, W symmetric positive definite */
            opt_slim_proxy(e, d, J, W, T);
            double M[9], P[9];
            for (int a = 0; a < d; a++)
                for (int b = 0; b < d; b++) {
                    double m = 0;
                    for (int q = 0; q < d; q++) m += W[q * d + a] * W[q * d + b];
                    M[a * d + b] = m;
                }
            for (int a = 0; a < d; a++)
                for (int b = 0; b < d; b++) {
                    double p = 0;
                    for (int q = 0; q < d; q++) p += M[a * d + q] * (J[q * d + b] - T[q * d + b]);
                    P[a * d + b] = p;
                }
            for (int k = 0; k < dd; k++) assert_true(fabs(2 * P[k] - G[k]) <= 1e-9 * (1 + gs));
            assert_true(M[0] > 0 && det_d(d, M) > 0);
            /* projected: no negative eigenvalue left (x^T H x >= 0) */
            assert_true(opt_isotropic_hessian(e, d, J, 1, Hp) >= 0);
            for (int trial = 0; trial < 10; trial++) {
                double x[9], q = 0;
                for (int k = 0; k < dd; k++) x[k] = rng_uniform(&r, -1, 1);
                for (int m = 0; m < dd; m++)
                    for (int k = 0; k < dd; k++) q += x[m] * Hp[m * dd + k] * x[k];
                assert_true(q >= -1e-9 * hs);
            }
        }
}

/* Largest symmetric Dirichlet density over the faces of p's map. */
static double worst_density(scaf_param_t *p, int nf)
{
    double *E = malloc(sizeof(double) * (size_t)nf), worst = 0;
    assert_non_null(E);
    assert_true(param_face_energy(p, E));
    for (int f = 0; f < nf; f++) worst = fmax(worst, E[f]);
    free(E);
    return worst;
}

static void parametrization_is_bijective_and_evens_out(void **state)
{
    (void)state;
    opt_energy e = exp_sd();
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("holes", 6, &m, &err), SCAF_OK);
    double worst[2];
    for (int k = 0; k < 2; k++) {
        scaf_options_t o = scaf_options_default();
        o.energy = k ? (scaf_energy)e : SCAF_ENERGY_SYMMETRIC_DIRICHLET;
        scaf_param_t *p = scaf_param_new(&o);
        assert_non_null(p);
        assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
        assert_int_equal(scaf_param_run(p, 60, NULL, NULL), SCAF_OK);
        int nuv = scaf_param_uv_count(p);
        double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
        int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
        assert_non_null(UV);
        assert_non_null(FT);
        assert_int_equal(scaf_param_get_uv(p, UV, FT), SCAF_OK);
        bij_report rep;
        assert_int_equal(bij_check(nuv, UV, m.nf, FT, NULL, NULL, &rep, &err), SCAF_OK);
        assert_true(rep.bijective);
        worst[k] = worst_density(p, m.nf);
        free(UV);
        free(FT);
        scaf_param_destroy(p);
    }
    assert_true(worst[1] < worst[0]);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(value_is_exp_of_symmetric_dirichlet),
        cmocka_unit_test(gradient_hessian_and_proxy),
        cmocka_unit_test(parametrization_is_bijective_and_evens_out),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
