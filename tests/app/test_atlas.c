/* Tests of app/atlas: the multi-chart atlas on generated meshes.
 *
 * Meshes are built here: many small curved patches (each a component, a
 * disk), patches with a hole, the cubesphere sample (6 vt charts), a closed
 * component. Properties asserted, all decided by independent code: after
 * EVERY iteration the map is bijective by the exact checker, the chart gap
 * is at least padding * side (the normalized padding), and an accepted
 * step lowers that iteration's total energy; the normalized output lies in
 * the unit square with the same properties; seams are preserved (two
 * corners share an output UV exactly when they shared an input vt);
 * invalid charts and non-bijective input UVs are refused with a message
 * naming the chart / the reason. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas.h"
#include "geom/coord_scale.h"
#include "app/atlas_pack.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/samples.h"

/* ---- generated meshes ---------------------------------------------------- */

/* n patches, patch i an (r+1) x (r+1) grid of size s_i, bent in z, laid out
 * far apart in 3D; with hole, the middle cell of each patch is removed
 * (r must be odd). */
static void patches(mesh *m, int n, int r, int hole)
{
    int nvp = (r + 1) * (r + 1), nfp = 2 * r * r - (hole ? 2 : 0);
    memset(m, 0, sizeof *m);
    m->nv = n * nvp;
    m->nf = n * nfp;
    m->V = malloc(sizeof(double) * 3 * (size_t)m->nv);
    m->F = malloc(sizeof(int) * 3 * (size_t)m->nf);
    assert_non_null(m->V);
    assert_non_null(m->F);
    int f = 0;
    for (int p = 0; p < n; p++) {
        double s = 0.5 + 0.37 * (p % 7) + 0.11 * (p % 3);
        for (int j = 0; j <= r; j++)
            for (int i = 0; i <= r; i++) {
                double *v = m->V + 3 * (size_t)(p * nvp + j * (r + 1) + i);
                double x = s * i / r, y = s * j / r;
                v[0] = x + 10.0 * p;
                v[1] = y;
                v[2] = 0.3 * s * sin(1.3 * x / s + p) * cos(0.7 * y / s);
            }
        for (int j = 0; j < r; j++)
            for (int i = 0; i < r; i++) {
                if (hole && i == r / 2 && j == r / 2) continue;
                int a = p * nvp + j * (r + 1) + i, b = a + 1, c = a + r + 1, d = c + 1;
                int *t = m->F + 3 * (size_t)f;
                t[0] = a, t[1] = b, t[2] = d;
                t[3] = a, t[4] = d, t[5] = c;
                f += 2;
            }
    }
    assert_int_equal(f, m->nf);
}

/* ---- per-iteration checks ---------------------------------------------- */

typedef struct check_state {
    int iterations, compact_iterations;
    double padding;
} check_state;

static int check_iteration(const atlas *a, const atlas_iteration *it, void *user)
{
    check_state *s = user;
    s->iterations++;
    if (it->phase == ATLAS_COMPACT) s->compact_iterations++;
    bij_report r;
    scaf_error err;
    assert_int_equal(bij_check(a->nw, a->loop.uv, a->nf, a->Fw, a->chart, NULL, &r, &err), SCAF_OK);
    assert_true(r.bijective);
    assert_int_equal(r.flipped, 0);
    assert_int_equal(r.boundary_crossings, 0);
    if (s->padding > 0.0 && a->ncharts > 1) {
        double g, side = atlas_side(a);
        assert_int_equal(
            chart_gap_min(a->nw, a->loop.uv, a->nf, a->Fw, a->chart, 0.0, &g, NULL, &err), SCAF_OK);
        assert_true(g >= s->padding * side);
    }
    if (it->info.step > 0.0) assert_true(it->info.total_after < it->info.total_before);
    return 0;
}

