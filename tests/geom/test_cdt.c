/* Tests for geom/cdt: the scaffold mesher on small, hand-made domains.
 *
 * Every output goes through cdt_check (cdt_check.h): exact orientation,
 * segments present, constrained empty circles, no triangle in a chart,
 * Euler characteristic, angle and area bounds away from chart edges.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/cdt_check.h"

static cdt_output run_ok(const cdt_builder *b, const cdt_options *opt)
{
    cdt_input in = cb_input(b);
    cdt_output out;
    scaf_error err;
    err_clear(&err);
    scaf_status s = cdt_triangulate(&in, opt, &out, &err);
    if (s != SCAF_OK) fail_msg("cdt_triangulate failed: %s", err.message);
    return out;
}

static void assert_checked(const cdt_builder *b, const cdt_options *opt, const cdt_output *out,
                           int chi)
{
    cdt_check_stats st = cdt_check(b, opt, out, chi, 1);
    if (!st.ok) fail_msg("%s", st.why);
    if (opt && opt->min_angle_deg > 0 && st.nfree_bad > 0)
        fail_msg("%d of %d triangles away from charts are below %g degrees (min %g)", st.nfree_bad,
                 st.nfree, opt->min_angle_deg, st.min_angle_free);
}

/* The triangles cover exactly the expected area (relative to `scale`). */
static void assert_area(const cdt_builder *b, const cdt_options *opt, const cdt_output *out,
                        int chi, double want, double scale)
{
    double got = cdt_check(b, opt, out, chi, 0).area;
    if (!(fabs(got - want) < 1e-9 * scale))
        fail_msg("triangle area %.17g, expected %.17g", got, want);
}

static void box_only_is_refined(void **state)
{
    (void)state;
    cdt_builder b;
    cb_init(&b);
    double area = 12;
    /* a plain square with a generous area bound */
    cb_rect(&b, 0, 0, 4, 3);
    cdt_options opt = cdt_default_options();
    opt.max_area = 0.05;
    cdt_output out = run_ok(&b, &opt);
    assert_checked(&b, &opt, &out, 1);
    assert_true(out.ntriangles >= (int)(area / opt.max_area));
    assert_area(&b, &opt, &out, 1, area, area);
    cdt_output_free(&out);
    cb_free(&b);
}

static void single_chart_default_quality(void **state)
{
    (void)state;
    cdt_builder b;
    double box;
    cb_wiggly_in_box(&b, 300, 0.3, -0.2, 1.0, 0.2, 7, &box);
    cdt_options opt = cdt_default_options();
    cdt_output out = run_ok(&b, &opt);
    assert_checked(&b, &opt, &out, 0);
    assert_area(&b, &opt, &out, 0, box - b.chart_area, box);
    assert_true(out.nsteiner > 0);
    /* graded: far fewer triangles than a uniform mesh at the chart's edge length */
    assert_true(out.ntriangles < 20 * 300);
    cdt_output_free(&out);
    cb_free(&b);
}

static void no_refinement_is_pure_cdt(void **state)
{
    (void)state;
    cdt_builder b;
    cb_wiggly_in_box(&b, 100, 0, 0, 1.0, 0.4, 5, NULL);
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = 0;
    cdt_output out = run_ok(&b, &opt);
    assert_int_equal(out.nsteiner, 0);
    assert_int_equal(out.npoints, b.np);
    assert_checked(&b, &opt, &out, 0);
    cdt_output_free(&out);
    cb_free(&b);
}

static void chart_with_hole_and_nested_chart(void **state)
{
    (void)state;
    cdt_builder b;
    cb_init(&b);
    cb_wiggly_loop(&b, 80, 0, 0, 2.0, 0.1, 5, 0);   /* outer */
    cb_wiggly_loop(&b, 60, 0, 0, 1.2, 0.1, 3, 1);   /* chart hole: clockwise */
    cb_wiggly_loop(&b, 40, 0.1, 0, 0.5, 0.2, 4, 0); /* nested */
    double box;
    cb_box(&b, 3.0, &box);
    cdt_options opt = cdt_default_options();
    cdt_output out = run_ok(&b, &opt);
    /* the free space is two annuli: the box outside the outer chart
       loop, and the chart's hole around the nested chart: chi = 0 + 0 */
    assert_checked(&b, &opt, &out, 0);
    assert_area(&b, &opt, &out, 0, box - b.chart_area, box);
    /* some triangles lie in the chart's hole, around the nested chart */
    int inside = 0;
    for (int t = 0; t < out.ntriangles; t++) {
        const double *p = out.points + 2 * out.triangles[3 * t];
        if (hypot(p[0], p[1]) < 1.0) inside++;
    }
    assert_true(inside > 0);
    cdt_output_free(&out);
    cb_free(&b);
}

