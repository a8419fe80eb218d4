/* Hard positional constraints of app/deform, every iteration watched
 * through the progress callback:
 *   - pins: pinned vertices keep their bits (memcmp against the rest
 *     shape after every iteration) while soft handles drag the rest of the
 *     spiral strip; without the pins the same vertices move;
 *   - hard targets: the circle -> spiral drag (mesh/spiral_strip) with
 *     every target hard ends with every vertex exactly on its target
 *     (handle error == 0), bijective (exact checker); a vertex that reached
 *     its target keeps those bits in every later iteration;
 *   - infeasible: held corners of a triangle flipped at their targets (a
 *     spiral triangle's hard targets swapped; a grid vertex sent out of
 *     its ring of pinned neighbours) are refused before any iteration; a
 *     hard target on top of a pinned vertex elsewhere is never met, and the
 *     run ends after the bounded stall, well before its iteration cap. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/deform.h"
#include "geom/bijectivity.h"
#include "mesh/samples.h"
#include "mesh/spiral_strip.h"

enum { SEG = 26, NV = 2 * (SEG + 1), NFR = SPIRAL_STRIP_FRAMES - 1 };

typedef struct watch {
    deform_options *o;
    const mesh *m;
    const double *P;      /* rest */
    const double *target; /* per vertex, for hard runs (NULL: none) */
    const int *pins;
    int npins;
    int iterations, failures, pins_moved, moved_after_reached;
    int reached_at[NV]; /* first iteration on the target exactly (0: never) */
    double last[2 * NV];
} watch;

static int each_iteration(const scaf_iteration_info_t *info, void *user)
{
    watch *w = user;
    const double *X = w->o->current;
    bij_report rep;
    if (bij_check(w->m->nv, X, w->m->nf, w->m->F, NULL, NULL, &rep, NULL) != SCAF_OK ||
        !rep.bijective)
        w->failures++;
    for (int i = 0; i < w->npins; i++)
        if (memcmp(X + 2 * w->pins[i], w->P + 2 * w->pins[i], 2 * sizeof(double)) != 0)
            w->pins_moved++;
    for (int v = 0; w->target && v < w->m->nv; v++) {
        if (w->reached_at[v] && memcmp(X + 2 * v, w->last + 2 * v, 2 * sizeof(double)) != 0)
            w->moved_after_reached++;
        if (!w->reached_at[v] && X[2 * v] == w->target[2 * v] &&
            X[2 * v + 1] == w->target[2 * v + 1])
            w->reached_at[v] = info->iteration;
    }
    memcpy(w->last, X, sizeof(double) * 2 * (size_t)w->m->nv);
    w->iterations++;
    return 0;
}

static double *planar(const mesh *m)
{
    double *P = malloc(sizeof(double) * 2 * (size_t)m->nv);
    assert_non_null(P);
    for (int v = 0; v < m->nv; v++) P[2 * v] = m->V[3 * v], P[2 * v + 1] = m->V[3 * v + 1];
    return P;
}

/* The spiral's targets T (NV by 2) and its drag frames after them. */
static double *spiral_targets(void)
{
    double *T = malloc(sizeof(double) * 2 * NV * SPIRAL_STRIP_FRAMES);
    assert_non_null(T);
    spiral_strip_curl(SEG, 1.0, T);
    for (int f = 0; f < NFR; f++)
        spiral_strip_curl(SEG, (f + 1.0) / SPIRAL_STRIP_FRAMES, T + 2 * (size_t)NV * (f + 1));
    return T;
}

/* The strip dragged by soft handles on every vertex but pins[0..npins):
 * the final positions in X. */
