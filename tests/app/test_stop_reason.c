/* Why a run stopped (scaf_stop_reason, include/scaf/scaf.h): every
 * reason the parametrization and the atlas can give is reached on a small
 * generated mesh and reported by scaf_param_stop_reason /
 * scaf_atlas_stop_reason, and it agrees with the iterations seen by the
 * progress callback (a zero step ends the run at the iteration whose step
 * was 0, even with tolerance 0; the cap at exactly the cap; ...). Every
 * reason has a distinct snake_case name. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/samples.h"
#include "scaf/scaf.h"

/* ---- parametrization ------------------------------------------------------ */

typedef struct seen {
    int calls;
    double last_step;
    double first_criterion, last_criterion;
    int cancel_at; /* return nonzero at this call (0: never) */
} seen;

static int on_param(const scaf_iteration_info_t *info, void *user)
{
    seen *s = user;
    s->calls++;
    s->last_step = info->step;
    if (s->calls == 1) s->first_criterion = info->criterion;
    s->last_criterion = info->criterion;
    return s->cancel_at && s->calls == s->cancel_at;
}

/* A context on a generated sample (without its UVs) with these options. */
static scaf_param_t *param_on(const char *sample, int size, const scaf_options_t *o, mesh *m)
{
    scaf_error err;
    assert_int_equal(mesh_sample_make(sample, size, m, &err), SCAF_OK);
    scaf_param_t *p = scaf_param_new(o);
    assert_non_null(p);
    assert_int_equal(scaf_param_set_mesh(p, m->V, m->nv, m->F, m->nf, NULL, 0, NULL), SCAF_OK);
    return p;
}

static void param_reasons(void **state)
{
    (void)state;
    mesh m;
    scaf_options_t o = scaf_options_default();

    /* before any run; the cap */
    scaf_param_t *p = param_on("hemisphere", 4, &o, &m);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_NONE);
    seen s = {0};
    assert_int_equal(scaf_param_run(p, 2, on_param, &s), SCAF_OK);
    assert_int_equal(s.calls, 2);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_ITERATIONS);
    /* a new mesh forgets the last run */
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_NONE);
    scaf_param_destroy(p);
    mesh_free(&m);

    /* the tolerance, well before the cap: SLIM steps are judged by the
     * same criterion (the linear tail), from the 4th iteration on */
    o.tolerance = 1e-2;
    o.solver = SCAF_SOLVER_SLIM;
    p = param_on("hemisphere", 4, &o, &m);
    memset(&s, 0, sizeof s);
    assert_int_equal(scaf_param_run(p, 100, on_param, &s), SCAF_OK);
    assert_true(s.calls < 100 && s.calls >= 4);
    assert_true(s.last_step > 0.0);
    assert_true(s.last_criterion < o.tolerance);
    assert_true(isinf(s.first_criterion));
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_CONVERGED);
    scaf_param_destroy(p);
    mesh_free(&m);

    /* auto (the default): a full Newton step with a small decrement */
    o.solver = SCAF_SOLVER_AUTO;
    p = param_on("hemisphere", 4, &o, &m);
    memset(&s, 0, sizeof s);
    assert_int_equal(scaf_param_run(p, 100, on_param, &s), SCAF_OK);
    assert_true(s.calls < 100);
    assert_true(s.last_step == 1.0);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_CONVERGED);
    scaf_param_destroy(p);
    mesh_free(&m);

    /* tolerance 0 on a mesh that converges: a zero step ends the run
     * before the cap (the "asked for 300, stopped at 41") */
    o.tolerance = 0.0;
    p = param_on("hemisphere", 4, &o, &m);
    memset(&s, 0, sizeof s);
    assert_int_equal(scaf_param_run(p, 1000, on_param, &s), SCAF_OK);
    assert_true(s.calls < 1000);
    assert_true(s.last_step == 0.0);
    assert_int_equal(scaf_param_iterations(p), s.calls);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_ZERO_STEP);
    scaf_param_destroy(p);
    mesh_free(&m);

    /* cancelled by the callback */
    p = param_on("hemisphere", 4, &o, &m);
    memset(&s, 0, sizeof s);
    s.cancel_at = 3;
    assert_int_equal(scaf_param_run(p, 10, on_param, &s), SCAF_ERR_CANCELLED);
    assert_int_equal(s.calls, 3);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_CANCELLED);
    /* and the next run says its own reason */
    memset(&s, 0, sizeof s);
    assert_int_equal(scaf_param_run(p, 1, on_param, &s), SCAF_OK);
    assert_int_equal(scaf_param_stop_reason(p), SCAF_STOP_ITERATIONS);
    scaf_param_destroy(p);
    mesh_free(&m);
    assert_int_equal(scaf_param_stop_reason(NULL), SCAF_STOP_NONE);
}

