/* Adversarial and randomized tests for geom/cdt: what SCAF does to its scaffold.
 *
 * Hundreds of charts, chart boundaries 1e-12 apart (between charts and
 * within one folded chart), nearly collinear boundary chains, long thin
 * gaps, random star-shaped charts. Each output is checked exactly by
 * cdt_check (cdt_check.h); refinement must finish without hitting its cap.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/cdt_check.h"

static unsigned rnd_state = 1;
static double rnd(void) /* deterministic per test (reset by each test) */
{
    rnd_state = rnd_state * 1664525u + 1013904223u;
    return (rnd_state >> 8) / 16777216.0;
}

static void run_and_check(cdt_builder *b, const cdt_options *opt, int chi, int strict_angles)
{
    cdt_input in = cb_input(b);
    cdt_output out;
    scaf_error err;
    err_clear(&err);
    if (cdt_triangulate(&in, opt, &out, &err) != SCAF_OK)
        fail_msg("cdt_triangulate failed: %s", err.message);
    cdt_check_stats st = cdt_check(b, opt, &out, chi, 1);
    if (!st.ok) fail_msg("%s", st.why);
    if (strict_angles && st.nfree_bad > 0)
        fail_msg("%d of %d triangles away from charts below the bound (min %g)", st.nfree_bad,
                 st.nfree, st.min_angle_free);
    assert_false(out.capped);
    print_message("    %d points (%d Steiner), %d triangles, min angle %.2f (all) %.2f (away "
                  "from charts, %d triangles), %d refused\n",
                  out.npoints, out.nsteiner, out.ntriangles, st.min_angle_all, st.min_angle_free,
                  st.nfree, out.nrejected);
    cdt_output_free(&out);
}

/* The usual ending: add the 3x scaffold box, mesh with the default options,
 * check as run_and_check does, free the builder. */
static void boxed_default_run_and_check(cdt_builder *b, int chi, int strict_angles)
{
    cb_box(b, 3.0, NULL);
    cdt_options opt = cdt_default_options();
    run_and_check(b, &opt, chi, strict_angles);
    cb_free(b);
}

/* a random star-shaped polygon in the disk (cx, cy, r), n vertices, CCW */
static void star(double *xy, int n, double cx, double cy, double r)
{
    double ph = rnd() * 6.283185307179586;
    for (int i = 0; i < n; i++) {
        double t = ph + 6.283185307179586 * (i + 0.8 * rnd()) / n;
        double rr = r * (0.3 + 0.7 * rnd());
        xy[2 * i] = cx + rr * cos(t);
        xy[2 * i + 1] = cy + rr * sin(t);
    }
}

static void hundreds_of_charts_on_a_grid(void **state)
{
    (void)state;
    rnd_state = 7;
    cdt_builder b;
    cb_init(&b);
    int k = 0;
    for (int i = 0; i < 20; i++)
        for (int j = 0; j < 20; j++) {
            double xy[2 * 16];
            int n = 3 + (int)(rnd() * 13);
            star(xy, n, i, j, 0.45);
            cb_loop(&b, xy, n);
            k++;
        }
    boxed_default_run_and_check(&b, 1 - k, 1);
}

static void random_charts_many_seeds(void **state)
{
    (void)state;
    for (unsigned seed = 1; seed <= 20; seed++) {
        rnd_state = seed;
        cdt_builder b;
        cb_init(&b);
        int k = 0;
        int g = 1 + (int)(rnd() * 5);
        for (int i = 0; i < g; i++)
            for (int j = 0; j < g; j++) {
                if (rnd() < 0.3) continue;
                double xy[2 * 64];
                int n = 3 + (int)(rnd() * 60);
                star(xy, n, i + 0.1 * rnd(), j + 0.1 * rnd(), 0.4 + 0.09 * rnd());
                cb_loop(&b, xy, n);
                k++;
            }
        if (k == 0) continue;
        cb_box(&b, 2.0 + 2 * rnd(), NULL);
        cdt_options opt = cdt_default_options();
        opt.min_angle_deg = 10 + 20 * rnd();
        if (seed % 3 == 0) opt.max_area = 0.05;
        run_and_check(&b, &opt, 1 - k, seed % 3 != 0);
        cb_free(&b);
    }
}

