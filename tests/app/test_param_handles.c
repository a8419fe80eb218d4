/* Tests for scaf_param_set_handles (public API): soft positional
 * constraints on a parametrization.
 *   - a corner of a grid pulled far out gets close to its target, the map
 *     bijective after every iteration (exact check of scaf_param_get_uv);
 *   - moving the handle between runs moves the map; n = 0 removes them;
 *   - scale-free: the mesh and the targets scaled by 2^5 give the UVs
 *     scaled by exactly 2^5;
 *   - bad calls are refused (SCAF_ERR_USAGE) and the public default is the
 *     library's. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/bijectivity.h"
#include "mesh/samples.h"
#include "opt/handle_term.h"
#include "scaf/scaf.h"

typedef struct checker {
    scaf_param_t *p;
    int nf, failures, checked;
    double *uv;
    int *ft;
} checker;

static int check_each(const scaf_iteration_info_t *info, void *user)
{
    (void)info;
    checker *c = user;
    assert_int_equal(scaf_param_get_uv(c->p, c->uv, c->ft), SCAF_OK);
    bij_report rep;
    if (bij_check(scaf_param_uv_count(c->p), c->uv, c->nf, c->ft, NULL, NULL, &rep, NULL) !=
            SCAF_OK ||
        !rep.bijective)
        c->failures++;
    c->checked++;
    return 0;
}

/* Run the grid scaled by s with the corner (UV index found by its 3D
 * vertex 0) pulled to s * target; the corner's final UV into out. */
static void pulled_grid(double s, const double target[2], int iterations, double *corner,
                        double *first_uv, int *handle_out)
{
    mesh m;
    assert_int_equal(mesh_sample_make("grid", 6, &m, NULL), SCAF_OK);
    for (int i = 0; i < 3 * m.nv; i++) m.V[i] *= s;
    scaf_param_t *p = scaf_param_new(NULL);
    assert_non_null(p);
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    int nuv = scaf_param_uv_count(p);
    checker c = {p,
                 m.nf,
                 0,
                 0,
                 malloc(sizeof(double) * 2 * (size_t)nuv),
                 malloc(sizeof(int) * 3 * (size_t)m.nf)};
    assert_true(c.uv && c.ft);
    assert_int_equal(scaf_param_get_uv(p, c.uv, c.ft), SCAF_OK);
    int h = c.ft[0]; /* corner of face 0: 3D vertex 0 */
    double t[2] = {c.uv[2 * h] + s * target[0], c.uv[2 * h + 1] + s * target[1]};
    if (first_uv) first_uv[0] = c.uv[2 * h], first_uv[1] = c.uv[2 * h + 1];
    assert_int_equal(scaf_param_set_handles(p, 1, &h, t, SCAF_HANDLE_WEIGHT_DEFAULT), SCAF_OK);
    assert_int_equal(scaf_param_run(p, iterations, check_each, &c), SCAF_OK);
    assert_int_equal(c.failures, 0);
    assert_true(c.checked > 0);
    assert_int_equal(scaf_param_get_uv(p, c.uv, c.ft), SCAF_OK);
    corner[0] = c.uv[2 * h] - t[0], corner[1] = c.uv[2 * h + 1] - t[1];
    if (handle_out) *handle_out = h;
    free(c.uv);
    free(c.ft);
    scaf_param_destroy(p);
    mesh_free(&m);
}

static void handle_pulls_bijectively_and_scale_free(void **state)
{
    (void)state;
    const double target[2] = {-1.5, -1.0};
    double r1[2], r32[2], start[2];
    int h;
    pulled_grid(1.0, target, 15, r1, start, &h);
    double dist0 = hypot(target[0], target[1]), dist = hypot(r1[0], r1[1]);
    print_message("corner: %.4f from its target (it started %.4f away)\n", dist, dist0);
    assert_true(dist < 0.1 * dist0);
    pulled_grid(32.0, target, 15, r32, NULL, NULL);
    assert_true(r32[0] == 32.0 * r1[0] && r32[1] == 32.0 * r1[1]);
}

static void handles_change_and_clear(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("grid", 4, &m, NULL), SCAF_OK);
    scaf_param_t *p = scaf_param_new(NULL);
    int h = 0;
    double t[2] = {5, 5}, nan_t[2] = {NAN, 0};
    assert_int_equal(scaf_param_set_handles(p, 1, &h, t, 1.0), SCAF_ERR_USAGE); /* no mesh */
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    int nuv = scaf_param_uv_count(p), bad = nuv;
    assert_int_equal(scaf_param_set_handles(p, 1, &bad, t, 1.0), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_param_error(p), "vertex"));
    assert_int_equal(scaf_param_set_handles(p, 1, &h, nan_t, 1.0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_param_set_handles(p, 1, &h, t, -1.0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_param_set_handles(p, 1, NULL, t, 1.0), SCAF_ERR_USAGE);
    double *uv = malloc(sizeof(double) * 2 * (size_t)nuv),
           *uv2 = malloc(sizeof(double) * 2 * (size_t)nuv);
    assert_true(uv && uv2);
    /* two targets in turn: the handle follows */
    assert_int_equal(scaf_param_set_handles(p, 1, &h, t, SCAF_HANDLE_WEIGHT_DEFAULT), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 5, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_param_get_uv(p, uv, NULL), SCAF_OK);
    double t2[2] = {-5, 5};
    assert_int_equal(scaf_param_set_handles(p, 1, &h, t2, SCAF_HANDLE_WEIGHT_DEFAULT), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 5, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_param_get_uv(p, uv2, NULL), SCAF_OK);
    assert_true(hypot(uv2[2 * h] - t2[0], uv2[2 * h + 1] - t2[1]) <
                hypot(uv[2 * h] - t2[0], uv[2 * h + 1] - t2[1]));
    /* none: a zero-weight... n = 0 is accepted and the run goes on */
    assert_int_equal(scaf_param_set_handles(p, 0, NULL, NULL, SCAF_HANDLE_WEIGHT_DEFAULT), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 2, NULL, NULL), SCAF_OK);
    /* a new mesh drops them */
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 2, NULL, NULL), SCAF_OK);
    free(uv);
    free(uv2);
    scaf_param_destroy(p);
    mesh_free(&m);
    assert_true(SCAF_HANDLE_WEIGHT_DEFAULT == OPT_HANDLE_WEIGHT_RATIO_DEFAULT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(handle_pulls_bijectively_and_scale_free),
        cmocka_unit_test(handles_change_and_clear),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