/* ---- atlas ------------------------------------------------------------------ */

typedef struct atlas_seen {
    int calls, settle, compact;
    int cancel_at; /* return nonzero at this call (0: never) */
} atlas_seen;

static int on_atlas(const scaf_atlas_iteration_info_t *it, void *user)
{
    atlas_seen *s = user;
    s->calls++;
    if (it->phase == SCAF_ATLAS_SETTLE) s->settle++;
    else s->compact++;
    return s->cancel_at && s->calls == s->cancel_at;
}

/* Run an atlas of a generated sample (its vt charts when it has UVs);
 * returns the run's status, the reasons of both phases in r[2]. */
static scaf_status atlas_run_on(const char *sample, int size, const scaf_atlas_options_t *o,
                                atlas_seen *s, scaf_stop_reason r[2])
{
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make(sample, size, &m, &err), SCAF_OK);
    scaf_atlas_t *a = scaf_atlas_new(o);
    assert_non_null(a);
    assert_int_equal(mesh_has_uv(&m)
                         ? scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT)
                         : scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL),
                     SCAF_OK);
    assert_int_equal(scaf_atlas_stop_reason(a, SCAF_ATLAS_SETTLE), SCAF_STOP_NONE);
    assert_int_equal(scaf_atlas_stop_reason(a, SCAF_ATLAS_COMPACT), SCAF_STOP_NONE);
    s->calls = s->settle = s->compact = 0; /* (cancel_at is the caller's) */
    scaf_status st = scaf_atlas_run(a, on_atlas, s);
    r[0] = scaf_atlas_stop_reason(a, SCAF_ATLAS_SETTLE);
    r[1] = scaf_atlas_stop_reason(a, SCAF_ATLAS_COMPACT);
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE), s->settle);
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT), s->compact);
    scaf_atlas_destroy(a);
    mesh_free(&m);
    return st;
}

/* The defaults, as `scaf atlas` runs (the reasons below were measured with
 * them on these samples). */
static scaf_atlas_options_t small_atlas(void) { return scaf_atlas_options_default(); }

