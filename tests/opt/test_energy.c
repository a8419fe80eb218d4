/* Tests for opt/energy, opt/small_svd, opt/simplices: values at known
 * maps, gradients against central differences, invariance, SLIM property;
 * opt/sd2_lanes against the one-simplex-at-a-time sums and proxies, to the
 * bit. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/arap_barrier.h"
#include "opt/energy.h"
#include "opt/sd2_lanes.h"
#include "opt/simplices.h"
#include "opt/small_svd.h"
#include "rng.h"

static const opt_energy all_energies[] = {OPT_ENERGY_SYMMETRIC_DIRICHLET, OPT_ENERGY_ARAP,
                                          OPT_ENERGY_CONFORMAL};

static void matmul(int d, const double *A, const double *B, double *C)
{
    for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++) {
            double s = 0;
            for (int k = 0; k < d; k++) s += A[i * d + k] * B[k * d + j];
            C[i * d + j] = s;
        }
}

static void svd_reconstructs(void **state)
{
    (void)state;
    rng r = {7};
    for (int d = 2; d <= 3; d++)
        for (int trial = 0; trial < 2000; trial++) {
            double J[9], U[9], V[9], s[3];
            for (int k = 0; k < d * d; k++) J[k] = rng_uniform(&r, -2, 2);
            if (trial % 7 == 0) /* rank-deficient: duplicate a row */
                for (int a = 0; a < d; a++) J[d + a] = 0.5 * J[a];
            if (trial == 1)
                for (int k = 0; k < d * d; k++) J[k] = 0;
            svd_signed(d, J, U, s, V);
            assert_true(fabs(det_d(d, U) - 1) < 1e-9);
            assert_true(fabs(det_d(d, V) - 1) < 1e-9);
            for (int i = 0; i + 1 < d; i++) assert_true(s[i] >= fabs(s[i + 1]) - 1e-12);
            double detJ = det_d(d, J);
            if (fabs(detJ) > 1e-9) assert_true((s[d - 1] > 0) == (detJ > 0));
            double SVt[9], R[9];
            for (int i = 0; i < d; i++)
                for (int j = 0; j < d; j++) SVt[i * d + j] = s[i] * V[j * d + i];
            matmul(d, U, SVt, R);
            for (int k = 0; k < d * d; k++) assert_true(fabs(R[k] - J[k]) < 1e-10);
        }
}

/* svd_hypot: within 2 ulp of hypot where the plain formula is used, and
 * no underflow to 0 or overflow to infinity outside that range; a 2x2 SVD
 * of a tiny or a huge Jacobian stays exact up to rounding. */
static void hypot_fast_path(void **state)
{
    (void)state;
    rng r = {3};
    for (int t = 0; t < 10000; t++) {
        double a = rng_uniform(&r, -4, 4), b = rng_uniform(&r, -4, 4);
        double h = hypot(a, b), f = svd_hypot(a, b);
        assert_true(fabs(f - h) <= 2.0 * DBL_EPSILON * h);
    }
    static const double scale[4] = {1e-200, 1e-160, 1e160, 1e200};
    for (int k = 0; k < 4; k++) {
        double a = 3 * scale[k], b = 4 * scale[k], f = svd_hypot(a, b);
        assert_true(isfinite(f) && fabs(f - 5 * scale[k]) <= 4.0 * DBL_EPSILON * 5 * scale[k]);
        double J[4] = {a, -b, b, a}, U[4], V[4], s[2];
        svd2_signed(J, U, s, V);
        assert_true(fabs(s[0] - 5 * scale[k]) <= 1e-12 * 5 * scale[k]);
        assert_true(fabs(s[1] - 5 * scale[k]) <= 1e-12 * 5 * scale[k]);
    }
}

/* One-simplex set with rest corners P ((d+1) by d). */
static void one_simplex(opt_simplices *S, int d, const double *P)
{
    int idx[4] = {0, 1, 2, 3};
    assert_int_equal(opt_simplices_from_current(S, d, d + 1, P, 1, idx, 0.0, NULL), SCAF_OK);
}