static void boundaries_1e12_apart(void **state)
{
    (void)state;
    /* columns of squares whose facing edges are 1e-12 apart, with the
       vertices on the facing edges at different heights, plus a C-shaped
       chart whose arms close to a 1e-12 gap */
    cdt_builder b;
    cb_init(&b);
    int k = 0;
    for (int i = 0; i < 6; i++) {
        double x0 = i * (1 + 1e-12), x1 = x0 + 1;
        double xy[2 * 8];
        int n = 0;
        xy[n++] = x0, xy[n++] = 0;
        xy[n++] = x1, xy[n++] = 0;
        xy[n++] = x1, xy[n++] = 0.37 + 0.01 * i;
        xy[n++] = x1, xy[n++] = 1;
        xy[n++] = x0, xy[n++] = 1;
        xy[n++] = x0, xy[n++] = 0.61 - 0.02 * i;
        cb_loop(&b, xy, n / 2);
        k++;
    }
    /* C shape: a ring cut open by a 1e-12 slit on the right */
    {
        double xy[2 * 200];
        int n = 0, m = 60;
        double gap = 1e-12, cx = 3, cy = -2;
        for (int i = 0; i <= m; i++) { /* outer arc, from just above the slit round to below */
            double t = asin(gap / 1.0) + (6.283185307179586 - 2 * asin(gap / 1.0)) * i / m;
            xy[n++] = cx + cos(t), xy[n++] = cy + sin(t);
        }
        for (int i = m; i >= 0; i--) {
            double t = asin(gap / 0.5) + (6.283185307179586 - 2 * asin(gap / 0.5)) * i / m;
            xy[n++] = cx + 0.5 * cos(t), xy[n++] = cy + 0.5 * sin(t);
        }
        cb_loop(&b, xy, n / 2);
        k++;
    }
    boxed_default_run_and_check(&b, 1 - k, 0);
}

static void interleaved_combs_1e12_apart(void **state)
{
    (void)state;
    /* two comb-shaped charts whose teeth interleave with 1e-12 gaps on both
       sides of every tooth; the facing tooth sides carry different numbers
       of vertices, so the gaps hold only slivers */
    cdt_builder b;
    cb_init(&b);
    int teeth = 12;
    double g = 1e-12, w = 1.0; /* tooth width; gap g between neighbouring teeth */
    double *xy = malloc(4096 * sizeof(double));
    int n = 0;
    /* lower comb: base [0, L] x [-1, 0], teeth [2i(w+g), 2i(w+g)+w] x [0, 5] */
    double L = 2 * teeth * (w + g);
    xy[n++] = 0, xy[n++] = -1;
    xy[n++] = L, xy[n++] = -1;
    for (int i = teeth - 1; i >= 0; i--) {
        double x0 = 2 * i * (w + g), x1 = x0 + w;
        if (i == teeth - 1) xy[n++] = L, xy[n++] = 0;
        xy[n++] = x1, xy[n++] = 0;
        for (int k = 1; k <= 7; k++) /* right side going up */
            xy[n++] = x1, xy[n++] = 5.0 * k / 7;
        for (int k = 5; k >= 1; k--) /* left side coming down */
            xy[n++] = x0, xy[n++] = 5.0 * k / 5;
        xy[n++] = x0, xy[n++] = 0;
    }
    /* the loop is CCW: bottom edge left to right, then back along the teeth */
    cb_loop(&b, xy, n / 2);
    /* upper comb: top [0, L] x [6, 7], teeth hanging into the gaps */
    n = 0;
    xy[n++] = L, xy[n++] = 7;
    xy[n++] = 0, xy[n++] = 7;
    for (int i = 0; i < teeth; i++) {
        double x0 = 2 * i * (w + g) + w + g, x1 = x0 + w;
        xy[n++] = x0, xy[n++] = 6;
        for (int k = 1; k <= 3; k++) /* left side going down, facing the lower tooth */
            xy[n++] = x0, xy[n++] = 6 - 5.0 * k / 3;
        for (int k = 9; k >= 1; k--) xy[n++] = x1, xy[n++] = 6 - 5.0 * k / 9;
        xy[n++] = x1, xy[n++] = 6;
    }
    cb_loop(&b, xy, n / 2);
    free(xy);
    boxed_default_run_and_check(&b, -1, 0);
}

