/* Tests for the public 3D API (scaf/volume.h) through scaf/scaf.h alone:
 * scaf_inflate grows a generated sphere inside its box with every tet
 * positive (checked with scaf_check_tets, and the surface free with
 * scaf_check_surface); scaf_untangle frees the generated dented sphere;
 * scaf_flow with until_free stops at the first free step; scaf_tet_mesh
 * gives positive tets around the unmoved surface; the checks count
 * what a hand-made case has (two crossing triangles, an inverted tet).
 * Every run is cancelled from its progress callback (SCAF_ERR_CANCELLED,
 * the callback not called again), and bad options and arrays fail with
 * SCAF_ERR_USAGE and a message naming them (never a silent default);
 * arrays with an index out of range, SCAF_ERR_MESH naming it. */
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

#define ASSERT_USAGE(call, words)                                                                  \
    do {                                                                                           \
        assert_int_equal((call), SCAF_ERR_USAGE);                                                  \
        if (!strstr(scaf_volume_error(h), (words)))                                                \
            fail_msg("message '%s' lacks '%s'", scaf_volume_error(h), (words));                    \
    } while (0)

typedef struct watch {
    int calls;
    int cancel_at; /* call count; 0: never */
    int phases[2];
    int last_step[2];
    int flow_positions; /* flow steps that gave positions */
} watch;

static int on_step(const scaf_volume_step_info_t *info, void *user)
{
    watch *w = user;
    w->calls++;
    assert_true(info->phase == SCAF_VOLUME_FLOW_STEP || info->phase == SCAF_VOLUME_ITERATION);
    w->phases[info->phase]++;
    /* steps count up within their phase (scaf_flow's input check is step 0) */
    assert_true(info->step >= w->last_step[info->phase]);
    w->last_step[info->phase] = info->step;
    if (info->phase == SCAF_VOLUME_ITERATION) assert_true(info->tets > 0 && info->quality_min > 0);
    if (info->phase == SCAF_VOLUME_FLOW_STEP && info->X) w->flow_positions++;
    return w->cancel_at && w->calls == w->cancel_at;
}

static void sample(const char *name, int size, mesh *m)
{
    assert_int_equal(mesh_sample_make(name, size, m, NULL), SCAF_OK);
}

static void assert_free_surface(int nv, const double *X, int nf, const int *F)
{
    scaf_surface_report_t r = {.struct_size = sizeof r};
    assert_int_equal(scaf_check_surface(X, nv, F, nf, &r), SCAF_OK);
    assert_string_equal(r.message, "");
    assert_int_equal(r.faces, nf);
    assert_true(r.closed && r.manifold);
    assert_int_equal(r.pairs, 0);
    assert_true(r.intersection_free);
}

static double diagonal(int nv, const double *X)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], X[3 * i + k]);
            hi[k] = fmax(hi[k], X[3 * i + k]);
        }
    return sqrt(pow(hi[0] - lo[0], 2) + pow(hi[1] - lo[1], 2) + pow(hi[2] - lo[2], 2));
}