static void gradients_match_finite_differences(void **state)
{
    (void)state;
    rng r = {11};
    for (int d = 2; d <= 3; d++)
        for (size_t e = 0; e < sizeof all_energies / sizeof all_energies[0]; e++)
            for (int trial = 0; trial < 50; trial++) {
                double P[12], Y[12];
                rng_simplex(&r, d, P);
                rng_simplex(&r, d, Y);
                opt_simplices S;
                one_simplex(&S, d, P);
                S.weight[0] = rng_uniform(&r, 0.5, 2);
                opt_term t = {&S, all_energies[e]};
                double g[12] = {0};
                opt_term_gradient(&t, Y, g);
                double scale = 0;
                for (int k = 0; k < (d + 1) * d; k++) scale = fmax(scale, fabs(g[k]));
                for (int k = 0; k < (d + 1) * d; k++) {
                    double h = 1e-6, keep = Y[k];
                    Y[k] = keep + h;
                    double ep = opt_term_energy(&t, Y);
                    Y[k] = keep - h;
                    double em = opt_term_energy(&t, Y);
                    Y[k] = keep;
                    double fd = (ep - em) / (2 * h);
                    if (fabs(fd - g[k]) > 1e-5 * (1 + scale)) {
                        print_error("d=%d energy=%s trial=%d k=%d fd=%g g=%g\n", d,
                                    opt_energy_name(all_energies[e]), trial, k, fd, g[k]);
                        fail();
                    }
                }
                opt_simplices_free(&S);
            }
}

static void isometry_values(void **state)
{
    (void)state;
    rng r = {3};
    /* 2D: a 3D triangle laid flat, rotated and moved, has SD = 4. */
    for (int trial = 0; trial < 100; trial++) {
        double V[9], q[6], R[4], Y[6];
        for (int k = 0; k < 9; k++) V[k] = rng_uniform(&r, -1, 1);
        int F[3] = {0, 1, 2};
        opt_simplices S;
        assert_int_equal(opt_simplices_from_surface(&S, 3, V, 1, F, NULL), SCAF_OK);
        opt_flatten_triangle(V, V + 3, V + 6, q);
        rng_rotation(&r, 2, R);
        double tx = rng_uniform(&r, -5, 5), ty = rng_uniform(&r, -5, 5);
        for (int i = 0; i < 3; i++) {
            Y[2 * i] = R[0] * q[2 * i] + R[1] * q[2 * i + 1] + tx;
            Y[2 * i + 1] = R[2] * q[2 * i] + R[3] * q[2 * i + 1] + ty;
        }
        double J[4];
        opt_jacobian(&S, 0, Y, J);
        assert_true(fabs(opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J) - 4) < 1e-9);
        assert_true(fabs(opt_density(OPT_ENERGY_ARAP, 2, J)) < 1e-9);
        assert_true(fabs(opt_density(OPT_ENERGY_CONFORMAL, 2, J) - 1) < 1e-9);
        opt_term tt = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
        assert_true(fabs(opt_term_mean_energy(&tt, Y) - 4) < 1e-9);
        /* The weight is the 3D area. */
        double e1[3] = {V[3] - V[0], V[4] - V[1], V[5] - V[2]},
               e2[3] = {V[6] - V[0], V[7] - V[1], V[8] - V[2]};
        double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
               cz = e1[0] * e2[1] - e1[1] * e2[0];
        assert_true(fabs(S.weight[0] - 0.5 * sqrt(cx * cx + cy * cy + cz * cz)) < 1e-12);
        opt_simplices_free(&S);
    }
    /* 3D: rigid motion of a tet: SD = 6, ARAP 0; scaling keeps conformal at 1. */
    for (int trial = 0; trial < 100; trial++) {
        double P[12], R[9], Y[12];
        rng_simplex(&r, 3, P);
        rng_rotation(&r, 3, R);
        double sc = trial % 2 ? 1.0 : rng_uniform(&r, 0.2, 5);
        for (int i = 0; i < 4; i++)
            for (int a = 0; a < 3; a++)
                Y[3 * i + a] = sc *
                        (R[3 * a] * P[3 * i] + R[3 * a + 1] * P[3 * i + 1] +
                         R[3 * a + 2] * P[3 * i + 2]) +
                    1.5;
        opt_simplices S;
        one_simplex(&S, 3, P);
        double J[9];
        opt_jacobian(&S, 0, Y, J);
        assert_true(fabs(opt_density(OPT_ENERGY_CONFORMAL, 3, J) - 1) < 1e-9);
        if (sc == 1.0) {
            assert_true(fabs(opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 3, J) - 6) < 1e-9);
            assert_true(fabs(opt_density(OPT_ENERGY_ARAP, 3, J)) < 1e-9);
        } else {
            assert_true(opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 3, J) > 6);
        }
        opt_simplices_free(&S);
    }
}

