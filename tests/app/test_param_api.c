/* Tests for the scaf_param_* API on generated samples: the map is
 * bijective after every iteration (exact orientation of every triangle and
 * no crossing of chart boundary edges), every accepted step lowers its
 * iteration's total energy, the final energy is below the initial one, and
 * invalid charts are rejected with the chart named. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/param.h"
#include "geom/bijectivity.h"
#include "geom/predicates.h"
#include "mesh/samples.h"
#include "scaf/scaf.h"

/* ---- an independent bijectivity check (small meshes: quadratic) -------- */

static int seg_cross(const double *a, const double *b, const double *c, const double *d)
{
    /* Segments ab and cd intersect (properly, or touching) when they share
     * no endpoint: exact orientation tests. */
    double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a),
           o4 = orient2d(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return 1;
    if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) {
        /* collinear touching: check bounding boxes on the zero cases */
        const double *p[4] = {c, d, a, b};
        const double *s0[4] = {a, a, c, c}, *s1[4] = {b, b, d, d};
        double o[4] = {o1, o2, o3, o4};
        for (int k = 0; k < 4; k++)
            if (o[k] == 0) {
                double lx = fmin(s0[k][0], s1[k][0]), hx = fmax(s0[k][0], s1[k][0]);
                double ly = fmin(s0[k][1], s1[k][1]), hy = fmax(s0[k][1], s1[k][1]);
                if (p[k][0] >= lx && p[k][0] <= hx && p[k][1] >= ly && p[k][1] <= hy) return 1;
            }
    }
    return 0;
}

/* Number of violations: non-positive triangles + crossing boundary edge
 * pairs (own quadratic check), plus the kernel's checker's verdict. */
static int violations(const scaf_loop *L)
{
    int bad = 0;
    bij_report rep;
    scaf_error err;
    if (bij_check(L->nv, L->uv, L->nf, L->F, NULL, NULL, &rep, &err) != SCAF_OK) return 1000000;
    if (!rep.bijective || rep.flipped || rep.degenerate || rep.boundary_crossings) bad++;
    for (int f = 0; f < L->nf; f++) {
        const int *t = L->F + 3 * f;
        if (!(orient2d(L->uv + 2 * t[0], L->uv + 2 * t[1], L->uv + 2 * t[2]) > 0)) bad++;
    }
    for (int i = 0; i < L->nbedges; i++)
        for (int j = i + 1; j < L->nbedges; j++) {
            const int *e = L->bedges + 2 * i, *g = L->bedges + 2 * j;
            if (e[0] == g[0] || e[0] == g[1] || e[1] == g[0] || e[1] == g[1]) continue;
            if (seg_cross(L->uv + 2 * e[0], L->uv + 2 * e[1], L->uv + 2 * g[0], L->uv + 2 * g[1]))
                bad++;
        }
    return bad;
}

typedef struct watch {
    const scaf_param_t *p;
    int calls;
    int bad_maps;
    int energy_rises; /* accepted steps that did not lower the total */
    int stop_after;   /* cancel after this many calls (0: never) */
} watch;

static int check_iteration(const scaf_iteration_info_t *info, void *user)
{
    watch *w = user;
    w->calls++;
    if (violations(param_loop(w->p)) != 0) w->bad_maps++;
    if (info->step > 0 && !(info->total_after < info->total_before)) w->energy_rises++;
    if (!isfinite(info->energy)) w->bad_maps++;
    return w->stop_after && w->calls >= w->stop_after;
}

static void run_sample(const char *name, int size, int iterations, scaf_init init, double *e0,
                       double *e1)
{
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make(name, size, &m, &err), SCAF_OK);
    scaf_options_t o = scaf_options_default();
    o.init = init;
    o.tolerance = 0;
    scaf_param_t *p = scaf_param_new(&o);
    assert_non_null(p);
    scaf_status st = mesh_has_uv(&m)
        ? scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT)
        : scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
    if (st != SCAF_OK) print_error("%s: %s\n", name, scaf_param_error(p));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(violations(param_loop(p)), 0);
    *e0 = scaf_param_energy(p);
    watch w = {p, 0, 0, 0, 0};
    st = scaf_param_run(p, iterations, check_iteration, &w);
    if (st != SCAF_OK) print_error("%s: %s\n", name, scaf_param_error(p));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(w.calls, iterations);
    assert_int_equal(w.bad_maps, 0);
    assert_int_equal(w.energy_rises, 0);
    *e1 = scaf_param_energy(p);
    assert_true(*e1 < *e0);
    assert_true(*e1 >= 4.0);
    /* UV out: one per working vertex, FT consistent with the input faces. */
    int nuv = scaf_param_uv_count(p);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_int_equal(scaf_param_get_uv(p, UV, FT), SCAF_OK);
    for (int f = 0; f < m.nf; f++)
        for (int j = 0; j < 3; j++) assert_true(FT[3 * f + j] >= 0 && FT[3 * f + j] < nuv);
    for (int f = 0; f < m.nf; f++)
        assert_true(orient2d(UV + 2 * FT[3 * f], UV + 2 * FT[3 * f + 1], UV + 2 * FT[3 * f + 2]) >
                    0);
    free(UV);
    free(FT);
    scaf_param_destroy(p);
    mesh_free(&m);
}

