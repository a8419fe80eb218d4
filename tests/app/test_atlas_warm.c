/* Tests for app/atlas_warm: the two halves of a split chart, touching
 * along their seam, are placed apart with their shapes kept and the result
 * is bijective (exact checker) with the asked gap; a chart whose shape has
 * a clockwise triangle or a NaN takes its fallback shape. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas_warm.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"

/* Two unit squares side by side sharing the edge x = 1 in the plane, but
 * as two charts: vertices 0-3 (chart 0) and 4-7 (chart 1), the shared
 * corners duplicated (1 = 4, 2 = 7 in position). */
static const int F[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
static const int wchart[] = {0, 0, 0, 0, 1, 1, 1, 1};
static const double halves[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 2, 0, 2, 1, 1, 1};
/* a valid fallback: the squares far apart and smaller */
static const double tutte[] = {0, 0, .5, 0, .5, .5, 0, .5, 10, 0, 11, 0, 11, 1, 10, 1};

static double min_gap(const double *X, scaf_error *e)
{
    int chart[] = {0, 0, 1, 1}, *seg = NULL, nseg = 0;
    assert_int_equal(chart_gap_segments(4, F, chart, &seg, &nseg, e), SCAF_OK);
    double g;
    assert_int_equal(chart_gap_min_segments(X, seg, nseg, 0.0, &g, NULL, e), SCAF_OK);
    free(seg);
    return g;
}

static double side(const double *X)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], X[2 * i + k]);
            hi[k] = fmax(hi[k], X[2 * i + k]);
        }
    return fmax(hi[0] - lo[0], hi[1] - lo[1]);
}

/* X's chart c is src's chart c moved by one translation. */
static void is_translate(const double *X, const double *src, int c)
{
    int first = 4 * c;
    double dx = X[2 * first] - src[2 * first], dy = X[2 * first + 1] - src[2 * first + 1];
    for (int v = first; v < first + 4; v++) {
        assert_true(fabs(X[2 * v] - src[2 * v] - dx) < 1e-12);
        assert_true(fabs(X[2 * v + 1] - src[2 * v + 1] - dy) < 1e-12);
    }
}

static void touching_halves_placed_apart(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    bij_report r;
    int chart[] = {0, 0, 1, 1};
    /* as they are, the halves touch: not bijective */
    assert_int_equal(bij_check(8, halves, 4, F, chart, NULL, &r, &e), SCAF_OK);
    assert_false(r.bijective);
    double out[16];
    int warm = -1;
    double pad = 0.01;
    assert_int_equal(atlas_warm_layout(8, 4, F, wchart, 2, halves, tutte, pad, out, &warm, &e),
                     SCAF_OK);
    assert_int_equal(warm, 2);
    assert_int_equal(bij_check(8, out, 4, F, chart, NULL, &r, &e), SCAF_OK);
    assert_true(r.bijective);
    is_translate(out, halves, 0);
    is_translate(out, halves, 1);
    assert_true(min_gap(out, &e) > pad * side(out));
}

static void invalid_shapes_fall_back(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    double bad[16];
    memcpy(bad, halves, sizeof bad);
    bad[2 * 2 + 1] = -1.0; /* chart 0: vertex 2 below the x axis, triangle 0 clockwise */
    bad[2 * 5] = NAN;      /* chart 1: not finite */
    double out[16];
    int warm = -1;
    assert_int_equal(atlas_warm_layout(8, 4, F, wchart, 2, bad, tutte, 0.0, out, &warm, &e),
                     SCAF_OK);
    assert_int_equal(warm, 0);
    is_translate(out, tutte, 0);
    is_translate(out, tutte, 1);
    bij_report r;
    int chart[] = {0, 0, 1, 1};
    assert_int_equal(bij_check(8, out, 4, F, chart, NULL, &r, &e), SCAF_OK);
    assert_true(r.bijective);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(touching_halves_placed_apart),
        cmocka_unit_test(invalid_shapes_fall_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