static void check_output(const atlas *a, double padding)
{
    double *UV = malloc(sizeof(double) * 2 * (size_t)a->nw);
    assert_non_null(UV);
    atlas_normalized_uv(a, UV);
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 2 * a->nw; i++) {
        lo = fmin(lo, UV[i]);
        hi = fmax(hi, UV[i]);
    }
    assert_true(lo >= 0.0);
    assert_true(hi <= 1.0);
    bij_report r;
    scaf_error err;
    assert_int_equal(bij_check(a->nw, UV, a->nf, a->Fw, NULL, NULL, &r, &err), SCAF_OK);
    assert_true(r.bijective);
    double g;
    assert_int_equal(chart_gap_min(a->nw, UV, a->nf, a->Fw, NULL, 0.0, &g, NULL, &err), SCAF_OK);
    if (a->ncharts > 1) assert_true(g >= padding);
    /* and decided exactly on the normalized doubles */
    int ok = 0;
    assert_int_equal(chart_gap_certify(UV, a->seg, a->nseg, padding, &ok, NULL, &err), SCAF_OK);
    assert_true(ok);
    double eff = chart_packing_efficiency(a->nw, UV, a->nf, a->Fw);
    assert_true(eff > 0.0 && eff <= 1.0);
    free(UV);
}

/* ---- tests ------------------------------------------------------------------ */

static void many_patches_with_padding(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 12, 4, 0);
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    o.pack_cells = 256;
    o.settle_iterations = 6;
    o.compact_iterations = 6;
    atlas a;
    scaf_error err;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(a.ncharts, 12);
    check_state s = {0, 0, o.padding};
    assert_int_equal(atlas_run(&a, check_iteration, &s, &err), SCAF_OK);
    assert_true(s.iterations >= 2);
    assert_true(s.compact_iterations >= 1);
    /* compaction (and re-placement) never loosen the packing */
    assert_true(a.eff_after >= a.eff_before);
    check_output(&a, o.padding);
    double *E = malloc(sizeof(double) * (size_t)a.ncharts);
    atlas_chart_energy(&a, E);
    for (int c = 0; c < a.ncharts; c++) assert_true(E[c] >= 4.0 - 1e-9 && isfinite(E[c]));
    free(E);
    atlas_free(&a);
    mesh_free(&m);
}

static void patches_with_holes(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 4, 5, 1);
    atlas_options o = atlas_options_default();
    o.padding = 0.01;
    o.pack_cells = 256;
    o.settle_iterations = 4;
    o.compact_iterations = 4;
    atlas a;
    scaf_error err;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(a.ncharts, 4);
    check_state s = {0, 0, o.padding};
    assert_int_equal(atlas_run(&a, check_iteration, &s, &err), SCAF_OK);
    check_output(&a, o.padding);
    atlas_free(&a);
    mesh_free(&m);
}

/* 500 small charts: the default pipeline (4 texels at 1024), every
 * iteration checked. */
static void five_hundred_charts(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 500, 2, 0);
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    atlas a;
    scaf_error err;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(a.ncharts, 500);
    check_state s = {0, 0, o.padding};
    assert_int_equal(atlas_run(&a, check_iteration, &s, &err), SCAF_OK);
    assert_true(s.iterations >= 2);
    assert_true(s.compact_iterations >= 1);
    assert_true(a.eff_after >= a.eff_before);
    check_output(&a, o.padding);
    atlas_free(&a);
    mesh_free(&m);
}

/* The cubesphere sample: 6 vt charts; seams preserved. */
static void cubesphere_seams_preserved(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 4, &m, &err), SCAF_OK);
    assert_true(mesh_has_uv(&m));
    atlas_options o = atlas_options_default();
    o.padding = 0.004;
    o.pack_cells = 256;
    o.settle_iterations = 5;
    o.compact_iterations = 5;
    atlas a;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(a.ncharts, 6);
    assert_int_equal(a.split_uvs, 0);
    check_state s = {0, 0, o.padding};
    assert_int_equal(atlas_run(&a, check_iteration, &s, &err), SCAF_OK);
    check_output(&a, o.padding);
    /* corners share an output UV exactly when they share an input vt */
    int *first = malloc(sizeof(int) * (size_t)m.nuv);
    int *back = malloc(sizeof(int) * (size_t)a.nw);
    for (int i = 0; i < m.nuv; i++) first[i] = -1;
    for (int i = 0; i < a.nw; i++) back[i] = -1;
    for (int c = 0; c < 3 * m.nf; c++) {
        int in = m.FT[c], out = a.Fw[c];
        if (first[in] < 0) first[in] = out;
        assert_int_equal(first[in], out);
        if (back[out] < 0) back[out] = in;
        assert_int_equal(back[out], in);
    }
    free(first);
    free(back);
    atlas_free(&a);
    mesh_free(&m);
}

