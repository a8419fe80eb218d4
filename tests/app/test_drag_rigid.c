/* Tests of the drag API's rigid motions and deform cap (include/scaf/drag.h:
 * scaf_drag_rigid_*, scaf_drag_transform, scaf_drag_set_energy_cap;
 * src/app/drag_rigid.c, rigid_push.c, drag_cap.c).
 *
 * On spot's finished atlas (../shared/data/seams/spot.obj, started as
 * `scaf atlas` makes it; skipped when the file is absent): the smallest
 * chart dragged across the atlas to the other side of the layout in 24
 * frames (the total motion since the grab, as the editor sends it). After
 * every frame, checked by code independent of the engine: every other
 * chart's UVs are its UVs before the drag translated (to 1e-12 of the
 * layout's size), the dragged chart is its grab pose translated by the
 * reached fraction of the motion, the layout is bijective (exact checker)
 * and the output's padding certified exactly. Then rotate, scale and a
 * flip of a two-chart selection (flip refused without remirror, bytes
 * unchanged; with remirror a half turn), a pinned chart that never moves
 * and cannot be selected, undo / redo restoring bytes, bad arguments, and
 * the deform cap (no chart without a handle above 1.25 times its E). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"
#include "scaf/scaf.h"
#include "support/support.h"

typedef struct layout {
    int nw, nf, nc;
    double *UV;
    int *FT, *chart, *vchart;
} layout;

static void layout_read(const scaf_drag_t *d, layout *l)
{
    l->nw = scaf_drag_uv_count(d);
    l->nf = scaf_drag_face_count(d);
    l->nc = scaf_drag_chart_count(d);
    l->UV = malloc(sizeof(double) * 2 * (size_t)l->nw);
    l->FT = malloc(sizeof(int) * 3 * (size_t)l->nf);
    l->chart = malloc(sizeof(int) * (size_t)l->nf);
    l->vchart = malloc(sizeof(int) * (size_t)l->nw);
    assert_true(l->UV && l->FT && l->chart && l->vchart);
    assert_int_equal(scaf_drag_get_uv(d, l->UV, l->FT, l->chart), SCAF_OK);
    for (int f = 0; f < l->nf; f++)
        for (int j = 0; j < 3; j++) l->vchart[l->FT[3 * f + j]] = l->chart[f];
}

static void layout_free(layout *l)
{
    free(l->UV);
    free(l->FT);
    free(l->chart);
    free(l->vchart);
}

static double layout_side(const layout *l)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < l->nw; v++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], l->UV[2 * v + k]);
            hi[k] = fmax(hi[k], l->UV[2 * v + k]);
        }
    return fmax(hi[0] - lo[0], hi[1] - lo[1]);
}

/* Bijective (exact checker) and padded (exact certificate on the output). */
static void assert_valid(scaf_drag_t *d, double padding)
{
    layout l;
    layout_read(d, &l);
    bij_report r;
    assert_int_equal(bij_check(l.nw, l.UV, l.nf, l.FT, l.chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    double *UVn = malloc(sizeof(double) * 2 * (size_t)l.nw), gap = 0;
    assert_non_null(UVn);
    assert_int_equal(scaf_drag_get_output(d, UVn, NULL, NULL, NULL, &gap), SCAF_OK);
    assert_int_equal(bij_check(l.nw, UVn, l.nf, l.FT, l.chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    int *seg = NULL, nseg = 0, ok = 0;
    assert_int_equal(chart_gap_segments(l.nf, l.FT, l.chart, &seg, &nseg, NULL), SCAF_OK);
    assert_int_equal(chart_gap_certify(UVn, seg, nseg, padding, &ok, NULL, NULL), SCAF_OK);
    assert_true(ok);
    assert_true(gap >= padding);
    free(seg);
    free(UVn);
    layout_free(&l);
}

/* Largest deviation of chart c's vertices at b from a's translated by
 * their mean offset (0 for an exact translation); t gets the offset. */
static double translation_error(const layout *a, const layout *b, int c, double t[2])
{
    double s[2] = {0, 0};
    int n = 0;
    for (int v = 0; v < a->nw; v++)
        if (a->vchart[v] == c)
            s[0] += b->UV[2 * v] - a->UV[2 * v], s[1] += b->UV[2 * v + 1] - a->UV[2 * v + 1], n++;
    t[0] = s[0] / n, t[1] = s[1] / n;
    double e = 0.0;
    for (int v = 0; v < a->nw; v++)
        if (a->vchart[v] == c)
            e = fmax(e,
                     hypot(b->UV[2 * v] - a->UV[2 * v] - t[0],
                           b->UV[2 * v + 1] - a->UV[2 * v + 1] - t[1]));
    return e;
}

static scaf_drag_t *spot_atlas(double *padding)
{
    char path[4096];
    if (!test_data_path("seams/spot.obj", path, sizeof path)) return NULL;
    mesh m;
    scaf_error err;
    err_clear(&err);
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    scaf_drag_options_t o = scaf_drag_options_default();
    o.start = SCAF_DRAG_START_ATLAS; /* what `scaf edit` starts from */
    scaf_drag_t *d = scaf_drag_new(&o);
    assert_non_null(d);
    scaf_status st = scaf_drag_set_mesh(d, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
    if (st != SCAF_OK) fprintf(stderr, "%s\n", scaf_drag_error(d));
    assert_int_equal(st, SCAF_OK);
    mesh_free(&m);
    *padding = o.padding;
    return d;
}

static int smallest_chart(const scaf_drag_t *d)
{
    int best = 0;
    double area = INFINITY;
    for (int c = 0; c < scaf_drag_chart_count(d); c++) {
        scaf_drag_chart_info_t ci;
        assert_int_equal(scaf_drag_chart_info(d, c, &ci), SCAF_OK);
        if (ci.uv_area < area) area = ci.uv_area, best = c;
    }
    return best;
}

static void test_rigid_drag_across_spot(void **state)
{
    (void)state;
    double padding;
    scaf_drag_t *d = spot_atlas(&padding);
    if (!d) skip();
    layout l0;
    layout_read(d, &l0);
    double side = layout_side(&l0);
    int c = smallest_chart(d);
    scaf_drag_chart_info_t ci;
    assert_int_equal(scaf_drag_chart_info(d, c, &ci), SCAF_OK);
    /* across the atlas: to the point mirrored through the layout's middle */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < l0.nw; v++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], l0.UV[2 * v + k]);
            hi[k] = fmax(hi[k], l0.UV[2 * v + k]);
        }
    double to[2] = {lo[0] + hi[0] - ci.centroid[0], lo[1] + hi[1] - ci.centroid[1]};
    double mx = to[0] - ci.centroid[0], my = to[1] - ci.centroid[1];
    assert_true(hypot(mx, my) > 0.3 * side);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    assert_int_equal(scaf_drag_rigid_begin(d, &c, 1), SCAF_OK);
    enum { FRAMES = 24 };
    double reached = 0.0;
    int pushed_frames = 0;
    for (int f = 1; f <= FRAMES; f++) {
        double t = (double)f / FRAMES;
        scaf_drag_motion_t m = scaf_drag_motion_identity();
        m.dx = t * mx, m.dy = t * my;
        assert_int_equal(scaf_drag_rigid_move(d, &m, &reached), SCAF_OK);
        layout l;
        layout_read(d, &l);
        double off[2];
        int pushed = 0;
        for (int k = 0; k < l.nc; k++) {
            double e = translation_error(&l0, &l, k, off);
            assert_true(e <= 1e-12 * side);
            if (k == c) {
                assert_true(fabs(off[0] - reached * m.dx) <= 1e-12 * side);
                assert_true(fabs(off[1] - reached * m.dy) <= 1e-12 * side);
            } else if (hypot(off[0], off[1]) > 0.0) {
                pushed = 1;
            }
        }
        pushed_frames += pushed;
        layout_free(&l);
        assert_valid(d, padding);
    }
    /* it got across: the whole motion, pushing charts on the way */
    assert_true(reached == 1.0);
    assert_true(pushed_frames > 0);
    print_message("spot: chart %d moved %.3f of the side, %d of %d frames pushed others\n", c,
                  hypot(mx, my) / side, pushed_frames, FRAMES);
    assert_int_equal(scaf_drag_rigid_end(d), SCAF_OK);
    /* undo restores the bytes, redo the drag's */
    layout l1;
    layout_read(d, &l1);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    layout l2;
    layout_read(d, &l2);
    assert_memory_equal(l0.UV, l2.UV, sizeof(double) * 2 * (size_t)l0.nw);
    assert_int_equal(scaf_drag_redo(d), SCAF_OK);
    layout_free(&l2);
    layout_read(d, &l2);
    assert_memory_equal(l1.UV, l2.UV, sizeof(double) * 2 * (size_t)l0.nw);
    layout_free(&l2);
    layout_free(&l1);
    layout_free(&l0);
    scaf_drag_destroy(d);
}

/* Chart k's vertices at b equal f R(angle) (a - pivot) + pivot (+ any
 * translation): compared on differences to its first vertex. */
static double similarity_error(const layout *a, const layout *b, int c, double f, double angle)
{
    int v0 = -1;
    double e = 0.0, co = cos(angle), si = sin(angle);
    for (int v = 0; v < a->nw; v++) {
        if (a->vchart[v] != c) continue;
        if (v0 < 0) {
            v0 = v;
            continue;
        }
        double px = a->UV[2 * v] - a->UV[2 * v0], py = a->UV[2 * v + 1] - a->UV[2 * v0 + 1];
        double qx = b->UV[2 * v] - b->UV[2 * v0], qy = b->UV[2 * v + 1] - b->UV[2 * v0 + 1];
        e = fmax(e, hypot(qx - f * (co * px - si * py), qy - f * (si * px + co * py)));
    }
    return e;
}

static void test_rotate_scale_flip_selection(void **state)
{
    (void)state;
    double padding;
    scaf_drag_t *d = spot_atlas(&padding);
    if (!d) skip();
    int sel[2] = {smallest_chart(d), -1};
    sel[1] = sel[0] == 0 ? 1 : 0;
    struct {
        double angle, factor;
        scaf_drag_flip flip;
    } ops[] = {{0.9, 1.0, SCAF_DRAG_FLIP_NONE},
               {0.0, 1.3, SCAF_DRAG_FLIP_NONE},
               {0.0, 0.7, SCAF_DRAG_FLIP_NONE},
               {0.0, 1.0, SCAF_DRAG_FLIP_U}};
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        layout a;
        layout_read(d, &a);
        double side = layout_side(&a);
        scaf_drag_motion_t m = scaf_drag_motion_identity();
        m.angle = ops[i].angle, m.factor = ops[i].factor, m.flip = ops[i].flip;
        double reached = -1.0;
        if (m.flip != SCAF_DRAG_FLIP_NONE) {
            /* a mirror is refused, nothing changes */
            assert_int_equal(scaf_drag_transform(d, sel, 2, &m, &reached), SCAF_ERR_USAGE);
            assert_non_null(strstr(scaf_drag_error(d), "remirror"));
            layout b;
            layout_read(d, &b);
            assert_memory_equal(a.UV, b.UV, sizeof(double) * 2 * (size_t)a.nw);
            layout_free(&b);
            m.remirror = 1;
        }
        assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
        assert_int_equal(scaf_drag_transform(d, sel, 2, &m, &reached), SCAF_OK);
        assert_true(reached > 0.0);
        layout b;
        layout_read(d, &b);
        /* the selection: one similarity (a flip as a half turn) */
        double f = pow(m.factor, reached),
               ang = m.flip != SCAF_DRAG_FLIP_NONE ? 3.14159265358979323846 : reached * m.angle;
        for (int k = 0; k < 2; k++)
            assert_true(similarity_error(&a, &b, sel[k], f, ang) <= 1e-12 * side);
        /* the others: translations */
        double off[2];
        for (int k = 0; k < a.nc; k++)
            if (k != sel[0] && k != sel[1])
                assert_true(translation_error(&a, &b, k, off) <= 1e-12 * side);
        assert_valid(d, padding);
        print_message("op %zu: reached %.3f\n", i, reached);
        /* undo: bytes back */
        assert_int_equal(scaf_drag_undo(d), SCAF_OK);
        layout u;
        layout_read(d, &u);
        assert_memory_equal(a.UV, u.UV, sizeof(double) * 2 * (size_t)a.nw);
        layout_free(&u);
        assert_int_equal(scaf_drag_redo(d), SCAF_OK);
        layout_free(&a);
        layout_free(&b);
    }
    scaf_drag_destroy(d);
}

static void test_pinned_chart_stays(void **state)
{
    (void)state;
    double padding;
    scaf_drag_t *d = spot_atlas(&padding);
    if (!d) skip();
    layout a;
    layout_read(d, &a);
    int c = smallest_chart(d);
    /* pin one vertex of every other chart: nothing may be pushed */
    for (int k = 0; k < a.nc; k++) {
        if (k == c) continue;
        for (int v = 0; v < a.nw; v++)
            if (a.vchart[v] == k) {
                assert_int_equal(scaf_drag_pin_vertex(d, v, 1), SCAF_OK);
                break;
            }
    }
    int other = c == 0 ? 1 : 0;
    assert_int_equal(scaf_drag_rigid_begin(d, &other, 1), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "pinned"));
    scaf_drag_chart_info_t ci, co;
    assert_int_equal(scaf_drag_chart_info(d, c, &ci), SCAF_OK);
    assert_int_equal(scaf_drag_chart_info(d, other, &co), SCAF_OK);
    /* onto another chart: it stops before it */
    scaf_drag_motion_t m = scaf_drag_motion_identity();
    m.dx = co.centroid[0] - ci.centroid[0], m.dy = co.centroid[1] - ci.centroid[1];
    double reached = -1;
    assert_int_equal(scaf_drag_transform(d, &c, 1, &m, &reached), SCAF_OK);
    assert_true(reached < 1.0);
    layout b;
    layout_read(d, &b);
    for (int v = 0; v < a.nw; v++)
        if (a.vchart[v] != c) assert_memory_equal(a.UV + 2 * v, b.UV + 2 * v, 2 * sizeof(double));
    assert_valid(d, padding);
    layout_free(&a);
    layout_free(&b);
    scaf_drag_destroy(d);
}

