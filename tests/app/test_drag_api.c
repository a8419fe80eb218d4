/* Tests of the drag API (include/scaf/drag.h, src/app/drag.c).
 *
 * Meshes: two or three bumpy square patches side by side (one chart each,
 * no UVs), and the output of scaf_atlas on them (start from the input).
 * After every step the layout is checked by code independent of the drag
 * context: the exact checker (geom/bijectivity) on the layout-unit
 * positions with the API's own face charts, and the exact padding
 * certificate (geom/chart_gap) on the normalized positions the API hands
 * out for saving. Dragging: a chart onto another (it gets as close as the
 * padding allows, the other one is pushed away), a chart into free space
 * (reaches its target), a rigid rotation, a single vertex. Cancel and undo
 * restore bytes exactly. A chart dragged across a compacted atlas (the
 * cube sphere's) gets to its target with the padding kept. Every bad
 * argument gets a status and a message naming it, and changes nothing. */
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
#include "mesh/samples.h"
#include "scaf/scaf.h"

/* ---- fixture: np bumpy N x N patches, 3 units apart ------------------------- */

enum { N = 6, MAXP = 3 };

typedef struct patches {
    int nv, nf;
    double V[3 * MAXP * (N + 1) * (N + 1)];
    int F[3 * MAXP * 2 * N * N];
} patches;

static void make_patches(patches *m, int np)
{
    m->nv = m->nf = 0;
    for (int p = 0; p < np; p++) {
        int v0 = m->nv;
        for (int j = 0; j <= N; j++)
            for (int i = 0; i <= N; i++, m->nv++) {
                double x = (double)i / N, y = (double)j / N;
                m->V[3 * m->nv] = x + 3.0 * p;
                m->V[3 * m->nv + 1] = y;
                m->V[3 * m->nv + 2] = 0.2 * sin(3 * x + p) * cos(2 * y);
            }
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                int a = v0 + j * (N + 1) + i, b = a + 1, c = a + N + 1, d = c + 1;
                int *t = m->F + 3 * m->nf;
                t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
                m->nf += 2;
            }
    }
}

static scaf_drag_t *drag_on(const patches *m, const scaf_drag_options_t *o)
{
    scaf_drag_t *d = scaf_drag_new(o);
    assert_non_null(d);
    scaf_status st = scaf_drag_set_mesh(d, m->V, m->nv, m->F, m->nf, NULL, 0, NULL);
    if (st != SCAF_OK) fprintf(stderr, "%s\n", scaf_drag_error(d));
    assert_int_equal(st, SCAF_OK);
    return d;
}

/* ---- independent checks -------------------------------------------------------- */

typedef struct layout {
    int nw, nf, nc;
    double *UV; /* layout units */
    int *FT, *chart;
} layout;

static void layout_read(const scaf_drag_t *d, layout *l)
{
    l->nw = scaf_drag_uv_count(d);
    l->nf = scaf_drag_face_count(d);
    l->nc = scaf_drag_chart_count(d);
    l->UV = malloc(sizeof(double) * 2 * (size_t)l->nw);
    l->FT = malloc(sizeof(int) * 3 * (size_t)l->nf);
    l->chart = malloc(sizeof(int) * (size_t)l->nf);
    assert_true(l->UV && l->FT && l->chart);
    assert_int_equal(scaf_drag_get_uv(d, l->UV, l->FT, l->chart), SCAF_OK);
}

static void layout_free(layout *l)
{
    free(l->UV);
    free(l->FT);
    free(l->chart);
}

/* Centroid of chart c's layout vertices (plain mean: independent of the
 * API's area-weighted pivot). */
static void vertex_mean(const layout *l, int c, double out[2])
{
    int *seen = calloc((size_t)l->nw, sizeof(int));
    assert_non_null(seen);
    double s[2] = {0, 0};
    int n = 0;
    for (int f = 0; f < l->nf; f++)
        if (l->chart[f] == c)
            for (int j = 0; j < 3; j++) {
                int v = l->FT[3 * f + j];
                if (seen[v]) continue;
                seen[v] = 1;
                s[0] += l->UV[2 * v], s[1] += l->UV[2 * v + 1], n++;
            }
    free(seen);
    out[0] = s[0] / n, out[1] = s[1] / n;
}

/* The layout is bijective (exact checker) and its certified output keeps
 * the padding (exact certificate on the doubles handed out). */
