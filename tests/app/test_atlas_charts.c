/* Tests for app/atlas_charts: a distorted chart is split in two, or with
 * slit_cones cut open from its boundary and stays one disk; charts below
 * the bounds are left alone; a round after a split starts from the settled
 * layout; a mesh without vt is refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas_charts.h"
#include "geom/bijectivity.h"
#include "mesh/samples.h"
#include "mesh/uv_charts.h"

/* Sample `name` as one UV chart (vt index = vertex index). */
static void one_chart(const char *name, int size, mesh *out)
{
    scaf_error e;
    err_clear(&e);
    mesh m;
    assert_int_equal(mesh_sample_make(name, size, &m, &e), SCAF_OK);
    assert_int_equal(mesh_alloc(out, m.nv, m.nf, m.nv, &e), SCAF_OK);
    memcpy(out->V, m.V, sizeof(double) * 3 * (size_t)m.nv);
    memcpy(out->F, m.F, sizeof(int) * 3 * (size_t)m.nf);
    memcpy(out->FT, m.F, sizeof(int) * 3 * (size_t)m.nf);
    for (int v = 0; v < m.nv; v++) {
        out->UV[2 * v] = m.V[3 * v];
        out->UV[2 * v + 1] = m.V[3 * v + 1];
    }
    mesh_free(&m);
}

/* The kinds of m's UV charts: every one must be a disk (no holes). */
static int disk_charts(const mesh *m)
{
    scaf_error e;
    mesh_charts c;
    memset(&c, 0, sizeof c);
    assert_int_equal(mesh_charts_compute(m, &c, &e), SCAF_OK);
    for (int k = 0; k < c.ncharts; k++) assert_int_equal(mesh_chart_check(&c, k, 0, &e), SCAF_OK);
    int n = c.ncharts;
    mesh_charts_free(&c);
    return n;
}

static atlas_options quick(void)
{
    atlas_options a = atlas_options_default();
    a.settle_iterations = 10;
    return a;
}

static void distorted_chart_split_in_two(void **state)
{
    (void)state;
    mesh m;
    one_chart("hemisphere", 6, &m);
    atlas_options a = quick();
    atlas_charts_options o = atlas_charts_options_default();
    o.max_distortion = 4.01;
    o.min_fill = 0.0;
    o.max_rounds = 1;
    atlas_charts_info info;
    scaf_error e;
    assert_int_equal(atlas_charts_refine(&m, &a, &o, &info, &e), SCAF_OK);
    assert_int_equal(info.rounds, 1);
    assert_int_equal(info.distortion_splits, 1);
    assert_int_equal(info.charts_before, 1);
    assert_int_equal(info.charts_after, 2);
    assert_int_equal(disk_charts(&m), 2);
    mesh_free(&m);
}

static void distorted_chart_slit_stays_one_disk(void **state)
{
    (void)state;
    mesh m;
    one_chart("hemisphere", 6, &m);
    int nuv = m.nuv;
    atlas_options a = quick();
    atlas_charts_options o = atlas_charts_options_default();
    o.max_distortion = 4.01;
    o.min_fill = 0.0;
    o.max_rounds = 1;
    o.slit_cones = 1;
    atlas_charts_info info;
    scaf_error e;
    assert_int_equal(atlas_charts_refine(&m, &a, &o, &info, &e), SCAF_OK);
    assert_int_equal(info.distortion_slits, 1);
    assert_int_equal(info.distortion_splits, 0);
    assert_true(m.nuv > nuv); /* the slit's vertices doubled */
    assert_int_equal(disk_charts(&m), 1);
    mesh_free(&m);
}

/* The same seams: two corners share a vt in A exactly when they do in B
 * (the indices may be renumbered). */
