/* Tests for app/untangle and mesh/closed_surface.
 *
 * The generated `dented` sphere (cap pushed through the bottom): the
 * input intersects itself; the flow frees it in a few steps (the callback
 * proves the last flow step free and the ones before not, with its own
 * exact check); every iteration of the flow back is proved free by the
 * callback's own exact check (and by verify); the result has lowest
 * energy among the iterates, is free, and is much nearer the input than
 * the flowed surface; the run is deterministic. An input already free is
 * returned unchanged with no step. Refused: open, several components,
 * genus 1 (a torus), bad options; a cancelled run leaves nothing. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/untangle.h"
#include "geom/self_intersect.h"
#include "mesh/closed_surface.h"
#include "mesh/samples.h"

typedef struct watch {
    int nv, nf;
    const int *F;
    int flow_events, back_events;
    int last_flow_free, earlier_flow_free;
    int cancel_at; /* events; 0 = never */
} watch;

static long long pairs_of(int nv, const double *X, int nf, const int *F)
{
    si_report r;
    assert_int_equal(si_check(nv, X, nf, F, &r, NULL), SCAF_OK);
    return r.pairs + r.degenerate_faces;
}

static int on_event(const untangle_event *e, void *user)
{
    watch *w = user;
    assert_non_null(e->X);
    long long p = pairs_of(w->nv, e->X, w->nf, w->F);
    if (e->phase == UNTANGLE_FLOW) {
        assert_int_equal(e->step, ++w->flow_events);
        assert_int_equal(w->back_events, 0);
        assert_int_equal(p, e->pairs);
        if (w->last_flow_free) w->earlier_flow_free = 1; /* a free step was not the last */
        w->last_flow_free = p == 0;
    } else {
        assert_int_equal(e->step, ++w->back_events);
        assert_int_equal(p, 0);                       /* free at every iteration */
        assert_true(e->pairs == 0 || e->pairs == -1); /* -1: no verify */
        assert_true(isfinite(e->energy) && e->energy >= e->arap && e->arap >= 0);
        assert_true(e->tets > 0 && e->quality > 0);
    }
    return w->cancel_at && w->flow_events + w->back_events == w->cancel_at;
}

static void dented(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("dented", 4, &m, NULL), SCAF_OK);
    assert_true(pairs_of(m.nv, m.V, m.nf, m.F) > 0);
    untangle_options o = untangle_options_default();
    o.verify = 1;
    o.iterations = 60;
    watch w = {m.nv, m.nf, m.F, 0, 0, 0, 0, 0};
    untangle_result r;
    scaf_error err;
    scaf_status st = untangle_run(m.nv, m.V, m.nf, m.F, &o, on_event, &w, &r, &err);
    if (st != SCAF_OK) print_error("%s\n", err.message);
    assert_int_equal(st, SCAF_OK);
    assert_true(r.input_pairs > 0);
    assert_true(r.flow_steps >= 1 && r.flow_steps <= 8);
    assert_int_equal(w.flow_events, r.flow_steps);
    assert_true(w.last_flow_free);
    assert_false(w.earlier_flow_free);
    assert_int_equal(w.back_events, r.iterations);
    assert_true(r.iterations >= 1);
    assert_true(r.stop != UNTANGLE_ALREADY_FREE);
    assert_int_equal(r.nlog, r.flow_steps + r.iterations);
    /* the result is the iterate of lowest energy, free, nearer than the flowed */
    assert_true(r.best_iteration >= 1 && r.best_iteration <= r.iterations);
    const untangle_event *b = &r.log[r.flow_steps + r.best_iteration - 1];
    for (int i = r.flow_steps; i < r.nlog; i++) assert_true(r.log[i].energy >= b->energy);
    assert_true(r.rms == b->rms && r.max == b->max);
    assert_int_equal(pairs_of(m.nv, r.X, m.nf, m.F), 0);
    assert_int_equal(pairs_of(m.nv, r.flowed, m.nf, m.F), 0);
    assert_true(r.flowed_rms > 0);
    assert_true(r.rms < 0.5 * r.flowed_rms);
    /* deterministic */
    untangle_result r2;
    o.verify = 0;
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, &o, NULL, NULL, &r2, NULL), SCAF_OK);
    assert_int_equal(r2.iterations, r.iterations);
    assert_memory_equal(r2.X, r.X, sizeof(double) * 3 * (size_t)m.nv);
    untangle_result_free(&r2);
    untangle_result_free(&r);
    mesh_free(&m);
}

