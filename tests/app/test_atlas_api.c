/* Tests of the public atlas API (include/scaf/atlas.h, src/app/atlas_api.c).
 *
 * Every property of a layout handed out is decided here by code
 * independent of the atlas: the charts and boundary segments are found by
 * the test's own union-find and edge count, the padding by a brute-force
 * loop over all boundary segment pairs with the exact segment-distance test,
 * bijectivity by the exact checker, the packing efficiency and the
 * per-chart distortion recomputed from the arrays. Meshes: the cubesphere
 * sample (6 vt charts), two hand-made components without UVs, and
 * ../shared/data/seams/spot.obj when present (skipped otherwise). Also:
 * every argument error gives a status and a message (never a crash; the
 * sanitizer build checks for leaks on those paths), cancelling from the
 * progress callback, option validation. */
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
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "scaf/scaf.h"
#include "support/support.h"

/* ---- independent helpers ---------------------------------------------------- */

static int uf_root(int *p, int i)
{
    while (p[i] != i) i = p[i] = p[p[i]];
    return i;
}

/* Faces sharing an index (of IDX, nidx values) get one label; labels
 * 0..k-1 in order of first face. Returns k. */
static int labels_by_index(int nf, const int *IDX, int nidx, int *label)
{
    int *par = malloc(sizeof(int) * (size_t)nf), *owner = malloc(sizeof(int) * (size_t)nidx);
    int *id = malloc(sizeof(int) * (size_t)nf);
    assert_true(par && owner && id);
    for (int f = 0; f < nf; f++) par[f] = f, id[f] = -1;
    for (int i = 0; i < nidx; i++) owner[i] = -1;
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int i = IDX[3 * f + j];
            if (owner[i] < 0) owner[i] = f;
            else par[uf_root(par, f)] = uf_root(par, owner[i]);
        }
    int k = 0;
    for (int f = 0; f < nf; f++) {
        int r = uf_root(par, f);
        if (id[r] < 0) id[r] = k++;
        label[f] = id[r];
    }
    free(par);
    free(owner);
    free(id);
    return k;
}

/* Two label arrays describe the same partition of the faces. */
static void same_partition(int nf, const int *l1, int k1, const int *l2, int k2)
{
    assert_int_equal(k1, k2);
    int *to = malloc(sizeof(int) * (size_t)k1), *from = malloc(sizeof(int) * (size_t)k2);
    assert_true(to && from);
    for (int i = 0; i < k1; i++) to[i] = -1;
    for (int i = 0; i < k2; i++) from[i] = -1;
    for (int f = 0; f < nf; f++) {
        assert_true(l1[f] >= 0 && l1[f] < k1 && l2[f] >= 0 && l2[f] < k2);
        if (to[l1[f]] < 0) to[l1[f]] = l2[f];
        if (from[l2[f]] < 0) from[l2[f]] = l1[f];
        assert_int_equal(to[l1[f]], l2[f]);
        assert_int_equal(from[l2[f]], l1[f]);
    }
    free(to);
    free(from);
}

typedef struct edge {
    int lo, hi, a, b, chart;
} edge;

static int cmp_edge(const void *x, const void *y)
{
    const edge *p = x, *q = y;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    if (p->hi != q->hi) return p->hi < q->hi ? -1 : 1;
    return 0;
}

/* UV edges used by exactly one triangle: *nseg rows of edge. */
static edge *boundary(int nf, const int *FT, const int *label, int *nseg)
{
    edge *e = malloc(sizeof(edge) * 3 * (size_t)nf), *out = malloc(sizeof(edge) * 3 * (size_t)nf);
    assert_true(e && out);
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = FT[3 * f + j], b = FT[3 * f + (j + 1) % 3];
            e[3 * f + j] = (edge){a < b ? a : b, a < b ? b : a, a, b, label[f]};
        }
    qsort(e, 3 * (size_t)nf, sizeof *e, cmp_edge);
    int n = 0;
    for (int i = 0; i < 3 * nf;) {
        int j = i + 1;
        while (j < 3 * nf && !cmp_edge(&e[i], &e[j])) j++;
        if (j == i + 1) out[n++] = e[i];
        i = j;
    }
    free(e);
    *nseg = n;
    return out;
}