static void drag_with_pins(const int *pins, int npins, double *X, watch *w)
{
    mesh m;
    assert_int_equal(spiral_strip_make(SEG, &m, NULL), SCAF_OK);
    double *P = planar(&m), *T = spiral_targets();
    int hv[NV], nh = 0;
    double ht[2 * NV], frames[2 * NV * NFR];
    for (int v = 0; v < NV; v++) {
        int pinned = 0;
        for (int i = 0; i < npins; i++) pinned |= pins[i] == v;
        if (pinned) continue;
        ht[2 * nh] = T[2 * v], ht[2 * nh + 1] = T[2 * v + 1];
        hv[nh++] = v;
    }
    for (int f = 0; f < NFR; f++)
        for (int i = 0; i < nh; i++)
            for (int a = 0; a < 2; a++)
                frames[2 * (f * nh + i) + a] = T[2 * ((size_t)NV * (f + 1) + hv[i]) + a];
    deform_options o = deform_options_default();
    o.pins = pins;
    o.npins = npins;
    memset(w, 0, sizeof *w);
    *w = (watch){&o, &m, P, NULL, pins, npins, 0, 0, 0, 0, {0}, {0}};
    o.progress = each_iteration;
    o.user = w;
    deform_result r;
    scaf_error err;
    assert_int_equal(deform_run(NV, P, m.nf, m.F, nh, hv, ht, NFR, frames, &o, X, &r, &err),
                     SCAF_OK);
    assert_int_equal(w->iterations, r.iterations);
    assert_true(r.iterations > 4 * NFR);
    assert_int_equal(w->failures, 0);
    free(P);
    free(T);
    mesh_free(&m);
}

static void pinned_vertices_keep_their_bits(void **state)
{
    (void)state;
    /* the first station (its targets move little) and one further on */
    const int pins[3] = {0, 1, 8};
    double X[2 * NV], Y[2 * NV];
    watch w;
    drag_with_pins(pins, 3, X, &w);
    assert_int_equal(w.pins_moved, 0);
    mesh m;
    assert_int_equal(spiral_strip_make(SEG, &m, NULL), SCAF_OK);
    double *P = planar(&m);
    for (int i = 0; i < 3; i++)
        assert_memory_equal(X + 2 * pins[i], P + 2 * pins[i], 2 * sizeof(double));
    /* the control: no pins, but the same vertices without handles (held
     * by nothing) move */
    const int none[3] = {0, 1, 8};
    drag_with_pins(none, 0, Y, &w);
    int moved = 0;
    for (int i = 0; i < 3; i++)
        moved += memcmp(Y + 2 * pins[i], P + 2 * pins[i], 2 * sizeof(double)) != 0;
    assert_int_equal(moved, 3);
    free(P);
    mesh_free(&m);
}

static void hard_spiral_meets_every_target_exactly(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(spiral_strip_make(SEG, &m, NULL), SCAF_OK);
    double *P = planar(&m), *T = spiral_targets(), X[2 * NV];
    int hv[NV];
    unsigned char hard[NV];
    for (int v = 0; v < NV; v++) hv[v] = v, hard[v] = 1;
    deform_options o = deform_options_default();
    o.hard = hard;
    o.iterations = 300;
    watch w;
    memset(&w, 0, sizeof w);
    w.o = &o, w.m = &m, w.P = P, w.target = T;
    o.progress = each_iteration;
    o.user = &w;
    deform_result r;
    scaf_error err;
    assert_int_equal(deform_run(NV, P, m.nf, m.F, NV, hv, T, NFR, T + 2 * NV, &o, X, &r, &err),
                     SCAF_OK);
    print_message("hard spiral: %d iterations, E %.4f, %d of %d met, error %g\n", r.iterations,
                  r.energy, r.hard_reached, r.hard, r.max_handle_error);
    assert_int_equal(r.hard, NV);
    assert_int_equal(r.hard_reached, NV);
    assert_int_equal(r.infeasible, 0);
    assert_true(r.max_handle_error == 0.0);
    for (int v = 0; v < NV; v++) {
        assert_true(X[2 * v] == T[2 * v] && X[2 * v + 1] == T[2 * v + 1]);
        assert_true(w.reached_at[v] > 4 * NFR); /* not during the drag */
    }
    assert_int_equal(w.moved_after_reached, 0);
    assert_int_equal(w.failures, 0);
    bij_report rep;
    assert_int_equal(bij_check(NV, X, m.nf, m.F, NULL, NULL, &rep, NULL), SCAF_OK);
    assert_true(rep.bijective);
    free(P);
    free(T);
    mesh_free(&m);
}