static void nearly_collinear_boundary(void **state)
{
    (void)state;
    /* a chart whose bottom is 400 points on y = 0 moved by a few ulps up and
       down (both convex and reflex vertices within 1e-16), and a top that
       is exactly collinear */
    cdt_builder b;
    cb_init(&b);
    double xy[2 * 1000];
    int n = 0;
    for (int i = 0; i <= 400; i++) {
        double y = (i % 3 == 0) ? 0 : (i % 3 == 1 ? 1e-17 * (i % 7) : -1e-17 * (i % 5));
        xy[n++] = i / 400.0, xy[n++] = y;
    }
    for (int i = 400; i >= 0; i -= 2) xy[n++] = i / 400.0, xy[n++] = 0.25;
    cb_loop(&b, xy, n / 2);
    /* a second chart just below following the same wobble 1e-12 lower */
    int n2 = 0;
    double xy2[2 * 1000];
    for (int i = 400; i >= 0; i--) {
        double y = -1e-12 + ((i % 2) ? 1e-17 : -1e-17);
        xy2[n2++] = i / 400.0 + 1e-4, xy2[n2++] = y;
    }
    xy2[n2++] = 1e-4, xy2[n2++] = -0.3;
    xy2[n2++] = 1 + 1e-4, xy2[n2++] = -0.3;
    /* orientation: bottom chain goes right to left, so the chart below is
       on its left only if the loop is CCW: (1,0)..(0,0),(0,-0.3),(1,-0.3) */
    cb_loop(&b, xy2, n2 / 2);
    boxed_default_run_and_check(&b, -1, 0);
}

static void long_thin_gap(void **state)
{
    (void)state;
    cdt_builder b;
    cb_init(&b);
    double *xy = malloc(2 * 2100 * sizeof(double));
    int n = 0;
    /* lower chart: top edge from (10, 0) back to (0, 0) with 1000 steps */
    xy[n++] = 0, xy[n++] = -1;
    xy[n++] = 10, xy[n++] = -1;
    for (int i = 1000; i >= 0; i--) xy[n++] = 10.0 * i / 1000, xy[n++] = 0;
    cb_loop(&b, xy, n / 2);
    n = 0;
    /* upper chart: bottom edge 1e-6 higher with 777 steps */
    for (int i = 0; i <= 777; i++) xy[n++] = 10.0 * i / 777 + 1e-3, xy[n++] = 1e-6;
    xy[n++] = 10 + 1e-3, xy[n++] = 1;
    xy[n++] = 1e-3, xy[n++] = 1;
    cb_loop(&b, xy, n / 2);
    free(xy);
    boxed_default_run_and_check(&b, -1, 0);
}

static void charts_nested_in_holes_deeply(void **state)
{
    (void)state;
    /* rings inside rings: chart ring, free ring, chart ring, ... , a disk */
    cdt_builder b;
    cb_init(&b);
    int rings = 5;
    for (int r = 0; r < rings; r++) {
        double ro = 10 - 2 * r, ri = ro - 1;
        cb_wiggly_loop(&b, 64, 0, 0, ro, 0.02, 3, 0);
        cb_wiggly_loop(&b, 48, 0, 0, ri, 0.02, 5, 1);
    }
    cb_wiggly_loop(&b, 16, 0, 0, 0.5, 0.1, 2, 0);
    /* free pieces: outside (one hole) and 5 rings (each one hole): chi 0 */
    boxed_default_run_and_check(&b, 0, 1);
}

static void tiny_and_huge_coordinates(void **state)
{
    (void)state;
    double scales[] = {1e-9, 1e9, 1e-150, 1e120};
    for (int s = 0; s < 4; s++) {
        print_message("    scale %g\n", scales[s]); /* names the case if it fails */
        cdt_builder b;
        cb_init(&b);
        cb_wiggly_loop(&b, 100, 3 * scales[s], -scales[s], scales[s], 0.3, 6, 0);
        boxed_default_run_and_check(&b, 0, 1);
    }
}

