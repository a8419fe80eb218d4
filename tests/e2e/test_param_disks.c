/* End-to-end: `scaf param` on the larger disk meshes of ../shared/data
 * (bull_1, hilbert, mountain, aphrodite), bijective after EVERY iteration
 * (exact checker), each accepted step lowering its iteration's total energy.
 * The smaller disks, the seam meshes and plane_holes are in test_param.c.
 * Few iterations here: the point is the guarantee on hard shapes (hilbert's
 * boundary comes close to itself everywhere; bull_1 has a long cut), not
 * convergence, which bench/bench_param measures. Skipped when the data
 * folder is absent. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "support/param_watch.h"

static void run_or_skip(const char *rel, int iterations, scaf_init init)
{
    if (test_is_sanitized() && iterations > 2) iterations = 2;
    if (isnan(param_run_watched(rel, iterations, init, NULL, 0))) skip();
}

static void bull_1(void **state)
{
    (void)state;
    run_or_skip("disk/bull_1.obj", 6, SCAF_INIT_TUTTE);
}

static void hilbert(void **state)
{
    (void)state;
    run_or_skip("disk/hilbert.obj", 6, SCAF_INIT_TUTTE);
}

static void mountain(void **state)
{
    (void)state;
    run_or_skip("disk/mountain.obj", 4, SCAF_INIT_HARMONIC);
}

static void aphrodite(void **state)
{
    (void)state;
    run_or_skip("disk/aphrodite.obj", 3, SCAF_INIT_HARMONIC);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bull_1),
        cmocka_unit_test(hilbert),
        cmocka_unit_test(mountain),
        cmocka_unit_test(aphrodite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