static void assert_valid(scaf_drag_t *d, double padding)
{
    layout l;
    layout_read(d, &l);
    bij_report r;
    assert_int_equal(bij_check(l.nw, l.UV, l.nf, l.FT, l.chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    double *UVn = malloc(sizeof(double) * 2 * (size_t)l.nw), eff = 0, gap = 0;
    assert_non_null(UVn);
    assert_int_equal(scaf_drag_get_output(d, UVn, NULL, NULL, &eff, &gap), SCAF_OK);
    assert_int_equal(bij_check(l.nw, UVn, l.nf, l.FT, l.chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    for (int i = 0; i < 2 * l.nw; i++) assert_true(UVn[i] >= 0.0 && UVn[i] <= 1.0);
    int *seg = NULL, nseg = 0, ok = 0;
    assert_int_equal(chart_gap_segments(l.nf, l.FT, l.chart, &seg, &nseg, NULL), SCAF_OK);
    assert_int_equal(chart_gap_certify(UVn, seg, nseg, padding, &ok, NULL, NULL), SCAF_OK);
    assert_true(ok);
    assert_true(eff > 0.0 && eff <= 1.0);
    if (l.nc > 1) assert_true(gap >= padding);
    free(seg);
    free(UVn);
    layout_free(&l);
}

static double dist(const double a[2], const double b[2]) { return hypot(a[0] - b[0], a[1] - b[1]); }

/* ---- dragging ------------------------------------------------------------------ */

/* Chart 0 pulled onto chart 1's place: it moves toward it, never overlaps
 * it (bijective and padded after every step), and chart 1 gets pushed. */
static void test_drag_chart_onto_another(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    scaf_drag_t *d = drag_on(&m, &o);
    assert_int_equal(scaf_drag_chart_count(d), 2);
    layout l0;
    layout_read(d, &l0);
    double c0[2], c1[2];
    vertex_mean(&l0, 0, c0);
    vertex_mean(&l0, 1, c1);
    assert_int_equal(scaf_drag_move_chart(d, 0, c1[0] - c0[0], c1[1] - c0[1], 0.0), SCAF_OK);
    assert_int_equal(scaf_drag_handle_count(d), 1);
    double err0 = scaf_drag_max_handle_error(d), prev = err0;
    assert_true(err0 > 0.5 * dist(c0, c1));
    int decreased = 0;
    for (int k = 0; k < 12; k++) {
        assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
        assert_valid(d, o.padding);
        double e = scaf_drag_max_handle_error(d);
        if (e < prev) decreased++;
        prev = e;
    }
    assert_true(decreased >= 6);
    layout l1;
    layout_read(d, &l1);
    double d0[2], d1[2];
    vertex_mean(&l1, 0, d0);
    vertex_mean(&l1, 1, d1);
    /* chart 0 came much closer to chart 1's old place, chart 1 moved away */
    assert_true(dist(d0, c1) < 0.5 * dist(c0, c1));
    assert_true(dist(d1, c1) > 0.2 * dist(c0, c1));
    assert_true(scaf_drag_iterations(d) == 12);
    layout_free(&l0);
    layout_free(&l1);
    scaf_drag_destroy(d);
}

/* Pins: the layout read after every iteration (from the progress
 * callback) has the pinned vertices' bits, while chart 0 is dragged onto
 * chart 1 (one of its own vertices pinned, three of chart 1's) and then
 * compacted; bijective and padded after every step. Without the pins the
 * same vertices move. */
typedef struct pin_watch {
    scaf_drag_t *d;
    const int *pins;
    int npins;
    const double *at; /* nw by 2: the pinned vertices' positions */
    double *uv;       /* scratch */
    int iterations, moved;
} pin_watch;

static int pins_unmoved(const scaf_iteration_info_t *it, void *user)
{
    (void)it;
    pin_watch *w = user;
    assert_int_equal(scaf_drag_get_uv(w->d, w->uv, NULL, NULL), SCAF_OK);
    for (int i = 0; i < w->npins; i++)
        if (memcmp(w->uv + 2 * w->pins[i], w->at + 2 * w->pins[i], 2 * sizeof(double)) != 0)
            w->moved++;
    w->iterations++;
    return 0;
}

static int pinned_drag(int pin, int pins[4], int *moved)
{
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    scaf_drag_t *d = drag_on(&m, &o);
    layout l0;
    layout_read(d, &l0);
    int *wc = malloc(sizeof(int) * (size_t)l0.nw);
    assert_non_null(wc);
    assert_int_equal(scaf_drag_uv_charts(d, wc), SCAF_OK);
    /* chart 0's first vertex, chart 1's first three */
    int np = 0;
    for (int v = 0; v < l0.nw && np < 1; v++)
        if (wc[v] == 0) pins[np++] = v;
    for (int v = 0; v < l0.nw && np < 4; v++)
        if (wc[v] == 1) pins[np++] = v;
    assert_int_equal(np, 4);
    for (int i = 0; pin && i < 4; i++)
        assert_int_equal(scaf_drag_pin_vertex(d, pins[i], 1), SCAF_OK);
    assert_int_equal(scaf_drag_pinned_count(d), pin ? 4 : 0);
    assert_int_equal(scaf_drag_is_pinned(d, pins[0]), pin);
    double c0[2], c1[2];
    vertex_mean(&l0, 0, c0);
    vertex_mean(&l0, 1, c1);
    pin_watch w = {d, pins, 4, l0.UV, malloc(sizeof(double) * 2 * (size_t)l0.nw), 0, 0};
    assert_non_null(w.uv);
    assert_int_equal(scaf_drag_move_chart(d, 0, c1[0] - c0[0], c1[1] - c0[1], 0.0), SCAF_OK);
    for (int k = 0; k < 10; k++) {
        assert_int_equal(scaf_drag_step(d, 1, pins_unmoved, &w), SCAF_OK);
        assert_valid(d, o.padding);
    }
    assert_int_equal(scaf_drag_clear_handles(d), SCAF_OK);
    assert_int_equal(scaf_drag_compact(d, 5, pins_unmoved, &w), SCAF_OK);
    assert_valid(d, o.padding);
    assert_true(w.iterations >= 11);
    layout l1;
    layout_read(d, &l1);
    *moved = 0;
    for (int i = 0; i < 4; i++)
        *moved += memcmp(l1.UV + 2 * pins[i], l0.UV + 2 * pins[i], 2 * sizeof(double)) != 0;
    /* the dragged chart still came closer */
    double d0[2];
    vertex_mean(&l1, 0, d0);
    assert_true(dist(d0, c1) < dist(c0, c1));
    int moved_seen = w.moved;
    free(w.uv);
    free(wc);
    layout_free(&l0);
    layout_free(&l1);
    scaf_drag_destroy(d);
    return moved_seen;
}

static void test_pinned_vertices_keep_their_bits(void **state)
{
    (void)state;
    int pins[4], moved;
    assert_int_equal(pinned_drag(1, pins, &moved), 0);
    assert_int_equal(moved, 0);
    /* the control */
    assert_true(pinned_drag(0, pins, &moved) > 0);
    assert_int_equal(moved, 4);
    /* bad pins: nothing changes */
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    scaf_drag_t *d = drag_on(&m, &o);
    int nw = scaf_drag_uv_count(d);
    assert_int_equal(scaf_drag_pin_vertex(d, nw, 1), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "does not exist"));
    assert_int_equal(scaf_drag_pin_vertex(d, -1, 1), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_pinned_count(d), 0);
    assert_int_equal(scaf_drag_pin_vertex(d, 3, 1), SCAF_OK);
    assert_int_equal(scaf_drag_pin_vertex(d, 3, 1), SCAF_OK);
    assert_int_equal(scaf_drag_pinned_count(d), 1);
    assert_int_equal(scaf_drag_pin_vertex(d, 3, 0), SCAF_OK);
    assert_int_equal(scaf_drag_pinned_count(d), 0);
    scaf_drag_destroy(d);
}

/* A hard vertex target (a quarter of the way into its chart) is met
 * exactly (the same doubles; soft, the same pull stays short) within a
 * few steps, the vertex is then pinned and stays while another chart is
 * dragged; bijective and padded after every step. */
static void test_hard_vertex_target(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    scaf_drag_t *d = drag_on(&m, &o);
    layout l0;
    layout_read(d, &l0);
    double c0[2], c1[2];
    vertex_mean(&l0, 0, c0);
    vertex_mean(&l0, 1, c1);
    /* the vertex of chart 0 farthest from chart 1, pulled a quarter of the
     * way to its chart's middle: past its neighbours, so not at once */
    int v = -1;
    double far = -1.0;
    int *wc = malloc(sizeof(int) * (size_t)l0.nw);
    assert_non_null(wc);
    assert_int_equal(scaf_drag_uv_charts(d, wc), SCAF_OK);
    for (int u = 0; u < l0.nw; u++)
        if (wc[u] == 0 && dist(l0.UV + 2 * u, c1) > far) far = dist(l0.UV + 2 * u, c1), v = u;
    double t[2] = {l0.UV[2 * v] + 0.25 * (c0[0] - l0.UV[2 * v]),
                   l0.UV[2 * v + 1] + 0.25 * (c0[1] - l0.UV[2 * v + 1])};
    assert_int_equal(scaf_drag_move_vertex_hard(d, v, t[0], t[1]), SCAF_OK);
    assert_int_equal(scaf_drag_hard_pending(d), 1);
    assert_int_equal(scaf_drag_is_pinned(d, v), 0);
    int steps = 0;
    while (scaf_drag_hard_pending(d) > 0 && steps < 30) {
        assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
        assert_valid(d, o.padding);
        steps++;
    }
    print_message("hard vertex target met after %d steps\n", steps);
    assert_int_equal(scaf_drag_hard_pending(d), 0);
    assert_int_equal(scaf_drag_is_pinned(d, v), 1);
    layout l1;
    layout_read(d, &l1);
    assert_true(l1.UV[2 * v] == t[0] && l1.UV[2 * v + 1] == t[1]);
    /* chart 1 dragged toward chart 0: v stays */
    assert_int_equal(scaf_drag_clear_handles(d), SCAF_OK);
    assert_int_equal(scaf_drag_move_chart(d, 1, 0.5 * (c0[0] - c1[0]), 0.5 * (c0[1] - c1[1]), 0),
                     SCAF_OK);
    assert_int_equal(scaf_drag_step(d, 6, NULL, NULL), SCAF_OK);
    assert_valid(d, o.padding);
    layout l2;
    layout_read(d, &l2);
    assert_true(l2.UV[2 * v] == t[0] && l2.UV[2 * v + 1] == t[1]);
    scaf_drag_destroy(d);
    /* the control: soft, the same pull stays short of the target */
    d = drag_on(&m, &o);
    assert_int_equal(scaf_drag_move_vertex(d, v, t[0], t[1]), SCAF_OK);
    assert_int_equal(scaf_drag_step(d, steps + 5, NULL, NULL), SCAF_OK);
    assert_true(scaf_drag_max_handle_error(d) > 0.0);
    free(wc);
    layout_free(&l0);
    layout_free(&l1);
    layout_free(&l2);
    scaf_drag_destroy(d);
}

/* A settled chart (the finished atlas: its distortion at a minimum) pulled
 * a short way into free space reaches its target: nothing holds it back.
 * (From the Tutte start the soft pull stops about 2% of the chart's size
 * short: the distortion energy pulls toward the rest shape as hard.) */
static void test_drag_chart_free_space(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    o.start = SCAF_DRAG_START_ATLAS;
    scaf_drag_t *d = drag_on(&m, &o);
    scaf_drag_chart_info_t ci;
    assert_int_equal(scaf_drag_chart_info(d, 1, &ci), SCAF_OK);
    double size = sqrt(ci.uv_area);
    /* away from chart 0: chart 1 lies to its right or above */
    layout l;
    layout_read(d, &l);
    double c0[2], c1[2];
    vertex_mean(&l, 0, c0);
    vertex_mean(&l, 1, c1);
    double dx = c1[0] - c0[0], dy = c1[1] - c0[1], n = hypot(dx, dy);
    assert_int_equal(scaf_drag_move_chart(d, 1, 0.3 * size * dx / n, 0.3 * size * dy / n, 0.0),
                     SCAF_OK);
    assert_int_equal(scaf_drag_step(d, 15, NULL, NULL), SCAF_OK);
    assert_valid(d, scaf_drag_options_default().padding);
    assert_true(scaf_drag_max_handle_error(d) < 0.002 * size);
    scaf_drag_chart_info_t after;
    assert_int_equal(scaf_drag_chart_info(d, 1, &after), SCAF_OK);
    assert_true(after.held);
    assert_true(fabs(after.centroid[0] - ci.centroid[0] - 0.3 * size * dx / n) < 0.002 * size);
    assert_true(fabs(after.centroid[1] - ci.centroid[1] - 0.3 * size * dy / n) < 0.002 * size);
    layout_free(&l);
    scaf_drag_destroy(d);
}

/* The finished atlas of the 6-chart cube sphere (compacted: gaps at the
 * padding, charts squeezed below their distortion optimum), chart 0
 * dragged to the middle of the layout as an editor does (the target a
 * little further each frame, one step per frame): it gets there, pushing
 * the others aside, bijective and padded after every step. Without the
 * padding in the drag's energy (app/drag_barrier) the padding test
 * shortened every step, chart 0's share too, and it stayed where it was
 * (handle error 0.31 of the side after the 20 frames). */
static void test_drag_compacted_atlas(void **state)
{
    (void)state;
    mesh cs;
    assert_int_equal(mesh_sample_make("cubesphere", 8, &cs, NULL), SCAF_OK);
    scaf_drag_options_t o = scaf_drag_options_default();
    o.start = SCAF_DRAG_START_ATLAS;
    scaf_drag_t *d = scaf_drag_new(&o);
    assert_int_equal(scaf_drag_set_mesh(d, cs.V, cs.nv, cs.F, cs.nf, cs.UV, cs.nuv, cs.FT),
                     SCAF_OK);
    mesh_free(&cs);
    layout l;
    layout_read(d, &l);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, c0[2];
    for (int v = 0; v < l.nw; v++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], l.UV[2 * v + k]);
            hi[k] = fmax(hi[k], l.UV[2 * v + k]);
        }
    double mid[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    vertex_mean(&l, 0, c0);
    assert_true(dist(c0, mid) > 0.2 * side);
    enum { FRAMES = 20 };
    for (int f = 1; f <= FRAMES; f++) {
        double t = (double)f / FRAMES;
        assert_int_equal(
            scaf_drag_move_chart(d, 0, t * (mid[0] - c0[0]), t * (mid[1] - c0[1]), 0.0), SCAF_OK);
        assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
        assert_valid(d, o.padding);
    }
    assert_true(scaf_drag_max_handle_error(d) < 0.01 * side);
    layout_free(&l);
    scaf_drag_destroy(d);
}

/* A quarter turn about the chart's centroid: its vertices end near the
 * grab pose turned (checked here with the test's own rotation). */
static void test_rigid_rotation(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    layout g;
    layout_read(d, &g);
    int *wc = malloc(sizeof(int) * (size_t)g.nw);
    assert_non_null(wc);
    assert_int_equal(scaf_drag_uv_charts(d, wc), SCAF_OK);
    scaf_drag_chart_info_t ci;
    assert_int_equal(scaf_drag_chart_info(d, 0, &ci), SCAF_OK);
    double size = sqrt(ci.uv_area), angle = 0.5 * 3.14159265358979323846;
    assert_int_equal(scaf_drag_move_chart(d, 0, 0.0, 0.0, angle), SCAF_OK);
    for (int k = 0; k < 15; k++) {
        assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
        assert_valid(d, scaf_drag_options_default().padding);
    }
    layout l;
    layout_read(d, &l);
    double worst = 0.0;
    for (int v = 0; v < g.nw; v++) {
        if (wc[v] != 0) continue;
        double x = g.UV[2 * v] - ci.centroid[0], y = g.UV[2 * v + 1] - ci.centroid[1];
        double t[2] = {ci.centroid[0] - y, ci.centroid[1] + x}; /* turned by +90 degrees */
        worst = fmax(worst, dist(t, l.UV + 2 * v));
    }
    assert_true(worst < 0.02 * size);
    /* its distortion barely changed: a rigid motion */
    scaf_drag_chart_info_t after;
    assert_int_equal(scaf_drag_chart_info(d, 0, &after), SCAF_OK);
    assert_true(after.energy < ci.energy * 1.01);
    free(wc);
    layout_free(&g);
    layout_free(&l);
    scaf_drag_destroy(d);
}

/* One vertex dragged outward a little: its error shrinks, bijective. */
static void test_drag_vertex(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    layout l;
    layout_read(d, &l);
    scaf_drag_chart_info_t ci;
    assert_int_equal(scaf_drag_chart_info(d, 0, &ci), SCAF_OK);
    int v = l.FT[0]; /* a corner of face 0 */
    double size = sqrt(ci.uv_area);
    double tx = l.UV[2 * v] + 0.1 * size, ty = l.UV[2 * v + 1] - 0.1 * size;
    assert_int_equal(scaf_drag_move_vertex(d, v, tx, ty), SCAF_OK);
    double e0 = scaf_drag_max_handle_error(d);
    assert_true(fabs(e0 - hypot(0.1 * size, 0.1 * size)) < 1e-12 * size);
    assert_int_equal(scaf_drag_step(d, 8, NULL, NULL), SCAF_OK);
    assert_valid(d, scaf_drag_options_default().padding);
    assert_true(scaf_drag_max_handle_error(d) < 0.2 * e0);
    /* cleared: no handle, error 0 */
    assert_int_equal(scaf_drag_clear_vertex(d, v), SCAF_OK);
    assert_int_equal(scaf_drag_handle_count(d), 0);
    assert_true(scaf_drag_max_handle_error(d) == 0.0);
    layout_free(&l);
    scaf_drag_destroy(d);
}

/* ---- cancel and undo ------------------------------------------------------------- */

static void test_cancel_and_undo_restore_bytes(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    layout a, b, c;
    layout_read(d, &a);
    assert_int_equal(scaf_drag_cancel(d), SCAF_ERR_USAGE); /* no step yet */
    assert_int_equal(scaf_drag_undo(d), SCAF_ERR_USAGE);   /* no checkpoint */
    assert_true(strstr(scaf_drag_error(d), "undo") != NULL);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    assert_int_equal(scaf_drag_undo_count(d), 1);
    assert_int_equal(scaf_drag_move_chart(d, 0, 0.5, 0.2, 0.3), SCAF_OK);
    assert_int_equal(scaf_drag_step(d, 2, NULL, NULL), SCAF_OK);
    layout_read(d, &b);
    assert_true(memcmp(a.UV, b.UV, sizeof(double) * 2 * (size_t)a.nw) != 0);
    double eb = scaf_drag_energy(d);
    assert_int_equal(scaf_drag_step(d, 3, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_drag_iterations(d), 5);
    assert_int_equal(scaf_drag_cancel(d), SCAF_OK);
    layout_read(d, &c);
    assert_memory_equal(b.UV, c.UV, sizeof(double) * 2 * (size_t)a.nw);
    assert_true(scaf_drag_energy(d) == eb);
    assert_int_equal(scaf_drag_iterations(d), 2);
    layout_free(&c);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    assert_int_equal(scaf_drag_undo_count(d), 0);
    layout_read(d, &c);
    assert_memory_equal(a.UV, c.UV, sizeof(double) * 2 * (size_t)a.nw);
    assert_int_equal(scaf_drag_iterations(d), 0);
    assert_valid(d, scaf_drag_options_default().padding);
    /* handles stay: the drag goes on from the restored layout */
    assert_int_equal(scaf_drag_handle_count(d), 1);
    assert_int_equal(scaf_drag_step(d, 2, NULL, NULL), SCAF_OK);
    assert_valid(d, scaf_drag_options_default().padding);
    layout_free(&a);
    layout_free(&b);
    layout_free(&c);
    scaf_drag_destroy(d);
}

/* Redo restores what each undo left, bit for bit, undo goes back again;
 * a checkpoint or a step drops what can be redone. */
static void test_redo_restores_bytes(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    layout a, b, c, r;
    layout_read(d, &a);
    assert_int_equal(scaf_drag_redo(d), SCAF_ERR_USAGE); /* nothing undone */
    assert_true(strstr(scaf_drag_error(d), "redo") != NULL);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    assert_int_equal(scaf_drag_move_chart(d, 0, 0.5, 0.2, 0.3), SCAF_OK);
    assert_int_equal(scaf_drag_step(d, 2, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    layout_read(d, &b);
    assert_int_equal(scaf_drag_step(d, 2, NULL, NULL), SCAF_OK);
    layout_read(d, &c);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    assert_int_equal(scaf_drag_redo_count(d), 2);
    assert_int_equal(scaf_drag_undo_count(d), 0);
    assert_int_equal(scaf_drag_redo(d), SCAF_OK);
    layout_read(d, &r);
    assert_memory_equal(b.UV, r.UV, sizeof(double) * 2 * (size_t)a.nw);
    assert_int_equal(scaf_drag_iterations(d), 2);
    layout_free(&r);
    assert_int_equal(scaf_drag_redo(d), SCAF_OK);
    layout_read(d, &r);
    assert_memory_equal(c.UV, r.UV, sizeof(double) * 2 * (size_t)a.nw);
    assert_int_equal(scaf_drag_iterations(d), 4);
    layout_free(&r);
    assert_int_equal(scaf_drag_redo_count(d), 0);
    assert_int_equal(scaf_drag_undo_count(d), 2);
    /* undo after redo: back again */
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    layout_read(d, &r);
    assert_memory_equal(b.UV, r.UV, sizeof(double) * 2 * (size_t)a.nw);
    layout_free(&r);
    assert_int_equal(scaf_drag_redo_count(d), 1);
    /* a step drops the redo; so does a checkpoint */
    assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_drag_redo_count(d), 0);
    assert_int_equal(scaf_drag_redo(d), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    assert_int_equal(scaf_drag_redo_count(d), 1);
    assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
    assert_int_equal(scaf_drag_redo_count(d), 0);
    assert_valid(d, scaf_drag_options_default().padding);
    layout_free(&a);
    layout_free(&b);
    layout_free(&c);
    scaf_drag_destroy(d);
}

/* The stack keeps undo_depth checkpoints, the oldest dropped. */
static void test_undo_depth(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_options_t o = scaf_drag_options_default();
    o.undo_depth = 2;
    scaf_drag_t *d = drag_on(&m, &o);
    layout s1;
    assert_int_equal(scaf_drag_move_vertex(d, 0, -1.0, -1.0), SCAF_OK);
    for (int k = 0; k < 3; k++) {
        assert_int_equal(scaf_drag_checkpoint(d), SCAF_OK);
        if (k == 1) layout_read(d, &s1);
        assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_OK);
    }
    assert_int_equal(scaf_drag_undo_count(d), 2);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    assert_int_equal(scaf_drag_undo(d), SCAF_OK);
    layout c;
    layout_read(d, &c);
    assert_memory_equal(s1.UV, c.UV, sizeof(double) * 2 * (size_t)c.nw);
    assert_int_equal(scaf_drag_undo(d), SCAF_ERR_USAGE);
    layout_free(&s1);
    layout_free(&c);
    scaf_drag_destroy(d);
}

static int stop_after_two(const scaf_iteration_info_t *it, void *user)
{
    (*(int *)user)++;
    return it->iteration >= 2;
}

static void test_progress_cancels(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    assert_int_equal(scaf_drag_move_chart(d, 1, 1.0, 0.0, 0.0), SCAF_OK);
    int calls = 0;
    assert_int_equal(scaf_drag_step(d, 10, stop_after_two, &calls), SCAF_ERR_CANCELLED);
    assert_int_equal(calls, 2);
    assert_int_equal(scaf_drag_iterations(d), 2);
    assert_valid(d, scaf_drag_options_default().padding);
    scaf_drag_destroy(d);
}

/* ---- starts, compaction, measures ------------------------------------------------ */

/* The finished atlas of scaf_atlas is a valid start; its layout is the
 * input's up to one uniform scale and a translation. */
static void test_start_from_input(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 3);
    scaf_atlas_t *a = scaf_atlas_new(NULL);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_atlas_run(a, NULL, NULL), SCAF_OK);
    int nuv = scaf_atlas_uv_count(a);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_true(UV && FT);
    assert_int_equal(scaf_atlas_get_uv(a, UV, FT, NULL), SCAF_OK);
    scaf_drag_options_t o = scaf_drag_options_default();
    o.start = SCAF_DRAG_START_INPUT;
    scaf_drag_t *d = scaf_drag_new(&o);
    assert_int_equal(scaf_drag_set_mesh(d, m.V, m.nv, m.F, m.nf, UV, nuv, FT), SCAF_OK);
    assert_int_equal(scaf_drag_uv_count(d), nuv);
    double *out = malloc(sizeof(double) * 2 * (size_t)nuv), eff = 0;
    assert_non_null(out);
    assert_int_equal(scaf_drag_get_output(d, out, NULL, NULL, &eff, NULL), SCAF_OK);
    for (int i = 0; i < 2 * nuv; i++) assert_true(fabs(out[i] - UV[i]) < 1e-12);
    assert_true(fabs(eff - scaf_atlas_packing_efficiency(a)) < 1e-12);
    assert_valid(d, o.padding);
    /* without UVs: a usage error naming the start */
    scaf_drag_t *e = scaf_drag_new(&o);
    assert_int_equal(scaf_drag_set_mesh(e, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    assert_true(strstr(scaf_drag_error(e), "START_INPUT") != NULL);
    assert_int_equal(scaf_drag_uv_count(e), 0);
    scaf_drag_destroy(e);
    free(out);
    free(UV);
    free(FT);
    scaf_drag_destroy(d);
    scaf_atlas_destroy(a);
}

/* Compaction packs the grid start tighter, keeping the padding. */
static void test_compact(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 3);
    scaf_drag_t *d = drag_on(&m, NULL);
    double e0 = scaf_drag_packing_efficiency(d);
    assert_int_equal(scaf_drag_move_chart(d, 0, 0.1, 0.0, 0.0), SCAF_OK);
    assert_int_equal(scaf_drag_compact(d, 10, NULL, NULL), SCAF_OK);
    assert_valid(d, scaf_drag_options_default().padding);
    assert_true(scaf_drag_packing_efficiency(d) > e0);
    /* the handle survived compaction */
    assert_int_equal(scaf_drag_handle_count(d), 1);
    assert_int_equal(scaf_drag_cancel(d), SCAF_OK);
    assert_true(scaf_drag_packing_efficiency(d) == e0);
    scaf_drag_destroy(d);
}

/* scaf_drag_set_padding: a padding the layout does not keep is refused
 * (nothing changes); a smaller one holds from then on: compaction packs
 * tighter than the old padding allowed and the output is certified with
 * the new one. No mesh, out of range, or a context of padding 0: refused. */
static void test_set_padding(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 3);
    scaf_drag_t *none = scaf_drag_new(NULL);
    assert_int_equal(scaf_drag_set_padding(none, 0.001), SCAF_ERR_USAGE);
    scaf_drag_destroy(none);
    scaf_drag_options_t zero = scaf_drag_options_default();
    zero.padding = 0.0;
    scaf_drag_t *d0 = drag_on(&m, &zero);
    assert_int_equal(scaf_drag_set_padding(d0, 0.001), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d0), "padding 0"));
    scaf_drag_destroy(d0);
    scaf_drag_t *d = drag_on(&m, NULL);
    double p0 = scaf_drag_options_default().padding;
    assert_int_equal(scaf_drag_compact(d, 30, NULL, NULL), SCAF_OK);
    assert_int_equal(scaf_drag_set_padding(d, 0.0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_set_padding(d, 0.5), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_set_padding(d, 0.45), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_drag_error(d), "smallest chart gap"));
    assert_true(scaf_drag_padding(d) == p0);
    assert_valid(d, p0);
    double e0 = scaf_drag_packing_efficiency(d);
    assert_int_equal(scaf_drag_set_padding(d, p0 / 8), SCAF_OK);
    assert_true(scaf_drag_padding(d) == p0 / 8);
    assert_int_equal(scaf_drag_compact(d, 30, NULL, NULL), SCAF_OK);
    assert_valid(d, p0 / 8);
    assert_true(scaf_drag_packing_efficiency(d) >= e0);
    scaf_drag_destroy(d);
}