static void hole_seeds_work_like_flags(void **state)
{
    (void)state;
    cdt_builder b;
    cb_wiggly_in_box(&b, 50, 0, 0, 1.0, 0.1, 3, NULL);
    for (int s = 0; s < b.ns; s++) b.hole[s] = 0;
    b.seeds = malloc(2 * sizeof(double));
    b.seeds[0] = 0.01;
    b.seeds[1] = 0.02;
    b.nseeds = 1;
    cdt_options opt = cdt_default_options();
    cdt_output out = run_ok(&b, &opt);
    assert_checked(&b, &opt, &out, 0);
    cdt_output_free(&out);
    cb_free(&b);
}

static void chart_edges_are_never_split(void **state)
{
    (void)state;
    /* long chart edges next to tiny ones: refinement wants to split them */
    cdt_builder b;
    cb_init(&b);
    double xy[] = {0, 0, 10, 0, 10, 0.001, 9.999, 0.002, 10, 0.003, 10, 5, 0, 5};
    cb_loop(&b, xy, 7);
    cb_box(&b, 3.0, NULL);
    cdt_options opt = cdt_default_options();
    opt.max_area = 2.0;
    cdt_output out = run_ok(&b, &opt);
    /* area and angle bounds cannot hold next to a 10-long unsplittable edge:
       check only the structure here */
    assert_checked(&b, NULL, &out, 0);
    int chart_subs = 0;
    for (int i = 0; i < out.nsubsegments; i++)
        if (!b.split[out.subsegment_of[i]]) chart_subs++;
    assert_int_equal(chart_subs, 7);
    cdt_output_free(&out);
    cb_free(&b);
}

static void small_input_angle_terminates(void **state)
{
    (void)state;
    /* a notch of free space with a 0.9 degree angle at its bottom, a thin
       wedge-shaped gap between two charts, and a spiky chart */
    cdt_builder b;
    cb_init(&b);
    double notch[] = {0, 0, 4, 0, 4, 3, 2.01, 3, 2, 0.5, 1.99, 3, 0, 3};
    cb_loop(&b, notch, 7);
    double a = 0.5 * 3.14159265358979323846 / 180;
    double w1[] = {0, -2, 5, -2, 5, -1, 0, -1};
    double w2[] = {0, -1 + 1e-3, 5, -1 + 5 * tan(a) + 1e-3, 0, -0.5};
    cb_loop(&b, w1, 4);
    cb_loop(&b, w2, 3);
    double sp[] = {7, 0, 8, 0, 7.5 + 1e-3, 0.5, 7.5, 4};
    cb_loop(&b, sp, 4);
    cb_box(&b, 3.0, NULL);
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = 30;
    cdt_output out = run_ok(&b, &opt);
    assert_checked(&b, &opt, &out, -3);
    assert_false(out.capped);
    cdt_output_free(&out);
    cb_free(&b);
}

static void deterministic(void **state)
{
    (void)state;
    cdt_builder b;
    cb_wiggly_in_box(&b, 500, 0, 0, 1.0, 0.3, 11, NULL);
    cdt_options opt = cdt_default_options();
    cdt_output o1 = run_ok(&b, &opt), o2 = run_ok(&b, &opt);
    assert_int_equal(o1.npoints, o2.npoints);
    assert_int_equal(o1.ntriangles, o2.ntriangles);
    assert_memory_equal(o1.points, o2.points, (size_t)o1.npoints * 2 * sizeof(double));
    assert_memory_equal(o1.triangles, o2.triangles, (size_t)o1.ntriangles * 3 * sizeof(int));
    cdt_output_free(&o1);
    cdt_output_free(&o2);
    cb_free(&b);
}