static void rotation_invariance(void **state)
{
    (void)state;
    rng r = {5};
    for (int d = 2; d <= 3; d++)
        for (size_t e = 0; e < 3; e++)
            for (int trial = 0; trial < 50; trial++) {
                double P[12], Y[12], Z[12], R[9];
                rng_simplex(&r, d, P);
                rng_simplex(&r, d, Y);
                rng_rotation(&r, d, R);
                for (int i = 0; i <= d; i++)
                    for (int a = 0; a < d; a++) {
                        double s = 0;
                        for (int k = 0; k < d; k++) s += R[a * d + k] * Y[i * d + k];
                        Z[i * d + a] = s;
                    }
                opt_simplices S;
                one_simplex(&S, d, P);
                opt_term t = {&S, all_energies[e]};
                double ey = opt_term_energy(&t, Y), ez = opt_term_energy(&t, Z);
                assert_true(fabs(ey - ez) <= 1e-10 * fabs(ey) + 1e-12);
                /* Inverted maps: every energy is a barrier (ARAP through
                 * its b(det J)): infinite. */
                for (int a = 0; a < d; a++)
                    Z[a] = Y[a], Z[d + a] = Y[2 * d + a], Z[2 * d + a] = Y[d + a];
                for (int i = 3; i <= d; i++)
                    for (int a = 0; a < d; a++) Z[i * d + a] = Y[i * d + a];
                double ei = opt_term_energy(&t, Z);
                assert_true(isinf(ei));
                opt_simplices_free(&S);
            }
}

/* SLIM: the gradient of ||W (J - T)||^2 at the current J is dE/dJ. */
static void slim_proxy_gradient_matches(void **state)
{
    (void)state;
    rng r = {9};
    for (int d = 2; d <= 3; d++)
        for (size_t e = 0; e < 3; e++) {
            if (d == 3 && all_energies[e] == OPT_ENERGY_CONFORMAL) continue; /* approximate there */
            for (int trial = 0; trial < 500; trial++) {
                double J[9];
                do {
                    for (int k = 0; k < d * d; k++) J[k] = rng_uniform(&r, -2, 2);
                } while (det_d(d, J) < 0.01);
                if (trial == 0) /* exactly a rotation: the 0/0 case of the weights */
                    for (int k = 0; k < d * d; k++) J[k] = (k % (d + 1) == 0);
                double W[9], T[9], G[9], M[9], D[9], P[9];
                opt_slim_proxy(all_energies[e], d, J, W, T);
                opt_density_grad(all_energies[e], d, J, G);
                double Wt[9];
                for (int a = 0; a < d; a++)
                    for (int b = 0; b < d; b++) Wt[a * d + b] = W[b * d + a];
                matmul(d, Wt, W, M);
                for (int k = 0; k < d * d; k++) D[k] = J[k] - T[k];
                matmul(d, M, D, P);
                double scale = 0;
                for (int k = 0; k < d * d; k++) scale = fmax(scale, fabs(G[k]));
                for (int k = 0; k < d * d; k++) {
                    if (fabs(2 * P[k] - G[k]) > 1e-8 * (1 + scale)) {
                        print_error("d=%d %s trial %d: proxy grad %g vs %g\n", d,
                                    opt_energy_name(all_energies[e]), trial, 2 * P[k], G[k]);
                        fail();
                    }
                }
                /* W symmetric positive definite. */
                double wmax = 0;
                for (int k = 0; k < d * d; k++) wmax = fmax(wmax, fabs(W[k]));
                for (int a = 0; a < d; a++)
                    for (int b = 0; b < d; b++)
                        assert_true(fabs(W[a * d + b] - W[b * d + a]) < 1e-12 * (1 + wmax));
                assert_true(det_d(d, M) > 0 && M[0] > 0);
            }
        }
}