/* Brute force over every pair of boundary segments of different charts:
 * all at distance >= P, decided exactly (pairs whose boxes are more than
 * 2P apart along an axis are far beyond any rounding and skipped); *gap
 * gets the smallest distance in floating point. */
static int padding_holds(const double *UV, const edge *s, int n, double P, double *gap)
{
    int ok = 1;
    *gap = INFINITY;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            if (s[i].chart == s[j].chart) continue;
            const double *p1 = UV + 2 * s[i].a, *p2 = UV + 2 * s[i].b, *q1 = UV + 2 * s[j].a,
                         *q2 = UV + 2 * s[j].b;
            double d = chart_segment_distance(p1, p2, q1, q2);
            if (d < *gap) *gap = d;
            if (!(P > 0.0)) continue;
            double far = 2.0 * P;
            if (fmin(q1[0], q2[0]) - fmax(p1[0], p2[0]) > far ||
                fmin(p1[0], p2[0]) - fmax(q1[0], q2[0]) > far ||
                fmin(q1[1], q2[1]) - fmax(p1[1], p2[1]) > far ||
                fmin(p1[1], p2[1]) - fmax(q1[1], q2[1]) > far)
                continue;
            if (!chart_segment_distance_at_least(p1, p2, q1, q2, P)) ok = 0;
        }
    return ok;
}

static double tri_area2(const double *a, const double *b, const double *c)
{
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

static double tri_area3(const double *a, const double *b, const double *c)
{
    double u[3], v[3];
    for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
           z = u[0] * v[1] - u[1] * v[0];
    return 0.5 * sqrt(x * x + y * y + z * z);
}

/* ||J||^2 and ||J^-1||^2 of the map from the 3D triangle to the UV one. */
static void jacobian_norms(const double *p0, const double *p1, const double *p2, const double *u0,
                           const double *u1, const double *u2, double *jj, double *ji)
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) e1[k] = p1[k] - p0[k], e2[k] = p2[k] - p0[k];
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    double x2 = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
    double y2 = 2.0 * tri_area3(p0, p1, p2) / l1;
    /* X = [l1 x2; 0 y2], U = [u1-u0 u2-u0], J = U X^-1 */
    double a = u1[0] - u0[0], b = u2[0] - u0[0], c = u1[1] - u0[1], d = u2[1] - u0[1];
    double Xi[4] = {1.0 / l1, -x2 / (l1 * y2), 0.0, 1.0 / y2};
    double J[4] = {a * Xi[0], a * Xi[1] + b * Xi[3], c * Xi[0], c * Xi[1] + d * Xi[3]};
    double det = J[0] * J[3] - J[1] * J[2];
    *jj = J[0] * J[0] + J[1] * J[1] + J[2] * J[2] + J[3] * J[3];
    *ji = *jj / (det * det);
}

/* ---- checking a layout handed out by the API ----------------------------------- */

typedef struct input {
    const double *V;
    int nv;
    const int *F;
    int nf;
    const int *FT; /* NULL: charts are the components */
    int nuv;
} input;

