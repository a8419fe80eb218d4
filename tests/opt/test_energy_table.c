/* Tests for opt/energy_kind and opt/energy_table: every row of the table,
 * whatever its energy, is checked here, so a new energy is tested by
 * adding its row. Per row: a unique identifier that parses back (with
 * '-' for '_' too) and so do its aliases; at a rotation the energy is
 * finite with zero gradient (every row's minimum contains the
 * rotations); its gradient and its Hessian (opt/isotropic_hessian on the
 * row's singular-value derivatives) match central differences; its SLIM
 * weights are positive and its optional 2D shortcut agrees with its
 * general path; an inverted Jacobian is infinite. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/energy.h"
#include "opt/energy_kind.h"
#include "opt/isotropic_hessian.h"
#include "opt/small_svd.h"
#include "rng.h"

static void names_are_unique_and_parse(void **state)
{
    (void)state;
    assert_int_equal(opt_energy_count(), opt_energy_table_size);
    assert_true(opt_energy_count() >= 3);
    assert_false(opt_energy_valid(-1));
    assert_false(opt_energy_valid(opt_energy_count()));
    assert_string_equal(opt_energy_name((opt_energy)opt_energy_count()), "unknown");
    for (int e = 0; e < opt_energy_count(); e++) {
        const opt_energy_kind *k = opt_energy_table[e];
        assert_non_null(k->name);
        assert_non_null(k->aliases);
        assert_true(k->help && strlen(k->help) > 10);
        assert_non_null(k->density);
        assert_non_null(k->density_grad);
        assert_non_null(k->slim_weights);
        assert_non_null(k->sv_hessian);
        assert_true(k->scale_offset >= 0.0);
        for (const char *c = k->name; *c; c++) assert_true((*c >= 'a' && *c <= 'z') || *c == '_');
        for (int f = 0; f < e; f++) assert_string_not_equal(k->name, opt_energy_table[f]->name);
        assert_string_equal(opt_energy_name((opt_energy)e), k->name);
        opt_energy got = (opt_energy)-1;
        assert_int_equal(opt_energy_parse(k->name, &got), 0);
        assert_int_equal((int)got, e);
        char dashed[64];
        size_t n = strlen(k->name);
        assert_true(n < sizeof dashed);
        for (size_t i = 0; i <= n; i++) dashed[i] = k->name[i] == '_' ? '-' : k->name[i];
        got = (opt_energy)-1;
        assert_int_equal(opt_energy_parse(dashed, &got), 0);
        assert_int_equal((int)got, e);
        char alias[64];
        for (const char *w = k->aliases; *w;) { /* every alias names this row */
            size_t m = strcspn(w, " ");
            assert_true(m > 0 && m < sizeof alias);
            memcpy(alias, w, m);
            alias[m] = 0;
            got = (opt_energy)-1;
            assert_int_equal(opt_energy_parse(alias, &got), 0);
            assert_int_equal((int)got, e);
            w += m;
            while (*w == ' ') w++;
        }
    }
    opt_energy got = OPT_ENERGY_ARAP;
    assert_int_equal(opt_energy_parse("no_such_energy", &got), -1);
    assert_int_equal(opt_energy_parse("", &got), -1);
    assert_int_equal(opt_energy_parse("symmetric", &got), -1); /* a prefix is not a name */
    assert_int_equal((int)got, OPT_ENERGY_ARAP);
}

/* A random J with det J in a comfortable range (no barrier, no overflow). */
static void random_jacobian(rng *r, int d, double *J)
{
    do {
        for (int k = 0; k < d * d; k++) J[k] = rng_uniform(r, -1.6, 1.6);
        for (int k = 0; k < d; k++) J[k * d + k] += 1.0;
    } while (det_d(d, J) < 0.3 || det_d(d, J) > 3.0);
}

static void rotations_are_minima_and_inversions_infinite(void **state)
{
    (void)state;
    rng r = {5};
    for (int e = 0; e < opt_energy_count(); e++)
        for (int d = 2; d <= 3; d++)
            for (int trial = 0; trial < 20; trial++) {
                double R[9], G[9];
                rng_rotation(&r, d, R);
                double v = opt_density_grad((opt_energy)e, d, R, G);
                assert_true(isfinite(v));
                assert_true(fabs(v - opt_density((opt_energy)e, d, R)) <= 1e-12 * (1 + fabs(v)));
                for (int k = 0; k < d * d; k++) assert_true(fabs(G[k]) < 1e-9 * (1 + fabs(v)));
                double F[9];
                memcpy(F, R, sizeof F);
                for (int b = 0; b < d; b++) F[b] = -F[b]; /* a reflection: det -1 */
                assert_true(isinf(opt_density((opt_energy)e, d, F)));
                assert_true(isinf(opt_density_grad((opt_energy)e, d, F, G)));
            }
}