static void inflate_grows_bijectively(void **state)
{
    (void)state;
    mesh m;
    sample("icosphere", 2, &m);
    scaf_inflate_options_t o = scaf_inflate_options_default();
    assert_int_equal(o.struct_size, sizeof o);
    o.scale = 1.5;
    o.iterations = 6;
    scaf_volume_t *h = scaf_volume_new();
    watch w = {0};
    scaf_status st = scaf_inflate(h, m.V, m.nv, m.F, m.nf, &o, on_step, &w);
    if (st != SCAF_OK) print_error("%s\n", scaf_volume_error(h));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(w.phases[SCAF_VOLUME_ITERATION], 6);
    assert_int_equal(w.phases[SCAF_VOLUME_FLOW_STEP], 0);
    assert_int_equal(scaf_volume_vertex_count(h), m.nv);
    double *X = malloc(sizeof(double) * 3 * (size_t)m.nv);
    assert_int_equal(scaf_volume_get_positions(h, X), SCAF_OK);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_int_equal(s.iterations, 6);
    /* it grew, and the summary measures what the positions say */
    assert_true(s.diagonal_after > 1.05 * s.diagonal_before);
    assert_true(s.diagonal_before == diagonal(m.nv, m.V));
    assert_true(s.diagonal_after == diagonal(m.nv, X));
    for (int i = 0; i < m.nv; i++)
        for (int k = 0; k < 3; k++)
            assert_true(X[3 * i + k] > s.box_lo[k] && X[3 * i + k] < s.box_hi[k]);
    assert_free_surface(m.nv, X, m.nf, m.F);
    /* the tets: surface vertices first (at X), every tet positive, both labels */
    int np = scaf_volume_tet_vertex_count(h), nt = scaf_volume_tet_count(h);
    assert_true(np > m.nv && nt > 0);
    double *P = malloc(sizeof(double) * 3 * (size_t)np);
    int *T = malloc(sizeof(int) * 4 * (size_t)nt), *label = malloc(sizeof(int) * (size_t)nt);
    assert_int_equal(scaf_volume_get_tets(h, P, T, label), SCAF_OK);
    assert_memory_equal(P, X, sizeof(double) * 3 * (size_t)m.nv);
    int inside = 0, outside = 0;
    for (int t = 0; t < nt; t++) inside += label[t] == 1, outside += label[t] == 2;
    assert_int_equal(inside + outside, nt);
    assert_true(inside > 0 && outside > 0);
    scaf_tets_report_t tr = {.struct_size = sizeof tr};
    assert_int_equal(scaf_check_tets(P, np, T, nt, &tr), SCAF_OK);
    assert_int_equal(tr.tets, nt);
    assert_int_equal(tr.positive, nt);
    assert_true(tr.valid);
    /* no untangle result: the flowed positions are refused */
    assert_int_equal(scaf_volume_get_flowed(h, X), SCAF_ERR_USAGE);
    free(P);
    free(T);
    free(label);
    free(X);
    scaf_volume_destroy(h);
    mesh_free(&m);
}

/* The same run at 2^200 times the size gives 2^200 times the positions. */
static void inflate_scale_free(void **state)
{
    (void)state;
    mesh m;
    sample("icosphere", 1, &m);
    scaf_inflate_options_t o = scaf_inflate_options_default();
    o.iterations = 2;
    scaf_volume_t *h = scaf_volume_new();
    assert_int_equal(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &o, NULL, NULL), SCAF_OK);
    double *X = malloc(sizeof(double) * 3 * (size_t)m.nv);
    double *Y = malloc(sizeof(double) * 3 * (size_t)m.nv);
    assert_int_equal(scaf_volume_get_positions(h, X), SCAF_OK);
    for (int i = 0; i < 3 * m.nv; i++) m.V[i] = ldexp(m.V[i], 200);
    assert_int_equal(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &o, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_volume_get_positions(h, Y), SCAF_OK);
    for (int i = 0; i < 3 * m.nv; i++) assert_true(Y[i] == ldexp(X[i], 200));
    free(X);
    free(Y);
    scaf_volume_destroy(h);
    mesh_free(&m);
}