/* Everything that must hold for the output of a (after set_mesh or run). */
static void check_output(scaf_atlas_t *a, const input *in, double padding)
{
    int nuv = scaf_atlas_uv_count(a), nc = scaf_atlas_chart_count(a), nf = in->nf;
    assert_true(nuv > 0 && nc > 0);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    int *FT = malloc(sizeof(int) * 3 * (size_t)nf), *chart = malloc(sizeof(int) * (size_t)nf);
    int *lin = malloc(sizeof(int) * (size_t)nf), *lout = malloc(sizeof(int) * (size_t)nf);
    int *back = malloc(sizeof(int) * (size_t)nuv);
    assert_true(UV && FT && chart && lin && lout && back);
    scaf_status st = scaf_atlas_get_uv(a, UV, FT, chart);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);

    /* in the unit square, one corner each way touching it */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < nuv; i++)
        for (int k = 0; k < 2; k++) {
            assert_true(UV[2 * i + k] >= 0.0 && UV[2 * i + k] <= 1.0);
            lo[k] = fmin(lo[k], UV[2 * i + k]);
            hi[k] = fmax(hi[k], UV[2 * i + k]);
        }
    assert_true(lo[0] == 0.0 && lo[1] == 0.0);
    assert_true(hi[0] == 1.0 || hi[1] == 1.0);

    /* every face keeps its chart; each output UV belongs to one vertex */
    for (int c = 0; c < 3 * nf; c++) assert_true(FT[c] >= 0 && FT[c] < nuv);
    int kin = in->FT ? labels_by_index(nf, in->FT, in->nuv, lin)
                     : labels_by_index(nf, in->F, in->nv, lin);
    int kout = labels_by_index(nf, FT, nuv, lout);
    assert_int_equal(kin, nc);
    same_partition(nf, lin, kin, lout, kout);
    same_partition(nf, chart, nc, lout, kout);
    for (int i = 0; i < nuv; i++) back[i] = -1;
    for (int c = 0; c < 3 * nf; c++) {
        if (back[FT[c]] < 0) back[FT[c]] = in->F[c];
        assert_int_equal(back[FT[c]], in->F[c]);
    }

    /* bijective, decided exactly */
    bij_report r;
    scaf_error err;
    assert_int_equal(bij_check(nuv, UV, nf, FT, NULL, NULL, &r, &err), SCAF_OK);
    assert_true(r.bijective);
    assert_int_equal(r.flipped, 0);
    assert_int_equal(r.boundary_crossings, 0);

    /* padding, by brute force with the exact distance test */
    int nseg;
    edge *seg = boundary(nf, FT, lout, &nseg);
    double gap;
    assert_true(padding_holds(UV, seg, nseg, padding, &gap));
    if (nc > 1) assert_true(gap >= padding);
    double rgap = scaf_atlas_min_chart_gap(a);
    if (nc == 1) assert_true(isinf(rgap) && isinf(gap));
    else assert_true(fabs(rgap - gap) <= 1e-12 * fmax(gap, 1e-300));
    free(seg);

    /* efficiency = chart UV area / unit square, recomputed */
    double area = 0.0;
    for (int f = 0; f < nf; f++)
        area += fabs(tri_area2(UV + 2 * FT[3 * f], UV + 2 * FT[3 * f + 1], UV + 2 * FT[3 * f + 2]));
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    double eff = area / (side * side), reff = scaf_atlas_packing_efficiency(a);
    assert_true(eff > 0.0 && eff <= 1.0);
    assert_true(fabs(reff - eff) <= 1e-12);

    /* per-chart distortion: recomputed from V and the normalized UV up to
     * the one unknown scale t = s^2 of the normalization, E_c = a_c t +
     * b_c / t; t from the total energy, then every chart must agree */
    double *E = malloc(sizeof(double) * (size_t)nc), *ac = calloc((size_t)nc, sizeof(double));
    double *bc = calloc((size_t)nc, sizeof(double)), *wc = calloc((size_t)nc, sizeof(double));
    assert_true(E && ac && bc && wc);
    assert_int_equal(scaf_atlas_chart_distortion(a, E), SCAF_OK);
    double A = 0.0, B = 0.0, W = 0.0;
    for (int f = 0; f < nf; f++) {
        const int *t = in->F + 3 * f, *u = FT + 3 * f;
        double jj, ji, w = tri_area3(in->V + 3 * t[0], in->V + 3 * t[1], in->V + 3 * t[2]);
        jacobian_norms(in->V + 3 * t[0], in->V + 3 * t[1], in->V + 3 * t[2], UV + 2 * u[0],
                       UV + 2 * u[1], UV + 2 * u[2], &jj, &ji);
        ac[chart[f]] += w * jj;
        bc[chart[f]] += w * ji;
        wc[chart[f]] += w;
        A += w * jj, B += w * ji, W += w;
    }
    A /= W, B /= W;
    double Etot = scaf_atlas_energy(a), disc = fmax(0.0, Etot * Etot - 4.0 * A * B);
    assert_true(isfinite(Etot) && Etot >= 4.0 - 1e-9);
    int agree = 0;
    for (int root = 0; root < 2 && !agree; root++) {
        double t = (Etot + (root ? -1.0 : 1.0) * sqrt(disc)) / (2.0 * A);
        int all = t > 0.0;
        for (int c = 0; c < nc && all; c++) {
            double e = (ac[c] * t + bc[c] / t) / wc[c];
            if (!(fabs(e - E[c]) <= 1e-5 * E[c])) all = 0;
        }
        agree = all;
    }
    assert_true(agree);
    for (int c = 0; c < nc; c++) assert_true(E[c] >= 4.0 - 1e-9);
    free(E);
    free(ac);
    free(bc);
    free(wc);
    free(UV);
    free(FT);
    free(chart);
    free(lin);
    free(lout);
    free(back);
}

