/* Tests for scaffold/tri2: rest frames, energies, gradients against finite
 * differences, SLIM elements and the flip-free step. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "scaffold/tri2.h"

static void rest_frame_of_flat_triangle_gives_rotation(void **state)
{
    (void)state;
    /* A triangle in the plane z = 1, mapped to UV by the identity on (x, y)
     * rotated by 30 degrees: J must be a rotation, SD energy 4. */
    double p0[3] = {0.2, 0.1, 1}, p1[3] = {1.3, 0.4, 1}, p2[3] = {0.5, 1.7, 1};
    double Dminv[4];
    double area = tri2_rest_from_3d(p0, p1, p2, Dminv);
    assert_true(fabs(area - 0.5 * fabs((1.1) * (1.6) - (0.3) * (0.3))) < 1e-12);
    double c = cos(0.5236), s = sin(0.5236);
    double u0[2] = {c * p0[0] - s * p0[1], s * p0[0] + c * p0[1]};
    double u1[2] = {c * p1[0] - s * p1[1], s * p1[0] + c * p1[1]};
    double u2[2] = {c * p2[0] - s * p2[1], s * p2[0] + c * p2[1]};
    double J[4];
    tri2_jacobian(u0, u1, u2, Dminv, J);
    assert_true(fabs(J[0] * J[3] - J[1] * J[2] - 1.0) < 1e-12);
    assert_true(fabs(tri2_energy(SCAF_ENERGY_SYMMETRIC_DIRICHLET, J) - 4.0) < 1e-12);
    assert_true(fabs(tri2_energy(SCAF_ENERGY_ARAP, J)) < 1e-12);
    assert_true(fabs(tri2_energy(SCAF_ENERGY_CONFORMAL, J) - 2.0) < 1e-12);
    /* Mirrored image: infinite energy. */
    tri2_jacobian(u0, u2, u1, Dminv, J);
    assert_true(isinf(tri2_energy(SCAF_ENERGY_SYMMETRIC_DIRICHLET, J)));
}

static void degenerate_3d_triangle_has_zero_area(void **state)
{
    (void)state;
    double p0[3] = {0, 0, 0}, p1[3] = {1, 1, 1}, p2[3] = {2, 2, 2}, D[4];
    assert_true(tri2_rest_from_3d(p0, p1, p2, D) == 0.0);
}

static void gradient_matches_finite_differences(void **state)
{
    (void)state;
    double J[4] = {1.3, 0.4, -0.2, 0.7};
    for (int e = 0; e <= SCAF_ENERGY_CONFORMAL; e++) {
        double G[4];
        tri2_energy_grad((scaf_energy)e, J, G);
        for (int k = 0; k < 4; k++) {
            double h = 1e-6, Jp[4], Jm[4];
            for (int j = 0; j < 4; j++) Jp[j] = Jm[j] = J[j];
            Jp[k] += h;
            Jm[k] -= h;
            double fd = (tri2_energy((scaf_energy)e, Jp) - tri2_energy((scaf_energy)e, Jm)) / (2 * h);
            assert_true(fabs(fd - G[k]) < 1e-5 * (1.0 + fabs(fd)));
        }
    }
}

static void slim_weights_reproduce_energy_gradient(void **state)
{
    (void)state;
    /* SLIM's proxy a||W(J - R)||^2 has, at the current J, the same
     * gradient as the energy a E(J) (Rabinovich et al., Sec. 4). */
    double Dminv[4] = {0.9, -0.3, 0.0, 1.2};
    double x[6] = {0.1, 0.0, 1.4, 0.2, 0.3, 1.1};
    for (int e = SCAF_ENERGY_SYMMETRIC_DIRICHLET; e <= SCAF_ENERGY_ARAP; e++) {
        double J[4], W[4], R[4], K[36], b[6], G[4];
        tri2_jacobian(x, x + 2, x + 4, Dminv, J);
        tri2_slim_weights((scaf_energy)e, J, W, R);
        tri2_slim_element(1.0, Dminv, W, R, K, b);
        tri2_energy_grad((scaf_energy)e, J, G);
        /* proxy gradient: K x - b; energy gradient by corners */
        double g[3][2] = {{-(Dminv[0] + Dminv[2]), -(Dminv[1] + Dminv[3])}, {Dminv[0], Dminv[1]}, {Dminv[2], Dminv[3]}};
        for (int i = 0; i < 3; i++)
            for (int k = 0; k < 2; k++) {
                double pg = -b[2 * i + k];
                for (int j = 0; j < 6; j++) pg += K[(2 * i + k) * 6 + j] * x[j];
                double eg = G[2 * k] * g[i][0] + G[2 * k + 1] * g[i][1];
                assert_true(fabs(pg - eg) < 1e-8 * (1.0 + fabs(eg)));
            }
        /* K symmetric positive semidefinite diagonal */
        for (int r = 0; r < 6; r++) {
            assert_true(K[r * 6 + r] >= 0.0);
            for (int c = 0; c < 6; c++) assert_true(fabs(K[r * 6 + c] - K[c * 6 + r]) < 1e-12);
        }
    }
}

static void max_step_finds_collapse(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
    double z[2] = {0, 0}, dc[2] = {0, -2};
    /* c moves down by 2t: collinear at t = 0.5 */
    assert_true(fabs(tri2_max_step(a, b, c, z, z, dc) - 0.5) < 1e-15);
    double up[2] = {0, 1};
    assert_true(isinf(tri2_max_step(a, b, c, z, z, up)));
    /* rotation of c around a never degenerates before passing through... a
     * quadratic case: b and c both move */
    double db[2] = {-1, 1}, dc2[2] = {1, -1};
    double t = tri2_max_step(a, b, c, z, db, dc2);
    /* b(t) = (1-t, t), c(t) = (t, 1-t): det = (1-t)^2 - t^2 = 1 - 2t */
    assert_true(fabs(t - 0.5) < 1e-15);
}

static void guard_replaces_tiny_rest_triangle(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0.5, 1e-9}, D[4];
    double used = tri2_rest_from_2d(a, b, c, 0.01, D);
    assert_true(fabs(used - 0.01) < 1e-15);
    /* equilateral of area eps: det(Dminv) = 1 / (2 eps) */
    assert_true(fabs((D[0] * D[3] - D[1] * D[2]) - 1.0 / (2 * 0.01)) < 1e-9);
    double c2[2] = {0.5, 1.0};
    used = tri2_rest_from_2d(a, b, c2, 0.01, D);
    assert_true(fabs(used - 0.5) < 1e-15);
    double J[4];
    tri2_jacobian(a, b, c2, D, J);
    assert_true(fabs(J[0] - 1) < 1e-15 && fabs(J[3] - 1) < 1e-15 && fabs(J[1]) < 1e-15 && fabs(J[2]) < 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rest_frame_of_flat_triangle_gives_rotation),
        cmocka_unit_test(degenerate_3d_triangle_has_zero_area),
        cmocka_unit_test(gradient_matches_finite_differences),
        cmocka_unit_test(slim_weights_reproduce_energy_gradient),
        cmocka_unit_test(max_step_finds_collapse),
        cmocka_unit_test(guard_replaces_tiny_rest_triangle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
