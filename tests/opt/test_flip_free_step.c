/* Tests for opt/flip_free_step and opt/line_search: the largest flip-free
 * step is right (exact orientation just below it, ~zero area at it), and the
 * line search never inverts and lowers the energy. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>

#include "geom/predicates.h"
#include "opt/flip_free_step.h"
#include "opt/line_search.h"
#include "rng.h"

static double area2(const double *x0, const double *x1, const double *x2)
{
    return (x1[0] - x0[0]) * (x2[1] - x0[1]) - (x1[1] - x0[1]) * (x2[0] - x0[0]);
}

static void known_triangle_roots(void **state)
{
    (void)state;
    double x[6] = {0, 0, 1, 0, 0, 1};
    double z[6] = {0};
    /* Apex moves down by 2 per unit t: collapses at t = 0.5. */
    double d[6] = {0, 0, 0, 0, 0, -2};
    assert_true(fabs(opt_max_step_triangle(x, x + 2, x + 4, d, d + 2, d + 4) - 0.5) < 1e-15);
    /* No motion, translation, growth: never flips. */
    assert_true(isinf(opt_max_step_triangle(x, x + 2, x + 4, z, z + 2, z + 4)));
    double tr[6] = {3, -1, 3, -1, 3, -1};
    assert_true(isinf(opt_max_step_triangle(x, x + 2, x + 4, tr, tr + 2, tr + 4)));
    double grow[6] = {0, 0, 1, 0, 0, 1};
    assert_true(isinf(opt_max_step_triangle(x, x + 2, x + 4, grow, grow + 2, grow + 4)));
    /* Shrinking to the origin: a double root at t = 1 (area (1-t)^2). */
    double shrink[6] = {0, 0, -1, 0, 0, -1};
    double t = opt_max_step_triangle(x, x + 2, x + 4, shrink, shrink + 2, shrink + 4);
    assert_true(fabs(t - 1) < 1e-7 && t <= 1);
    /* Collapse onto the centroid at t = 0.5 (a double root). */
    double c[2] = {1.0 / 3, 1.0 / 3}, h[6];
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 2; a++) h[2 * i + a] = 2 * (c[a] - x[2 * i + a]);
    t = opt_max_step_triangle(x, x + 2, x + 4, h, h + 2, h + 4);
    assert_true(fabs(t - 0.5) < 1e-7 && t <= 0.5);
    /* Already degenerate: no step. */
    double flat[6] = {0, 0, 1, 0, 2, 0};
    assert_true(opt_max_step_triangle(flat, flat + 2, flat + 4, d, d + 2, d + 4) == 0.0);
}

static void random_triangle_steps(void **state)
{
    (void)state;
    rng r = {21};
    int finite = 0;
    for (int trial = 0; trial < 20000; trial++) {
        double x[6], d[6], y[6];
        rng_simplex(&r, 2, x);
        for (int k = 0; k < 6; k++) d[k] = rng_uniform(&r, -3, 3);
        if (trial % 5 == 0) d[0] = d[2] = d[4] = 0.25; /* a linear-coefficient-only case */
        double t = opt_max_step_triangle(x, x + 2, x + 4, d, d + 2, d + 4);
        assert_true(t > 0);
        double ts[3] = {t * (1 - 1e-7), t * 0.5, t * 1e-3};
        if (isinf(t)) {
            ts[0] = 10;
            ts[1] = 1e3;
            ts[2] = 1e6;
        }
        for (int s = 0; s < 3; s++) {
            for (int k = 0; k < 6; k++) y[k] = x[k] + ts[s] * d[k];
            assert_true(orient2d(y, y + 2, y + 4) > 0);
        }
        if (isfinite(t)) {
            finite++;
            for (int k = 0; k < 6; k++) y[k] = x[k] + t * d[k];
            double scale = 0;
            for (int k = 0; k < 6; k++) scale = fmax(scale, fabs(y[k]));
            assert_true(fabs(area2(y, y + 2, y + 4)) < 1e-9 * (1 + scale * scale));
            /* Past the root it is inverted (unless it was a double root). */
            for (int k = 0; k < 6; k++) y[k] = x[k] + t * (1 + 1e-6) * d[k];
            double a2 = orient2d(y, y + 2, y + 4);
            (void)a2;
        }
    }
    assert_true(finite > 1000);
}

static double det3(const double *x)
{
    double e[9];
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 3; a++) e[a * 3 + k] = x[3 * (k + 1) + a] - x[a];
    return det_d(3, e);
}

/* opt_max_step skips work for triangles that cannot lower its running
 * minimum: it must still return exactly the minimum of
 * opt_max_step_triangle over the triangles, in every order. */