static void untangle_frees_the_dented_sphere(void **state)
{
    (void)state;
    mesh m;
    sample("dented", 4, &m);
    scaf_surface_report_t in = {.struct_size = sizeof in};
    assert_int_equal(scaf_check_surface(m.V, m.nv, m.F, m.nf, &in), SCAF_OK);
    assert_true(in.pairs > 0 && !in.intersection_free);
    scaf_untangle_options_t o = scaf_untangle_options_default();
    o.iterations = 15;
    o.verify = 1;
    scaf_volume_t *h = scaf_volume_new();
    watch w = {0};
    scaf_status st = scaf_untangle(h, m.V, m.nv, m.F, m.nf, &o, on_step, &w);
    if (st != SCAF_OK) print_error("%s\n", scaf_volume_error(h));
    assert_int_equal(st, SCAF_OK);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_int_equal(s.input_defects, in.pairs + in.degenerate_faces);
    assert_true(s.steps >= 1);
    assert_int_equal(w.phases[SCAF_VOLUME_FLOW_STEP], s.steps);
    assert_int_equal(w.phases[SCAF_VOLUME_ITERATION], s.iterations);
    assert_int_equal(w.flow_positions, 0); /* only scaf_flow gives them */
    assert_true(s.best_iteration >= 1 && s.best_iteration <= s.iterations);
    assert_true(s.rms < s.flowed_rms);
    assert_string_not_equal(scaf_untangle_stop_name(s.stop), "unknown");
    double *X = malloc(sizeof(double) * 3 * (size_t)m.nv);
    assert_int_equal(scaf_volume_get_flowed(h, X), SCAF_OK);
    assert_free_surface(m.nv, X, m.nf, m.F);
    assert_int_equal(scaf_volume_get_positions(h, X), SCAF_OK);
    assert_free_surface(m.nv, X, m.nf, m.F);
    /* an input already free comes back as it is */
    assert_int_equal(scaf_untangle(h, X, m.nv, m.F, m.nf, NULL, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_int_equal(s.stop, SCAF_UNTANGLE_ALREADY_FREE);
    assert_string_equal(scaf_untangle_stop_name(s.stop), "already_free");
    double *Y = malloc(sizeof(double) * 3 * (size_t)m.nv);
    assert_int_equal(scaf_volume_get_positions(h, Y), SCAF_OK);
    assert_memory_equal(X, Y, sizeof(double) * 3 * (size_t)m.nv);
    free(X);
    free(Y);
    scaf_volume_destroy(h);
    mesh_free(&m);
}

static void flow_until_free(void **state)
{
    (void)state;
    mesh m;
    sample("dented", 4, &m);
    scaf_flow_options_t o = scaf_flow_options_default();
    o.until_free = 1;
    o.steps = 50;
    scaf_volume_t *h = scaf_volume_new();
    watch w = {0};
    assert_int_equal(scaf_flow(h, m.V, m.nv, m.F, m.nf, &o, on_step, &w), SCAF_OK);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_true(s.input_defects > 0);
    assert_int_equal(s.defects, 0);
    assert_true(s.steps >= 1 && s.steps < 50);
    assert_int_equal(w.phases[SCAF_VOLUME_FLOW_STEP], s.steps + 1); /* + the start */
    double *X = malloc(sizeof(double) * 3 * (size_t)m.nv);
    assert_int_equal(scaf_volume_get_positions(h, X), SCAF_OK);
    assert_free_surface(m.nv, X, m.nf, m.F);
    /* one step fewer is not free: the run stopped at the first free one */
    o.steps = s.steps - 1;
    if (o.steps >= 1) {
        assert_int_equal(scaf_flow(h, m.V, m.nv, m.F, m.nf, &o, NULL, NULL), SCAF_ERR_NUMERIC);
        assert_non_null(strstr(scaf_volume_error(h), "still intersects itself"));
    }
    /* without until_free: every step, unchecked */
    o = scaf_flow_options_default();
    o.steps = 3;
    w = (watch){0};
    assert_int_equal(scaf_flow(h, m.V, m.nv, m.F, m.nf, &o, on_step, &w), SCAF_OK);
    assert_int_equal(w.calls, 4); /* the start and 3 steps */
    assert_int_equal(w.flow_positions, 4);
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_int_equal(s.steps, 3);
    assert_int_equal(s.input_defects, -1);
    free(X);
    scaf_volume_destroy(h);
    mesh_free(&m);
}

/* The tet scaffold alone: the surface's vertices first and unmoved, every
 * tet positive, the counts of the summary those of the labels. */
static void tet_mesh_alone(void **state)
{
    (void)state;
    mesh m;
    sample("icosphere", 2, &m);
    scaf_tet_options_t o = scaf_tet_options_default();
    o.box_cells = 3;
    scaf_volume_t *h = scaf_volume_new();
    assert_int_equal(scaf_tet_mesh(h, m.V, m.nv, m.F, m.nf, &o), SCAF_OK);
    int np = scaf_volume_tet_vertex_count(h), nt = scaf_volume_tet_count(h);
    assert_true(np > m.nv && nt > 0);
    double *P = malloc(sizeof(double) * 3 * (size_t)np);
    int *T = malloc(sizeof(int) * 4 * (size_t)nt), *label = malloc(sizeof(int) * (size_t)nt);
    assert_int_equal(scaf_volume_get_tets(h, P, T, label), SCAF_OK);
    assert_memory_equal(P, m.V, sizeof(double) * 3 * (size_t)m.nv);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    int inside = 0;
    for (int t = 0; t < nt; t++) inside += label[t] == 1;
    assert_int_equal(s.tets_inside, inside);
    assert_true(inside > 0 && inside < nt);
    assert_int_equal(s.box_vertices, 6 * 3 * 3 + 2); /* a 3 x 3 grid on each side */
    for (int i = 0; i < np; i++)
        for (int k = 0; k < 3; k++)
            assert_true(P[3 * i + k] >= s.box_lo[k] && P[3 * i + k] <= s.box_hi[k]);
    scaf_tets_report_t tr = {.struct_size = sizeof tr};
    assert_int_equal(scaf_check_tets(P, np, T, nt, &tr), SCAF_OK);
    assert_true(tr.valid);
    o.box_cells = 65;
    ASSERT_USAGE(scaf_tet_mesh(h, m.V, m.nv, m.F, m.nf, &o), "box_cells 65");
    assert_int_equal(scaf_volume_tet_count(h), 0);
    assert_int_equal(scaf_tet_mesh(h, m.V, m.nv, m.F, m.nf - 1, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_volume_error(h), "tet needs a closed manifold"));
    free(P);
    free(T);
    free(label);
    scaf_volume_destroy(h);
    mesh_free(&m);
}

/* Cancelled from the callback: SCAF_ERR_CANCELLED, no call after it. */
static void cancel_from_progress(void **state)
{
    (void)state;
    mesh m, d;
    sample("icosphere", 1, &m);
    sample("dented", 4, &d);
    scaf_volume_t *h = scaf_volume_new();
    watch w = {.cancel_at = 2};
    scaf_inflate_options_t io = scaf_inflate_options_default();
    io.iterations = 5;
    assert_int_equal(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &io, on_step, &w), SCAF_ERR_CANCELLED);
    assert_int_equal(w.calls, 2);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK); /* the last finished iteration */
    assert_int_equal(s.iterations, 2);
    w = (watch){.cancel_at = 1};
    assert_int_equal(scaf_untangle(h, d.V, d.nv, d.F, d.nf, NULL, on_step, &w), SCAF_ERR_CANCELLED);
    assert_int_equal(w.calls, 1);
    assert_int_equal(scaf_volume_vertex_count(h), 0); /* untangle keeps nothing */
    scaf_flow_options_t fo = scaf_flow_options_default();
    w = (watch){.cancel_at = 3}; /* the start, steps 1 and 2 */
    assert_int_equal(scaf_flow(h, d.V, d.nv, d.F, d.nf, &fo, on_step, &w), SCAF_ERR_CANCELLED);
    assert_int_equal(w.calls, 3);
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_OK);
    assert_int_equal(s.steps, 2);
    scaf_volume_destroy(h);
    mesh_free(&m);
    mesh_free(&d);
}

