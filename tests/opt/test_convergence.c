/* Tests for opt/convergence: the estimated relative distance to the
 * minimum from an iteration history. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>

#include "opt/convergence.h"

/* Feed E_k = e_min + c rho^k for k = 0..n; returns the last criterion. */
static double feed_linear(opt_convergence *c, double e_min, double rho, int n)
{
    double crit = INFINITY, e = e_min + 1.0;
    for (int k = 1; k <= n; k++) {
        double next = e_min + pow(rho, k);
        crit = opt_convergence_update(c, e, next, 0.0);
        e = next;
    }
    return crit;
}

/* Not judged before the window is full. */
static void unknown_at_first(void **state)
{
    (void)state;
    opt_convergence c;
    opt_convergence_reset(&c);
    for (int k = 0; k < OPT_CONV_WINDOW; k++)
        assert_true(isinf(opt_convergence_update(&c, 2.0, 1.0, 1e-12)));
    assert_true(isfinite(opt_convergence_update(&c, 1.0, 0.999, 0.0)));
}

/* Linear convergence: the tail is the true remaining distance, whatever
 * the rate, where one iteration's decrease underestimates it by
 * rho / (1 - rho) (100x at rho = 0.99). */
static void linear_tail_is_the_distance(void **state)
{
    (void)state;
    const double rates[] = {0.1, 0.5, 0.9, 0.98};
    for (int i = 0; i < 4; i++) {
        opt_convergence c;
        opt_convergence_reset(&c);
        double rho = rates[i], e_min = 1.0;
        int n = 8; /* < OPT_CONV_STALL: the tail alone */
        double crit = feed_linear(&c, e_min, rho, n);
        double e = e_min + pow(rho, n), truth = (e - e_min) / e;
        assert_true(fabs(crit - truth) <= 1e-4 * truth);
    }
}

/* One slow iteration in a fast-shrinking but still far sequence does not
 * make it look converged: the largest ratio of the window counts. */
static void one_slow_iteration_is_not_convergence(void **state)
{
    (void)state;
    opt_convergence c;
    opt_convergence_reset(&c);
    const double dec[] = {1.0, 0.9, 0.8, 1e-9, 0.7};
    double e = 100.0, crit = 0.0;
    for (int k = 0; k < 5; k++) {
        crit = opt_convergence_update(&c, e, e - dec[k], 0.0);
        e -= dec[k];
        if (k == 3) assert_true(crit > 1e-3); /* the slow one: 1e-9 / E alone */
    }
    /* stalled sequences count as rho = OPT_CONV_RHO_MAX */
    opt_convergence_reset(&c);
    e = 100.0;
    for (int k = 0; k < 6; k++) {
        crit = opt_convergence_update(&c, e, e - 1e-3, 0.0);
        e -= 1e-3;
    }
    double want = 1e-3 / e * OPT_CONV_RHO_MAX / (1.0 - OPT_CONV_RHO_MAX);
    assert_true(fabs(crit - want) <= 1e-9 * want);
}

/* The Newton decrement counts when it is the larger; a rise counts by its
 * size. */
static void decrement_and_rises(void **state)
{
    (void)state;
    opt_convergence c;
    opt_convergence_reset(&c);
    double crit = feed_linear(&c, 1.0, 0.01, 8); /* quadratic-like: tail tiny */
    assert_true(crit < 1e-12);
    assert_true(opt_convergence_update(&c, 1.0, 1.0 - 1e-14, 1e-3) == 1e-3);
    opt_convergence_reset(&c);
    double e = 1.0;
    for (int k = 0; k < 4; k++) {
        double next = k % 2 ? e - 1e-4 : e + 1e-4; /* oscillating */
        crit = opt_convergence_update(&c, e, next, 0.0);
        e = next;
    }
    assert_true(crit >= 1e-4 * OPT_CONV_RHO_MAX / (1.0 - OPT_CONV_RHO_MAX) * 0.5);
}

/* An energy going back and forth without net progress (the SCAF loop's
 * noise floor) converges by the stall rule after OPT_CONV_STALL
 * iterations, while the tail alone would say 100 times the swing. */
static void no_progress_is_a_stall(void **state)
{
    (void)state;
    opt_convergence c;
    opt_convergence_reset(&c);
    double e = 4.0, crit = 0.0;
    for (int k = 0; k < 30; k++) {
        double next = 4.0 + 1e-5 * ((k * 7) % 5); /* swings of up to 4e-5 */
        crit = opt_convergence_update(&c, e, next, 5e-5);
        if (k < OPT_CONV_STALL + 4) assert_true(crit >= 5e-5 || k >= OPT_CONV_STALL);
        e = next;
    }
    /* the lowest energy (4.0) has not moved for 10 iterations and the
     * last one is at most 4e-5 above it */
    assert_true(crit <= 4e-5 / 4.0 * (1 + 1e-9));
    /* a steady decrease is no stall */
    opt_convergence_reset(&c);
    e = 4.0;
    for (int k = 0; k < 30; k++) {
        crit = opt_convergence_update(&c, e, e - 1e-3, 0.0);
        e -= 1e-3;
    }
    assert_true(crit > 1e-3);
    /* nor is a steady rise (the lowest energy stays put, the energy does
     * not: the run's objective also holds the scaffold) */
    opt_convergence_reset(&c);
    e = 4.0;
    for (int k = 0; k < 30; k++) {
        crit = opt_convergence_update(&c, e, e + 1e-3, 0.0);
        e += 1e-3;
    }
    assert_true(crit > 1e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unknown_at_first),
        cmocka_unit_test(linear_tail_is_the_distance),
        cmocka_unit_test(one_slow_iteration_is_not_convergence),
        cmocka_unit_test(decrement_and_rises),
        cmocka_unit_test(no_progress_is_a_stall),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