/* The trig-free 2D proxy equals the one built from the explicit SVD. */
static void proxy_2d_matches_svd(void **state)
{
    (void)state;
    rng r = {17};
    for (int trial = 0; trial < 2000; trial++) {
        double J[4], U[4], V[4], sv[2], W[4], T[4];
        do {
            for (int k = 0; k < 4; k++) J[k] = rng_uniform(&r, -2, 2);
        } while (det_d(2, J) <= 1e-3);
        if (trial == 0) {
            J[0] = 1.5;
            J[1] = 0;
            J[2] = 0;
            J[3] = 1.5;
        } /* equal singular values */
        svd2_signed(J, U, sv, V);
        for (int e = 0; e < 2; e++) {
            /* (ARAP's barrier changes its weights below det OPT_ARAP_BARRIER_DET) */
            if (e == 1 && det_d(2, J) < OPT_ARAP_BARRIER_DET) continue;
            double w[2];
            for (int i = 0; i < 2; i++)
                w[i] = e == 0 ? sqrt((sv[i] + 1) * (sv[i] * sv[i] + 1) / (sv[i] * sv[i] * sv[i]))
                              : 1.0;
            opt_slim_proxy(e == 0 ? OPT_ENERGY_SYMMETRIC_DIRICHLET : OPT_ENERGY_ARAP, 2, J, W, T);
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) {
                    double wr = U[a * 2] * w[0] * U[b * 2] + U[a * 2 + 1] * w[1] * U[b * 2 + 1];
                    double tr = U[a * 2] * V[b * 2] + U[a * 2 + 1] * V[b * 2 + 1];
                    assert_true(fabs(W[a * 2 + b] - wr) < 1e-9 * (1 + fabs(wr)));
                    assert_true(fabs(T[a * 2 + b] - tr) < 1e-12);
                }
        }
    }
}

static void conformal_3d_proxy_is_spd(void **state)
{
    (void)state;
    rng r = {13};
    for (int trial = 0; trial < 500; trial++) {
        double J[9], W[9], T[9];
        do {
            for (int k = 0; k < 9; k++) J[k] = rng_uniform(&r, -2, 2);
        } while (det_d(3, J) < 0.01);
        opt_slim_proxy(OPT_ENERGY_CONFORMAL, 3, J, W, T);
        for (int k = 0; k < 9; k++) assert_true(isfinite(W[k]) && isfinite(T[k]));
        assert_true(W[0] > 0 && W[0] * W[4] - W[1] * W[3] > 0 && det_d(3, W) > 0);
    }
}

/* Capped weights: W^T W never exceeds the cap; the uncapped maximum is
 * reported; with a cap above it the proxy is unchanged. */
static void capped_proxy(void **state)
{
    (void)state;
    for (int d = 2; d <= 3; d++) {
        double J[9] = {0};
        for (int a = 0; a < d; a++) J[a * d + a] = a == 0 ? 1e-4 : 1.0; /* w2 ~ 1e12 */
        double W[9], T[9], W2[9], T2[9];
        double w2 = opt_slim_proxy_capped(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, 1e6, W, T);
        assert_true(w2 > 1e11);
        /* W is diagonal here: entries are the capped weights. */
        for (int a = 0; a < d; a++) assert_true(W[a * d + a] * W[a * d + a] <= 1e6 * (1 + 1e-12));
        assert_true(fabs(W[0] * W[0] - 1e6) < 1e-3);
        opt_slim_proxy(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, W, T);
        opt_slim_proxy_capped(OPT_ENERGY_SYMMETRIC_DIRICHLET, d, J, 2 * w2, W2, T2);
        assert_memory_equal(W, W2, d * d * sizeof(double));
        assert_memory_equal(T, T2, d * d * sizeof(double));
    }
}