static void bad_options_and_arrays(void **state)
{
    (void)state;
    mesh m;
    sample("icosphere", 1, &m);
    scaf_volume_t *h = scaf_volume_new();
    scaf_inflate_options_t io = scaf_inflate_options_default();
    io.scale = -1;
    ASSERT_USAGE(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &io, NULL, NULL), "scale -1");
    assert_int_equal(scaf_volume_vertex_count(h), 0); /* no result, no silent default */
    io = scaf_inflate_options_default();
    io.box_scale = 1.0;
    ASSERT_USAGE(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &io, NULL, NULL), "box_scale");
    io = scaf_inflate_options_default();
    io.solver = SCAF_SOLVER_AUTO;
    ASSERT_USAGE(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &io, NULL, NULL), "solver");
    io = scaf_inflate_options_default();
    io.struct_size = 8;
    ASSERT_USAGE(scaf_inflate(h, m.V, m.nv, m.F, m.nf, &io, NULL, NULL), "struct_size is 8");
    scaf_untangle_options_t uo = scaf_untangle_options_default();
    uo.tolerance = 1.0;
    ASSERT_USAGE(scaf_untangle(h, m.V, m.nv, m.F, m.nf, &uo, NULL, NULL), "tolerance");
    /* no surface: the options alone are checked (what `scaf untangle` does
     * before reading its input) */
    ASSERT_USAGE(scaf_untangle(h, NULL, 0, NULL, 0, &uo, NULL, NULL), "tolerance");
    uo = scaf_untangle_options_default();
    assert_int_equal(scaf_untangle(h, NULL, 0, NULL, 0, &uo, NULL, NULL), SCAF_ERR_MESH);
    uo.struct_size = 0;
    ASSERT_USAGE(scaf_untangle(h, m.V, m.nv, m.F, m.nf, &uo, NULL, NULL), "struct_size");
    scaf_flow_options_t fo = scaf_flow_options_default();
    fo.steps = 0;
    ASSERT_USAGE(scaf_flow(h, m.V, m.nv, m.F, m.nf, &fo, NULL, NULL), "steps 0");
    fo = scaf_flow_options_default();
    fo.delta = NAN;
    ASSERT_USAGE(scaf_flow(h, m.V, m.nv, m.F, m.nf, &fo, NULL, NULL), "time step");
    /* arrays */
    ASSERT_USAGE(scaf_flow(h, NULL, m.nv, m.F, m.nf, NULL, NULL, NULL), "bad mesh arrays");
    int keep = m.F[5];
    m.F[5] = m.nv;
    assert_int_equal(scaf_inflate(h, m.V, m.nv, m.F, m.nf, NULL, NULL, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_volume_error(h), "face 1 references vertex"));
    m.F[5] = keep;
    /* an open surface: refused naming why */
    assert_int_equal(scaf_inflate(h, m.V, m.nv, m.F, m.nf - 1, NULL, NULL, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_volume_error(h), "open"));
    assert_non_null(strstr(scaf_volume_error(h), "closed manifold"));
    /* getters without a result */
    double x[3];
    assert_int_equal(scaf_volume_get_positions(h, x), SCAF_ERR_USAGE);
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    assert_int_equal(scaf_volume_get_summary(h, &s), SCAF_ERR_USAGE);
    /* reports: a struct_size that cannot hold the message is refused */
    scaf_surface_report_t r = {.struct_size = 4};
    assert_int_equal(scaf_check_surface(m.V, m.nv, m.F, m.nf, &r), SCAF_ERR_USAGE);
    r.struct_size = sizeof r;
    m.F[0] = -1;
    assert_int_equal(scaf_check_surface(m.V, m.nv, m.F, m.nf, &r), SCAF_ERR_MESH);
    assert_non_null(strstr(r.message, "face 0 references vertex -1"));
    scaf_volume_destroy(h);
    scaf_volume_destroy(NULL);
    mesh_free(&m);
}