static void mesh_step_is_exact_minimum(void **state)
{
    (void)state;
    rng r = {99};
    enum { NV = 60, NT = 200 };
    double X[2 * NV], D[2 * NV];
    int idx[3 * NT];
    opt_simplices S = {2, NT, idx, NULL, NULL, NULL};
    int finite = 0;
    for (int trial = 0; trial < 50; trial++) {
        for (int i = 0; i < 2 * NV; i++) {
            X[i] = rng_uniform(&r, -1, 1);
            D[i] = rng_uniform(&r, -1, 1) * (trial % 5 == 0 ? 1e-3 : 1.0);
        }
        for (int t = 0; t < NT; t++) {
            int a = (int)rng_uniform(&r, 0, NV), b = (int)rng_uniform(&r, 0, NV),
                c = (int)rng_uniform(&r, 0, NV);
            a = a % NV;
            b = b % NV;
            c = c % NV;
            if (a == b || b == c || a == c) {
                b = (a + 1) % NV;
                c = (a + 2) % NV;
            }
            /* orient counter-clockwise so most triangles are valid */
            double o = (X[2 * b] - X[2 * a]) * (X[2 * c + 1] - X[2 * a + 1]) -
                (X[2 * b + 1] - X[2 * a + 1]) * (X[2 * c] - X[2 * a]);
            if (o < 0) {
                int tmp = b;
                b = c;
                c = tmp;
            }
            idx[3 * t] = a;
            idx[3 * t + 1] = b;
            idx[3 * t + 2] = c;
        }
        /* every prefix: the running minimum of a batch's lane filter (opt
         * skips a triangle whose root cannot lower it) checked at each
         * length, across batch boundaries, not only at the end */
        double want = INFINITY;
        for (int t = 0; t < NT; t++) {
            const int *ix = idx + 3 * t;
            double v = opt_max_step_triangle(X + 2 * ix[0], X + 2 * ix[1], X + 2 * ix[2],
                                             D + 2 * ix[0], D + 2 * ix[1], D + 2 * ix[2]);
            if (v < want) want = v;
            S.n = t + 1;
            double got = opt_max_step(&S, X, D);
            assert_memory_equal(&got, &want, sizeof got);
        }
        finite += want > 0 && isfinite(want);
    }
    assert_true(finite >= 25); /* the minimum is a real root most of the time */
}

/* Each triangle alone (the lane kernel's every branch seen, not only the
 * minimum): opt_max_step on a one-triangle set equals
 * opt_max_step_triangle, bit for bit, for directions of every kind:
 * random, rigid translations and rotations (no root), one corner moving
 * (a linear area), zero, and triangles already inverted or flat. */
static void each_triangle_alone(void **state)
{
    (void)state;
    rng r = {103};
    int kinds[6] = {0};
    for (int k = 0; k < 600; k++) {
        double X[6], D[6];
        int idx[3] = {0, 1, 2};
        opt_simplices S = {2, 1, idx, NULL, NULL, NULL};
        for (int i = 0; i < 6; i++) {
            X[i] = rng_uniform(&r, -1, 1);
            D[i] = rng_uniform(&r, -2, 2);
        }
        int kind = k % 6;
        kinds[kind]++;
        if (kind == 1) /* a translation: the area never changes */
            for (int i = 2; i < 6; i++) D[i] = D[i % 2];
        if (kind == 2) /* one corner moves: the area is linear in t */
            for (int i = 0; i < 4; i++) D[i] = 0;
        if (kind == 3)
            for (int i = 0; i < 6; i++) D[i] = 0;
        if (kind == 4) /* a rotation about the origin */
            for (int i = 0; i < 3; i++) D[2 * i] = -X[2 * i + 1], D[2 * i + 1] = X[2 * i];
        if (kind == 5) /* flat */
            X[4] = X[0], X[5] = X[1];
        double want = opt_max_step_triangle(X, X + 2, X + 4, D, D + 2, D + 4);
        double got = opt_max_step(&S, X, D);
        assert_memory_equal(&got, &want, sizeof got);
    }
    for (int kind = 0; kind < 6; kind++) assert_true(kinds[kind] > 0);
}

