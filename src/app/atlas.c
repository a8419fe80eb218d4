/* app/atlas: joint bijective optimization of all charts, compaction,
 * padding (see atlas.h).
 *
 * Setup goes through the scaf_param API (chart extraction and checks,
 * Tutte on circles on a grid) and then runs its own scaf_loop over the
 * same working mesh, so the atlas can install the loop's hooks: `prepare`
 * (compaction: box moved inward after the rest shapes are taken, close
 * chart pairs stiffened) and `feasible` (the padding constraint).
 */
#include "app/atlas.h"
#include "app/atlas_charts.h"
#include "app/seam_source.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"
#include "app/atlas_align.h"
#include "app/atlas_pack.h"
#include "app/atlas_warm.h"
#include "app/param.h"
#include "app/uv_fans.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "geom/coord_scale.h"
#include "geom/predicates.h"
#include "mesh/uv_verdict.h"
#include "opt/convergence.h"
#include "opt/flip_free_step.h"

/* Margin on the padding so rounding in the final normalization cannot
 * bring a gap below it. */
#define PAD_MARGIN 1.000001

atlas_options atlas_options_default(void)
{
    atlas_options o;
    memset(&o, 0, sizeof o);
    o.base = scaf_options_default();
    /* The atlas keeps the Tutte start: mean-value settles faster but packs
     * 1-4 points less densely on the seams meshes (bench/RESULTS-init.md). */
    o.base.init = SCAF_INIT_TUTTE;
    /* Settling: SLIM, then Newton (auto), run to convergence; compaction
     * keeps SLIM (its hooks were tuned and measured with it). */
    o.base.solver = SCAF_SOLVER_AUTO;
    o.padding = 0.0;
    o.init_input = 0;
    o.init_warm = 0;
    o.settle_iterations = 200;
    o.settle_tolerance = 1e-4;
    o.compact_iterations = 150;
    o.compact_box_scale = 1.05;
    o.compact_fraction = 0.65;
    o.compact_rest_scale = 0.8;
    o.distortion_tolerance = 0.05;
    o.progress_tolerance = 1.5e-3;
    o.progress_window = 4;
    o.repack = 1;
    o.rotate = 1;
    o.pack_cells = 1024;
    o.pack_gap_factor = 2.0;
    o.pack_picks = 2;
    o.compact_lambda_ratio = 1.0;
    o.max_distortion = -1.0;
    o.split_charts = -1;
    return o;
}

void atlas_free(atlas *a)
{
    if (!a) return;
    free(a->Fw);
    free(a->chart);
    free(a->wchart);
    free(a->seg);
    scaf_loop_free(&a->loop);
    memset(a, 0, sizeof *a);
}

/* ---- geometry of the layout ------------------------------------------------- */

static void bbox(const double *uv, int n, double lo[2], double hi[2])
{
    lo[0] = lo[1] = INFINITY;
    hi[0] = hi[1] = -INFINITY;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            double x = uv[2 * (size_t)i + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
}

static double side_of(const double *uv, int n)
{
    double lo[2], hi[2];
    bbox(uv, n, lo, hi);
    return fmax(hi[0] - lo[0], hi[1] - lo[1]);
}

double atlas_side(const atlas *a) { return side_of(a->loop.uv, a->nw); }

double atlas_energy(const atlas *a) { return scaf_loop_energy(&a->loop); }

scaf_status atlas_gap(const atlas *a, double *gap, scaf_error *err)
{
    double g;
    scaf_status st = chart_gap_min_segments(a->loop.uv, a->seg, a->nseg, 0.0, &g, NULL, err);
    double s = atlas_side(a);
    *gap = s > 0.0 ? g / s : g;
    return st;
}

void atlas_normalized_uv(const atlas *a, double *UV)
{
    double lo[2], hi[2];
    bbox(a->loop.uv, a->nw, lo, hi);
    double s = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(s > 0.0)) s = 1.0;
    for (int i = 0; i < a->nw; i++)
        for (int k = 0; k < 2; k++)
            UV[2 * (size_t)i + k] = (a->loop.uv[2 * (size_t)i + k] - lo[k]) / s;
}

void atlas_chart_energy(const atlas *a, double *E)
{
    double *fe = malloc(sizeof(double) * (size_t)(a->nf ? a->nf : 1));
    double *w = calloc((size_t)(a->ncharts ? a->ncharts : 1), sizeof(double));
    for (int c = 0; c < a->ncharts; c++) E[c] = 0.0;
    if (!fe || !w) {
        for (int c = 0; c < a->ncharts; c++) E[c] = NAN;
        free(fe);
        free(w);
        return;
    }
    scaf_loop_face_energy(&a->loop, fe);
    for (int s = 0; s < a->nf; s++) {
        int f = a->loop.chart_face[s];
        double A = a->loop.chart.weight[s];
        E[a->chart[f]] += A * fe[f];
        w[a->chart[f]] += A;
    }
    for (int c = 0; c < a->ncharts; c++) E[c] = w[c] > 0.0 ? E[c] / w[c] : NAN;
    free(fe);
    free(w);
}

/* ---- hooks -------------------------------------------------------------------- */

double atlas_padding_need(const atlas *a, const double *X)
{
    return a->opt.padding * side_of(X, a->nw) * PAD_MARGIN;
}

/* Padding: every pair of charts at least padding * side apart at X. */
static int feasible_gap(void *user, const scaf_loop *L, const double *X, int nall)
{
    (void)nall;
    (void)L;
    atlas *a = user;
    if (!(a->opt.padding > 0.0)) return 1;
    double need = atlas_padding_need(a, X), g;
    scaf_error e;
    err_clear(&e);
    if (chart_gap_min_segments(X, a->seg, a->nseg, need, &g, NULL, &e) != SCAF_OK) return 0;
    if (!(g > need)) a->padding_rejects++;
    return g > need;
}

