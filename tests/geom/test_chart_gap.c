/* Tests of geom/chart_gap: chart labels, smallest distance between
 * different charts (against brute-force segment distances), packing
 * efficiency on layouts whose numbers are known by construction. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/chart_gap.h"

/* Unit squares (2 triangles each) with lower-left corners at (ox[i], oy[i]). */
static void squares(int n, const double *ox, const double *oy, double *UV, int *F)
{
    for (int i = 0; i < n; i++) {
        double *p = UV + 8 * i;
        p[0] = ox[i], p[1] = oy[i];
        p[2] = ox[i] + 1, p[3] = oy[i];
        p[4] = ox[i] + 1, p[5] = oy[i] + 1;
        p[6] = ox[i], p[7] = oy[i] + 1;
        int *t = F + 6 * i, b = 4 * i;
        t[0] = b, t[1] = b + 1, t[2] = b + 2;
        t[3] = b, t[4] = b + 2, t[5] = b + 3;
    }
}

static void two_squares_gap(void **state)
{
    (void)state;
    double ox[2] = {0, 1.25}, oy[2] = {0, 0.5}, UV[16];
    int F[12], chart[4], nc;
    squares(2, ox, oy, UV, F);
    scaf_error err;
    assert_int_equal(chart_gap_labels(8, 4, F, chart, &nc, &err), SCAF_OK);
    assert_int_equal(nc, 2);
    assert_int_equal(chart[0], chart[1]);
    assert_int_not_equal(chart[0], chart[2]);
    double g;
    int pair[2];
    assert_int_equal(chart_gap_min(8, UV, 4, F, NULL, 0.0, &g, pair, &err), SCAF_OK);
    assert_true(fabs(g - 0.25) < 1e-15);
    assert_int_equal(pair[0], 0);
    assert_int_equal(pair[1], 1);
    /* a radius below the gap finds nothing */
    assert_int_equal(chart_gap_min(8, UV, 4, F, NULL, 0.2, &g, NULL, &err), SCAF_OK);
    assert_true(isinf(g));
    /* touching squares: gap exactly 0 */
    ox[1] = 1.0;
    squares(2, ox, oy, UV, F);
    assert_int_equal(chart_gap_min(8, UV, 4, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(g == 0.0);
    /* one chart: no pair */
    assert_int_equal(chart_gap_min(8, UV, 2, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(isinf(g));
}

static void corner_distance(void **state)
{
    (void)state;
    double ox[2] = {0, 4}, oy[2] = {0, 5}, UV[16];
    int F[12];
    squares(2, ox, oy, UV, F);
    double g;
    scaf_error err;
    assert_int_equal(chart_gap_min(8, UV, 4, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(fabs(g - 5.0) < 1e-12); /* (1,1) to (4,5) */
}

/* Many random squares on a lattice (never overlapping): grid search equals
 * brute force over all boundary segment pairs. */
static void random_layout_matches_brute_force(void **state)
{
    (void)state;
    enum { N = 60 };
    double ox[N], oy[N], UV[8 * N];
    int F[6 * N];
    unsigned seed = 12345;
    for (int i = 0; i < N; i++) {
        seed = seed * 1103515245u + 12345u;
        double jx = (seed >> 8) % 1000 / 1000.0 * 0.8;
        seed = seed * 1103515245u + 12345u;
        double jy = (seed >> 8) % 1000 / 1000.0 * 0.8;
        ox[i] = 2.0 * (i % 8) + jx;
        oy[i] = 2.0 * (i / 8) + jy;
    }
    squares(N, ox, oy, UV, F);
    double g;
    scaf_error err;
    assert_int_equal(chart_gap_min(4 * N, UV, 2 * N, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    double best = INFINITY;
    for (int a = 0; a < N; a++)
        for (int b = a + 1; b < N; b++)
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++) {
                    const double *p1 = UV + 8 * a + 2 * i, *p2 = UV + 8 * a + 2 * ((i + 1) % 4);
                    const double *q1 = UV + 8 * b + 2 * j, *q2 = UV + 8 * b + 2 * ((j + 1) % 4);
                    double d = chart_segment_distance(p1, p2, q1, q2);
                    if (d < best) best = d;
                }
    assert_true(g == best);
    unsigned char mark[N] = {0};
    long np;
    assert_int_equal(chart_gap_min(4 * N, UV, 2 * N, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    int *seg, nseg, chart[2 * N], nc;
    assert_int_equal(chart_gap_labels(4 * N, 2 * N, F, chart, &nc, &err), SCAF_OK);
    assert_int_equal(chart_gap_segments(2 * N, F, chart, &seg, &nseg, &err), SCAF_OK);
    assert_int_equal(nseg, 4 * N);
    assert_int_equal(chart_gap_mark_close(UV, seg, nseg, best * 1.0000001, mark, &np, &err),
                     SCAF_OK);
    assert_true(np >= 1);
    int marked = 0;
    for (int i = 0; i < N; i++) marked += mark[i];
    assert_true(marked >= 2);
    free(seg);
}

/* chart_gap_close_pairs lists exactly the pairs of segments of different
 * charts closer than the radius (brute force over all pairs), each once. */
static void close_pairs_match_brute_force(void **state)
{
    (void)state;
    enum { N = 40 };
    double ox[N], oy[N], UV[8 * N];
    int F[6 * N], chart[2 * N], nc, *seg, nseg;
    unsigned seed = 777;
    for (int i = 0; i < N; i++) {
        seed = seed * 1103515245u + 12345u;
        ox[i] = 1.4 * (i % 8) + (seed >> 8) % 1000 / 1000.0 * 0.3;
        seed = seed * 1103515245u + 12345u;
        oy[i] = 1.4 * (i / 8) + (seed >> 8) % 1000 / 1000.0 * 0.3;
    }
    squares(N, ox, oy, UV, F);
    scaf_error err;
    assert_int_equal(chart_gap_labels(4 * N, 2 * N, F, chart, &nc, &err), SCAF_OK);
    assert_int_equal(chart_gap_segments(2 * N, F, chart, &seg, &nseg, &err), SCAF_OK);
    const double radius[3] = {0.15, 0.4, 0.9};
    for (int r = 0; r < 3; r++) {
        int *pairs = NULL;
        long np = -1;
        assert_int_equal(chart_gap_close_pairs(UV, seg, nseg, radius[r], &pairs, &np, &err),
                         SCAF_OK);
        unsigned char *seen = calloc((size_t)nseg * nseg, 1);
        assert_non_null(seen);
        for (long k = 0; k < np; k++) {
            int a = pairs[2 * k], b = pairs[2 * k + 1];
            assert_true(a >= 0 && a < nseg && b >= 0 && b < nseg);
            assert_true(seg[3 * a + 2] != seg[3 * b + 2]);
            int lo = a < b ? a : b, hi = a < b ? b : a;
            assert_int_equal(seen[lo * nseg + hi], 0); /* once */
            seen[lo * nseg + hi] = 1;
        }
        long want = 0;
        for (int a = 0; a < nseg; a++)
            for (int b = a + 1; b < nseg; b++) {
                if (seg[3 * a + 2] == seg[3 * b + 2]) continue;
                double d = chart_segment_distance(UV + 2 * seg[3 * a], UV + 2 * seg[3 * a + 1],
                                                  UV + 2 * seg[3 * b], UV + 2 * seg[3 * b + 1]);
                if (d < radius[r]) {
                    want++;
                    assert_int_equal(seen[a * nseg + b], 1);
                }
            }
        assert_true(np == want);
        assert_true(r == 0 || want > 0);
        free(seen);
        free(pairs);
    }
    free(seg);
}

static void packing_efficiency(void **state)
{
    (void)state;
    /* two unit squares side by side at distance 0.5: area 2, side 2.5 */
    double ox[2] = {0, 1.5}, oy[2] = {0, 0}, UV[16];
    int F[12];
    squares(2, ox, oy, UV, F);
    assert_true(fabs(chart_packing_efficiency(8, UV, 4, F) - 2.0 / 6.25) < 1e-15);
    /* one square: 1 */
    assert_true(fabs(chart_packing_efficiency(4, UV, 2, F) - 1.0) < 1e-15);
}

static void segment_distance(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {2, 0}, c[2] = {1, -1}, d[2] = {1, 1}, e[2] = {3, 1},
           f[2] = {4, 1};
    assert_true(chart_segment_distance(a, b, c, d) == 0.0); /* crossing */
    assert_true(fabs(chart_segment_distance(a, b, e, f) - sqrt(2.0)) < 1e-15);
}

/* Exact boundaries: the certificate holds at exactly P and fails at the
 * next double above, for the three nearest-point cases. */
static void certified_exact_boundary(void **state)
{
    (void)state;
    double above = nextafter(5.0, 6.0);
    /* interior: segment (-3,-4)-(3,4), point (4,-3): distance exactly 5 */
    double a[2] = {-3, -4}, b[2] = {3, 4}, p[2] = {4, -3}, p2[2] = {8, -6};
    assert_true(chart_segment_distance_at_least(a, b, p, p2, 5.0));
    assert_false(chart_segment_distance_at_least(a, b, p, p2, above));
    /* endpoint a: (4,-3) from the segment (0,0)-(3,4) is 5 at (0,0) */
    double o[2] = {0, 0}, q[2] = {8, -6};
    assert_true(chart_segment_distance_at_least(o, b, p, q, 5.0));
    assert_false(chart_segment_distance_at_least(o, b, p, q, above));
    /* endpoint b: (6,8)+(4,-3) from (0,0)-(6,8) */
    double e[2] = {6, 8}, r[2] = {10, 5}, r2[2] = {14, 2};
    assert_true(chart_segment_distance_at_least(o, e, r, r2, 5.0));
    assert_false(chart_segment_distance_at_least(o, e, r, r2, above));
    /* crossing segments are at distance 0 */
    double c1[2] = {1, -1}, c2[2] = {1, 1}, d1[2] = {0, 0}, d2[2] = {2, 0};
    assert_false(chart_segment_distance_at_least(c1, c2, d1, d2, 1e-300 * 0x1p900));
}

static void certified_layouts(void **state)
{
    (void)state;
    double ox[2] = {0, 1.25}, oy[2] = {0, 0.5}, UV[16];
    int F[12], chart[4], nc, *seg = NULL, nseg = 0, ok = 0, pair[2];
    squares(2, ox, oy, UV, F);
    scaf_error err;
    assert_int_equal(chart_gap_labels(8, 4, F, chart, &nc, &err), SCAF_OK);
    assert_int_equal(chart_gap_segments(4, F, chart, &seg, &nseg, &err), SCAF_OK);
    assert_int_equal(chart_gap_certify(UV, seg, nseg, 0.25, &ok, pair, &err), SCAF_OK);
    assert_true(ok);
    assert_int_equal(chart_gap_certify(UV, seg, nseg, nextafter(0.25, 1.0), &ok, pair, &err),
                     SCAF_OK);
    assert_false(ok);
    assert_int_equal(pair[0], 0);
    assert_int_equal(pair[1], 1);
    assert_int_equal(chart_gap_certify(UV, seg, nseg, 0.0, &ok, NULL, &err), SCAF_OK);
    assert_true(ok);
    /* a coordinate the exact test cannot take is refused, not guessed */
    UV[0] = 1e-300;
    assert_int_equal(chart_gap_certify(UV, seg, nseg, 0.25, &ok, NULL, &err), SCAF_ERR_NUMERIC);
    free(seg);
}

/* Random segment pairs: the exact decision agrees with the floating-point
 * distance wherever that is not within 1e-9 of the threshold, and random
 * layouts certify exactly when their measured gap is clearly above P. */
static void certified_agrees_with_distance(void **state)
{
    (void)state;
    unsigned s = 12345u;
    int agree = 0, n = 20000;
    for (int i = 0; i < n; i++) {
        double x[8];
        for (int k = 0; k < 8; k++) {
            s = s * 1103515245u + 12345u;
            x[k] = (double)(s >> 8) / (double)(1u << 24);
        }
        double P = 0.05 + 0.3 * x[0] * x[7];
        double d = chart_segment_distance(x, x + 2, x + 4, x + 6);
        int cert = chart_segment_distance_at_least(x, x + 2, x + 4, x + 6, P);
        if (fabs(d - P) > 1e-9) {
            assert_int_equal(cert, d >= P);
            agree++;
        }
        /* just below / above the measured distance (whose rounding error,
         * relative to d, grows as d shrinks against the segment lengths:
         * 1e-12 is exceeded at d = 1.7e-5 here) */
        if (d > 1e-3) {
            assert_true(chart_segment_distance_at_least(x, x + 2, x + 4, x + 6, d * (1.0 - 1e-9)));
            assert_false(chart_segment_distance_at_least(x, x + 2, x + 4, x + 6, d * (1.0 + 1e-9)));
        }
    }
    assert_true(agree > n / 2);
}

/* Gap and efficiency do not depend on the units of the layout: the same
 * squares scaled by 2^k (subnormal to near the largest double) give the
 * gap scaled by exactly 2^k and the same efficiency, bit for bit. */
static void scale_free_results(void **state)
{
    (void)state;
    double ox[3] = {0, 1.25, 0.5}, oy[3] = {0, 0.5, 2.0}, UV0[24], UV[24];
    int F[18];
    squares(3, ox, oy, UV0, F);
    scaf_error err;
    double g0, g;
    int pair0[2], pair[2];
    assert_int_equal(chart_gap_min(12, UV0, 6, F, NULL, 0.0, &g0, pair0, &err), SCAF_OK);
    double eff0 = chart_packing_efficiency(12, UV0, 6, F);
    assert_true(isfinite(g0) && g0 > 0.0);
    assert_true(eff0 > 0.0 && eff0 <= 1.0);
    const int k[] = {1, -1, 200, -200, 510, 1020, -600, -1020, -1060};
    for (size_t t = 0; t < sizeof k / sizeof *k; t++) {
        for (int i = 0; i < 24; i++) UV[i] = ldexp(UV0[i], k[t]);
        assert_int_equal(chart_gap_min(12, UV, 6, F, NULL, 0.0, &g, pair, &err), SCAF_OK);
        assert_true(g == ldexp(g0, k[t]));
        assert_int_equal(pair[0], pair0[0]);
        assert_int_equal(pair[1], pair0[1]);
        assert_true(chart_packing_efficiency(12, UV, 6, F) == eff0);
        /* a radius in the same units finds the same pair */
        assert_int_equal(chart_gap_min(12, UV, 6, F, NULL, ldexp(2.0 * g0, k[t]), &g, NULL, &err),
                         SCAF_OK);
        assert_true(g == ldexp(g0, k[t]));
        unsigned char mark[3] = {0, 0, 0};
        int *seg, nseg, chart[6], nc;
        long np;
        assert_int_equal(chart_gap_labels(12, 6, F, chart, &nc, &err), SCAF_OK);
        assert_int_equal(chart_gap_segments(6, F, chart, &seg, &nseg, &err), SCAF_OK);
        assert_int_equal(
            chart_gap_mark_close(UV, seg, nseg, ldexp(1.01 * g0, k[t]), mark, &np, &err), SCAF_OK);
        free(seg);
        assert_true(np > 0);
        assert_true(mark[pair0[0]] && mark[pair0[1]]);
    }
}

/* Extreme but finite coordinates: finite answers, never an overflowing
 * grid (a single triangle up to 1e308 used to ask for 2^64 bytes). */
static void extreme_coordinates(void **state)
{
    (void)state;
    scaf_error err;
    double g;
    int F1[3] = {0, 1, 2};
    const double big[] = {1e308, 1e155, 1e-200, 1e-310, 4.9e-324};
    for (size_t t = 0; t < sizeof big / sizeof *big; t++) {
        double UV[6] = {0, 0, big[t], 0, 0, big[t]};
        assert_int_equal(chart_gap_min(3, UV, 1, F1, NULL, 0.0, &g, NULL, &err), SCAF_OK);
        assert_true(isinf(g)); /* one chart */
        assert_true(chart_packing_efficiency(3, UV, 1, F1) == 0.5);
        double UV2[6] = {-big[t], -big[t], big[t], -big[t], -big[t], big[t]};
        assert_true(chart_packing_efficiency(3, UV2, 1, F1) == 0.5);
    }
    /* an extent tiny next to the coordinates (side^2 underflows): finite,
     * not NaN (fuzz_uv_numbers: a triangle on two points) */
    double thin[6] = {0x1.9cfc8c6df91p-172,
                      0x1.240000601p-1013,
                      0x1.9cfc8c6df91p-172,
                      0x0.000a24001656dp-1022,
                      0,
                      0};
    int F10[3] = {1, 0, 0};
    double e_thin = chart_packing_efficiency(3, thin, 1, F10);
    assert_true(isfinite(e_thin) && e_thin >= 0.0);
    double sliver[6] = {1.0, 1e-300, 1.0 + 0x1p-52, 1e-300, 1.0, 3e-300};
    double e_sliver = chart_packing_efficiency(3, sliver, 1, F1);
    assert_true(isfinite(e_sliver) && e_sliver >= 0.0);
    /* two charts 3e154 apart: finite (the squared distance overflows) */
    double UV[12] = {0, 0, 1e154, 0, 0, 1e154, 4e154, 0, 5e154, 0, 4e154, 1e154};
    int F2[6] = {0, 1, 2, 3, 4, 5};
    assert_int_equal(chart_gap_min(6, UV, 2, F2, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(fabs(g - 3e154) <= 1e139);
    /* a gap beyond the largest double: a specific error, not infinity */
    double far[12] = {-1.7e308, 0, -1.6e308, 0, -1.7e308, 1, 1.6e308, 0, 1.7e308, 0, 1.6e308, 1};
    assert_int_equal(chart_gap_min(6, far, 2, F2, NULL, 0.0, &g, NULL, &err), SCAF_ERR_NUMERIC);
    assert_non_null(strstr(err.message, "largest double"));
}

/* Charts without a boundary edge (a triangle with one UV index three
 * times; two triangles covering each other) still have points: with
 * another chart the gap is a number, never "fewer than two charts"
 * (found by fuzz_uv_numbers). */
static void charts_without_boundary(void **state)
{
    (void)state;
    /* a point chart (UV 3 = (3, 4)) next to the triangle (0,0) (1,0) (0,1):
     * nearest at (0, 1) */
    double UV[12] = {0, 0, 1, 0, 0, 1, 3, 4, 0, 0, 0, 0};
    scaf_error err;
    double g;
    int point[6] = {0, 1, 2, 3, 3, 3};
    assert_int_equal(chart_gap_min(4, UV, 2, point, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(fabs(g - sqrt(18.0)) < 1e-12);
    /* a triangle (5,5) (6,5) (5,6) given twice: its edges pair up, no
     * boundary; distance from its first corner (5, 5) to the hypotenuse */
    double UV2[12] = {0, 0, 1, 0, 0, 1, 5, 5, 6, 5, 5, 6};
    int doubled[9] = {0, 1, 2, 3, 4, 5, 3, 4, 5};
    assert_int_equal(chart_gap_min(6, UV2, 3, doubled, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(fabs(g - 4.5 * sqrt(2.0)) < 1e-12);
}

/* A positive gap below the smallest double is reported as the smallest
 * positive double, never 0 (which means touching): the point chart at
 * (5.565e-320, 0) lies about 1e-334 from the sliver (0,0)-(9.5e-308,
 * 1.8e-322); found by fuzz_uv_numbers. */
static void gap_below_smallest_double(void **state)
{
    (void)state;
    double UV[12] = {9.456776927139342e-308, 1.8e-322, 5.565e-320, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    int F[6] = {1, 1, 1, 0, 5, 2};
    scaf_error err;
    double g;
    assert_int_equal(chart_gap_min(6, UV, 2, F, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    assert_true(g > 0.0);
    assert_true(g == nextafter(0.0, 1.0));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_squares_gap),
        cmocka_unit_test(corner_distance),
        cmocka_unit_test(random_layout_matches_brute_force),
        cmocka_unit_test(close_pairs_match_brute_force),
        cmocka_unit_test(packing_efficiency),
        cmocka_unit_test(segment_distance),
        cmocka_unit_test(certified_exact_boundary),
        cmocka_unit_test(certified_layouts),
        cmocka_unit_test(certified_agrees_with_distance),
        cmocka_unit_test(scale_free_results),
        cmocka_unit_test(extreme_coordinates),
        cmocka_unit_test(charts_without_boundary),
        cmocka_unit_test(gap_below_smallest_double),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
