/* The atlas's settle phase runs to convergence before packing: with the
 * default options it stops "converged" (the estimated distance to the
 * minimum below settle_tolerance; the old phase stopped on one
 * iteration's decrease or at a 30-iteration cap, "tolerance" /
 * "iteration_limit") and its energy is within 1e-3 (relative) of the
 * energy the same phase reaches when run to the end (no step left or 400
 * iterations, tolerance 0). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas.h"
#include "app/atlas_charts.h"
#include "scaffold/scaf_loop.h"
#include "mesh/samples.h"

/* Settle only (no re-placement, no compaction); returns the settled E. */
static double settle(const mesh *m, int iterations, double tolerance, scaf_stop_reason *why)
{
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    o.compact_iterations = 0;
    o.repack = 0;
    o.rotate = 0;
    if (iterations > 0) o.settle_iterations = iterations;
    o.settle_tolerance = tolerance;
    atlas a;
    scaf_error err;
    assert_int_equal(atlas_init(&a, m, &o, &err), SCAF_OK);
    assert_int_equal(atlas_run(&a, NULL, NULL, &err), SCAF_OK);
    *why = a.settle_stop;
    double e = a.settled_energy;
    atlas_free(&a);
    return e;
}

static void settles_to_convergence(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 3, &m, &err), SCAF_OK);
    scaf_stop_reason why, why_end;
    double e = settle(&m, 0, atlas_options_default().settle_tolerance, &why);
    double e_end = settle(&m, 400, 0.0, &why_end);
    assert_int_equal(why, SCAF_STOP_CONVERGED);
    assert_true(e >= e_end * (1.0 - 1e-12));
    assert_true((e - e_end) / e_end <= 1e-3);
    mesh_free(&m);
}

/* Charts cut for a distortion bound (automatic seams: 4.2) are not
 * compacted above it: the relative tolerance (5%) alone took settled
 * atlases above the bound their charts were split for. */
static void compaction_stays_within_the_bound(void **state)
{
    (void)state;
    const char *names[] = {"icosphere", "dented"};
    const int sizes[] = {5, 5};
    for (int i = 0; i < 2; i++) {
        mesh m;
        scaf_error err;
        assert_int_equal(mesh_sample_make(names[i], sizes[i], &m, &err), SCAF_OK);
        atlas_options o = atlas_options_default();
        o.padding = 4.0 / 1024.0;
        atlas a;
        assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
        assert_int_equal(atlas_run(&a, NULL, NULL, &err), SCAF_OK);
        double bound = ATLAS_CHARTS_MAX_DISTORTION;
        double cap = a.settled_energy > bound ? a.settled_energy : bound;
        double e = scaf_loop_energy(&a.loop);
        print_message("%s %d: settled %.6f final %.6f\n", names[i], sizes[i], a.settled_energy, e);
        assert_true(e <= cap * (1.0 + 1e-12));
        atlas_free(&a);
        mesh_free(&m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(settles_to_convergence),
        cmocka_unit_test(compaction_stays_within_the_bound),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