static void tet_steps(void **state)
{
    (void)state;
    double x[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    double d[12] = {0};
    d[11] = -2; /* apex down: flat at t = 0.5 */
    double t = opt_max_step_tet(x, x + 3, x + 6, x + 9, d, d + 3, d + 6, d + 9);
    assert_true(fabs(t - 0.5) < 1e-12);
    double z[12] = {0};
    assert_true(isinf(opt_max_step_tet(x, x + 3, x + 6, x + 9, z, z + 3, z + 6, z + 9)));
    /* Shrinking to a point: triple root at t = 1. */
    double sh[12];
    for (int k = 0; k < 12; k++) sh[k] = -x[k];
    t = opt_max_step_tet(x, x + 3, x + 6, x + 9, sh, sh + 3, sh + 6, sh + 9);
    assert_true(fabs(t - 1) < 1e-4 && t <= 1);
    rng r = {23};
    int finite = 0;
    for (int trial = 0; trial < 20000; trial++) {
        double p[12], dd[12], y[12];
        rng_simplex(&r, 3, p);
        for (int k = 0; k < 12; k++) dd[k] = rng_uniform(&r, -3, 3);
        t = opt_max_step_tet(p, p + 3, p + 6, p + 9, dd, dd + 3, dd + 6, dd + 9);
        assert_true(t > 0);
        double ts[3] = {t * (1 - 1e-7), t * 0.5, t * 1e-3};
        if (isinf(t)) {
            ts[0] = 10;
            ts[1] = 1e3;
            ts[2] = 1e6;
        }
        for (int s = 0; s < 3; s++) {
            for (int k = 0; k < 12; k++) y[k] = p[k] + ts[s] * dd[k];
            assert_true(orient3d(y, y + 3, y + 6, y + 9) < 0); /* positive tet */
        }
        if (isfinite(t)) {
            finite++;
            for (int k = 0; k < 12; k++) y[k] = p[k] + t * dd[k];
            double scale = 0;
            for (int k = 0; k < 12; k++) scale = fmax(scale, fabs(y[k]));
            assert_true(fabs(det3(y)) < 1e-8 * (1 + scale * scale * scale));
        }
    }
    assert_true(finite > 1000);
}

static void polynomial_edge_cases(void **state)
{
    (void)state;
    double c1[4] = {1, -1, 0, 0}; /* linear: root 1 */
    assert_true(opt_first_positive_root(3, c1) == 1.0);
    double c2[4] = {1, 0, -1, 0}; /* 1 - t^2: root 1 */
    assert_true(fabs(opt_first_positive_root(3, c2) - 1) < 1e-15);
    double c3[4] = {1, 0, 0, -1}; /* 1 - t^3: root 1 */
    assert_true(fabs(opt_first_positive_root(3, c3) - 1) < 1e-15);
    double c4[4] = {1, -3, 3, 0}; /* 1 - 3t + 3t^2 > 0 always */
    assert_true(isinf(opt_first_positive_root(3, c4)));
    double c5[4] = {6, -11, 6, -1}; /* (1-t)(2-t)(3-t) */
    assert_true(fabs(opt_first_positive_root(3, c5) - 1) < 1e-12);
    double c6[4] = {1, 1e-300, -1e-300, 1e-310}; /* tiny coefficients */
    double r6 = opt_first_positive_root(3, c6);
    assert_true(r6 > 0);
}

/* A fan of triangles around a center vertex; the center is pushed hard
 * toward one side: the search must stop before any triangle flips and
 * lower the energy. */
static void line_search_never_flips(void **state)
{
    (void)state;
    int seg = 12;
    double X[2 * 13], D[2 * 13] = {0};
    int F[3 * 12];
    X[0] = 0;
    X[1] = 0;
    for (int j = 0; j < seg; j++) {
        X[2 + 2 * j] = cos(2 * 3.14159265358979 * j / seg);
        X[3 + 2 * j] = sin(2 * 3.14159265358979 * j / seg);
        F[3 * j] = 0;
        F[3 * j + 1] = 1 + j;
        F[3 * j + 2] = 1 + (j + 1) % seg;
    }
    opt_simplices S;
    /* Rest shape: the same fan with the center off to one side. */
    double R[2 * 13];
    memcpy(R, X, sizeof X);
    R[0] = 0.5;
    R[1] = 0.2;
    assert_int_equal(opt_simplices_from_current(&S, 2, 13, R, seg, F, 0.0, NULL), SCAF_OK);
    opt_term t = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_simplex_term st = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET, NULL, 0};
    opt_obj_term ot = opt_simplex_term_make(&st);
    D[0] = 5;
    D[1] = 1; /* far past the boundary */
    opt_ls_result res;
    double e0 = opt_obj_energy(&ot, 1, X);
    assert_int_equal(opt_line_search(&ot, 1, 2, 13, X, D, NULL, &res, NULL), SCAF_OK);
    assert_true(res.step > 0);
    assert_true(res.max_flip_free < 1);
    assert_true(res.step <= 0.8 * res.max_flip_free);
    assert_true(opt_obj_valid(&ot, 1, X));
    assert_true(res.energy_after < e0);
    assert_true(fabs(opt_obj_energy(&ot, 1, X) - res.energy_after) < 1e-12 * e0);
    /* Ascent direction: no step, X unchanged. */
    double keep[26];
    memcpy(keep, X, sizeof keep);
    D[0] = -D[0];
    D[1] = -D[1];
    double g[26] = {0};
    opt_term_gradient(&t, X, g);
    for (int k = 0; k < 26; k++) D[k] = g[k];
    assert_int_equal(opt_line_search(&ot, 1, 2, 13, X, D, NULL, &res, NULL), SCAF_OK);
    assert_true(res.step == 0);
    assert_memory_equal(keep, X, sizeof keep);
    /* Invalid start: an inverted triangle is reported. */
    X[0] = 3;
    scaf_error e;
    for (int k = 0; k < 26; k++) D[k] = 0;
    assert_int_equal(opt_line_search(&ot, 1, 2, 13, X, D, NULL, &res, &e), SCAF_ERR_NUMERIC);
    assert_false(opt_obj_valid(&ot, 1, X));
    opt_simplices_free(&S);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(known_triangle_roots),
        cmocka_unit_test(random_triangle_steps),
        cmocka_unit_test(tet_steps),
        cmocka_unit_test(mesh_step_is_exact_minimum),
        cmocka_unit_test(each_triangle_alone),
        cmocka_unit_test(polynomial_edge_cases),
        cmocka_unit_test(line_search_never_flips),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