/* Measures against the test's own sums. */
static void test_measures(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    scaf_drag_t *d = drag_on(&m, NULL);
    layout l;
    layout_read(d, &l);
    double *E = malloc(sizeof(double) * (size_t)l.nf);
    assert_non_null(E);
    assert_int_equal(scaf_drag_face_energy(d, E), SCAF_OK);
    int faces[2] = {0, 0};
    for (int f = 0; f < l.nf; f++) {
        assert_true(E[f] >= 4.0 - 1e-9);
        faces[l.chart[f]]++;
    }
    for (int c = 0; c < 2; c++) {
        scaf_drag_chart_info_t ci;
        assert_int_equal(scaf_drag_chart_info(d, c, &ci), SCAF_OK);
        assert_int_equal(ci.faces, faces[c]);
        assert_int_equal(ci.uvs, (N + 1) * (N + 1));
        assert_true(ci.energy >= 4.0 && ci.uv_area > 0.0 && !ci.held);
    }
    double area = 0.0, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int f = 0; f < l.nf; f++) {
        const double *p = l.UV + 2 * l.FT[3 * f], *q = l.UV + 2 * l.FT[3 * f + 1],
                     *r = l.UV + 2 * l.FT[3 * f + 2];
        area += 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    }
    for (int v = 0; v < l.nw; v++)
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], l.UV[2 * v + k]), hi[k] = fmax(hi[k], l.UV[2 * v + k]);
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    assert_true(fabs(scaf_drag_packing_efficiency(d) - area / (side * side)) < 1e-9);
    assert_true(scaf_drag_energy(d) >= 4.0);
    free(E);
    layout_free(&l);
    scaf_drag_destroy(d);
}