static void atlas_reasons(void **state)
{
    (void)state;
    scaf_stop_reason r[2];
    atlas_seen s = {0};
    /* Which of the compaction's tests fires first depends on the last
     * digits of the map, which depend on the BLAS thread count (and on the
     * solver's summation order): one thread, whatever the machine has. */
    int threads = scaf_set_threads(1);

    /* settle: the cap; compaction: the cap */
    scaf_atlas_options_t o = small_atlas();
    o.settle_iterations = 1;
    o.compact_iterations = 1;
    o.distortion_tolerance = 10.0; /* checked before the cap */
    assert_int_equal(atlas_run_on("cubesphere", 3, &o, &s, r), SCAF_OK);
    assert_int_equal(s.settle, 1);
    assert_int_equal(s.compact, 1);
    assert_int_equal(r[0], SCAF_STOP_ITERATIONS);
    assert_int_equal(r[1], SCAF_STOP_ITERATIONS);

    /* settle: the tolerance; no compaction (compact_iterations 0) */
    o = small_atlas();
    o.settle_tolerance = 1e-2;
    o.compact_iterations = 0;
    assert_int_equal(atlas_run_on("hemisphere", 4, &o, &s, r), SCAF_OK);
    assert_true(s.settle < o.settle_iterations);
    assert_int_equal(s.compact, 0);
    assert_int_equal(r[0], SCAF_STOP_CONVERGED);
    assert_int_equal(r[1], SCAF_STOP_NONE);

    /* settle with tolerance 0 on a mesh that converges: a zero step (a
     * flat grid, E 4 exactly: the hemisphere without vt reached it from
     * Tutte, but its automatic charts now start from the layout their
     * refinement settled, from which steps in the last digits go on past
     * 1000 iterations, as on cubesphere 3) */
    o = small_atlas();
    o.settle_tolerance = 0.0;
    o.settle_iterations = 1000;
    assert_int_equal(atlas_run_on("grid", 6, &o, &s, r), SCAF_OK);
    assert_true(s.settle < 1000);
    assert_int_equal(r[0], SCAF_STOP_ZERO_STEP);

    /* ... and where steps go on in the last digits (cubesphere 3's E
     * drifts by 1e-10 after iteration 60; charts started from their
     * settled layout): no new low in 10 iterations ends the run at the
     * loop's noise floor (both ran to the cap before) */
    o.settle_iterations = 400;
    assert_int_equal(atlas_run_on("cubesphere", 3, &o, &s, r), SCAF_OK);
    assert_true(s.settle < 400);
    assert_int_equal(r[0], SCAF_STOP_NOISE_FLOOR);
    o.compact_iterations = 0;
    assert_int_equal(atlas_run_on("hemisphere", 4, &o, &s, r), SCAF_OK);
    assert_true(s.settle < 400);
    assert_int_equal(r[0], SCAF_STOP_NOISE_FLOOR);

    /* compaction: E may not grow at all: the distortion limit */
    o = small_atlas();
    o.distortion_tolerance = 0.0;
    assert_int_equal(atlas_run_on("cubesphere", 3, &o, &s, r), SCAF_OK);
    assert_true(s.compact < o.compact_iterations);
    assert_int_equal(r[1], SCAF_STOP_DISTORTION);

    /* compaction with room for distortion: the layout stops shrinking
     * (cubesphere 6 stalls first since the working vertices are numbered
     * breadth first: which test fires first follows the map's last digits) */
    o = small_atlas();
    o.distortion_tolerance = 10.0;
    assert_int_equal(atlas_run_on("cubesphere", 5, &o, &s, r), SCAF_OK);
    assert_true(s.compact < o.compact_iterations);
    assert_int_equal(r[1], SCAF_STOP_PACKING_STALLED);

    /* ... or no step is taken three times in a row (a stiffer scaffold;
     * which test fires first follows the map's last digits: this one was
     * found by trying sizes and weights) */
    o.compact_iterations = 300;
    o.compact_lambda_ratio = 4.0;
    assert_int_equal(atlas_run_on("cubesphere", 4, &o, &s, r), SCAF_OK);
    assert_true(s.compact < o.compact_iterations);
    assert_int_equal(r[1], SCAF_STOP_ZERO_STEP);

    /* cancelled in the settle phase: compaction never ran */
    o = small_atlas();
    s.cancel_at = 1;
    assert_int_equal(atlas_run_on("cubesphere", 3, &o, &s, r), SCAF_ERR_CANCELLED);
    assert_int_equal(r[0], SCAF_STOP_CANCELLED);
    assert_int_equal(r[1], SCAF_STOP_NONE);

    /* cancelled in compaction: settling ended by its own rule */
    o = small_atlas();
    o.settle_iterations = 2;
    s.cancel_at = 3;
    assert_int_equal(atlas_run_on("cubesphere", 3, &o, &s, r), SCAF_ERR_CANCELLED);
    assert_int_equal(r[0], SCAF_STOP_ITERATIONS);
    assert_int_equal(r[1], SCAF_STOP_CANCELLED);

    assert_int_equal(scaf_atlas_stop_reason(NULL, SCAF_ATLAS_SETTLE), SCAF_STOP_NONE);
    if (threads > 0) scaf_set_threads(threads);
}

/* ---- names ------------------------------------------------------------------ */

static void names_are_distinct_words(void **state)
{
    (void)state;
    const scaf_stop_reason all[] = {
        SCAF_STOP_NONE,      SCAF_STOP_ITERATIONS, SCAF_STOP_TOLERANCE,  SCAF_STOP_ZERO_STEP,
        SCAF_STOP_CANCELLED, SCAF_STOP_ERROR,      SCAF_STOP_DISTORTION, SCAF_STOP_PACKING_STALLED,
        SCAF_STOP_CONVERGED, SCAF_STOP_NOISE_FLOOR};
    int n = (int)(sizeof all / sizeof all[0]);
    for (int i = 0; i < n; i++) {
        const char *a = scaf_stop_reason_name(all[i]);
        assert_non_null(a);
        assert_string_not_equal(a, "unknown");
        for (const char *c = a; *c; c++) assert_true((*c >= 'a' && *c <= 'z') || *c == '_');
        for (int j = 0; j < i; j++) assert_string_not_equal(a, scaf_stop_reason_name(all[j]));
    }
    assert_string_equal(scaf_stop_reason_name(SCAF_STOP_ITERATIONS), "iteration_limit");
    assert_string_equal(scaf_stop_reason_name(SCAF_STOP_ZERO_STEP), "zero_step");
    assert_string_equal(scaf_stop_reason_name(SCAF_STOP_NOISE_FLOOR), "noise_floor");
    assert_string_equal(scaf_stop_reason_name((scaf_stop_reason)99), "unknown");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_reasons),
        cmocka_unit_test(atlas_reasons),
        cmocka_unit_test(names_are_distinct_words),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