static void gradient_and_hessian_match_finite_differences(void **state)
{
    (void)state;
    rng r = {17};
    for (int e = 0; e < opt_energy_count(); e++)
        for (int d = 2; d <= 3; d++)
            for (int trial = 0; trial < 40; trial++) {
                int dd = d * d;
                double J[9], G[9], H[81];
                random_jacobian(&r, d, J);
                double v = opt_density_grad((opt_energy)e, d, J, G);
                assert_true(isfinite(v));
                assert_true(opt_isotropic_hessian((opt_energy)e, d, J, 0, H) >= 0);
                double gs = 0, hs = 0;
                for (int k = 0; k < dd; k++) gs = fmax(gs, fabs(G[k]));
                for (int k = 0; k < dd * dd; k++) hs = fmax(hs, fabs(H[k]));
                for (int k = 0; k < dd; k++) {
                    double h = 1e-6, keep = J[k], Gp[9], Gm[9];
                    J[k] = keep + h;
                    double ep = opt_density_grad((opt_energy)e, d, J, Gp);
                    J[k] = keep - h;
                    double em = opt_density_grad((opt_energy)e, d, J, Gm);
                    J[k] = keep;
                    double fd = (ep - em) / (2 * h);
                    if (fabs(fd - G[k]) > 1e-6 * (1 + gs)) {
                        print_error("%s d=%d trial %d: dE/dJ[%d] %.12g, differences %.12g\n",
                                    opt_energy_name((opt_energy)e), d, trial, k, G[k], fd);
                        fail();
                    }
                    for (int m = 0; m < dd; m++) {
                        double fh = (Gp[m] - Gm[m]) / (2 * h);
                        if (fabs(fh - H[m * dd + k]) > 1e-5 * (1 + hs)) {
                            print_error("%s d=%d trial %d: H[%d][%d] %.12g, differences %.12g\n",
                                        opt_energy_name((opt_energy)e), d, trial, m, k,
                                        H[m * dd + k], fh);
                            fail();
                        }
                    }
                }
            }
}

/* W^T W and T of the general path: the row's weights along J's SVD. */
static void general_proxy(const opt_energy_kind *k, int d, const double *J, double *M, double *T)
{
    double U[9], V[9], s[3], w2[3], t[3];
    svd_signed(d, J, U, s, V);
    k->slim_weights(d, s, w2, t);
    for (int i = 0; i < d; i++) assert_true(w2[i] > 0 && isfinite(w2[i]) && isfinite(t[i]));
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double m = 0, ta = 0;
            for (int q = 0; q < d; q++) {
                m += U[a * d + q] * w2[q] * U[b * d + q];
                ta += U[a * d + q] * t[q] * V[b * d + q];
            }
            M[a * d + b] = m;
            T[a * d + b] = ta;
        }
}

static void slim_weights_positive_and_shortcut_agrees(void **state)
{
    (void)state;
    rng r = {23};
    for (int e = 0; e < opt_energy_count(); e++) {
        const opt_energy_kind *k = opt_energy_table[e];
        for (int d = 2; d <= 3; d++)
            for (int trial = 0; trial < 200; trial++) {
                double J[9], W[9], T[9], Mg[9], Tg[9];
                random_jacobian(&r, d, J);
                general_proxy(k, d, J, Mg, Tg);
                opt_slim_proxy((opt_energy)e, d, J, W, T); /* the shortcut where the row has one */
                double scale = 0;
                for (int q = 0; q < d * d; q++) scale = fmax(scale, fabs(Mg[q]));
                for (int a = 0; a < d; a++)
                    for (int b = 0; b < d; b++) {
                        double m = 0; /* (W^T W)[a][b]; W is symmetric */
                        for (int q = 0; q < d; q++) m += W[q * d + a] * W[q * d + b];
                        assert_true(fabs(m - Mg[a * d + b]) <= 1e-9 * (1 + scale));
                        assert_true(fabs(T[a * d + b] - Tg[a * d + b]) <= 1e-9);
                    }
            }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(names_are_unique_and_parse),
        cmocka_unit_test(rotations_are_minima_and_inversions_infinite),
        cmocka_unit_test(gradient_and_hessian_match_finite_differences),
        cmocka_unit_test(slim_weights_positive_and_shortcut_agrees),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