/* The padding failed at X: freeze (zero the direction of) every chart of
 * a pair closer than the padding, so the others can still move. */
static int freeze_close(void *user, const scaf_loop *L, const double *X, double *dir, int nall)
{
    (void)nall;
    atlas *a = user;
    double need = atlas_padding_need(a, X);
    unsigned char *mark = calloc((size_t)a->ncharts, 1);
    if (!mark) return 0;
    long np = 0;
    scaf_error e;
    err_clear(&e);
    int changed = 0;
    if (chart_gap_mark_close(X, a->seg, a->nseg, need, mark, &np, &e) == SCAF_OK && np > 0) {
        for (int v = 0; v < L->nv; v++)
            if (mark[a->wchart[v]] &&
                (dir[2 * (size_t)v] != 0.0 || dir[2 * (size_t)v + 1] != 0.0)) {
                dir[2 * (size_t)v] = dir[2 * (size_t)v + 1] = 0.0;
                changed = 1;
            }
        /* scaffold-only corners of triangles touching a frozen chart stay
         * too, so the thin triangles there cannot collapse */
        const scaffold_view *sc = scaf_loop_scaffold_view(L);
        for (int s = 0; s < sc->n; s++) {
            const int *t = sc->simplices + 3 * s;
            int touch = 0;
            for (int i = 0; i < 3; i++)
                if (t[i] < L->nv && mark[a->wchart[t[i]]]) touch = 1;
            if (touch)
                for (int i = 0; i < 3; i++)
                    if (t[i] >= L->nv) dir[2 * (size_t)t[i]] = dir[2 * (size_t)t[i] + 1] = 0.0;
        }
    }
    free(mark);
    return changed;
}

/* Every scaffold triangle strictly positive at X, decided exactly. */
static int scaffold_positive(const scaf_loop *L, const double *X)
{
    const scaffold_view *sc = scaf_loop_scaffold_view(L);
    for (int s = 0; s < sc->n; s++) {
        const int *t = sc->simplices + 3 * s;
        if (!(orient2d(X + 2 * (size_t)t[0], X + 2 * (size_t)t[1], X + 2 * (size_t)t[2]) > 0.0))
            return 0;
    }
    return 1;
}

/* Contraction of the short axis, (short / long)^ASPECT_POWER of the long
 * one: 32 packs best of 0, 8, 32, 128, 1000 on spot, blub, human_neutral
 * and the cube sphere (bench/RESULTS-atlas.md). */
enum { ASPECT_POWER = 32 };
static scaf_status compact_prepare(void *user, scaf_loop *L, double *X, int nall, scaf_error *err)
{
    atlas *a = user;
    const scaffold_view *sc = scaf_loop_scaffold_view(L);
    opt_simplices *rest = scaf_loop_scaffold_rest(L);
    double *proxy_weight = scaf_loop_scaffold_proxy_weights(L);
    /* ---- stiffen scaffold triangles bridging two close charts ---------- */
    double side = side_of(X, L->nv);
    double near = 3.0 * a->opt.padding * side;
    if (near <= 0.0) near = 0.01 * side;
    a->stiffened = 0;
    double sigma = a->opt.compact_rest_scale;
    for (int s = 0; s < sc->n; s++) {
        const int *t = sc->simplices + 3 * s;
        int bridge = 0, boxed = 0;
        double dmin = INFINITY;
        for (int i = 0; i < 3; i++)
            if (t[i] >= L->nv && sc->extra_fixed[t[i] - L->nv]) boxed = 1;
        for (int i = 0; i < 3 && !bridge; i++)
            for (int j = i + 1; j < 3 && !bridge; j++) {
                int u = t[i], v = t[j];
                if (u >= L->nv || v >= L->nv || a->wchart[u] == a->wchart[v]) continue;
                const double *p = X + 2 * (size_t)u, *q = X + 2 * (size_t)v;
                double d = hypot(p[0] - q[0], p[1] - q[1]);
                if (d < dmin) dmin = d;
                if (d < near) bridge = 1;
            }
        if (bridge) {
            /* a close pair: stiff, and pushed apart when nearly at the padding */
            rest->weight[s] *= 100.0;
            proxy_weight[s] *= 100.0;
            a->stiffened++;
            double pad = a->opt.padding * side;
            if (dmin < 2.0 * pad && rest->vol[s] > sc->eps) {
                double grow = fmin(2.0 * pad / dmin, 2.0);
                for (int i = 0; i < 6; i++) rest->grad[6 * (size_t)s + i] /= grow;
                rest->vol[s] *= grow * grow;
            }
        } else if (!boxed && sigma < 1.0 && rest->vol[s] > sc->eps) {
            /* rest shape shrunk by sigma: the free space wants to contract */
            for (int i = 0; i < 6; i++) rest->grad[6 * (size_t)s + i] /= sigma;
            rest->vol[s] *= sigma * sigma;
        }
    }
    /* ---- move the box inward ------------------------------------------- */
    double *D = calloc(2 * (size_t)nall, sizeof *D);
    double *X0 = malloc(sizeof(double) * 2 * (size_t)nall);
    if (!D || !X0) {
        free(D);
        free(X0);
        return err_nomem(err, "compaction");
    }
    memcpy(X0, X, sizeof(double) * 2 * (size_t)nall);
    double cx = 0.5 * (sc->box_lo[0] + sc->box_hi[0]), cy = 0.5 * (sc->box_lo[1] + sc->box_hi[1]);
    /* Only the longest side of the layout counts (it is scaled into the
     * unit square): contract the long axis, the short one only as the
     * layout nears a square, so the charts spread along the short axis. */
    double lo[2], hi[2];
    bbox(X, L->nv, lo, hi);
    double w = hi[0] - lo[0], h = hi[1] - lo[1], ax = 1.0, ay = 1.0;
    if (w > 0.0 && h > 0.0) {
        if (w > h) ay = pow(h / w, ASPECT_POWER);
        else ax = pow(w / h, ASPECT_POWER);
    }
    for (int i = 0; i < sc->nextra; i++)
        if (sc->extra_fixed[i]) {
            size_t v = (size_t)(L->nv + i);
            D[2 * v] = ax * (cx - X[2 * v]);
            D[2 * v + 1] = ay * (cy - X[2 * v + 1]);
        }
    double t = opt_max_step(rest, X, D);
    if (t > 1.0) t = 1.0;
    t *= a->opt.compact_fraction;
    for (int k = 0; k < 60 && t > 0.0; k++) {
        for (int i = 0; i < sc->nextra; i++)
            if (sc->extra_fixed[i]) {
                size_t v = (size_t)(L->nv + i);
                X[2 * v] = X0[2 * v] + t * D[2 * v];
                X[2 * v + 1] = X0[2 * v + 1] + t * D[2 * v + 1];
            }
        if (scaffold_positive(L, X)) break;
        t *= 0.5;
        if (k == 59) t = 0.0;
    }
    if (!(t > 0.0)) memcpy(X, X0, sizeof(double) * 2 * (size_t)nall);
    free(D);
    free(X0);
    return SCAF_OK;
}