static void checks_count_by_hand(void **state)
{
    (void)state;
    /* two triangles crossing through each other, sharing no vertex */
    double V[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5, 0.5, -1, 0.5, 0.5, 1, 3, 3, 0};
    int F[] = {0, 1, 2, 3, 4, 5};
    scaf_surface_report_t r = {.struct_size = sizeof r};
    assert_int_equal(scaf_check_surface(V, 6, F, 2, &r), SCAF_OK);
    assert_int_equal(r.pairs, 1);
    assert_int_equal(r.crossing_pairs, 1);
    assert_int_equal(r.nfirst, 1);
    assert_int_equal(r.first[0][0], 0);
    assert_int_equal(r.first[0][1], 1);
    assert_false(r.closed);
    assert_int_equal(r.boundary_edges, 6);
    assert_false(r.intersection_free);
    /* a tet and its mirror image */
    double P[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    int T[] = {0, 1, 2, 3, 0, 2, 1, 3, 0, 1, 2, 2};
    scaf_tets_report_t t = {.struct_size = sizeof t};
    assert_int_equal(scaf_check_tets(P, 4, T, 1, &t), SCAF_OK);
    assert_true(t.valid);
    assert_int_equal(scaf_check_tets(P, 4, T, 3, &t), SCAF_OK);
    assert_false(t.valid);
    assert_int_equal(t.positive, 1);
    assert_int_equal(t.inverted, 1);
    assert_int_equal(t.degenerate, 1);
    assert_int_equal(t.first_bad, 1);
    P[4] = NAN;
    assert_int_equal(scaf_check_tets(P, 4, T, 1, &t), SCAF_ERR_MESH);
    assert_non_null(strstr(t.message, "not finite"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(inflate_grows_bijectively),
        cmocka_unit_test(inflate_scale_free),
        cmocka_unit_test(untangle_frees_the_dented_sphere),
        cmocka_unit_test(flow_until_free),
        cmocka_unit_test(tet_mesh_alone),
        cmocka_unit_test(cancel_from_progress),
        cmocka_unit_test(bad_options_and_arrays),
        cmocka_unit_test(checks_count_by_hand),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