static void cancelled(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("dented", 4, &m, NULL), SCAF_OK);
    watch w = {m.nv, m.nf, m.F, 0, 0, 0, 0, 0};
    w.cancel_at = 8; /* during the flow back */
    untangle_result r;
    scaf_error err;
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, NULL, on_event, &w, &r, &err),
                     SCAF_ERR_CANCELLED);
    assert_null(r.X);
    assert_null(r.log);
    mesh_free(&m);
}

static void already_free(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, NULL), SCAF_OK);
    watch w = {m.nv, m.nf, m.F, 0, 0, 0, 0, 0};
    untangle_result r;
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, NULL, on_event, &w, &r, NULL), SCAF_OK);
    assert_int_equal(r.stop, UNTANGLE_ALREADY_FREE);
    assert_int_equal(r.input_pairs, 0);
    assert_int_equal(r.flow_steps + r.iterations + r.nlog + w.flow_events + w.back_events, 0);
    assert_memory_equal(r.X, m.V, sizeof(double) * 3 * (size_t)m.nv);
    assert_true(r.rms == 0 && r.max == 0);
    untangle_result_free(&r);
    mesh_free(&m);
}

/* A torus, n x n quads split in two: genus 1. */
static void torus(mesh *m, int n)
{
    assert_int_equal(mesh_alloc(m, n * n, 2 * n * n, 0, NULL), SCAF_OK);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double u = 2 * 3.14159265358979 * i / n, v = 2 * 3.14159265358979 * j / n;
            double *p = m->V + 3 * (i * n + j);
            p[0] = (1 + 0.4 * cos(v)) * cos(u);
            p[1] = (1 + 0.4 * cos(v)) * sin(u);
            p[2] = 0.4 * sin(v);
            int a = i * n + j, b = (i + 1) % n * n + j, c = (i + 1) % n * n + (j + 1) % n,
                d = i * n + (j + 1) % n, *f = m->F + 6 * (i * n + j);
            f[0] = a, f[1] = b, f[2] = c, f[3] = a, f[4] = c, f[5] = d;
        }
}

static void refusals(void **state)
{
    (void)state;
    mesh m;
    untangle_result r;
    scaf_error err;
    torus(&m, 12);
    assert_int_equal(closed_surface_check(&m, 0, &err), SCAF_OK);
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, NULL, NULL, NULL, &r, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "genus 1"));
    assert_null(r.X);
    mesh_free(&m);
    assert_int_equal(mesh_sample_make("hemisphere", 3, &m, NULL), SCAF_OK);
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, NULL, NULL, NULL, &r, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "open"));
    mesh_free(&m);
    /* two spheres: twice the faces of one, the second shifted */
    mesh one;
    assert_int_equal(mesh_sample_make("icosphere", 2, &one, NULL), SCAF_OK);
    assert_int_equal(mesh_alloc(&m, 2 * one.nv, 2 * one.nf, 0, NULL), SCAF_OK);
    for (int k = 0; k < 3 * one.nv; k++) m.V[k] = one.V[k], m.V[3 * one.nv + k] = one.V[k] + 3;
    for (int k = 0; k < 3 * one.nf; k++) m.F[k] = one.F[k], m.F[3 * one.nf + k] = one.F[k] + one.nv;
    assert_int_equal(closed_surface_check(&m, 0, &err), SCAF_OK);
    assert_int_equal(untangle_run(m.nv, m.V, m.nf, m.F, NULL, NULL, NULL, &r, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "2 connected components"));
    mesh_free(&m);
    /* options */
    untangle_options bad[5];
    for (int k = 0; k < 5; k++) bad[k] = untangle_options_default();
    bad[0].delta = 0;
    bad[1].flow_steps = 0;
    bad[2].iterations = 0;
    bad[3].tolerance = 1;
    bad[4].anchor_ratio = -1;
    for (int k = 0; k < 5; k++) {
        assert_int_equal(untangle_run(one.nv, one.V, one.nf, one.F, &bad[k], NULL, NULL, &r, &err),
                         SCAF_ERR_USAGE);
        assert_null(r.X);
    }
    /* too few flow steps: numeric failure naming what is left */
    mesh d;
    assert_int_equal(mesh_sample_make("dented", 4, &d, NULL), SCAF_OK);
    untangle_options o = untangle_options_default();
    o.flow_steps = 1;
    assert_int_equal(untangle_run(d.nv, d.V, d.nf, d.F, &o, NULL, NULL, &r, &err),
                     SCAF_ERR_NUMERIC);
    assert_non_null(strstr(err.message, "did not free"));
    assert_null(r.X);
    mesh_free(&d);
    mesh_free(&one);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dented),
        cmocka_unit_test(cancelled),
        cmocka_unit_test(already_free),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