static void hemisphere_is_bijective_every_iteration(void **state)
{
    (void)state;
    double e0, e1;
    run_sample("hemisphere", 8, 8, SCAF_INIT_TUTTE, &e0, &e1);
    print_message("hemisphere: E %.6f -> %.6f\n", e0, e1);
}

static void hemisphere_harmonic_init(void **state)
{
    (void)state;
    double e0, e1;
    run_sample("hemisphere", 6, 4, SCAF_INIT_HARMONIC, &e0, &e1);
}

static void surface_with_holes(void **state)
{
    (void)state;
    double e0, e1;
    run_sample("holes", 0, 6, SCAF_INIT_TUTTE, &e0, &e1);
    print_message("holes: E %.6f -> %.6f\n", e0, e1);
}

static void multi_chart_with_seams(void **state)
{
    (void)state;
    double e0, e1;
    run_sample("cubesphere", 4, 6, SCAF_INIT_TUTTE, &e0, &e1);
    print_message("cubesphere: E %.6f -> %.6f\n", e0, e1);
}

/* With the input's seams only (SCAF_SEAMS_INPUT), as before automatic
 * seams: the sample is refused naming the chart. */
static void expect_mesh_error(const char *name, const char *needle)
{
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make(name, 0, &m, &err), SCAF_OK);
    scaf_options_t o = scaf_options_default();
    o.seams = SCAF_SEAMS_INPUT;
    scaf_param_t *p = scaf_param_new(&o);
    scaf_status st = scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
    assert_int_equal(st, SCAF_ERR_MESH);
    const char *msg = scaf_param_error(p);
    if (!strstr(msg, needle)) print_error("message '%s' lacks '%s'\n", msg, needle);
    assert_non_null(strstr(msg, needle));
    assert_int_equal(scaf_param_run(p, 1, NULL, NULL), SCAF_ERR_USAGE);
    scaf_param_destroy(p);
    mesh_free(&m);
}

static void closed_mesh_is_rejected_naming_the_chart(void **state)
{
    (void)state;
    expect_mesh_error("tetrahedron", "chart 0");
    expect_mesh_error("cubesphere", "chart 0"); /* without its UVs: one closed component */
}

/* The default seams cut a closed or handled mesh without UVs open:
 * set_mesh succeeds, says so, and the map after a few iterations is
 * bijective (exact check) with one chart per component. */