static void lattice_rectangles_degenerate(void **state)
{
    (void)state;
    /* rectangles on an integer lattice: many exactly collinear and
       cocircular points, segments along shared lines, a box on the lattice */
    cdt_builder b;
    cb_init(&b);
    int k = 0;
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) {
            double x = 3 * i, y = 3 * j, w = 1 + (i + j) % 2;
            double xy[] = {x, y, x + w, y, x + w, y + 1, x + w, y + 2, x, y + 2, x, y + 1};
            cb_loop(&b, xy, 6);
            k++;
        }
    cb_rect(&b, -6, -6, 24, 24);
    for (int pass = 0; pass < 2; pass++) {
        cdt_options opt = cdt_default_options();
        opt.min_angle_deg = pass ? 25 : 0;
        cdt_output out = run_ok(&b, &opt);
        assert_checked(&b, &opt, &out, 1 - k);
        cdt_output_free(&out);
    }
    cb_free(&b);
}

static void steiner_cap_is_respected(void **state)
{
    (void)state;
    cdt_builder b;
    cb_wiggly_in_box(&b, 200, 0, 0, 1.0, 0.3, 9, NULL);
    cdt_options opt = cdt_default_options();
    opt.max_area = 1e-4;
    opt.max_steiner = 50;
    cdt_output out = run_ok(&b, &opt);
    assert_true(out.capped);
    assert_true(out.nsteiner <= 50);
    assert_checked(&b, NULL, &out, 0);
    cdt_output_free(&out);
    cb_free(&b);
}

static void isolated_points_become_vertices(void **state)
{
    (void)state;
    cdt_builder b;
    cb_init(&b);
    double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    cb_loop(&b, sq, 4);
    cb_box(&b, 3.0, NULL);
    int extra = cb_point(&b, 1.5, 0.5);
    int extra2 = cb_point(&b, -0.75, 1.25);
    cdt_options opt = cdt_default_options();
    cdt_output out = run_ok(&b, &opt);
    assert_checked(&b, &opt, &out, 0);
    int seen = 0;
    for (int i = 0; i < 3 * out.ntriangles; i++)
        seen |= (out.triangles[i] == extra) | ((out.triangles[i] == extra2) << 1);
    assert_int_equal(seen, 3);
    cdt_output_free(&out);
    cb_free(&b);
}

static void empty_and_trivial_inputs(void **state)
{
    (void)state;
    cdt_input in;
    memset(&in, 0, sizeof in);
    cdt_output out;
    scaf_error err;
    assert_int_equal(cdt_triangulate(&in, NULL, &out, &err), SCAF_OK);
    assert_int_equal(out.ntriangles, 0);
    cdt_output_free(&out);
    /* points without segments: nothing is enclosed */
    double pts[] = {0, 0, 1, 0, 0, 1};
    in.npoints = 3;
    in.points = pts;
    assert_int_equal(cdt_triangulate(&in, NULL, &out, &err), SCAF_OK);
    assert_int_equal(out.ntriangles, 0);
    assert_int_equal(out.npoints, 3);
    cdt_output_free(&out);
    /* a single triangle enclosed by unsplittable segments */
    int segs[] = {0, 1, 1, 2, 2, 0};
    in.nsegments = 3;
    in.segments = segs;
    assert_int_equal(cdt_triangulate(&in, NULL, &out, &err), SCAF_OK);
    assert_int_equal(out.ntriangles, 1);
    assert_int_equal(out.nsubsegments, 3);
    cdt_output_free(&out);
    /* bad options */
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = 70;
    assert_int_equal(cdt_triangulate(&in, &opt, &out, &err), SCAF_ERR_USAGE);
}

/* ------------------------------------------------------------ invalid input */

/* One invalid input: how to build it (after the builder is initialised) and
 * a phrase the error message must contain. */
typedef struct invalid_case {
    const char *name;
    void (*build)(cdt_builder *b);
    const char *needle;
} invalid_case;

static const double square02[] = {0, 0, 2, 0, 2, 2, 0, 2};