/* ---- meshes --------------------------------------------------------------------- */

/* Two curved grid patches (r x r cells, different sizes), far apart in 3D:
 * two components, no UVs. */
static mesh two_patches(int r)
{
    mesh m;
    memset(&m, 0, sizeof m);
    int nvp = (r + 1) * (r + 1), nfp = 2 * r * r;
    m.nv = 2 * nvp;
    m.nf = 2 * nfp;
    m.V = malloc(sizeof(double) * 3 * (size_t)m.nv);
    m.F = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_true(m.V && m.F);
    int f = 0;
    for (int p = 0; p < 2; p++) {
        double s = p ? 1.7 : 1.0;
        for (int j = 0; j <= r; j++)
            for (int i = 0; i <= r; i++) {
                double *v = m.V + 3 * (p * nvp + j * (r + 1) + i), x = s * i / r, y = s * j / r;
                v[0] = x + 10.0 * p;
                v[1] = y;
                v[2] = 0.25 * s * sin(1.1 * x / s + p) * cos(0.9 * y / s);
            }
        for (int j = 0; j < r; j++)
            for (int i = 0; i < r; i++) {
                int a = p * nvp + j * (r + 1) + i, b = a + 1, c = a + r + 1, d = c + 1;
                int *t = m.F + 3 * f;
                t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
                f += 2;
            }
    }
    return m;
}

static scaf_atlas_options_t quick_options(void)
{
    scaf_atlas_options_t o = scaf_atlas_options_default();
    o.pack_cells = 256;
    o.settle_iterations = 5;
    o.compact_iterations = 5;
    return o;
}

/* ---- progress -------------------------------------------------------------------- */

typedef struct watch {
    int calls, settle, compact, order_broken, bad;
    int last_iteration;
    double padding;
    int multi;
    int stop_after; /* cancel after this many calls (0 never) */
    int stop_at_first_compact;
} watch;

static int on_progress(const scaf_atlas_iteration_info_t *it, void *user)
{
    watch *w = user;
    w->calls++;
    if (it->iteration != w->last_iteration + 1) w->bad++;
    w->last_iteration = it->iteration;
    if (it->phase == SCAF_ATLAS_SETTLE) {
        w->settle++;
        if (w->compact) w->order_broken++;
        if (it->phase_iteration != w->settle) w->bad++;
    } else if (it->phase == SCAF_ATLAS_COMPACT) {
        w->compact++;
        if (it->phase_iteration != w->compact) w->bad++;
    } else {
        w->bad++;
    }
    if (!isfinite(it->energy) || !(it->energy >= 4.0 - 1e-9)) w->bad++;
    if (!(it->efficiency > 0.0 && it->efficiency <= 1.0)) w->bad++;
    if (w->multi ? !(it->gap >= w->padding) : !isinf(it->gap)) w->bad++;
    if (!(it->seconds >= 0.0)) w->bad++;
    if (it->loop.step > 0.0 && !(it->loop.total_after < it->loop.total_before)) w->bad++;
    if (w->stop_at_first_compact && it->phase == SCAF_ATLAS_COMPACT) return 1;
    return w->stop_after && w->calls >= w->stop_after;
}