static void builders_refuse_bad_input(void **state)
{
    (void)state;
    double V[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0}; /* collinear */
    int F[3] = {0, 1, 2}, Fbad[3] = {0, 1, 5};
    opt_simplices S;
    scaf_error e;
    assert_int_equal(opt_simplices_from_surface(&S, 3, V, 1, F, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "triangle 0"));
    assert_int_equal(opt_simplices_from_surface(&S, 3, V, 1, Fbad, &e), SCAF_ERR_USAGE);
    /* Current-shape rest with the degeneracy guard: a collinear triangle
     * gets an equilateral rest shape of the given area. */
    double X[6] = {0, 0, 1, 0, 2, 0};
    assert_int_equal(opt_simplices_from_current(&S, 2, 3, X, 1, F, 0.0, &e), SCAF_ERR_MESH);
    assert_int_equal(opt_simplices_from_current(&S, 2, 3, X, 1, F, 0.25, &e), SCAF_OK);
    assert_true(fabs(S.vol[0] - 0.25) < 1e-12);
    double Y[6] = {0, 0, 1, 0, 0.5, sqrt(3.0) / 2};
    double J[4];
    opt_jacobian(&S, 0, Y, J);
    /* An equilateral triangle of area sqrt(3)/4 vs rest area 1/4: a pure scaling. */
    assert_true(fabs(opt_density(OPT_ENERGY_CONFORMAL, 2, J) - 1) < 1e-9);
    opt_simplices_free(&S);
}

/* The guard's rest shape is a continuous function of the current shape:
 * a sliver squeezed from four times the guard area to an eighth of it, in
 * small steps, sees its scaffold energy (symmetric Dirichlet of the
 * current shape against its own rest, times the rest area) change by
 * little from one step to the next. The paper's guard jumped at min_vol
 * from rest = current (density 4) to a regular rest (a sliver against it:
 * density ~ 40 here); a re-rested scaffold then pushed back by a jump at each
 * iteration where the boundary closed in (ARAP on camel_b cycled). */
static void guard_is_continuous(void **state)
{
    (void)state;
    const double min_vol = 0.01, base = 1.0; /* sliver: base 1, area 4 min_vol .. min_vol / 8 */
    int F[3] = {0, 1, 2};
    double prev = NAN, worst = 0;
    for (int k = 0; k <= 4000; k++) {
        double area = 4 * min_vol * pow(1.0 / 32, k / 4000.0);
        double h = 2 * area / base;
        double X[6] = {0, 0, base, 0, 0.3 * base, h};
        opt_simplices S;
        assert_int_equal(opt_simplices_from_current(&S, 2, 3, X, 1, F, min_vol, NULL), SCAF_OK);
        /* The rest never falls below the smaller of the area and the guard's quarter. */
        assert_true(S.vol[0] >= fmin(area, min_vol / 4) * (1 - 1e-12));
        double J[4];
        opt_jacobian(&S, 0, X, J);
        double e = S.vol[0] * opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J);
        if (area >= 2 * min_vol) assert_true(fabs(e - 4 * area) < 1e-9 * area); /* rest = current */
        if (k > 0) worst = fmax(worst, fabs(e - prev) / fmax(e, prev));
        prev = e;
        opt_simplices_free(&S);
    }
    assert_true(worst < 0.02);
}

/* The lane sums (opt/sd2_lanes) are the serial loops' to the bit:
 * random triangles, first some of them inverted or degenerate at X (+inf
 * energy, NaN slope), then all made positive (every slope finite); each
 * simplex alone, and ranges of every length mod 8 from several starts. */