/* ---- bad input ------------------------------------------------------------------- */

static void test_bad_input(void **state)
{
    (void)state;
    patches m;
    make_patches(&m, 2);
    /* no mesh */
    scaf_drag_t *d = scaf_drag_new(NULL);
    double uv[2];
    assert_int_equal(scaf_drag_step(d, 1, NULL, NULL), SCAF_ERR_USAGE);
    assert_true(strstr(scaf_drag_error(d), "no mesh") != NULL);
    assert_int_equal(scaf_drag_move_vertex(d, 0, 0, 0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_get_uv(d, uv, NULL, NULL), SCAF_ERR_USAGE);
    assert_true(isnan(scaf_drag_energy(d)) && isnan(scaf_drag_max_handle_error(d)));
    assert_int_equal(scaf_drag_chart_count(d), 0);
    /* NULL context */
    assert_int_equal(scaf_drag_step(NULL, 1, NULL, NULL), SCAF_ERR_USAGE);
    assert_non_null(scaf_drag_error(NULL));
    scaf_drag_destroy(NULL);
    /* bad mesh: index out of range */
    m.F[4] = m.nv + 5;
    assert_int_equal(scaf_drag_set_mesh(d, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    assert_true(strlen(scaf_drag_error(d)) > 0);
    make_patches(&m, 2);
    assert_int_equal(scaf_drag_set_mesh(d, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    layout a, b;
    layout_read(d, &a);
    int nw = scaf_drag_uv_count(d);
    /* unknown vertex / chart, non-finite targets: nothing changes */
    assert_int_equal(scaf_drag_move_vertex(d, nw, 0.0, 0.0), SCAF_ERR_USAGE);
    char want[64];
    snprintf(want, sizeof want, "vertex %d does not exist", nw);
    assert_true(strstr(scaf_drag_error(d), want) != NULL);
    assert_int_equal(scaf_drag_move_vertex(d, -1, 0.0, 0.0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_move_vertex(d, 0, NAN, 0.0), SCAF_ERR_USAGE);
    assert_true(strstr(scaf_drag_error(d), "not finite") != NULL);
    assert_int_equal(scaf_drag_move_vertex(d, 0, 0.0, INFINITY), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_move_chart(d, 2, 0.0, 0.0, 0.0), SCAF_ERR_USAGE);
    assert_true(strstr(scaf_drag_error(d), "chart 2 does not exist") != NULL);
    assert_int_equal(scaf_drag_move_chart(d, 0, NAN, 0.0, 0.0), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_move_chart(d, 0, 0.0, 0.0, INFINITY), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_clear_chart(d, -1), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_clear_vertex(d, nw), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_handle_count(d), 0);
    scaf_drag_chart_info_t ci;
    assert_int_equal(scaf_drag_chart_info(d, 5, &ci), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_chart_info(d, 0, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_step(d, 0, NULL, NULL), SCAF_ERR_USAGE);
    assert_true(strstr(scaf_drag_error(d), "0 must be >= 1") != NULL);
    assert_int_equal(scaf_drag_compact(d, -1, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_get_uv(d, NULL, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_get_output(d, NULL, NULL, NULL, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_uv_charts(d, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_drag_face_energy(d, NULL), SCAF_ERR_USAGE);
    layout_read(d, &b);
    assert_memory_equal(a.UV, b.UV, sizeof(double) * 2 * (size_t)nw);
    assert_int_equal(scaf_drag_iterations(d), 0);
    layout_free(&a);
    layout_free(&b);
    scaf_drag_destroy(d);
    /* invalid options: no context, and the check names the field
     * (tests/app/test_api_options.c tries every field) */
    scaf_drag_options_t o = scaf_drag_options_default();
    char why[256];
    o.undo_depth = 0;
    assert_null(scaf_drag_new(&o));
    assert_int_equal(scaf_drag_options_check(&o, why, sizeof why), SCAF_ERR_USAGE);
    assert_true(strstr(why, "undo_depth") != NULL);
    o = scaf_drag_options_default();
    o.padding = 0.7;
    assert_null(scaf_drag_new(&o));
    assert_int_equal(scaf_drag_options_check(&o, why, sizeof why), SCAF_ERR_USAGE);
    assert_true(strstr(why, "padding") != NULL);
    o = scaf_drag_options_default();
    o.weight_ratio = NAN;
    assert_null(scaf_drag_new(&o));
    assert_int_equal(scaf_drag_options_check(&o, why, sizeof why), SCAF_ERR_USAGE);
    assert_true(strstr(why, "weight_ratio") != NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_drag_chart_onto_another),
        cmocka_unit_test(test_pinned_vertices_keep_their_bits),
        cmocka_unit_test(test_hard_vertex_target),
        cmocka_unit_test(test_drag_chart_free_space),
        cmocka_unit_test(test_drag_compacted_atlas),
        cmocka_unit_test(test_rigid_rotation),
        cmocka_unit_test(test_drag_vertex),
        cmocka_unit_test(test_cancel_and_undo_restore_bytes),
        cmocka_unit_test(test_redo_restores_bytes),
        cmocka_unit_test(test_undo_depth),
        cmocka_unit_test(test_progress_cancels),
        cmocka_unit_test(test_start_from_input),
        cmocka_unit_test(test_compact),
        cmocka_unit_test(test_set_padding),
        cmocka_unit_test(test_measures),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
