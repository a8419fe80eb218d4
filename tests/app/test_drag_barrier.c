/* Tests of the padding barrier of a drag (src/app/drag_barrier.c).
 *
 * On the cube sphere's own 3 x 2 UV layout (app/atlas from the input UVs)
 * with a padding just below its smallest gap, so pairs and walls are
 * active: the slope the term reports equals the energy's central
 * difference along random directions, and so does its Newton right-hand
 * side (the negative gradient); the energy is infinite where the hook
 * would reject the layout (a chart moved onto its neighbour's padding, the
 * layout grown beyond the step's allowance) and finite where the pairs
 * moved apart. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas.h"
#include "app/drag_barrier.h"
#include "geom/chart_gap.h"
#include "mesh/samples.h"
#include "opt/objective.h"

typedef struct fixture {
    mesh m;
    atlas a;
    drag_barrier b;
    opt_obj_term t;
    int *dof;
    double side;
} fixture;

static void setup_fixture(fixture *f)
{
    memset(f, 0, sizeof *f);
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 3, &f->m, &err), SCAF_OK);
    /* the input layout's smallest gap, relative to its side */
    double g;
    assert_int_equal(chart_gap_min(f->m.nuv, f->m.UV, f->m.nf, f->m.FT, NULL, 0.0, &g, NULL, &err),
                     SCAF_OK);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < f->m.nuv; v++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], f->m.UV[2 * v + k]);
            hi[k] = fmax(hi[k], f->m.UV[2 * v + k]);
        }
    atlas_options o = atlas_options_default();
    o.init_input = 1;
    o.padding = 0.9 * g / fmax(hi[0] - lo[0], hi[1] - lo[1]);
    assert_int_equal(atlas_init(&f->a, &f->m, &o, &err), SCAF_OK);
    assert_int_equal(f->a.ncharts, 6);
    assert_int_equal(drag_barrier_init(&f->b, &f->a, &err), SCAF_OK);
    f->t = drag_barrier_make(&f->b);
    f->dof = malloc(sizeof(int) * (size_t)f->a.nw);
    assert_non_null(f->dof);
    for (int v = 0; v < f->a.nw; v++) f->dof[v] = v;
    /* the pattern op sets the iteration's barrier up at the loop's positions */
    assert_int_equal(f->t.ops->pattern(&f->t, f->dof, f->a.nw, &err), SCAF_OK);
    assert_true(f->b.n > 0 && f->b.nact > 0 && f->b.walls);
    f->side = atlas_side(&f->a);
}

static void teardown_fixture(fixture *f)
{
    opt_obj_term_free(&f->t);
    drag_barrier_free(&f->b);
    atlas_free(&f->a);
    mesh_free(&f->m);
    free(f->dof);
}

static double random_unit(unsigned *seed)
{
    *seed = *seed * 1103515245u + 12345u;
    return (double)((*seed >> 8) % 2001) / 1000.0 - 1.0;
}

/* X + s D */
static void along(int n, const double *X, const double *D, double s, double *Y)
{
    for (int i = 0; i < 2 * n; i++) Y[i] = X[i] + s * D[i];
}