static void build_crossing_squares(cdt_builder *b)
{
    static const double sq2[] = {1, 1, 3, 1, 3, 3, 1, 3};
    cb_loop(b, square02, 4);
    cb_loop(b, sq2, 4);
    cb_box(b, 3, NULL);
}

static void build_point_on_segment(cdt_builder *b)
{
    cb_loop(b, square02, 4);
    cb_point(b, 1, 0); /* on segment 0 */
    cb_box(b, 3, NULL);
}

static void build_duplicate_point(cdt_builder *b)
{
    cb_loop(b, square02, 4);
    cb_point(b, 2, 2);
    cb_box(b, 3, NULL);
}

static void build_nan_coordinate(cdt_builder *b)
{
    cb_loop(b, square02, 4);
    cb_box(b, 3, NULL);
    b->pts[3] = NAN;
}

static void build_bad_segment_index(cdt_builder *b)
{
    cb_loop(b, square02, 4);
    cb_box(b, 3, NULL);
    b->seg[3] = 99;
}

static void build_overlapping_collinear(cdt_builder *b)
{
    int p0 = cb_point(b, 0, 0), p1 = cb_point(b, 2, 0), p2 = cb_point(b, 1, 0),
        p3 = cb_point(b, 3, 0);
    cb_segment(b, p0, p1, 0, 0);
    cb_segment(b, p2, p3, 0, 0);
    cb_box(b, 3, NULL);
}

static const invalid_case invalid_cases[] = {
    {"crossing_segments_fail", build_crossing_squares, "crosses segment"},
    {"point_on_segment_fails", build_point_on_segment, "interior of segment 0"},
    {"duplicate_points_fail", build_duplicate_point, "points 2 and 4 coincide"},
    {"nan_fails", build_nan_coordinate, "non-finite"},
    {"bad_index_fails", build_bad_segment_index, "segment 1"},
    {"overlapping_collinear_segments_fail", build_overlapping_collinear, "interior of segment"},
};

/* The case's input is refused with SCAF_ERR_MESH, the message names the
 * problem, and the output is left empty. */
static void invalid_input_fails(void **state)
{
    const invalid_case *c = *state;
    cdt_builder b;
    cb_init(&b);
    c->build(&b);
    cdt_input in = cb_input(&b);
    cdt_output out;
    scaf_error err;
    err_clear(&err);
    scaf_status s = cdt_triangulate(&in, NULL, &out, &err);
    if (s != SCAF_ERR_MESH)
        fail_msg("%s: status %d, expected SCAF_ERR_MESH (%d)", c->name, (int)s, (int)SCAF_ERR_MESH);
    if (!strstr(err.message, c->needle))
        fail_msg("%s: message '%s' lacks '%s'", c->name, err.message, c->needle);
    assert_int_equal(out.ntriangles, 0);
    assert_null(out.triangles);
    cb_free(&b);
}

/* one cmocka test per row, named after it */
#define INVALID_CASE(i)                                                                            \
    {                                                                                              \
        invalid_cases[i].name, invalid_input_fails, NULL, NULL, (void *)&invalid_cases[i]          \
    }

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_only_is_refined),
        cmocka_unit_test(single_chart_default_quality),
        cmocka_unit_test(no_refinement_is_pure_cdt),
        cmocka_unit_test(chart_with_hole_and_nested_chart),
        cmocka_unit_test(hole_seeds_work_like_flags),
        cmocka_unit_test(chart_edges_are_never_split),
        cmocka_unit_test(small_input_angle_terminates),
        cmocka_unit_test(deterministic),
        cmocka_unit_test(lattice_rectangles_degenerate),
        cmocka_unit_test(steiner_cap_is_respected),
        cmocka_unit_test(isolated_points_become_vertices),
        cmocka_unit_test(empty_and_trivial_inputs),
        INVALID_CASE(0),
        INVALID_CASE(1),
        INVALID_CASE(2),
        INVALID_CASE(3),
        INVALID_CASE(4),
        INVALID_CASE(5),
    };
    _Static_assert(sizeof invalid_cases / sizeof invalid_cases[0] == 6,
                   "one INVALID_CASE entry per row of invalid_cases");
    return cmocka_run_group_tests(tests, NULL, NULL);
}