static void test_bad_arguments(void **state)
{
    (void)state;
    double padding;
    scaf_drag_t *d = spot_atlas(&padding);
    if (!d) skip();
    int nc = scaf_drag_chart_count(d), bad = nc, good = 0;
    scaf_drag_motion_t m = scaf_drag_motion_identity();
    assert_int_equal(scaf_drag_rigid_move(d, &m, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "rigid_begin"));
    assert_int_equal(scaf_drag_rigid_begin(d, &bad, 1), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "does not exist"));
    assert_int_equal(scaf_drag_rigid_begin(d, NULL, 1), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_rigid_begin(d, &good, 0), SCAF_ERR_USAGE);
    m.factor = 0.0;
    assert_int_equal(scaf_drag_transform(d, &good, 1, &m, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "factor"));
    m = scaf_drag_motion_identity();
    m.dx = NAN;
    assert_int_equal(scaf_drag_transform(d, &good, 1, &m, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "dx"));
    assert_int_equal(scaf_drag_set_energy_cap(d, 0.5), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_set_energy_cap(d, NAN), SCAF_ERR_USAGE);
    assert_true(scaf_drag_energy_cap(d) == SCAF_DRAG_ENERGY_CAP_DEFAULT);
    assert_int_equal(scaf_drag_set_energy_cap(d, 0.0), SCAF_OK);
    assert_true(scaf_drag_energy_cap(d) == 0.0);
    scaf_drag_destroy(d);
}