static void slope_matches_central_difference(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f);
    int n = f.a.nw;
    double *X = malloc(sizeof(double) * 2 * (size_t)n);
    double *D = malloc(sizeof(double) * 2 * (size_t)n), *Y = malloc(sizeof(double) * 2 * (size_t)n);
    double *rhs = calloc(2 * (size_t)n, sizeof(double));
    assert_true(X && D && Y && rhs);
    /* the layout jittered (by far less than the barrier's room), so no
     * boundary segment is axis-aligned */
    unsigned seed = 99;
    for (int i = 0; i < 2 * n; i++) X[i] = f.a.loop.uv[i] + 1e-4 * f.side * random_unit(&seed);
    assert_int_equal(f.t.ops->hessian_fill(&f.t, f.dof, X, 1, rhs, NULL), SCAF_OK);
    for (int trial = 0; trial < 5; trial++) {
        for (int i = 0; i < 2 * n; i++) D[i] = random_unit(&seed) * f.side;
        double e0 = 0.0, slope = 0.0;
        f.t.ops->energy_slope(&f.t, X, D, &e0, &slope);
        assert_true(isfinite(e0) && e0 > 0.0);
        assert_true(e0 == f.t.ops->energy(&f.t, X));
        double h = 1e-9;
        along(n, X, D, h, Y);
        double ep = f.t.ops->energy(&f.t, Y);
        along(n, X, D, -h, Y);
        double em = f.t.ops->energy(&f.t, Y);
        double fd = (ep - em) / (2.0 * h);
        assert_true(fabs(fd - slope) <= 1e-4 * fabs(slope) + 1e-9 * e0);
        double g = 0.0; /* the Newton right-hand side is -grad */
        for (int i = 0; i < 2 * n; i++) g -= rhs[i] * D[i];
        assert_true(fabs(g - slope) <= 1e-9 * fabs(slope) + 1e-12 * e0);
    }
    free(X);
    free(D);
    free(Y);
    free(rhs);
    teardown_fixture(&f);
}

static void infinite_where_the_padding_fails(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f);
    int n = f.a.nw;
    const double *X = f.a.loop.uv;
    double *Y = malloc(sizeof(double) * 2 * (size_t)n);
    assert_non_null(Y);
    double cen[2] = {0, 0};
    for (int v = 0; v < n; v++) cen[0] += X[2 * v] / n, cen[1] += X[2 * v + 1] / n;
    /* the layout grown by 10% about its centre: every gap grows too, but
     * the side beyond the step's allowance (the walls) */
    for (int v = 0; v < n; v++)
        for (int k = 0; k < 2; k++) Y[2 * v + k] = cen[k] + 1.1 * (X[2 * v + k] - cen[k]);
    assert_true(isinf(f.t.ops->energy(&f.t, Y)));
    /* shrunk by 10%: the side shrinks, the gaps below the barrier's padding */
    for (int v = 0; v < n; v++)
        for (int k = 0; k < 2; k++) Y[2 * v + k] = cen[k] + 0.9 * (X[2 * v + k] - cen[k]);
    assert_true(isinf(f.t.ops->energy(&f.t, Y)));
    /* each chart pulled 2% toward the centre, the gaps grow: finite and lower */
    memcpy(Y, X, sizeof(double) * 2 * (size_t)n);
    double cc[6][3] = {{0}};
    for (int v = 0; v < n; v++) {
        int c = f.a.wchart[v];
        cc[c][0] += X[2 * v], cc[c][1] += X[2 * v + 1], cc[c][2] += 1.0;
    }
    for (int v = 0; v < n; v++) {
        int c = f.a.wchart[v];
        for (int k = 0; k < 2; k++) {
            double m = cc[c][k] / cc[c][2];
            Y[2 * v + k] = X[2 * v + k] + 0.02 * (cen[k] - m) - 0.04 * (X[2 * v + k] - m);
        }
    }
    double e = f.t.ops->energy(&f.t, Y);
    assert_true(isfinite(e) && e < f.t.ops->energy(&f.t, X));
    free(Y);
    teardown_fixture(&f);
}

/* Disabled (compaction), the term is empty: energy 0 whatever X. */
static void disabled_is_empty(void **state)
{
    (void)state;
    fixture f;
    setup_fixture(&f);
    drag_barrier_enable(&f.b, 0);
    assert_int_equal(f.t.ops->pattern(&f.t, f.dof, f.a.nw, NULL), SCAF_OK);
    assert_int_equal(f.b.n, 0);
    assert_int_equal(f.b.nact, 0);
    assert_true(f.t.ops->energy(&f.t, f.a.loop.uv) == 0.0);
    teardown_fixture(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(slope_matches_central_difference),
        cmocka_unit_test(infinite_where_the_padding_fails),
        cmocka_unit_test(disabled_is_empty),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