/* Do segments (a,b) and (c,d) meet anywhere but at a shared endpoint, or
 * does a point lie in a segment's interior? (brute force, exact) */
static int on_open_segment(const double *a, const double *b, const double *p)
{
    if (orient2d(a, b, p) != 0) return 0;
    if ((p[0] == a[0] && p[1] == a[1]) || (p[0] == b[0] && p[1] == b[1])) return 0;
    return fmin(a[0], b[0]) <= p[0] && p[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= p[1] &&
        p[1] <= fmax(a[1], b[1]);
}

static int invalid_soup(const cdt_builder *b)
{
    for (int s = 0; s < b->ns; s++) {
        const double *a = b->pts + 2 * b->seg[2 * s], *c = b->pts + 2 * b->seg[2 * s + 1];
        for (int i = 0; i < b->np; i++)
            if (on_open_segment(a, c, b->pts + 2 * i)) return 1;
        for (int t = s + 1; t < b->ns; t++) {
            const double *p = b->pts + 2 * b->seg[2 * t], *q = b->pts + 2 * b->seg[2 * t + 1];
            double o1 = orient2d(a, c, p), o2 = orient2d(a, c, q);
            double o3 = orient2d(p, q, a), o4 = orient2d(p, q, c);
            if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
                ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
                return 1;
        }
    }
    return 0;
}

static void random_segment_soup_matches_brute_force(void **state)
{
    (void)state;
    int nvalid = 0, ninvalid = 0;
    for (unsigned trial = 1; trial <= 300; trial++) {
        rnd_state = trial * 7919u;
        cdt_builder b;
        cb_init(&b);
        unsigned char used[64] = {0};
        int np = 6 + (int)(rnd() * 10);
        while (b.np < np) {
            int g = (int)(rnd() * 36);
            if (used[g]) continue;
            used[g] = 1;
            cb_point(&b, g % 6 + (trial % 2 ? 1e-13 * (g % 3) : 0), g / 6);
        }
        int ns = 1 + (int)(rnd() * 6);
        for (int i = 0; i < ns; i++) {
            int u = (int)(rnd() * np), w = (int)(rnd() * np);
            if (u != w) /* some interior segments splittable, at any slope */
                cb_segment(&b, u, w, trial % 4 == 0 && rnd() < 0.5, 0);
        }
        int expect_error = invalid_soup(&b);
        cb_rect(&b, -10, -10, 20, 20);
        cdt_input in = cb_input(&b);
        cdt_output out;
        scaf_error err;
        cdt_options opt = cdt_default_options();
        opt.min_angle_deg = trial % 3 ? 20 : 0;
        scaf_status st = cdt_triangulate(&in, &opt, &out, &err);
        if (expect_error) {
            if (st != SCAF_ERR_MESH)
                fail_msg("trial %u: invalid input accepted (status %d)", trial, (int)st);
            ninvalid++;
        } else {
            if (st != SCAF_OK) fail_msg("trial %u: valid input refused: %s", trial, err.message);
            cdt_check_stats cs = cdt_check(&b, NULL, &out, 1, 0);
            if (!cs.ok) fail_msg("trial %u: %s", trial, cs.why);
            cdt_output_free(&out);
            nvalid++;
        }
        cb_free(&b);
    }
    print_message("    %d valid, %d invalid soups\n", nvalid, ninvalid);
    assert_true(nvalid > 30 && ninvalid > 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hundreds_of_charts_on_a_grid),
        cmocka_unit_test(random_charts_many_seeds),
        cmocka_unit_test(boundaries_1e12_apart),
        cmocka_unit_test(interleaved_combs_1e12_apart),
        cmocka_unit_test(nearly_collinear_boundary),
        cmocka_unit_test(long_thin_gap),
        cmocka_unit_test(charts_nested_in_holes_deeply),
        cmocka_unit_test(tiny_and_huge_coordinates),
        cmocka_unit_test(random_segment_soup_matches_brute_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
