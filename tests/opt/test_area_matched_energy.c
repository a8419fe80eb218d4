/* Tests for opt/area_matched_energy: 4 at an isometry, invariant under
 * uniform scaling, translation and rotation of the UVs, the closed form of
 * linear maps, and infinite for a flipped face. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "opt/area_matched_energy.h"

/* a 3 by 3 grid of squares tilted out of the z = 0 plane, 18 faces, and
 * its plane coordinates */
enum { N = 3, NV = (N + 1) * (N + 1), NF = 2 * N * N };
static double V[3 * NV], P[2 * NV];
static int F[3 * NF];

static void grid(void)
{
    double c = cos(0.3), s = sin(0.3);
    for (int j = 0, v = 0; j <= N; j++)
        for (int i = 0; i <= N; i++, v++) {
            double x = i + 0.2 * (j % 2), y = 0.9 * j; /* not all right triangles */
            P[2 * v] = x, P[2 * v + 1] = y;
            V[3 * v] = x, V[3 * v + 1] = c * y, V[3 * v + 2] = s * y;
        }
    for (int j = 0, f = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int a = j * (N + 1) + i, b = a + 1, d = a + N + 1, e = d + 1;
            int *t = F + 3 * f;
            t[0] = a, t[1] = b, t[2] = e, t[3] = a, t[4] = e, t[5] = d;
            f += 2;
        }
}

/* UV = T(P) for the linear map [m00 m01; m10 m11], scaled, rotated, moved */
static double energy_of(double m00, double m01, double m10, double m11, double scale, double angle)
{
    double UV[2 * NV], c = cos(angle), s = sin(angle);
    for (int v = 0; v < NV; v++) {
        double x = m00 * P[2 * v] + m01 * P[2 * v + 1], y = m10 * P[2 * v] + m11 * P[2 * v + 1];
        UV[2 * v] = scale * (c * x - s * y) + 17.0, UV[2 * v + 1] = scale * (s * x + c * y) - 3.0;
    }
    return area_matched_energy(V, F, NF, UV, F);
}

static void isometry_is_four(void **state)
{
    (void)state;
    grid();
    assert_true(fabs(energy_of(1, 0, 0, 1, 1, 0) - 4.0) < 1e-12);
    assert_true(fabs(energy_of(1, 0, 0, 1, 1e-3, 2.0) - 4.0) < 1e-12);
    assert_true(fabs(energy_of(1, 0, 0, 1, 250.0, -1.0) - 4.0) < 1e-12);
}

static void linear_maps_closed_form(void **state)
{
    (void)state;
    grid();
    /* (2x, y/2): det 1, s = 1: ||J||^2 = ||J^-1||^2 = 4.25 */
    assert_true(fabs(energy_of(2, 0, 0, 0.5, 1, 0) - 8.5) < 1e-12);
    /* (2x, y): det 2, s^2 = 1/2: s J = diag(sqrt 2, 1/sqrt 2), 2.5 + 2.5 */
    double e = energy_of(2, 0, 0, 1, 1, 0);
    assert_true(fabs(e - 5.0) < 1e-12);
    /* the same map at any scale and turn: scale-free */
    assert_true(fabs(energy_of(2, 0, 0, 1, 0.01, 0.7) - e) < 1e-12 * e);
    /* shear (x + y, y): det 1, ||J||^2 = 3 */
    assert_true(fabs(energy_of(1, 1, 0, 1, 1, 0) - 6.0) < 1e-12);
}

static void flipped_is_infinite(void **state)
{
    (void)state;
    grid();
    assert_true(isinf(energy_of(-1, 0, 0, 1, 1, 0))); /* mirrored */
    double UV[2 * NV];
    for (int k = 0; k < 2 * NV; k++) UV[k] = P[k];
    UV[2 * 5] = 5.0; /* an inner vertex dragged far right folds its faces */
    assert_true(isinf(area_matched_energy(V, F, NF, UV, F)));
    for (int k = 0; k < 2 * NV; k++) UV[k] = 0.0; /* every face flat */
    assert_true(isinf(area_matched_energy(V, F, NF, UV, F)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(isometry_is_four),
        cmocka_unit_test(linear_maps_closed_form),
        cmocka_unit_test(flipped_is_infinite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