/* Deform mode: a chart pulled onto its neighbour; every iteration kept
 * leaves every chart without a handle at most the cap times its E at the
 * drag's start. With a tight cap (1.01) some iterations are refused. */
static void test_deform_cap(void **state)
{
    (void)state;
    double padding;
    scaf_drag_t *d = spot_atlas(&padding);
    if (!d) skip();
    int nc = scaf_drag_chart_count(d);
    double *E0 = malloc(sizeof(double) * (size_t)nc);
    assert_non_null(E0);
    int c = smallest_chart(d), other = c == 0 ? 1 : 0;
    scaf_drag_chart_info_t ci, co;
    assert_int_equal(scaf_drag_chart_info(d, c, &ci), SCAF_OK);
    assert_int_equal(scaf_drag_chart_info(d, other, &co), SCAF_OK);
    for (int k = 0; k < nc; k++) {
        scaf_drag_chart_info_t x;
        assert_int_equal(scaf_drag_chart_info(d, k, &x), SCAF_OK);
        E0[k] = x.energy;
    }
    const double cap = 1.01;
    assert_int_equal(scaf_drag_set_energy_cap(d, cap), SCAF_OK);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    for (int f = 1; f <= 12; f++) {
        double t = f / 12.0;
        assert_int_equal(scaf_drag_move_chart(d, c, t * (co.centroid[0] - ci.centroid[0]),
                                              t * (co.centroid[1] - ci.centroid[1]), 0.0),
                         SCAF_OK);
        assert_int_equal(scaf_drag_step(d, 2, NULL, NULL), SCAF_OK);
        for (int k = 0; k < nc; k++) {
            if (k == c) continue;
            scaf_drag_chart_info_t x;
            assert_int_equal(scaf_drag_chart_info(d, k, &x), SCAF_OK);
            assert_true(x.energy <= cap * E0[k]);
        }
    }
    assert_valid(d, padding);
    print_message("deform cap: %ld iterations refused\n", scaf_drag_capped_count(d));
    assert_true(scaf_drag_capped_count(d) > 0);
    free(E0);
    scaf_drag_destroy(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_drag_across_spot),
        cmocka_unit_test(test_rotate_scale_flip_selection),
        cmocka_unit_test(test_pinned_chart_stays),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_deform_cap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
