/* Tests of geom/min_box: the exact convex hull, the least-area rectangle
 * angle and the smallest-square angle, checked against the known answers
 * for rotated rectangles and squares and against a fine sweep of angles. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "geom/min_box.h"

#define PI 3.14159265358979323846

/* A w x h rectangle's corners, its edge midpoints and center, turned by a. */
static int rectangle(double w, double h, double a, double *P)
{
    double pts[9][2] = {{0, 0},       {w, 0},       {w, h},
                        {0, h},       {0.5 * w, 0}, {w, 0.5 * h},
                        {0.5 * w, h}, {0, 0.5 * h}, {0.5 * w, 0.5 * h}};
    for (int i = 0; i < 9; i++) {
        P[2 * i] = cos(a) * pts[i][0] - sin(a) * pts[i][1];
        P[2 * i + 1] = sin(a) * pts[i][0] + cos(a) * pts[i][1];
    }
    return 9;
}

/* distance of two angles modulo pi/2 */
static double angle_dist(double a, double b)
{
    double d = fmod(fabs(a - b), 0.5 * PI);
    return fmin(d, 0.5 * PI - d);
}

static void hull_drops_interior_and_collinear(void **state)
{
    (void)state;
    double P[18];
    int n = rectangle(2.0, 1.0, 0.0, P), hull[10];
    int nh = min_box_hull(P, n, hull);
    assert_int_equal(nh, 4);
    for (int i = 0; i < nh; i++) assert_true(hull[i] < 4);
    /* counter-clockwise from the lowest-leftmost */
    assert_int_equal(hull[0], 0);
    assert_int_equal(hull[1], 1);
    assert_int_equal(hull[2], 2);
    assert_int_equal(hull[3], 3);
    /* duplicates and fewer than three points */
    double Q[6] = {1, 1, 1, 1, 2, 3};
    assert_int_equal(min_box_hull(Q, 3, hull), 2);
    assert_int_equal(min_box_hull(Q, 0, hull), 0);
}

static void least_area_rectangle_undoes_a_turn(void **state)
{
    (void)state;
    double P[18];
    int hull[10];
    for (int k = 0; k < 12; k++) {
        double a = 0.13 * k;
        int n = rectangle(3.0, 1.0, a, P), nh = min_box_hull(P, n, hull);
        double t = min_box_area_angle(P, hull, nh), w, h;
        /* turning by t brings it back to axis parallel: the turn is -a mod pi/2 */
        assert_true(angle_dist(t, -a) < 1e-12);
        min_box_extent(P, hull, nh, t, &w, &h);
        assert_true(fabs(w * h - 3.0) < 1e-12);
    }
}

static void smallest_square_of_a_strip_is_diagonal(void **state)
{
    (void)state;
    double P[18];
    int hull[10];
    /* a long strip: its smallest square holds it along the diagonal */
    int n = rectangle(8.0, 1.0, 0.2, P), nh = min_box_hull(P, n, hull);
    double side, t = min_box_square_angle(P, hull, nh, &side), w, h;
    assert_true(fabs(side - 9.0 / sqrt(2.0)) < 1e-9);
    min_box_extent(P, hull, nh, t, &w, &h);
    assert_true(fabs(fmax(w, h) - side) < 1e-12);
    /* no angle of a fine sweep does better */
    for (int i = 0; i < 9000; i++) {
        min_box_extent(P, hull, nh, 0.5 * PI * i / 9000.0, &w, &h);
        assert_true(fmax(w, h) >= side - 1e-12);
    }
    /* a square turned by 0.4: turned back (side 1, not sqrt 2) */
    n = rectangle(1.0, 1.0, 0.4, P);
    nh = min_box_hull(P, n, hull);
    t = min_box_square_angle(P, hull, nh, &side);
    assert_true(fabs(side - 1.0) < 1e-12);
    assert_true(angle_dist(t, -0.4) < 1e-12);
}

static void square_angle_beats_a_sweep_on_random_sets(void **state)
{
    (void)state;
    unsigned s = 12345u;
    double P[2 * 40];
    int hull[41];
    for (int trial = 0; trial < 50; trial++) {
        double sx = 1.0 + trial % 5, sy = 1.0 + (trial * 7) % 3;
        for (int i = 0; i < 40; i++) {
            s = s * 1103515245u + 12345u;
            P[2 * i] = sx * ((s >> 8) % 10000) / 10000.0;
            s = s * 1103515245u + 12345u;
            P[2 * i + 1] = sy * ((s >> 8) % 10000) / 10000.0;
        }
        int nh = min_box_hull(P, 40, hull);
        double side, w, h;
        min_box_square_angle(P, hull, nh, &side);
        for (int i = 0; i < 2000; i++) {
            min_box_extent(P, hull, nh, 0.5 * PI * i / 2000.0, &w, &h);
            assert_true(fmax(w, h) >= side - 1e-12);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hull_drops_interior_and_collinear),
        cmocka_unit_test(least_area_rectangle_undoes_a_turn),
        cmocka_unit_test(smallest_square_of_a_strip_is_diagonal),
        cmocka_unit_test(square_angle_beats_a_sweep_on_random_sets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