/* ---- setup -------------------------------------------------------------------- */

/* x[i] *= 2^s for all i; the first i where that rounds (leaves the normal
 * range), or -1 when every product is exact. */
static int scale_exactly(double *x, size_t n, int s)
{
    int bad = -1;
    for (size_t i = 0; i < n; i++) {
        double y = ldexp(x[i], s);
        if (bad < 0 && ldexp(y, -s) != x[i]) bad = (int)(i > INT_MAX ? INT_MAX : i);
        x[i] = y;
    }
    return bad;
}

static int finite_at_least(double x, double lo) { return isfinite(x) && x >= lo; }

scaf_status atlas_options_check(const atlas_options *o, char *msg, size_t size)
{
    if (param_options_check(&o->base, msg, size) != SCAF_OK) return SCAF_ERR_USAGE;
    const char *bad = NULL;
    if (o->init_input != 0 && o->init_input != 1) bad = "init_input must be 0 or 1";
    else if (o->init_warm != 0 && o->init_warm != 1) bad = "init_warm must be 0 or 1";
    else if (o->settle_iterations < 0) bad = "settle_iterations must be >= 0";
    else if (!finite_at_least(o->settle_tolerance, 0.0))
        bad = "settle_tolerance must be a finite number >= 0";
    else if (o->compact_iterations < 0) bad = "compact_iterations must be >= 0";
    else if (!finite_at_least(o->distortion_tolerance, 0.0))
        bad = "distortion_tolerance must be a finite number >= 0";
    else if (o->repack != 0 && o->repack != 1) bad = "repack must be 0 or 1";
    else if (o->rotate != 0 && o->rotate != 1) bad = "rotate must be 0 or 1";
    else if (o->pack_cells < 16 || o->pack_cells > 8192) bad = "pack_cells must be in [16, 8192]";
    else if (!(o->compact_lambda_ratio > 0.0) || !isfinite(o->compact_lambda_ratio))
        bad = "compact_lambda_ratio must be a finite number > 0";
    else if (!(o->pack_gap_factor >= 1.0) || !isfinite(o->pack_gap_factor))
        bad = "pack_gap_factor must be a finite number >= 1";
    else if (!(o->compact_rest_scale > 0.0) || !(o->compact_rest_scale <= 1.0))
        bad = "compact_rest_scale must be in (0, 1]";
    else if (!(o->compact_box_scale >= 1.0) || !(o->compact_box_scale <= 1e6))
        bad = "compact_box_scale must be in [1, 1e6]";
    else if (!(o->compact_fraction > 0.0) || !(o->compact_fraction < 1.0))
        bad = "compact_fraction must be in (0, 1)";
    else if (o->pack_picks < 1 || o->pack_picks > 16) bad = "pack_picks must be in [1, 16]";
    else if (!finite_at_least(o->progress_tolerance, 0.0))
        bad = "progress_tolerance must be a finite number >= 0";
    else if (o->progress_window < 1 || o->progress_window > 64)
        bad = "progress_window must be in [1, 64]";
    else if (!(o->max_distortion < 0.0 || o->max_distortion == 0.0 ||
               (o->max_distortion > 4.0 && isfinite(o->max_distortion))))
        bad = "max_distortion must be > 4 (4 is an isometry), 0 (never split) or < 0 (default)";
    else if (o->split_charts < -1 || o->split_charts > 1)
        bad = "split_charts must be -1 (default), 0 or 1";
    /* the output's padding is certified exactly (geom/chart_gap), which
     * takes paddings of at least 2^-200 */
    else if (!(o->padding == 0.0 || (o->padding >= CHART_GAP_EXACT_MIN && o->padding < 0.5))) {
        if (msg && size)
            snprintf(msg, size, "padding %g must be 0 or in [2^-200, 0.5) ([%.17g, 0.5))",
                     o->padding, CHART_GAP_EXACT_MIN);
        return SCAF_ERR_USAGE;
    }
    if (!bad) return SCAF_OK;
    if (msg && size) snprintf(msg, size, "%s", bad);
    return SCAF_ERR_USAGE;
}