static void flipped_held_triangles_are_refused_up_front(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(spiral_strip_make(SEG, &m, NULL), SCAF_OK);
    double *P = planar(&m), *T = spiral_targets(), X[2 * NV];
    int hv[NV];
    unsigned char hard[NV];
    for (int v = 0; v < NV; v++) hv[v] = v, hard[v] = 1;
    /* two corners of triangle 1 swap targets: it is flipped there */
    int a = m.F[0], b = m.F[1];
    for (int k = 0; k < 2; k++) {
        double s = T[2 * a + k];
        T[2 * a + k] = T[2 * b + k], T[2 * b + k] = s;
    }
    deform_options o = deform_options_default();
    o.hard = hard;
    watch w;
    memset(&w, 0, sizeof w);
    w.o = &o, w.m = &m, w.P = P;
    o.progress = each_iteration;
    o.user = &w;
    deform_result r;
    scaf_error err;
    assert_int_equal(deform_run(NV, P, m.nf, m.F, NV, hv, T, 0, NULL, &o, X, &r, &err),
                     SCAF_ERR_MESH);
    assert_int_equal(r.infeasible, 1);
    assert_int_equal(w.iterations, 0);
    assert_non_null(strstr(err.message, "infeasible: triangle 1 "));
    /* soft, the same targets are a run like any other */
    o.hard = NULL;
    o.iterations = 5;
    assert_int_equal(deform_run(NV, P, m.nf, m.F, NV, hv, T, 0, NULL, &o, X, &r, &err), SCAF_OK);
    assert_int_equal(r.infeasible, 0);
    free(P);
    free(T);
    mesh_free(&m);

    /* a grid vertex with its ring pinned, sent outside the ring */
    assert_int_equal(mesh_sample_make("grid", 4, &m, NULL), SCAF_OK);
    P = planar(&m);
    int centre = -1;
    for (int v = 0; v < m.nv && centre < 0; v++)
        if (fabs(P[2 * v] - 0.5 * (P[0] + P[2 * (m.nv - 1)])) < 1e-12 &&
            fabs(P[2 * v + 1] - 0.5 * (P[1] + P[2 * (m.nv - 1) + 1])) < 1e-12)
            centre = v;
    assert_true(centre >= 0);
    int ring[16], nring = 0;
    for (int f = 0; f < m.nf; f++)
        for (int j = 0; j < 3; j++)
            if (m.F[3 * f + j] == centre)
                for (int k = 0; k < 3; k++) {
                    int u = m.F[3 * f + k], seen = u == centre;
                    for (int i = 0; i < nring; i++) seen |= ring[i] == u;
                    if (!seen) ring[nring++] = u;
                }
    assert_true(nring >= 4);
    double target[2] = {P[0] - 1.0, P[1] - 1.0}, *Y = malloc(sizeof(double) * 2 * (size_t)m.nv);
    unsigned char one = 1;
    o = deform_options_default();
    o.hard = &one;
    o.pins = ring;
    o.npins = nring;
    assert_non_null(Y);
    assert_int_equal(deform_run(m.nv, P, m.nf, m.F, 1, &centre, target, 0, NULL, &o, Y, &r, &err),
                     SCAF_ERR_MESH);
    assert_int_equal(r.infeasible, 1);
    assert_non_null(strstr(err.message, "pinned"));
    free(Y);
    free(P);
    mesh_free(&m);
}

static void unreachable_hard_target_ends_after_a_bounded_stall(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(spiral_strip_make(SEG, &m, NULL), SCAF_OK);
    double *P = planar(&m), X[2 * NV];
    /* vertex 0 sent onto pinned vertex 30 (not a neighbour): no bijective
     * map puts two vertices on one point */
    int hv = 0, pin = 30;
    double ht[2] = {P[60], P[61]};
    unsigned char hard = 1;
    deform_options o = deform_options_default();
    o.hard = &hard;
    o.pins = &pin;
    o.npins = 1;
    o.iterations = 1000;
    watch w;
    memset(&w, 0, sizeof w);
    w.o = &o, w.m = &m, w.P = P, w.pins = &pin, w.npins = 1;
    o.progress = each_iteration;
    o.user = &w;
    deform_result r;
    scaf_error err;
    assert_int_equal(deform_run(NV, P, m.nf, m.F, 1, &hv, ht, 0, NULL, &o, X, &r, &err), SCAF_OK);
    print_message("unreachable: stopped after %d iterations, miss %g\n", r.iterations,
                  r.max_handle_error);
    assert_int_equal(r.infeasible, 2);
    assert_int_equal(r.hard_reached, 0);
    assert_true(r.max_handle_error > 0.0);
    assert_true(r.iterations < 200);
    assert_int_equal(w.pins_moved, 0);
    assert_int_equal(w.failures, 0);
    free(P);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pinned_vertices_keep_their_bits),
        cmocka_unit_test(hard_spiral_meets_every_target_exactly),
        cmocka_unit_test(flipped_held_triangles_are_refused_up_front),
        cmocka_unit_test(unreachable_hard_target_ends_after_a_bounded_stall),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
