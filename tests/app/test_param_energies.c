/* ARAP and conformal in the SCAF loop keep every mesh triangle away from
 * collapse. ARAP alone is no barrier: on a sphere with one triangle
 * removed (generated here), where ARAP's unconstrained minimum would
 * invert triangles, the old loop crushed them (smallest area ratio
 * det J = 5e-7, symmetric Dirichlet E = 8e11, stopped after 10
 * iterations as "tolerance"); with ARAP's barrier b(det J) (opt/energy)
 * the squeezed triangles stay near the barrier's range (det J ~ 0.07), and
 * with Newton both energies converge. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "opt/energy.h"
#include "scaf/scaf.h"
#include "support/sanitized.h"
#include "support/support.h"

/* Smallest UV area / 3D area over the triangles (the map's det J). */
static double smallest_area_ratio(const mesh *m, const double *UV, const int *FT)
{
    double lo = INFINITY;
    for (int f = 0; f < m->nf; f++) {
        const double *a = m->V + 3 * m->F[3 * f], *b = m->V + 3 * m->F[3 * f + 1],
                     *c = m->V + 3 * m->F[3 * f + 2];
        double u[3], v[3];
        for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
        double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2],
               cz = u[0] * v[1] - u[1] * v[0];
        double a3 = 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
        const double *p = UV + 2 * FT[3 * f], *q = UV + 2 * FT[3 * f + 1],
                     *r = UV + 2 * FT[3 * f + 2];
        double a2 = 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
        if (a2 / a3 < lo) lo = a2 / a3;
    }
    return lo;
}

static int count_calls(const scaf_iteration_info_t *info, void *user)
{
    (void)info;
    ++*(int *)user;
    return 0;
}

/* The icosphere (size 3, 180 triangles) without its first triangle: a
 * disk, and very far from developable. */
static void punctured_sphere(mesh *m)
{
    scaf_error err;
    assert_int_equal(mesh_sample_make("icosphere", 3, m, &err), SCAF_OK);
    m->nf--;
    memmove(m->F, m->F + 3, sizeof(int) * 3 * (size_t)m->nf);
}

/* A run with default options but the energy on m: the output is bijective
 * (exact checker); smallest area ratio, E, iterations and stop reason out. */