/* Every chart from its shape in UV2 (by FT2's corners) where valid, the
 * others from their Tutte shape in uv0, re-placed (app/atlas_warm); uv0
 * takes the result only when the exact checker proves it bijective. */
static scaf_status warm_start(atlas *a, const double *UV2, const int *FT2, double *uv0,
                              scaf_error *err)
{
    size_t n2 = 2 * (size_t)a->nw;
    double *shape = malloc(sizeof(double) * (n2 ? n2 : 1));
    double *out = malloc(sizeof(double) * (n2 ? n2 : 1));
    scaf_status st = SCAF_OK;
    if (!shape || !out) {
        st = err_nomem(err, "atlas");
        goto out;
    }
    for (int f = 0; f < a->nf; f++)
        for (int j = 0; j < 3; j++)
            memcpy(shape + 2 * (size_t)a->Fw[3 * f + j], UV2 + 2 * (size_t)FT2[3 * f + j],
                   sizeof(double) * 2);
    int warm = 0;
    st = atlas_warm_layout(a->nw, a->nf, a->Fw, a->wchart, a->ncharts, shape, uv0,
                           a->opt.padding * PAD_MARGIN, out, &warm, err);
    if (st != SCAF_OK || warm == 0) goto out;
    bij_report r;
    st = bij_check(a->nw, out, a->nf, a->Fw, a->chart, NULL, &r, err);
    if (st == SCAF_OK && r.bijective) {
        memcpy(uv0, out, sizeof(double) * n2);
        a->warm_charts = warm;
    }
out:
    free(shape);
    free(out);
    return st;
}