/* ---- tests ----------------------------------------------------------------------- */

static void cubesphere_six_vt_charts(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 4, &m, &err), SCAF_OK);
    scaf_atlas_options_t o = quick_options();
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    assert_string_equal(scaf_atlas_error(a), "");
    scaf_status st = scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);
    input in = {m.V, m.nv, m.F, m.nf, m.FT, m.nuv};
    /* the starting layout is already certified */
    check_output(a, &in, o.padding);
    watch w = {0};
    w.padding = o.padding;
    w.multi = 1;
    st = scaf_atlas_run(a, on_progress, &w);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(w.bad, 0);
    assert_int_equal(w.order_broken, 0);
    assert_true(w.settle >= 1 && w.compact >= 1);
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE), w.settle);
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT), w.compact);
    check_output(a, &in, o.padding);
    /* once per mesh */
    assert_int_equal(scaf_atlas_run(a, NULL, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_atlas_error(a), "already"));
    /* the layout is still there after the refused call */
    check_output(a, &in, o.padding);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

static void two_components_without_uv(void **state)
{
    (void)state;
    mesh m = two_patches(5);
    scaf_atlas_options_t o = quick_options();
    o.padding = 0.02;
    o.repack = 0;
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_atlas_chart_count(a), 2);
    assert_int_equal(scaf_atlas_uv_count(a), m.nv);
    input in = {m.V, m.nv, m.F, m.nf, NULL, 0};
    watch w = {0};
    w.padding = o.padding;
    w.multi = 1;
    assert_int_equal(scaf_atlas_run(a, on_progress, &w), SCAF_OK);
    assert_int_equal(w.bad, 0);
    check_output(a, &in, o.padding);
    /* a new mesh on the same context: one component, run again */
    mesh one = m;
    one.nf = m.nf / 2;
    one.nv = m.nv / 2;
    assert_int_equal(scaf_atlas_set_mesh(a, one.V, one.nv, one.F, one.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_atlas_chart_count(a), 1);
    watch w1 = {0};
    w1.multi = 0;
    assert_int_equal(scaf_atlas_run(a, on_progress, &w1), SCAF_OK);
    assert_int_equal(w1.bad, 0);
    input in1 = {one.V, one.nv, one.F, one.nf, NULL, 0};
    check_output(a, &in1, o.padding);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

static void cancel_from_progress(void **state)
{
    (void)state;
    mesh m = two_patches(4);
    input in = {m.V, m.nv, m.F, m.nf, NULL, 0};
    scaf_atlas_options_t o = quick_options();
    /* in the settle phase */
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    watch w = {0};
    w.padding = o.padding;
    w.multi = 1;
    w.stop_after = 2;
    assert_int_equal(scaf_atlas_run(a, on_progress, &w), SCAF_ERR_CANCELLED);
    assert_int_equal(w.calls, 2);
    assert_true(strlen(scaf_atlas_error(a)) > 0);
    /* the cancelled iteration's step stands and is counted (as in param) */
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE) +
                         scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT),
                     2);
    check_output(a, &in, o.padding); /* the last finished iteration's layout */
    assert_int_equal(scaf_atlas_run(a, on_progress, &w), SCAF_ERR_USAGE);
    scaf_atlas_destroy(a);
    /* in the compact phase */
    a = scaf_atlas_new(&o);
    assert_non_null(a);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    watch w2 = {0};
    w2.padding = o.padding;
    w2.multi = 1;
    w2.stop_at_first_compact = 1;
    assert_int_equal(scaf_atlas_run(a, on_progress, &w2), SCAF_ERR_CANCELLED);
    assert_int_equal(w2.compact, 1);
    assert_int_equal(w2.bad, 0);
    check_output(a, &in, o.padding);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