static void run_energy_on(const mesh *mp, scaf_energy e, double *ratio, double *E, int *iterations,
                          scaf_stop_reason *stop)
{
    const mesh m = *mp;
    scaf_options_t o = scaf_options_default();
    o.energy = e;
    scaf_param_t *p = scaf_param_new(&o);
    assert_non_null(p);
    assert_int_equal(scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    *iterations = 0;
    assert_int_equal(scaf_param_run(p, 0, count_calls, iterations), SCAF_OK);
    int nuv = scaf_param_uv_count(p);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_int_equal(scaf_param_get_uv(p, UV, FT), SCAF_OK);
    *ratio = smallest_area_ratio(&m, UV, FT);
    bij_report rep;
    assert_int_equal(bij_check(nuv, UV, m.nf, FT, NULL, NULL, &rep, NULL), SCAF_OK);
    assert_true(rep.bijective);
    *E = scaf_param_energy(p);
    *stop = scaf_param_stop_reason(p);
    free(UV);
    free(FT);
    scaf_param_destroy(p);
}

static void run_energy(scaf_energy e, double *ratio, double *E, int *iterations,
                       scaf_stop_reason *stop)
{
    mesh m;
    punctured_sphere(&m);
    run_energy_on(&m, e, ratio, E, iterations, stop);
    mesh_free(&m);
}

static void arap_does_not_collapse(void **state)
{
    (void)state;
    double ratio, E;
    int its;
    scaf_stop_reason stop;
    run_energy(SCAF_ENERGY_ARAP, &ratio, &E, &its, &stop);
    /* measured: 0.064 (old loop: 5e-7 after 10 iterations) */
    assert_true(ratio > 0.01);
    assert_true(E < 1e3);
    assert_true(its > 10);
    /* with Newton (opt/isotropic_hessian) and the logarithmic barrier:
     * converged after 73 iterations, 80 with the continuous scaffold guard
     * (SLIM and (0.1/det - 1)^3 before: at the 200-iteration cap,
     * criterion 3.5e-4) */
    assert_int_equal(stop, SCAF_STOP_CONVERGED);
}

static void conformal_does_not_collapse(void **state)
{
    (void)state;
    double ratio, E;
    int its;
    scaf_stop_reason stop;
    run_energy(SCAF_ENERGY_CONFORMAL, &ratio, &E, &its, &stop);
    assert_true(ratio > 1e-3); /* measured 0.0043 */
    assert_true(isfinite(E));
    assert_int_equal(stop, SCAF_STOP_CONVERGED); /* 6 iterations (14 before the guard blend) */
}

/* hand_lowres (its mean-value start crushes the fingers to det J ~ 1e-7):
 * both energies converge with the default options. ARAP needed the
 * logarithmic barrier: with (0.1/det - 1)^3 Newton grows a crushed
 * triangle's area by a quarter per step and the run ended at the
 * 200-iteration cap (criterion 5e-5); now converged after 104 iterations.
 * Conformal: 7 (SLIM before: 95). Skipped without ../shared/data. */
static void hand_lowres_converges(void **state)
{
    (void)state;
    char path[4096];
    if (!test_data_path("disk/hand_lowres.obj", path, sizeof path)) skip();
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    const scaf_energy energies[2] = {SCAF_ENERGY_ARAP, SCAF_ENERGY_CONFORMAL};
    for (int k = 0; k < 2; k++) {
        double ratio, E;
        int its;
        scaf_stop_reason stop;
        run_energy_on(&m, energies[k], &ratio, &E, &its, &stop);
        assert_int_equal(stop, SCAF_STOP_CONVERGED);
        assert_true(ratio > 0.0);
    }
    mesh_free(&m);
}

/* ARAP with the default options on the shared mesh `rel` stops converged
 * within the cap, bijective with no collapsed triangle. Skipped without
 * ../shared/data, and under the sanitizers (seconds in Release). */
static void arap_converges_on(const char *rel)
{
    char path[4096];
    if (test_is_sanitized() || !test_data_path(rel, path, sizeof path)) skip();
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    double ratio, E;
    int its;
    scaf_stop_reason stop;
    run_energy_on(&m, SCAF_ENERGY_ARAP, &ratio, &E, &its, &stop);
    assert_int_equal(stop, SCAF_STOP_CONVERGED);
    assert_true(its < 200);
    assert_true(ratio > 0.0);
    mesh_free(&m);
}

/* camel_b's bijective ARAP minimum is a contact (a boundary vertex closing
 * on a boundary edge). With the paper's scaffold guard (rest jumps to a
 * regular triangle below eps) the re-rested scaffold pushed the boundary
 * back each time the gap fell under it: a cycle, iteration_limit at 200
 * (criterion 4.6e-4). With the guard blended continuously (opt/simplices)
 * it converges (117 iterations; 36 since ARAP is judged relative to
 * E + 1, app/param). */
static void camel_b_arap_converges(void **state)
{
    (void)state;
    arap_converges_on("disk/camel_b.obj");
}

/* hilbert is planar: ARAP's minimum is 0 (the identity), approached
 * sublinearly from the crushed start. Judged relative to E alone the run
 * never looked converged (iteration_limit at 200, criterion 0.087, E ~
 * 1e-6); relative to E + 1 (app/param) it converges (83 iterations). */
static void hilbert_arap_converges(void **state)
{
    (void)state;
    arap_converges_on("disk/hilbert.obj");
}

/* The barrier: ARAP unchanged above OPT_ARAP_BARRIER_DET, growing without
 * bound (like -ln(det J)^3) as det J -> 0, infinite for det J <= 0. */
static void arap_barrier_values(void **state)
{
    (void)state;
    double J[4] = {1.0, 0.0, 0.0, 0.2}; /* det 0.2: plain ARAP (0.8^2) */
    assert_true(fabs(opt_density(OPT_ENERGY_ARAP, 2, J) - 0.64) < 1e-12);
    double last = 0.0;
    for (double s = 0.09; s > 1e-6; s *= 0.5) {
        J[3] = s;
        double e = opt_density(OPT_ENERGY_ARAP, 2, J);
        assert_true(e > (1 - s) * (1 - s) && e > last);
        last = e;
    }
    assert_true(last > 1e3); /* -ln(x / 0.1)^3 at x = 1.4e-6: 1.4e3 */
    J[3] = 0.0;
    assert_true(isinf(opt_density(OPT_ENERGY_ARAP, 2, J)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(arap_barrier_values),    cmocka_unit_test(arap_does_not_collapse),
        cmocka_unit_test(hand_lowres_converges),  cmocka_unit_test(camel_b_arap_converges),
        cmocka_unit_test(hilbert_arap_converges), cmocka_unit_test(conformal_does_not_collapse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