/* The compaction result is the best packed layout within the distortion
 * tolerance: an iteration that overshoots E (the cube sphere of size 5
 * does, at its 8th) is not kept. */
typedef struct best_state {
    double e_max, best_eff;
    int compact, over;
} best_state;

static int track_best(const atlas *a, const atlas_iteration *it, void *user)
{
    best_state *b = user;
    if (it->phase != ATLAS_COMPACT) return 0;
    if (b->compact++ == 0) {
        /* the layout the phase started from */
        b->e_max = (1.0 + a->opt.distortion_tolerance) * a->settled_energy;
        b->best_eff = isnan(a->eff_packed) ? a->eff_before : a->eff_packed;
    }
    if (it->info.energy > b->e_max) b->over++;
    else if (it->efficiency > b->best_eff) b->best_eff = it->efficiency;
    return 0;
}

static void compaction_keeps_best_layout(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 5, &m, &err), SCAF_OK);
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    o.rotate = 0; /* the result is the compaction's, not turned afterwards */
    atlas a;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    best_state b = {0};
    assert_int_equal(atlas_run(&a, track_best, &b, &err), SCAF_OK);
    assert_true(b.compact >= 1);
    double eff = chart_packing_efficiency(a.nw, a.loop.uv, a.nf, a.Fw);
    assert_true(eff == b.best_eff);
    assert_true(scaf_loop_energy(&a.loop) <= b.e_max);
    print_message("cube sphere 5: %d compaction iterations, %d over the tolerance, kept an earlier "
                  "layout: %d\n",
                  b.compact, b.over, a.compact_restored);
    /* an overshooting iteration ends the phase, so it was undone */
    assert_true(b.over == 0 || a.compact_restored);
    assert_true(b.over > 0); /* this mesh does overshoot (else the test tests nothing) */
    check_output(&a, o.padding);
    atlas_free(&a);
    mesh_free(&m);
}

static void closed_chart_is_refused(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("tetrahedron", 1, &m, &err), SCAF_OK);
    atlas a;
    atlas_options o = atlas_options_default();
    o.base.seams = SCAF_SEAMS_INPUT; /* the components as they are */
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "chart"));
    /* by default it is cut open (automatic seams) and certified */
    o = atlas_options_default();
    o.settle_iterations = 10;
    o.compact_iterations = 5;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(a.seams_used, SCAF_SEAMS_AUTO);
    assert_int_equal(atlas_run(&a, NULL, NULL, &err), SCAF_OK);
    check_output(&a, o.padding);
    atlas_free(&a);
    mesh_free(&m);
}