/* One bad call: its status, and a message. */
#define EXPECT(call, status)                                                                       \
    do {                                                                                           \
        assert_int_equal((call), (status));                                                        \
        assert_true(strlen(scaf_atlas_error(a)) > 0);                                              \
    } while (0)

static void argument_errors(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 2, &m, &err), SCAF_OK);
    double uv[2];
    double E[8];
    int nv = m.nv, nf = m.nf;

    /* a NULL context never crashes */
    assert_int_equal(scaf_atlas_set_mesh(NULL, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_set_options(NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_run(NULL, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_get_uv(NULL, uv, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_chart_distortion(NULL, E), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_uv_count(NULL), 0);
    assert_int_equal(scaf_atlas_chart_count(NULL), 0);
    assert_int_equal(scaf_atlas_iterations(NULL, SCAF_ATLAS_SETTLE), 0);
    assert_true(isnan(scaf_atlas_energy(NULL)));
    assert_true(isnan(scaf_atlas_packing_efficiency(NULL)));
    assert_true(isnan(scaf_atlas_min_chart_gap(NULL)));
    assert_true(strlen(scaf_atlas_error(NULL)) > 0);
    scaf_atlas_destroy(NULL);

    scaf_atlas_options_t o = quick_options();
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    /* before a mesh */
    EXPECT(scaf_atlas_run(a, NULL, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_get_uv(a, uv, NULL, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_chart_distortion(a, E), SCAF_ERR_USAGE);
    assert_true(isnan(scaf_atlas_packing_efficiency(a)));
    assert_true(isnan(scaf_atlas_min_chart_gap(a)));
    assert_int_equal(scaf_atlas_uv_count(a), 0);

    /* bad arrays */
    EXPECT(scaf_atlas_set_mesh(a, NULL, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, NULL, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, 0, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, -5, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, -1, NULL, 0, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, -1, m.FT), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, m.nuv, m.FT), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, m.FT), SCAF_ERR_USAGE);
    /* indices out of range name the face */
    int keep = m.F[7];
    m.F[7] = nv;
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_atlas_error(a), "face 2"));
    m.F[7] = -1;
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    m.F[7] = keep;
    keep = m.FT[4];
    m.FT[4] = m.nuv;
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, m.FT), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_atlas_error(a), "face 1"));
    m.FT[4] = keep;
    /* a non-finite position */
    double kv = m.V[5];
    m.V[5] = NAN;
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, m.FT), SCAF_ERR_MESH);
    m.V[5] = kv;
    /* a closed mesh with the components as charts (SCAF_SEAMS_INPUT) names
     * the chart; by default it is cut open */
    scaf_atlas_options_t oi = o;
    oi.seams = SCAF_SEAMS_INPUT;
    assert_int_equal(scaf_atlas_set_options(a, &oi), SCAF_OK);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_atlas_error(a), "chart"));
    assert_int_equal(scaf_atlas_set_options(a, &o), SCAF_OK);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_atlas_seams_used(a), SCAF_SEAMS_AUTO);
    oi.seams = (scaf_seams)9;
    EXPECT(scaf_atlas_set_options(a, &oi), SCAF_ERR_USAGE);
    /* a degenerate face */
    int t0[3] = {m.F[0], m.F[1], m.F[2]};
    m.F[2] = m.F[1];
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, m.FT), SCAF_ERR_MESH);
    memcpy(m.F, t0, sizeof t0);
    /* failed set_mesh leaves no mesh */
    EXPECT(scaf_atlas_run(a, NULL, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_chart_count(a), 0);

    /* init_input without UVs; a padding the start cannot give */
    scaf_atlas_options_t o2 = o;
    o2.init_input = 1;
    assert_int_equal(scaf_atlas_set_options(a, &o2), SCAF_OK);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, NULL, 0, NULL), SCAF_ERR_USAGE);
    o2 = o;
    o2.padding = 0.45;
    assert_int_equal(scaf_atlas_set_options(a, &o2), SCAF_OK);
    EXPECT(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, m.FT), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_atlas_error(a), "padding"));

    /* with a mesh: NULL outputs */
    assert_int_equal(scaf_atlas_set_options(a, &o), SCAF_OK);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, nv, m.F, nf, m.UV, m.nuv, m.FT), SCAF_OK);
    assert_string_equal(scaf_atlas_error(a), "");
    EXPECT(scaf_atlas_get_uv(a, NULL, NULL, NULL), SCAF_ERR_USAGE);
    EXPECT(scaf_atlas_chart_distortion(a, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_iterations(a, (scaf_atlas_phase)7), 0);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

static void option_validation(void **state)
{
    (void)state;
    scaf_atlas_options_t d = scaf_atlas_options_default();
    assert_true(d.padding >= 0.0 && d.padding < 0.5);
    scaf_atlas_t *a = scaf_atlas_new(NULL);
    assert_non_null(a);
    assert_string_equal(scaf_atlas_error(a), "");
    EXPECT(scaf_atlas_set_options(a, NULL), SCAF_ERR_USAGE);
    assert_int_equal(scaf_atlas_set_options(a, &d), SCAF_OK);

    enum { NBAD = 20 };
    for (int k = 0; k < NBAD; k++) {
        scaf_atlas_options_t o = d;
        switch (k) {
        case 0: o.padding = -0.001; break;
        case 1: o.padding = 0.5; break;
        case 2: o.padding = NAN; break;
        case 3: o.energy = (scaf_energy)42; break;
        case 4: o.init = (scaf_init)-1; break;
        case 5: o.init_input = 2; break;
        case 6: o.settle_iterations = -1; break;
        case 7: o.settle_tolerance = -1e-3; break;
        case 8: o.settle_tolerance = INFINITY; break;
        case 9: o.compact_iterations = -3; break;
        case 10: o.distortion_tolerance = NAN; break;
        case 11: o.repack = -1; break;
        case 12: o.pack_cells = 15; break;
        case 13: o.pack_cells = 8193; break;
        case 14: o.box_scale = 0.99; break;
        case 15: o.lambda_ratio = 0.0; break;
        case 16: o.lambda_ratio = INFINITY; break;
        case 17: o.compact_lambda_ratio = -1.0; break;
        case 18: o.box_scale = NAN; break;
        case 19: o.padding = 1e-61; break; /* below the exact certificate's 2^-200 */
        }
        EXPECT(scaf_atlas_set_options(a, &o), SCAF_ERR_USAGE);
        assert_non_null(strstr(scaf_atlas_error(a), "option"));
        /* no context is made with them, and the check says why */
        assert_null(scaf_atlas_new(&o));
        char why[256];
        assert_int_equal(scaf_atlas_options_check(&o, why, sizeof why), SCAF_ERR_USAGE);
        assert_string_equal(why, scaf_atlas_error(a));
    }

    /* a refused set_options keeps the previous options: a large padding
     * set before stays in force */
    scaf_atlas_options_t o = d;
    o.padding = 0.03;
    o.settle_iterations = 1;
    o.compact_iterations = 0;
    o.repack = 0;
    assert_int_equal(scaf_atlas_set_options(a, &o), SCAF_OK);
    scaf_atlas_options_t bad = o;
    bad.padding = -1.0;
    EXPECT(scaf_atlas_set_options(a, &bad), SCAF_ERR_USAGE);
    mesh m = two_patches(3);
    assert_int_equal(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_atlas_run(a, NULL, NULL), SCAF_OK);
    assert_true(scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE) <= 1);
    assert_int_equal(scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT), 0);
    input in = {m.V, m.nv, m.F, m.nf, NULL, 0};
    check_output(a, &in, 0.03);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