static void lanes_sum_like_one_at_a_time(void **state)
{
    (void)state;
    rng r = {97};
    const int n = 2000, nv = 500, nlong = 70; /* ranges from 0, 1, 2 up to nlong */
    opt_simplices S;
    assert_int_equal(opt_simplices_alloc(&S, 2, n, NULL), SCAF_OK);
    double X[2 * 500], D[2 * 500];
    for (int i = 0; i < 2 * nv; i++) {
        X[i] = rng_uniform(&r, -1, 1);
        D[i] = rng_uniform(&r, -1, 1);
    }
    for (int s = 0; s < n; s++) {
        int *ix = S.idx + 3 * s;
        for (int c = 0; c < 3; c++) ix[c] = (int)rng_uniform(&r, 0, nv - 1e-9);
        if (s % 9 == 4) ix[2] = ix[1]; /* degenerate: det 0 */
        for (int k = 0; k < 6; k++) S.grad[6 * s + k] = rng_uniform(&r, -3, 3);
        S.vol[s] = 1;
        S.weight[s] = rng_uniform(&r, 0.1, 2);
    }
    for (int phase = 0; phase < 2; phase++) {
        int inverted = 0, finite_slopes = 0;
        /* every simplex alone (its own bits), then longer ranges */
        for (int lo = 0; lo < n; lo++)
            for (int hi = lo; hi <= (lo < 3 ? nlong : lo + 1); hi++) {
                double e = 0, es = 0.5, sl = -0.25, J[4], JD[4], G[4];
                for (int s = lo; s < hi; s++) {
                    opt_jacobian(&S, s, X, J);
                    opt_jacobian(&S, s, D, JD);
                    double v = opt_density_grad(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J, G);
                    double dot = 0;
                    for (int q = 0; q < 4; q++) dot += G[q] * JD[q];
                    e += S.weight[s] * opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J);
                    sl += S.weight[s] * dot;
                    es += S.weight[s] * v;
                    inverted += isinf(v);
                }
                double le = opt_sd2_energy_range(&S, X, (size_t)lo, (size_t)hi);
                double les = 0.5, lsl = -0.25;
                opt_sd2_energy_slope_range(&S, X, D, (size_t)lo, (size_t)hi, &les, &lsl);
                assert_memory_equal(&le, &e, sizeof e);
                assert_memory_equal(&les, &es, sizeof es);
                if (isnan(sl)) {
                    assert_true(isnan(lsl));
                } else {
                    finite_slopes++;
                    assert_memory_equal(&lsl, &sl, sizeof sl);
                }
            }
        if (phase == 0) {
            assert_true(inverted > 0);
            /* all positive: a degenerate triangle gets distinct corners
             * (redrawn until its Jacobian is not singular), an inverted one
             * its second gradient column negated (det -> -det) */
            for (int s = 0; s < n; s++) {
                double J[4];
                for (;;) {
                    opt_jacobian(&S, s, X, J);
                    double det = J[0] * J[3] - J[1] * J[2];
                    if (det > 0) break;
                    if (det < 0) {
                        for (int c = 0; c < 3; c++) S.grad[6 * s + 2 * c + 1] *= -1;
                        continue;
                    }
                    S.idx[3 * s + 2] = (int)rng_uniform(&r, 0, nv - 1e-9);
                }
            }
        } else {
            assert_int_equal(inverted, 0);
            assert_int_equal(finite_slopes, 3 * (nlong + 1) - 3 + 2 * (n - 3));
        }
    }
    opt_simplices_free(&S);
}

/* opt_sd2_proxy_range against one simplex at a time: opt_slim_proxy_capped,
 * then M = W^T W, MT = M T and lin = pullback(G, MT) in proxy_block's
 * order; Jacobians of every kind the 2D proxy branches on (similarity,
 * anti-similarity, zero, reflections, squares below DBL_MIN and above
 * DBL_MAX for svd_hypot's fallback), with and without a cap, ranges not
 * multiples of 8. */