scaf_status atlas_init(atlas *a, const mesh *m, const atlas_options *o, scaf_error *err)
{
    memset(a, 0, sizeof *a);
    a->opt = o ? *o : atlas_options_default();
    scaf_status st = SCAF_OK;
    char msg[256];
    if (atlas_options_check(&a->opt, msg, sizeof msg) != SCAF_OK)
        return err_set(err, SCAF_ERR_USAGE, "%s", msg);
    if (a->opt.init_input && !mesh_has_uv(m))
        return err_set(err, SCAF_ERR_USAGE, "--init input: the mesh has no UVs (vt) to start from");
    /* the seams (app/seam_source): the input's, or automatic charts cut
     * into disks; the rest runs on them as if the input had them */
    seam_plan plan;
    st = seam_plan_make(m, a->opt.base.seams, 1, &plan, err);
    if (st != SCAF_OK) return st;
    a->seams_used = plan.used;
    a->seam_segments = plan.segments;
    snprintf(a->seams_why, sizeof a->seams_why, "%s", plan.why);
    mesh planned = *m;
    if (plan.changed) {
        planned.nuv = plan.nuv;
        planned.UV = plan.UV;
        planned.FT = plan.FT;
    }
    m = &planned;
    /* automatic charts split where they distort or pack badly (app/atlas_charts) */
    st = atlas_charts_apply(&planned, &a->opt, &plan, err);
    if (st != SCAF_OK) {
        seam_plan_free(&plan);
        return st;
    }
    if (a->opt.init_input && plan.used != SCAF_SEAMS_INPUT) {
        seam_plan_free(&plan);
        return err_set(err, SCAF_ERR_MESH,
                       "--init input: the input's seams do not cut the mesh into disks (%s); "
                       "start from the default instead",
                       a->seams_why);
    }
    if (a->opt.init_input) {
        /* the verdict of `scaf check` on the same data, with its counts */
        bij_report r;
        st = mesh_uv_verdict(m, &r, err);
        if (st != SCAF_OK) {
            seam_plan_free(&plan);
            return st;
        }
        if (!r.bijective) {
            char defects[320];
            bij_report_defects(&r, defects, sizeof defects);
            seam_plan_free(&plan);
            return err_set(err, SCAF_ERR_MESH,
                           "--init input: the input UVs are not bijective (as scaf check reports: "
                           "%s); "
                           "use the default start (Tutte on circles)",
                           defects);
        }
    }
    int *FT2 = NULL, *map = NULL, nuv2 = 0;
    double *UV2 = NULL, *W3 = NULL, *uv0 = NULL;
    scaf_param_t *p = NULL;
    if (mesh_has_uv(m)) {
        FT2 = malloc(sizeof(int) * 3 * (size_t)m->nf);
        if (!FT2) {
            st = err_nomem(err, "atlas");
            goto done;
        }
        st = uv_split_fans(m->nf, m->FT, m->nuv, FT2, &nuv2, &map, err);
        if (st != SCAF_OK) goto done;
        a->split_uvs = nuv2 - m->nuv;
        UV2 = malloc(sizeof(double) * 2 * (size_t)nuv2);
        if (!UV2) {
            st = err_nomem(err, "atlas");
            goto done;
        }
        for (int i = 0; i < nuv2; i++)
            memcpy(UV2 + 2 * (size_t)i, m->UV + 2 * (size_t)map[i], sizeof(double) * 2);
    }
    scaf_options_t po = a->opt.base;
    po.seams = SCAF_SEAMS_INPUT; /* decided above */
    p = scaf_param_new(&po);
    if (!p) {
        st = err_nomem(err, "atlas");
        goto done;
    }
    st = UV2 ? scaf_param_set_mesh(p, m->V, m->nv, m->F, m->nf, UV2, nuv2, FT2)
             : scaf_param_set_mesh(p, m->V, m->nv, m->F, m->nf, NULL, 0, NULL);
    if (st != SCAF_OK) {
        err_set(err, st, "%s", scaf_param_error(p));
        goto done;
    }
    a->nv = m->nv;
    a->nf = m->nf;
    a->ncharts = scaf_param_chart_count(p);
    a->nw = scaf_param_uv_count(p);
    a->Fw = malloc(sizeof(int) * 3 * (size_t)a->nf);
    a->chart = malloc(sizeof(int) * (size_t)a->nf);
    uv0 = malloc(sizeof(double) * 2 * (size_t)a->nw);
    W3 = malloc(sizeof(double) * 3 * (size_t)a->nw);
    if (!a->Fw || !a->chart || !uv0 || !W3) {
        st = err_nomem(err, "atlas");
        goto done;
    }
    /* the start and the positions in param's units (geom/coord_scale):
     * the atlas is normalized into the unit square, so these units never
     * show, and the result does not depend on the input's units */
    const scaf_loop *L = param_loop(p);
    memcpy(uv0, L->uv, sizeof(double) * 2 * (size_t)a->nw);
    memcpy(a->Fw, L->F, sizeof(int) * 3 * (size_t)a->nf);
    int e = coord_scale_exponent(m->V, 3, 3 * (size_t)m->nf, m->F);
    for (int f = 0; f < a->nf; f++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                W3[3 * (size_t)a->Fw[3 * f + j] + k] =
                    ldexp(m->V[3 * (size_t)m->F[3 * f + j] + k], -e);
    int nc = 0;
    st = chart_gap_labels(a->nw, a->nf, a->Fw, a->chart, &nc, err);
    if (st != SCAF_OK) goto done;
    st = chart_gap_segments(a->nf, a->Fw, a->chart, &a->seg, &a->nseg, err);
    if (st == SCAF_OK) st = interrupt_check(NULL, "setting up the atlas", err);
    if (st != SCAF_OK) goto done;
    a->wchart = malloc(sizeof(int) * (size_t)a->nw);
    if (!a->wchart) {
        st = err_nomem(err, "atlas");
        goto done;
    }
    for (int f = 0; f < a->nf; f++)
        for (int j = 0; j < 3; j++) a->wchart[a->Fw[3 * f + j]] = a->chart[f];

    /* ---- start from the input UVs: only when proved bijective ------------ */
    if (a->opt.init_input) {
        for (int f = 0; f < a->nf; f++)
            for (int j = 0; j < 3; j++)
                memcpy(uv0 + 2 * (size_t)a->Fw[3 * f + j], UV2 + 2 * (size_t)FT2[3 * f + j],
                       sizeof(double) * 2);
        /* The input is bijective (checked above); split pinch points are
         * distinct indices at one point now, which the scaffold cannot
         * separate: say so rather than quote other counts. */
        bij_report r;
        st = bij_check(a->nw, uv0, a->nf, a->Fw, a->chart, NULL, &r, err);
        if (st != SCAF_OK) goto done;
        if (!r.bijective) {
            char defects[320];
            bij_report_defects(&r, defects, sizeof defects);
            st = err_set(err, SCAF_ERR_MESH,
                         "--init input: the input UVs are bijective, but with its %d pinch "
                         "point(s) (a vt where a "
                         "chart touches itself) split into one UV per fan they are not (%s): the "
                         "optimizer cannot "
                         "start there; use the default start (Tutte on circles)",
                         a->split_uvs, defects);
            goto done;
        }
        /* Bring the input to the surface's scale (distortion is measured
         * against 3D lengths) with powers of two: first to its own unit
         * scale (largest coordinate in [1, 2), geom/coord_scale), so its
         * area neither overflows nor underflows whatever its units, then
         * to the surface's area. Exact in floating point (checked), so
         * every orientation and non-overlap the checker proved still
         * holds. */
        int eu = -coord_scale_exponent(uv0, 2, 3 * (size_t)a->nf, a->Fw),
            bad = scale_exactly(uv0, 2 * (size_t)a->nw, eu);
        double a3 = 0.0, a2 = 0.0;
        for (int f = 0; f < a->nf && bad < 0; f++) {
            const int *t = a->Fw + 3 * f;
            const double *p0 = W3 + 3 * (size_t)t[0], *p1 = W3 + 3 * (size_t)t[1],
                         *p2 = W3 + 3 * (size_t)t[2];
            double u[3], w[3];
            for (int k = 0; k < 3; k++) {
                u[k] = p1[k] - p0[k];
                w[k] = p2[k] - p0[k];
            }
            a3 += 0.5 *
                sqrt(pow(u[1] * w[2] - u[2] * w[1], 2) + pow(u[2] * w[0] - u[0] * w[2], 2) +
                     pow(u[0] * w[1] - u[1] * w[0], 2));
            const double *q0 = uv0 + 2 * (size_t)t[0], *q1 = uv0 + 2 * (size_t)t[1],
                         *q2 = uv0 + 2 * (size_t)t[2];
            a2 += 0.5 * ((q1[0] - q0[0]) * (q2[1] - q0[1]) - (q1[1] - q0[1]) * (q2[0] - q0[0]));
        }
        if (bad < 0 && a3 > 0.0 && a2 > 0.0) {
            int es = (int)lround(0.5 * log2(a3 / a2));
            if (es > 200) es = 200;
            if (es < -200) es = -200;
            bad = scale_exactly(uv0, 2 * (size_t)a->nw, es);
        }
        if (bad >= 0) {
            st = err_set(err, SCAF_ERR_MESH,
                         "--init input: the input UVs span too many orders of magnitude to be "
                         "brought to the "
                         "surface's scale exactly (UV coordinate %d would round); use the default "
                         "start",
                         bad);
            goto done;
        }
    }

    /* ---- start from a layout settled before: only when proved bijective -- */
    if (!a->opt.init_input && (a->opt.init_warm || plan.uv_start) && UV2) {
        st = warm_start(a, UV2, FT2, uv0, err);
        if (st != SCAF_OK) goto done;
    }

    /* ---- the padding must hold at the start ------------------------------ */
    if (a->opt.padding > 0.0) {
        double g, s = side_of(uv0, a->nw);
        st = chart_gap_min_segments(uv0, a->seg, a->nseg, 0.0, &g, NULL, err);
        if (st != SCAF_OK) goto done;
        if (!(g > a->opt.padding * s * PAD_MARGIN)) {
            st = err_set(err, SCAF_ERR_USAGE,
                         "padding %g is not met by the starting layout of %d charts (smallest gap "
                         "%g of the "
                         "square): use a smaller padding%s",
                         a->opt.padding, a->ncharts, g / s,
                         a->opt.init_input ? " or the default start" : "");
            goto done;
        }
    }
    scaf_loop_options lo = param_loop_options(&a->opt.base);
    st = interrupt_check(NULL, "setting up the atlas", err);
    if (st == SCAF_OK) st = scaf_loop_init(&a->loop, a->nw, W3, a->nf, a->Fw, uv0, &lo, err);
    if (st != SCAF_OK) goto done;
    if ((st = interrupt_check(NULL, "setting up the atlas's scaffold", err)) != SCAF_OK) goto done;
    a->loop.hooks.user = a;
    a->loop.hooks.feasible = feasible_gap;
    a->loop.hooks.restrict_dir = freeze_close;

done:
    seam_plan_free(&plan);
    scaf_param_destroy(p);
    free(FT2);
    free(map);
    free(UV2);
    free(W3);
    free(uv0);
    if (st != SCAF_OK) atlas_free(a);
    return st;
}

/* ---- the two phases ------------------------------------------------------------ */

/* Re-place the charts with the raster packer; keep the result only when
 * it is proved valid and packs better. */
static scaf_status repack_from(atlas *a, const double *base, scaf_error *err)
{
    size_t n2 = 2 * (size_t)a->nw;
    double *out = malloc(sizeof(double) * n2);
    if (!out) return err_nomem(err, "repacking");
    double eff0 = chart_packing_efficiency(a->nw, a->loop.uv, a->nf, a->Fw);
    double area = eff0 * pow(atlas_side(a), 2.0);
    double want = a->opt.padding * sqrt(area / 0.8) * a->opt.pack_gap_factor;
    scaf_status st = SCAF_OK;
    for (int attempt = 0; attempt < 6; attempt++) {
        scaf_error e2;
        err_clear(&e2);
        /* rank the strategies on a grid half as fine (abandoning those
         * that cannot be among the best pack_picks), place the best
         * pack_picks at full resolution, keep the smallest square */
        int ns = atlas_pack_strategies(a->ncharts), chosen = 0;
        long *side_c = malloc(sizeof(long) * (size_t)ns);
        double *trial = malloc(sizeof(double) * n2);
        if (!side_c || !trial) {
            free(side_c);
            free(trial);
            st = err_nomem(err, "repacking");
            break;
        }
        int npick = a->opt.pack_picks;
        st = atlas_pack(a->nw, base, a->nf, a->Fw, a->chart, a->wchart, a->ncharts,
                        a->opt.pack_cells / 2, want, -1, npick, &chosen, side_c, trial, &e2);
        double best_side = INFINITY;
        for (int pick = 0; pick < npick && st == SCAF_OK; pick++) {
            int k = -1;
            for (int i = 0; i < ns; i++)
                if (side_c[i] > 0 && (k < 0 || side_c[i] < side_c[k])) k = i;
            if (k < 0) break;
            side_c[k] = -1;
            st = atlas_pack(a->nw, base, a->nf, a->Fw, a->chart, a->wchart, a->ncharts,
                            a->opt.pack_cells, want, k, 0, NULL, NULL, trial, &e2);
            double sd = st == SCAF_OK ? side_of(trial, a->nw) : INFINITY;
            if (sd < best_side) {
                best_side = sd;
                memcpy(out, trial, sizeof(double) * n2);
            }
        }
        free(side_c);
        free(trial);
        if (st == SCAF_ERR_NOMEM) {
            *err = e2;
            break;
        }
        st = SCAF_OK;
        if (e2.code != SCAF_OK) break; /* no layout: keep the current one */
        int ok = 1;
        for (int f = 0; f < a->nf && ok; f++) {
            const int *t = a->Fw + 3 * f;
            if (!(orient2d(out + 2 * (size_t)t[0], out + 2 * (size_t)t[1], out + 2 * (size_t)t[2]) >
                  0.0))
                ok = 0;
        }
        if (!ok) break;
        double g, side = side_of(out, a->nw);
        st = chart_gap_min_segments(out, a->seg, a->nseg, 0.0, &g, NULL, err);
        if (st != SCAF_OK) break;
        if (!(g > a->opt.padding * side * PAD_MARGIN) || !(g > 0.0)) {
            /* the square came out larger than estimated: wider gap, again */
            want = fmax(1.03 * want, 1.005 * a->opt.padding * side);
            continue;
        }
        bij_report r;
        st = bij_check(a->nw, out, a->nf, a->Fw, a->chart, NULL, &r, err);
        if (st != SCAF_OK || !r.bijective) break;
        double eff1 = chart_packing_efficiency(a->nw, out, a->nf, a->Fw);
        if (eff1 > eff0) {
            memcpy(a->loop.uv, out, sizeof(double) * n2);
            a->eff_packed = eff1;
        }
        break;
    }
    free(out);
    return st;
}

/* The raster packer from the settled orientations and, with rotate, from
 * every chart turned to its least-area bounding rectangle (the packer
 * tries multiples of 45 or 90 degrees on top of either); the best layout
 * that passes the checks is kept. */
static scaf_status repack(atlas *a, scaf_error *err)
{
    a->eff_packed = NAN;
    double *aligned = NULL;
    if (a->opt.rotate) {
        aligned = malloc(sizeof(double) * 2 * (size_t)a->nw);
        if (!aligned) return err_nomem(err, "repacking");
        scaf_status st = atlas_align_charts(a->nw, a->loop.uv, a->nf, a->Fw, a->chart, a->wchart,
                                            a->ncharts, aligned, NULL, err);
        if (st != SCAF_OK) {
            free(aligned);
            return st;
        }
    }
    scaf_status st = repack_from(a, a->loop.uv, err);
    if (st == SCAF_OK && aligned) st = repack_from(a, aligned, err);
    free(aligned);
    return st;
}

/* Turn the whole layout to its smallest bounding square (app/atlas_align),
 * kept only when every chart gap still holds the padding and the exact
 * checker proves the turned layout bijective. */
static scaf_status turn_layout(atlas *a, scaf_error *err)
{
    size_t n2 = 2 * (size_t)a->nw;
    double *out = malloc(sizeof(double) * n2);
    if (!out) return err_nomem(err, "turning the layout");
    int turned = 0;
    scaf_status st = atlas_turn_to_square(a->nw, a->loop.uv, a->nf, a->Fw, out, &turned, err);
    if (st == SCAF_OK && turned) {
        double g;
        st = chart_gap_min_segments(out, a->seg, a->nseg, 0.0, &g, NULL, err);
        if (st == SCAF_OK && g > a->opt.padding * side_of(out, a->nw) * PAD_MARGIN && g > 0.0) {
            bij_report r;
            st = bij_check(a->nw, out, a->nf, a->Fw, a->chart, NULL, &r, err);
            if (st == SCAF_OK && r.bijective) {
                memcpy(a->loop.uv, out, sizeof(double) * n2);
                a->turns++;
            }
        }
    }
    free(out);
    return st;
}

/* One iteration of phase ph; conv (may be NULL) judges the mesh energy's
 * distance to its minimum: it->info.criterion. */
static scaf_status one_iteration(atlas *a, atlas_phase ph, opt_convergence *conv,
                                 atlas_progress_fn progress, void *user, atlas_iteration *it,
                                 scaf_error *err)
{
    memset(it, 0, sizeof *it);
    double e_before = conv ? scaf_loop_mesh_energy(&a->loop) : 0.0;
    scaf_status st = scaf_loop_step(&a->loop, &it->info, err);
    if (st != SCAF_OK) return st;
    if (conv)
        it->info.criterion = opt_convergence_update(conv, e_before, scaf_loop_mesh_energy(&a->loop),
                                                    it->info.decrement);
    /* counted before the callback: a cancel keeps this step */
    if (ph == ATLAS_COMPACT) a->compact_done++;
    else a->settle_done++;
    it->phase = ph;
    it->side = atlas_side(a);
    st = atlas_gap(a, &it->gap, err);
    if (st != SCAF_OK) return st;
    it->efficiency = chart_packing_efficiency(a->nw, a->loop.uv, a->nf, a->Fw);
    if (progress && progress(a, it, user))
        return err_set(err, SCAF_ERR_CANCELLED,
                       "stopped by the progress callback after iteration %d", it->info.iteration);
    return SCAF_OK;
}

void atlas_compact_begin(atlas *a)
{
    a->loop.opt.scaffold.box_scale = a->opt.compact_box_scale;
    a->loop.opt.lambda_ratio = a->opt.compact_lambda_ratio;
    a->loop.opt.scaffold.box_square = 0;
    a->loop.opt.solver = SCAF_SOLVER_SLIM; /* the hooks were tuned with SLIM */
    a->loop.hooks.prepare = compact_prepare;
}

void atlas_compact_end(atlas *a)
{
    a->loop.hooks.prepare = NULL;
    a->loop.opt = param_loop_options(&a->opt.base);
}

scaf_status atlas_compact_rule_begin(const atlas *a, atlas_compact_rule *r, double e_start,
                                     scaf_error *err)
{
    size_t n2 = 2 * (size_t)a->nw;
    r->e_max = (1.0 + a->opt.distortion_tolerance) * e_start;
    r->best_eff = chart_packing_efficiency(a->nw, a->loop.uv, a->nf, a->Fw);
    r->best = malloc(sizeof(double) * (n2 ? n2 : 1));
    if (!r->best) return err_nomem(err, "compaction");
    memcpy(r->best, a->loop.uv, sizeof(double) * n2);
    return SCAF_OK;
}

int atlas_compact_rule_after(const atlas *a, atlas_compact_rule *r, double energy,
                             double efficiency)
{
    if (!(energy <= r->e_max)) return 1;
    if (efficiency > r->best_eff) {
        r->best_eff = efficiency;
        memcpy(r->best, a->loop.uv, sizeof(double) * 2 * (size_t)a->nw);
    }
    return 0;
}

int atlas_compact_rule_end(atlas *a, atlas_compact_rule *r, int restore)
{
    size_t n2 = 2 * (size_t)a->nw;
    int restored = 0;
    if (restore && memcmp(r->best, a->loop.uv, sizeof(double) * n2) != 0) {
        memcpy(a->loop.uv, r->best, sizeof(double) * n2);
        restored = 1;
    }
    free(r->best);
    r->best = NULL;
    return restored;
}

/* Charts split for a distortion bound (automatic seams, or
 * --max-distortion) are not compacted above it: the compaction spends the
 * room between the settled E and the bound, never more (the relative
 * distortion tolerance took settled atlases of E 4.015 to 4.202, above
 * the 4.2 their charts were cut for). */
static void atlas_compact_bound(const atlas *a, atlas_compact_rule *r)
{
    double bound = a->opt.max_distortion;
    if (bound < 0.0) bound = a->seams_used != SCAF_SEAMS_INPUT ? ATLAS_CHARTS_MAX_DISTORTION : 0.0;
    if (!(bound > 0.0)) return;
    double cap = bound > a->settled_energy ? bound : a->settled_energy;
    if (cap < r->e_max) r->e_max = cap;
}

scaf_stop_reason atlas_stop_reason(const atlas *a)
{
    return a->compact_stop != SCAF_STOP_NONE ? a->compact_stop : a->settle_stop;
}

scaf_status atlas_run(atlas *a, atlas_progress_fn progress, void *user, scaf_error *err)
{
    scaf_status st = SCAF_OK;
    atlas_iteration it;
    /* ---- phase 1: settle the distortion -------------------------------- */
    a->loop.opt = param_loop_options(&a->opt.base);
    a->loop.hooks.prepare = NULL;
    a->settle_stop = a->opt.settle_iterations > 0 ? SCAF_STOP_ITERATIONS : SCAF_STOP_NONE;
    a->compact_stop = SCAF_STOP_NONE;
    /* to convergence: the estimated relative distance to the minimum
     * (opt/convergence, as scaf_param_run) below settle_tolerance */
    opt_convergence conv;
    opt_convergence_reset(&conv);
    for (int k = 0; k < a->opt.settle_iterations; k++) {
        st = one_iteration(a, ATLAS_SETTLE, &conv, progress, user, &it, err);
        if (st != SCAF_OK) {
            a->settle_stop = st == SCAF_ERR_CANCELLED ? SCAF_STOP_CANCELLED : SCAF_STOP_ERROR;
            return st;
        }
        if (it.info.step == 0.0) {
            a->settle_stop = SCAF_STOP_ZERO_STEP;
            break;
        }
        if (a->opt.settle_tolerance > 0.0 && it.info.criterion < a->opt.settle_tolerance) {
            a->settle_stop = SCAF_STOP_CONVERGED;
            break;
        }
        /* no new low for a while: E only moves at the loop's noise floor
         * (a chart started from its settled layout, with tolerance 0) */
        if (opt_convergence_no_new_low(&conv)) {
            a->settle_stop = SCAF_STOP_NOISE_FLOOR;
            break;
        }
    }
    a->settled_energy = scaf_loop_energy(&a->loop);
    a->eff_before = chart_packing_efficiency(a->nw, a->loop.uv, a->nf, a->Fw);
    st = atlas_gap(a, &a->gap_before, err);
    if (st != SCAF_OK) return st;

    a->eff_packed = NAN;
    if (a->opt.repack) {
        st = repack(a, err);
        if (st != SCAF_OK) return st;
    }
    a->turns = 0;
    if (a->opt.rotate) {
        st = turn_layout(a, err);
        if (st != SCAF_OK) return st;
    }

    /* ---- phase 2: compaction ------------------------------------------- */
    /* (one chart too: the box shrinks around it, its aspect nears the
     * square's within the distortion tolerance) */
    if (a->opt.compact_iterations > 0) {
        atlas_compact_begin(a);
        enum { MAXWIN = 64 };
        int win = a->opt.progress_window < 1  ? 1
            : a->opt.progress_window > MAXWIN ? MAXWIN
                                              : a->opt.progress_window;
        double hist[MAXWIN];
        int zero_steps = 0;
        /* the layout kept: atlas_compact_rule (an iteration may
         * overshoot the tolerance or lose efficiency; the result then
         * goes back to the best earlier layout, which was bijective and
         * padded after its own iteration) */
        atlas_compact_rule rule;
        st = atlas_compact_rule_begin(a, &rule, a->settled_energy, err);
        if (st != SCAF_OK) return st;
        atlas_compact_bound(a, &rule);
        a->compact_stop = SCAF_STOP_ITERATIONS;
        for (int k = 0; k < a->opt.compact_iterations; k++) {
            st = one_iteration(a, ATLAS_COMPACT, NULL, progress, user, &it, err);
            if (st != SCAF_OK) {
                a->compact_stop = st == SCAF_ERR_CANCELLED ? SCAF_STOP_CANCELLED : SCAF_STOP_ERROR;
                break;
            }
            if (atlas_compact_rule_after(a, &rule, it.info.energy, it.efficiency)) {
                a->compact_stop = SCAF_STOP_DISTORTION;
                break;
            }
            zero_steps = it.info.step == 0.0 ? zero_steps + 1 : 0;
            if (zero_steps >= 3) {
                a->compact_stop = SCAF_STOP_ZERO_STEP;
                break;
            }
            if (k >= win && hist[k % win] - it.side < a->opt.progress_tolerance * hist[k % win]) {
                a->compact_stop = SCAF_STOP_PACKING_STALLED;
                break;
            }
            hist[k % win] = it.side;
        }
        /* (a cancelled or failed run keeps its last finished iteration) */
        if (atlas_compact_rule_end(a, &rule, st == SCAF_OK)) a->compact_restored = 1;
        atlas_compact_end(a);
        if (st != SCAF_OK) return st;
    }
    if (a->opt.rotate) {
        st = turn_layout(a, err);
        if (st != SCAF_OK) return st;
    }
    a->eff_after = chart_packing_efficiency(a->nw, a->loop.uv, a->nf, a->Fw);
    return atlas_gap(a, &a->gap_after, err);
}