/* init_input: the cubesphere's own 3 x 2 atlas is bijective; with padding
 * 0 it is accepted as the start. */
static void init_from_input_uvs(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 3, &m, &err), SCAF_OK);
    scaf_atlas_options_t o = quick_options();
    o.init_input = 1;
    o.padding = 0.0;
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    scaf_status st = scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(scaf_atlas_run(a, NULL, NULL), SCAF_OK);
    input in = {m.V, m.nv, m.F, m.nf, m.FT, m.nuv};
    check_output(a, &in, 0.0);
    /* folded input UVs are refused */
    double *UV = malloc(sizeof(double) * 2 * (size_t)m.nuv);
    assert_non_null(UV);
    memcpy(UV, m.UV, sizeof(double) * 2 * (size_t)m.nuv);
    for (int i = 0; i < m.nuv; i++) UV[2 * i] = -UV[2 * i]; /* mirrored */
    EXPECT(scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, UV, m.nuv, m.FT), SCAF_ERR_MESH);
    assert_non_null(strstr(scaf_atlas_error(a), "bijective"));
    free(UV);
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

static void spot_data(void **state)
{
    (void)state;
    char path[4096];
    if (!test_data_path("seams/spot.obj", path, sizeof path)) skip();
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    assert_true(mesh_has_uv(&m));
    scaf_atlas_options_t o = scaf_atlas_options_default();
    o.settle_iterations = 8;
    o.compact_iterations = 8;
    scaf_atlas_t *a = scaf_atlas_new(&o);
    assert_non_null(a);
    scaf_status st = scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);
    watch w = {0};
    w.padding = o.padding;
    w.multi = scaf_atlas_chart_count(a) > 1;
    st = scaf_atlas_run(a, on_progress, &w);
    if (st != SCAF_OK) print_error("%s\n", scaf_atlas_error(a));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(w.bad, 0);
    /* charts by the input's seams: pinched vt are split by the atlas, so
     * compare with the partition by shared vt only when none is pinched */
    int nuv = scaf_atlas_uv_count(a);
    input in = {m.V, m.nv, m.F, m.nf, m.FT, m.nuv};
    int *lab = malloc(sizeof(int) * (size_t)m.nf);
    assert_non_null(lab);
    int kin = labels_by_index(m.nf, m.FT, m.nuv, lab);
    free(lab);
    if (kin != scaf_atlas_chart_count(a)) in.FT = NULL, in.nuv = 0; /* fall back below */
    if (in.FT) {
        check_output(a, &in, o.padding);
    } else {
        /* still: bijective and padded, by the same independent checks */
        double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
        int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf), *l = malloc(sizeof(int) * (size_t)m.nf);
        assert_true(UV && FT && l);
        assert_int_equal(scaf_atlas_get_uv(a, UV, FT, NULL), SCAF_OK);
        bij_report r;
        assert_int_equal(bij_check(nuv, UV, m.nf, FT, NULL, NULL, &r, &err), SCAF_OK);
        assert_true(r.bijective);
        labels_by_index(m.nf, FT, nuv, l);
        int nseg;
        edge *seg = boundary(m.nf, FT, l, &nseg);
        double gap;
        assert_true(padding_holds(UV, seg, nseg, o.padding, &gap));
        free(seg);
        free(UV);
        free(FT);
        free(l);
    }
    print_message("spot: %d charts, efficiency %.3f, gap %.5f, %d+%d iterations\n",
                  scaf_atlas_chart_count(a), scaf_atlas_packing_efficiency(a),
                  scaf_atlas_min_chart_gap(a), scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE),
                  scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT));
    scaf_atlas_destroy(a);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cubesphere_six_vt_charts),
        cmocka_unit_test(two_components_without_uv),
        cmocka_unit_test(cancel_from_progress),
        cmocka_unit_test(argument_errors),
        cmocka_unit_test(option_validation),
        cmocka_unit_test(init_from_input_uvs),
        cmocka_unit_test(spot_data),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