static void expect_cut_and_bijective(const double *V, int nv, const int *F, int nf)
{
    scaf_param_t *p = scaf_param_new(NULL);
    scaf_status st = scaf_param_set_mesh(p, V, nv, F, nf, NULL, 0, NULL);
    if (st != SCAF_OK) print_error("%s\n", scaf_param_error(p));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(scaf_param_seams_used(p), SCAF_SEAMS_AUTO);
    assert_int_equal(scaf_param_chart_count(p), 1);
    assert_int_equal(scaf_param_run(p, 5, NULL, NULL), SCAF_OK);
    int nuv = scaf_param_uv_count(p);
    assert_true(nuv > nv); /* the seams split vertices */
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)nf);
    assert_int_equal(scaf_param_get_uv(p, UV, FT), SCAF_OK);
    bij_report r;
    assert_int_equal(bij_check(nuv, UV, nf, FT, NULL, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    free(UV);
    free(FT);
    scaf_param_destroy(p);
}

static void closed_mesh_is_cut_by_default(void **state)
{
    (void)state;
    const char *names[] = {"tetrahedron", "cubesphere", "icosphere"};
    for (int i = 0; i < 3; i++) {
        mesh m;
        scaf_error err;
        assert_int_equal(mesh_sample_make(names[i], 0, &m, &err), SCAF_OK);
        expect_cut_and_bijective(m.V, m.nv, m.F, m.nf); /* cubesphere: its UVs left out */
        mesh_free(&m);
    }
}

static void genus_and_non_manifold_are_rejected(void **state)
{
    (void)state;
    /* A torus-like strip: a 4 x 3 grid wrapped in both directions has genus 1
     * ... simpler: an annulus glued into a cylinder closed at no end is a
     * disk with a hole (valid); two triangles sharing an edge with a third
     * (non-manifold edge) are not. */
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    int F[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    scaf_param_t *p = scaf_param_new(NULL);
    /* non-manifold: refused whatever the seams, naming the edge */
    assert_int_equal(scaf_param_set_mesh(p, V, 5, F, 3, NULL, 0, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_param_error(p), "chart 0"));
    assert_non_null(strstr(scaf_param_error(p), "0-1 has 3 faces"));
    scaf_options_t o = scaf_options_default();
    o.seams = SCAF_SEAMS_INPUT;
    assert_int_equal(scaf_param_set_options(p, &o), SCAF_OK);
    /* Torus: 3 x 3 grid with both directions wrapped. */
    double TV[9 * 3];
    int TF[18 * 3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double a = 2 * 3.14159265 * i / 3, b = 2 * 3.14159265 * j / 3;
            TV[3 * (3 * i + j)] = (2 + cos(b)) * cos(a);
            TV[3 * (3 * i + j) + 1] = (2 + cos(b)) * sin(a);
            TV[3 * (3 * i + j) + 2] = sin(b);
        }
    int k = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int a = 3 * i + j, b = 3 * ((i + 1) % 3) + j, c = 3 * ((i + 1) % 3) + (j + 1) % 3,
                d = 3 * i + (j + 1) % 3;
            TF[k++] = a;
            TF[k++] = b;
            TF[k++] = c;
            TF[k++] = a;
            TF[k++] = c;
            TF[k++] = d;
        }
    assert_int_equal(scaf_param_set_mesh(p, TV, 9, TF, 18, NULL, 0, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_param_error(p), "chart 0"));
    scaf_param_destroy(p);
    /* by default its handle is cut */
    expect_cut_and_bijective(TV, 9, TF, 18);
}

static void bad_arrays_and_options(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    int F[] = {0, 1, 3};
    scaf_param_t *p = scaf_param_new(NULL);
    assert_int_equal(scaf_param_set_mesh(p, V, 3, F, 1, NULL, 0, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_param_error(p), "face 0"));
    double N[] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
    int G[] = {0, 1, 2};
    assert_int_equal(scaf_param_set_mesh(p, N, 3, G, 1, NULL, 0, NULL), SCAF_ERR_MESH);
    scaf_options_t o = scaf_options_default();
    o.box_scale = 0.5;
    assert_int_equal(scaf_param_set_options(p, &o), SCAF_ERR_USAGE);
    o = scaf_options_default();
    o.lambda_ratio = -1;
    assert_int_equal(scaf_param_set_options(p, &o), SCAF_ERR_USAGE);
    assert_int_equal(scaf_param_set_options(p, NULL), SCAF_ERR_USAGE);
    /* One triangle: valid disk. */
    assert_int_equal(scaf_param_set_mesh(p, V, 3, G, 1, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 3, NULL, NULL), SCAF_OK);
    assert_true(scaf_param_energy(p) < 4.0 + 1e-6);
    scaf_param_destroy(p);
}

static void callback_can_cancel(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("hemisphere", 5, &m, &err), SCAF_OK);
    scaf_options_t o = scaf_options_default();
    o.tolerance = 0;
    scaf_param_t *p = scaf_param_new(&o);
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    watch w = {p, 0, 0, 0, 2};
    assert_int_equal(scaf_param_run(p, 10, check_iteration, &w), SCAF_ERR_CANCELLED);
    assert_int_equal(w.calls, 2);
    assert_int_equal(scaf_param_iterations(p), 2);
    assert_int_equal(violations(param_loop(p)), 0);
    scaf_param_destroy(p);
    mesh_free(&m);
}

static void defaults_are_documented_values(void **state)
{
    (void)state;
    scaf_options_t o = scaf_options_default();
    assert_int_equal(o.max_iterations, 200);
    assert_true(o.tolerance == 1e-5);
    assert_true(o.box_scale == 3.0);
    assert_true(o.lambda_ratio == 0.01);
    assert_true(o.min_angle_deg == 20.0);
    assert_int_equal(o.energy, SCAF_ENERGY_SYMMETRIC_DIRICHLET);
    assert_int_equal(o.init, SCAF_INIT_MVC);
    for (int k = 0; k < SCAF_PHASE_COUNT; k++)
        assert_string_not_equal(scaf_phase_name((scaf_phase)k), "unknown");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_are_documented_values),
        cmocka_unit_test(hemisphere_is_bijective_every_iteration),
        cmocka_unit_test(hemisphere_harmonic_init),
        cmocka_unit_test(surface_with_holes),
        cmocka_unit_test(multi_chart_with_seams),
        cmocka_unit_test(closed_mesh_is_rejected_naming_the_chart),
        cmocka_unit_test(closed_mesh_is_cut_by_default),
        cmocka_unit_test(genus_and_non_manifold_are_rejected),
        cmocka_unit_test(bad_arrays_and_options),
        cmocka_unit_test(callback_can_cancel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