static void lanes_proxy_like_one_at_a_time(void **state)
{
    (void)state;
    rng r = {101};
    const int n = 1000;
    opt_simplices S;
    assert_int_equal(opt_simplices_alloc(&S, 2, n, NULL), SCAF_OK);
    /* X holds each simplex's Jacobian directly: corners (0,0), (1,0), (0,1)
     * with gradients such that J = [x1 - x0, x2 - x0] */
    double *X = malloc(sizeof *X * 6 * n);
    for (int s = 0; s < n; s++) {
        double J[4];
        for (int k = 0; k < 4; k++) J[k] = rng_uniform(&r, -2, 2);
        switch (s % 10) {
        case 0: J[3] = J[0], J[2] = -J[1]; break;     /* similarity: R = 0 */
        case 1: J[3] = -J[0], J[2] = J[1]; break;     /* anti-similarity: Q = 0 */
        case 2: J[0] = J[1] = J[2] = J[3] = 0; break; /* Q = R = 0 */
        case 3:
            for (int k = 0; k < 4; k++) J[k] *= 1e-170;
            break; /* squares below DBL_MIN */
        case 4:
            for (int k = 0; k < 4; k++) J[k] *= 1e160;
            break; /* squares above DBL_MAX */
        default: break;
        }
        int *ix = S.idx + 3 * s;
        for (int c = 0; c < 3; c++) ix[c] = 3 * s + c;
        double *x = X + 6 * s;
        x[0] = x[1] = 0;
        x[2] = J[0], x[3] = J[2]; /* corner 1: column 0 of J */
        x[4] = J[1], x[5] = J[3]; /* corner 2: column 1 */
        double G[6] = {-1, -1, 1, 0, 0, 1};
        for (int k = 0; k < 6; k++) S.grad[6 * s + k] = G[k] * (1 + 0.25 * (s % 3 == 0));
        S.vol[s] = S.weight[s] = 1;
    }
    double *loc = malloc(sizeof *loc * 10 * n);
    const double caps[2] = {INFINITY, 50.0};
    for (int c = 0; c < 2; c++)
        for (int lo = 0; lo < 3; lo++) {
            double w2l = opt_sd2_proxy_range(&S, X, (size_t)lo, (size_t)n, caps[c], loc);
            double w2max = 0;
            for (int s = lo; s < n; s++) {
                double J[4], W[4], T[4], M[4], MT[4], lin[6];
                opt_jacobian(&S, s, X, J);
                double w2 =
                    opt_slim_proxy_capped(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J, caps[c], W, T);
                if (w2 > w2max) w2max = w2;
                for (int a = 0; a < 2; a++)
                    for (int b = 0; b < 2; b++) {
                        M[2 * a + b] = W[a] * W[b] + W[2 + a] * W[2 + b];
                    }
                for (int a = 0; a < 2; a++)
                    for (int b = 0; b < 2; b++)
                        MT[2 * a + b] = M[2 * a] * T[b] + M[2 * a + 1] * T[2 + b];
                opt_pullback(2, S.grad + 6 * s, MT, lin);
                assert_memory_equal(loc + 10 * (s - lo), M, sizeof M);
                assert_memory_equal(loc + 10 * (s - lo) + 4, lin, sizeof lin);
            }
            assert_memory_equal(&w2l, &w2max, sizeof w2max);
        }
    free(loc);
    free(X);
    opt_simplices_free(&S);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(svd_reconstructs),
        cmocka_unit_test(lanes_sum_like_one_at_a_time),
        cmocka_unit_test(lanes_proxy_like_one_at_a_time),
        cmocka_unit_test(hypot_fast_path),
        cmocka_unit_test(gradients_match_finite_differences),
        cmocka_unit_test(isometry_values),
        cmocka_unit_test(rotation_invariance),
        cmocka_unit_test(slim_proxy_gradient_matches),
        cmocka_unit_test(proxy_2d_matches_svd),
        cmocka_unit_test(conformal_3d_proxy_is_spd),
        cmocka_unit_test(capped_proxy),
        cmocka_unit_test(builders_refuse_bad_input),
        cmocka_unit_test(guard_is_continuous),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