static int same_seams(int nf, const int *A, int na, const int *B, int nb)
{
    int *ab = malloc(sizeof(int) * (size_t)na), *ba = malloc(sizeof(int) * (size_t)nb);
    assert_non_null(ab);
    assert_non_null(ba);
    for (int i = 0; i < na; i++) ab[i] = -1;
    for (int i = 0; i < nb; i++) ba[i] = -1;
    int same = 1;
    for (int h = 0; h < 3 * nf && same; h++) {
        if (ab[A[h]] < 0 && ba[B[h]] < 0) {
            ab[A[h]] = B[h];
            ba[B[h]] = A[h];
        }
        same = ab[A[h]] == B[h] && ba[B[h]] == A[h];
    }
    free(ab);
    free(ba);
    return same;
}

static void charts_within_bounds_untouched(void **state)
{
    (void)state;
    mesh m;
    one_chart("grid", 8, &m); /* flat: E 4, fills its box */
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_non_null(FT);
    memcpy(FT, m.FT, sizeof(int) * 3 * (size_t)m.nf);
    int nuv = m.nuv;
    atlas_options a = quick();
    atlas_charts_options o = atlas_charts_options_default();
    atlas_charts_info info;
    scaf_error e;
    assert_int_equal(atlas_charts_refine(&m, &a, &o, &info, &e), SCAF_OK);
    assert_int_equal(info.charts_after, 1);
    assert_true(same_seams(m.nf, FT, nuv, m.FT, m.nuv));
    free(FT);
    mesh_free(&m);
}

/* After a split the next round starts from the settled layout: both
 * halves keep their shapes (warm), and the layout m ends with (the final
 * atlas's start) has every triangle counter-clockwise. */
static void split_halves_restart_warm(void **state)
{
    (void)state;
    mesh m;
    one_chart("hemisphere", 6, &m);
    atlas_options a = quick();
    atlas_charts_options o = atlas_charts_options_default();
    o.max_distortion = 4.01;
    o.min_fill = 0.0;
    o.max_rounds = 2;
    o.max_splits = 1;
    atlas_charts_info info;
    scaf_error e;
    assert_int_equal(atlas_charts_refine(&m, &a, &o, &info, &e), SCAF_OK);
    assert_int_equal(info.rounds, 2);
    assert_true(info.distortion_splits >= 1);
    assert_int_equal(info.warm_charts, 2); /* round 2 ran on the two halves, both warm */
    bij_report r;
    int n = disk_charts(&m);
    assert_true(n >= 2);
    signed char *orient = malloc((size_t)m.nf);
    assert_non_null(orient);
    assert_int_equal(bij_check(m.nuv, m.UV, m.nf, m.FT, NULL, orient, &r, &e), SCAF_OK);
    assert_int_equal(r.positive, m.nf);
    free(orient);
    mesh_free(&m);
}

/* The atlas of a mesh without vt starts from the layout its chart
 * refinement settled (not from Tutte), and that start is bijective. */
static void atlas_starts_from_refined_layout(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 2, &m, &e), SCAF_OK);
    atlas_options o = quick();
    atlas a;
    assert_int_equal(atlas_init(&a, &m, &o, &e), SCAF_OK);
    assert_true(a.ncharts >= 2);
    assert_int_equal(a.warm_charts, a.ncharts);
    bij_report r;
    assert_int_equal(bij_check(a.nw, a.loop.uv, a.nf, a.Fw, a.chart, NULL, &r, &e), SCAF_OK);
    assert_true(r.bijective);
    atlas_free(&a);
    mesh_free(&m);
}

static void no_uv_refused(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 2, &m, &e), SCAF_OK);
    atlas_options a = quick();
    atlas_charts_options o = atlas_charts_options_default();
    assert_int_equal(atlas_charts_refine(&m, &a, &o, NULL, &e), SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "vt"));
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(distorted_chart_split_in_two),
        cmocka_unit_test(distorted_chart_slit_stays_one_disk),
        cmocka_unit_test(charts_within_bounds_untouched),
        cmocka_unit_test(split_halves_restart_warm),
        cmocka_unit_test(atlas_starts_from_refined_layout),
        cmocka_unit_test(no_uv_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