/* --init input: refused when the UVs overlap, used when bijective. */
static void init_input(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 2, 3, 0);
    /* UVs = the flat grid coordinates (x, y) of each patch: the two
     * patches overlap in UV */
    m.nuv = m.nv;
    m.UV = malloc(sizeof(double) * 2 * (size_t)m.nv);
    m.FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    for (int v = 0; v < m.nv; v++) {
        m.UV[2 * v] = m.V[3 * v] - 10.0 * (v / 16);
        m.UV[2 * v + 1] = m.V[3 * v + 1];
    }
    memcpy(m.FT, m.F, sizeof(int) * 3 * (size_t)m.nf);
    atlas_options o = atlas_options_default();
    o.init_input = 1;
    atlas a;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "not bijective"));
    /* move the second patch away: now bijective, and used as the start */
    for (int v = 16; v < m.nv; v++) m.UV[2 * v] += 5.0;
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    /* the start is the input up to one power-of-two scale: the surface's
     * (positions / 2^e, geom/coord_scale) over the UVs' (here the UVs
     * are at the surface's scale: factor 2^-e) */
    int e = coord_scale_exponent(m.V, 3, 3 * (size_t)m.nf, m.F);
    for (int c = 0; c < 3 * m.nf; c++) {
        assert_true(a.loop.uv[2 * a.Fw[c]] == ldexp(m.UV[2 * m.FT[c]], -e));
        assert_true(a.loop.uv[2 * a.Fw[c] + 1] == ldexp(m.UV[2 * m.FT[c] + 1], -e));
    }
    atlas_free(&a);
    /* UVs 8 times too small: the same start */
    for (int i = 0; i < 2 * m.nuv; i++) m.UV[i] /= 8.0;
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    for (int c = 0; c < 3 * m.nf; c++) {
        assert_true(a.loop.uv[2 * a.Fw[c]] == ldexp(8.0 * m.UV[2 * m.FT[c]], -e));
        assert_true(a.loop.uv[2 * a.Fw[c] + 1] == ldexp(8.0 * m.UV[2 * m.FT[c] + 1], -e));
    }
    atlas_free(&a);
    /* UVs in any units, subnormal to huge: the same start (was clamped at
     * 2^+-200 of rescaling, then failed in the scaffold) */
    const int k[] = {-1000, 900, 1000};
    for (size_t t = 0; t < sizeof k / sizeof *k; t++) {
        mesh s = m;
        s.UV = malloc(sizeof(double) * 2 * (size_t)m.nuv);
        assert_non_null(s.UV);
        for (int i = 0; i < 2 * m.nuv; i++) s.UV[i] = ldexp(8.0 * m.UV[i], k[t]);
        err_clear(&err);
        assert_int_equal(atlas_init(&a, &s, &o, &err), SCAF_OK);
        for (int c = 0; c < 3 * m.nf; c++) {
            assert_true(a.loop.uv[2 * a.Fw[c]] == ldexp(8.0 * m.UV[2 * m.FT[c]], -e));
            assert_true(a.loop.uv[2 * a.Fw[c] + 1] == ldexp(8.0 * m.UV[2 * m.FT[c] + 1], -e));
        }
        atlas_free(&a);
        free(s.UV);
    }
    mesh_free(&m);
}

static void padding_too_large_is_refused(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 30, 2, 0);
    atlas_options o = atlas_options_default();
    o.padding = 0.2;
    atlas a;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_ERR_USAGE);
    assert_non_null(strstr(err.message, "padding"));
    mesh_free(&m);
}

/* Every compaction and packing knob out of range (NaN included) is
 * refused before any work; the defaults and the bounds themselves pass. */
static void out_of_range_options_are_refused(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 30, 2, 0);
    enum { NBAD = 17 };
    for (int i = 0; i < NBAD; i++) {
        atlas_options o = atlas_options_default();
        switch (i) {
        case 0: o.pack_gap_factor = 0.99; break;
        case 1: o.pack_gap_factor = NAN; break;
        case 2: o.compact_lambda_ratio = 0.0; break;
        case 3: o.compact_lambda_ratio = NAN; break;
        case 4: o.compact_rest_scale = 0.0; break;
        case 5: o.compact_rest_scale = 1.01; break;
        case 6: o.compact_rest_scale = NAN; break;
        case 7: o.compact_box_scale = 0.99; break;
        case 8: o.compact_box_scale = NAN; break;
        case 9: o.compact_fraction = 0.0; break;
        case 10: o.compact_fraction = 1.0; break;
        case 11: o.compact_fraction = NAN; break;
        case 12: o.pack_cells = 15; break;
        case 13: o.pack_cells = 8193; break;
        case 14: o.pack_picks = 0; break;
        case 15: o.pack_picks = 17; break;
        default: o.compact_rest_scale = -1.0; break;
        }
        atlas a;
        scaf_error err;
        err_clear(&err);
        assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_ERR_USAGE);
        static const char *const knob[NBAD] = {
            "pack_gap_factor",      "pack_gap_factor",    "compact_lambda_ratio",
            "compact_lambda_ratio", "compact_rest_scale", "compact_rest_scale",
            "compact_rest_scale",   "compact_box_scale",  "compact_box_scale",
            "compact_fraction",     "compact_fraction",   "compact_fraction",
            "pack_cells",           "pack_cells",         "pack_picks",
            "pack_picks",           "compact_rest_scale"};
        assert_non_null(strstr(err.message, knob[i])); /* names the option and its range */
        assert_non_null(strstr(err.message, "must be"));
    }
    atlas_options o = atlas_options_default();
    o.pack_gap_factor = 1.0;
    o.compact_rest_scale = 1.0;
    o.compact_box_scale = 1.0;
    o.pack_cells = 8192;
    o.pack_picks = 16;
    atlas a;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    atlas_free(&a);
    mesh_free(&m);
}

/* The ranking's branch and bound (keep) abandons only strategies that
 * cannot be among the keep best: the chosen strategy and the keep
 * smallest squares equal those of the full ranking. */
static void pack_keep_matches_full_ranking(void **state)
{
    (void)state;
    mesh m;
    patches(&m, 12, 4, 0);
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    o.settle_iterations = 2;
    o.compact_iterations = 0;
    o.repack = 0;
    atlas a;
    scaf_error err;
    assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
    assert_int_equal(atlas_run(&a, NULL, NULL, &err), SCAF_OK);
    int ns = atlas_pack_strategies(a.ncharts), c0 = -1, c1 = -1;
    long *s0 = malloc(sizeof(long) * (size_t)ns), *s1 = malloc(sizeof(long) * (size_t)ns);
    double *o0 = malloc(sizeof(double) * 2 * (size_t)a.nw),
           *o1 = malloc(sizeof(double) * 2 * (size_t)a.nw);
    assert_non_null(s0);
    assert_non_null(s1);
    assert_non_null(o0);
    assert_non_null(o1);
    double gap = 2.0 * o.padding * atlas_side(&a);
    for (int keep = 1; keep <= 3; keep++) {
        assert_int_equal(atlas_pack(a.nw, a.loop.uv, a.nf, a.Fw, a.chart, a.wchart, a.ncharts, 128,
                                    gap, -1, 0, &c0, s0, o0, &err),
                         SCAF_OK);
        assert_int_equal(atlas_pack(a.nw, a.loop.uv, a.nf, a.Fw, a.chart, a.wchart, a.ncharts, 128,
                                    gap, -1, keep, &c1, s1, o1, &err),
                         SCAF_OK);
        assert_int_equal(s0[c0], s1[c1]);
        for (int i = 0; i < 2 * a.nw; i++) assert_true(o0[i] == o1[i]);
        /* the keep smallest sides are the same multiset */
        for (int k = 0; k < keep; k++) {
            int i0 = -1, i1 = -1;
            for (int i = 0; i < ns; i++) {
                if (s0[i] > 0 && (i0 < 0 || s0[i] < s0[i0])) i0 = i;
                if (s1[i] > 0 && (i1 < 0 || s1[i] < s1[i1])) i1 = i;
            }
            assert_true(i0 >= 0 && i1 >= 0);
            assert_int_equal(s0[i0], s1[i1]);
            s0[i0] = s1[i1] = -1;
        }
    }
    free(s0);
    free(s1);
    free(o0);
    free(o1);
    atlas_free(&a);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(many_patches_with_padding),
        cmocka_unit_test(patches_with_holes),
        cmocka_unit_test(five_hundred_charts),
        cmocka_unit_test(cubesphere_seams_preserved),
        cmocka_unit_test(compaction_keeps_best_layout),
        cmocka_unit_test(closed_chart_is_refused),
        cmocka_unit_test(init_input),
        cmocka_unit_test(padding_too_large_is_refused),
        cmocka_unit_test(out_of_range_options_are_refused),
        cmocka_unit_test(pack_keep_matches_full_ranking),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
