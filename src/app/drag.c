/* app/drag: the scaf_drag_* API (see include/scaf/drag.h).
 *
 * A drag context is an atlas (app/atlas: charts found and checked, the
 * starting layout, the padding hooks of its SCAF loop) plus the soft
 * positional term (opt/handle_term) added to that loop, fed by the handle
 * set of app/drag_handles. A step is the loop's iteration as is: the
 * scaffold re-meshed, SLIM or Newton, the flip-free line search with its
 * exact orientation checks, the atlas's padding test. So every layout a
 * step leaves is bijective and padded; the saved output goes through the
 * atlas's normalization and exact certificate (app/atlas_output).
 *
 * Undo keeps copies of the layout (the loop's positions and its iteration
 * count): the scaffold is rebuilt from the positions at every iteration,
 * so nothing else needs restoring.
 */
#include "scaf/drag.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/api_options.h"
#include "app/atlas.h"
#include "app/atlas_output.h"
#include "app/drag_barrier.h"
#include "app/drag_ctx.h"
#include "app/drag_handles.h"
#include "app/param.h"
#include "base/error.h"
#include "geom/chart_gap.h"
#include "mesh/mesh.h"
#include "opt/handle_term.h"

static void drop_hard(scaf_drag_t *d, int uv);

/* ---- options ---------------------------------------------------------------- */

scaf_drag_options_t scaf_drag_options_default(void)
{
    atlas_options in = atlas_options_default();
    scaf_drag_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.start = SCAF_DRAG_START_LAYOUT;
    o.padding = 4.0 / 1024.0;
    o.weight_ratio = SCAF_HANDLE_WEIGHT_DEFAULT;
    o.solver = SCAF_SOLVER_SLIM;
    o.box_scale = in.base.box_scale;
    o.lambda_ratio = in.base.lambda_ratio;
    o.undo_depth = 64;
    return o;
}

static atlas_options to_atlas(const scaf_drag_options_t *o)
{
    atlas_options in = atlas_options_default();
    in.padding = o->padding;
    in.init_input = o->start == SCAF_DRAG_START_INPUT;
    in.base.solver = o->solver;
    in.base.box_scale = o->box_scale;
    in.base.lambda_ratio = o->lambda_ratio;
    in.base.seams = o->seams;
    return in;
}

/* The caller's options into *out (NULL: defaults): SCAF_OK, or
 * SCAF_ERR_USAGE naming the struct_size or the first invalid field. */
static scaf_status options_take(scaf_drag_options_t *out, const scaf_drag_options_t *in,
                                scaf_error *err)
{
    const char *who = "invalid drag option";
    scaf_drag_options_t def = scaf_drag_options_default();
    scaf_status st = api_options_take(out, in, &def, sizeof def, "scaf_drag_options_t", err);
    if (st != SCAF_OK) return st;
    const scaf_drag_options_t *o = out;
    if (o->start != SCAF_DRAG_START_LAYOUT && o->start != SCAF_DRAG_START_INPUT &&
        o->start != SCAF_DRAG_START_ATLAS)
        return err_set(err, SCAF_ERR_USAGE, "%s: start %d is not a scaf_drag_start", who,
                       (int)o->start);
    st = api_check_real(err, who, "weight_ratio", o->weight_ratio, 0.0, INFINITY, API_OPEN_HI);
    if (st == SCAF_OK && ((int)o->seams < 0 || o->seams > SCAF_SEAMS_EXTEND))
        st = err_set(err, SCAF_ERR_USAGE, "%s: seams %d is not a scaf_seams", who, (int)o->seams);
    if (st == SCAF_OK && o->solver != SCAF_SOLVER_AUTO && o->solver != SCAF_SOLVER_SLIM &&
        o->solver != SCAF_SOLVER_NEWTON)
        st =
            err_set(err, SCAF_ERR_USAGE, "%s: solver %d is not a scaf_solver", who, (int)o->solver);
    if (st == SCAF_OK) st = api_check_int(err, who, "undo_depth", o->undo_depth, 1, 4096);
    if (st != SCAF_OK) return st;
    atlas_options in_atlas = to_atlas(o);
    char msg[256];
    if (atlas_options_check(&in_atlas, msg, sizeof msg) != SCAF_OK)
        return err_set(err, SCAF_ERR_USAGE, "%s: %s", who, msg);
    return SCAF_OK;
}

scaf_status scaf_drag_options_check(const scaf_drag_options_t *options, char *message, size_t size)
{
    scaf_error err;
    err_clear(&err);
    scaf_drag_options_t o;
    scaf_status st = options ? options_take(&o, options, &err)
                             : err_set(&err, SCAF_ERR_USAGE, "options is NULL");
    if (message && size) snprintf(message, size, "%s", err.message);
    return st;
}

scaf_drag_t *scaf_drag_new(const scaf_drag_options_t *options)
{
    scaf_drag_options_t o;
    if (options_take(&o, options, NULL) != SCAF_OK) return NULL;
    scaf_drag_t *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    err_clear(&d->err);
    d->opt = o;
    return d;
}

scaf_status scaf_drag_set_options(scaf_drag_t *d, const scaf_drag_options_t *options)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    if (!options) return err_set(&d->err, SCAF_ERR_USAGE, "options is NULL");
    scaf_drag_options_t o;
    scaf_status st = options_take(&o, options, &d->err);
    if (st == SCAF_OK) d->opt = o;
    return st;
}

/* ---- mesh ---------------------------------------------------------------------- */

static void drop_redo(scaf_drag_t *d)
{
    for (int i = 0; i < d->nredo; i++) free(d->redo[i].uv);
    free(d->redo);
    d->redo = NULL;
    d->nredo = 0;
}

void drag_ctx_changed(scaf_drag_t *d)
{
    drop_redo(d);
    d->out_state = 0;
}

static void drop_stack(scaf_drag_t *d)
{
    for (int i = 0; i < d->nstack; i++) free(d->stack[i].uv);
    free(d->stack);
    d->stack = NULL;
    d->nstack = 0;
    drop_redo(d);
}

static void drop_mesh(scaf_drag_t *d)
{
    drag_rigid_free(d);
    drag_cap_free(d);
    if (d->has_mesh) {
        atlas_free(&d->at); /* frees the loop and with it the term's block */
        opt_handle_term_free(&d->term);
        drag_barrier_free(&d->barrier);
        drag_handles_free(&d->handles);
    }
    memset(&d->at, 0, sizeof d->at);
    free(d->before.uv);
    memset(&d->before, 0, sizeof d->before);
    d->has_before = 0;
    drop_stack(d);
    free(d->hard_v);
    free(d->hard_xy);
    d->hard_v = NULL;
    d->hard_xy = NULL;
    d->nhard = d->cap_hard = 0;
    free(d->UVn);
    d->UVn = NULL;
    d->out_state = 0;
    d->has_mesh = 0;
    d->handles_dirty = 0;
}

void scaf_drag_destroy(scaf_drag_t *d)
{
    if (!d) return;
    drop_mesh(d);
    free(d);
}

const char *scaf_drag_error(const scaf_drag_t *d)
{
    return d ? d->err.message : "no drag context (NULL)";
}

static scaf_status need_mesh(scaf_drag_t *d)
{
    if (!d->has_mesh)
        return err_set(&d->err, SCAF_ERR_USAGE, "no mesh: call scaf_drag_set_mesh first");
    return SCAF_OK;
}

scaf_status scaf_drag_set_mesh(scaf_drag_t *d, const double *V, int nv, const int *F, int nf,
                               const double *UV, int nuv, const int *FT)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    drop_mesh(d);
    scaf_status st = param_check_arrays(V, nv, F, nf, UV, nuv, FT, &d->err);
    if (st != SCAF_OK) return st;
    if (d->opt.start == SCAF_DRAG_START_INPUT && nuv == 0)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "start is SCAF_DRAG_START_INPUT but no UVs (UV, FT) were given to start "
                       "from");
    mesh m = {nv,
              (double *)V,
              nf,
              (int *)F,
              nuv,
              nuv > 0 ? (double *)UV : NULL,
              nuv > 0 ? (int *)FT : NULL};
    atlas_options in = to_atlas(&d->opt);
    st = atlas_init(&d->at, &m, &in, &d->err);
    if (st != SCAF_OK) {
        memset(&d->at, 0, sizeof d->at);
        return st;
    }
    if (d->opt.start == SCAF_DRAG_START_ATLAS) {
        st = atlas_run(&d->at, NULL, NULL, &d->err);
        d->at.loop.iterations = 0;
    }
    size_t n2 = 2 * (size_t)d->at.nw;
    opt_handle_term_init(&d->term, 2, d->at.nw);
    if (st == SCAF_OK)
        st = drag_handles_init(&d->handles, d->at.nw, d->at.wchart, d->at.ncharts, &d->err);
    if (st == SCAF_OK) {
        opt_obj_term t = opt_handle_term_make(&d->term);
        st = scaf_loop_add_term(&d->at.loop, &t, &d->err);
    }
    if (st == SCAF_OK && d->opt.padding > 0.0) {
        st = drag_barrier_init(&d->barrier, &d->at, &d->err);
        if (st == SCAF_OK) {
            opt_obj_term t = drag_barrier_make(&d->barrier);
            st = scaf_loop_add_term(&d->at.loop, &t, &d->err);
        }
    }
    d->UVn = st == SCAF_OK ? malloc(sizeof(double) * n2) : NULL;
    d->before.uv = st == SCAF_OK ? malloc(sizeof(double) * n2) : NULL;
    if (st == SCAF_OK && (!d->UVn || !d->before.uv)) st = err_nomem(&d->err, "drag context");
    d->has_mesh = 1; /* so drop_mesh frees what was made */
    if (st != SCAF_OK) {
        if (d->err.code == SCAF_OK) d->err.code = st;
        scaf_error keep = d->err;
        drop_mesh(d);
        d->err = keep;
        return st;
    }
    return SCAF_OK;
}

int scaf_drag_chart_count(const scaf_drag_t *d) { return d && d->has_mesh ? d->at.ncharts : 0; }
int scaf_drag_uv_count(const scaf_drag_t *d) { return d && d->has_mesh ? d->at.nw : 0; }
int scaf_drag_face_count(const scaf_drag_t *d) { return d && d->has_mesh ? d->at.nf : 0; }

scaf_status scaf_drag_get_uv(const scaf_drag_t *d, double *UV, int *FT, int *chart)
{
    if (!d) return SCAF_ERR_USAGE;
    scaf_drag_t *m = (scaf_drag_t *)d; /* the message is the context's mutable part */
    err_clear(&m->err);
    scaf_status st = need_mesh(m);
    if (st != SCAF_OK) return st;
    if (!UV) return err_set(&m->err, SCAF_ERR_USAGE, "UV is NULL (give %d by 2 doubles)", d->at.nw);
    memcpy(UV, d->at.loop.uv, sizeof(double) * 2 * (size_t)d->at.nw);
    if (FT) memcpy(FT, d->at.Fw, sizeof(int) * 3 * (size_t)d->at.nf);
    if (chart) memcpy(chart, d->at.chart, sizeof(int) * (size_t)d->at.nf);
    return SCAF_OK;
}

scaf_status scaf_drag_uv_charts(const scaf_drag_t *d, int *chart)
{
    if (!d) return SCAF_ERR_USAGE;
    scaf_drag_t *m = (scaf_drag_t *)d;
    err_clear(&m->err);
    scaf_status st = need_mesh(m);
    if (st != SCAF_OK) return st;
    if (!chart) return err_set(&m->err, SCAF_ERR_USAGE, "chart is NULL (give %d ints)", d->at.nw);
    memcpy(chart, d->at.wchart, sizeof(int) * (size_t)d->at.nw);
    return SCAF_OK;
}

/* ---- handles -------------------------------------------------------------------- */

/* Area-weighted centroid and UV area of chart c's triangles at uv. */
static void chart_centroid(const atlas *a, int c, const double *uv, double cen[2], double *area)
{
    double sx = 0.0, sy = 0.0, sa = 0.0;
    for (int f = 0; f < a->nf; f++) {
        if (a->chart[f] != c) continue;
        const int *t = a->Fw + 3 * f;
        const double *p = uv + 2 * (size_t)t[0], *q = uv + 2 * (size_t)t[1],
                     *r = uv + 2 * (size_t)t[2];
        double ar = 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
        sx += ar * (p[0] + q[0] + r[0]) / 3.0;
        sy += ar * (p[1] + q[1] + r[1]) / 3.0;
        sa += ar;
    }
    cen[0] = sa > 0.0 ? sx / sa : 0.0;
    cen[1] = sa > 0.0 ? sy / sa : 0.0;
    if (area) *area = sa;
}

static scaf_status handles_changed(scaf_drag_t *d, scaf_status st)
{
    if (st == SCAF_OK) d->handles_dirty = 1;
    return st;
}

scaf_status scaf_drag_move_vertex(scaf_drag_t *d, int uv, double x, double y)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    return handles_changed(d, drag_handles_move_vertex(&d->handles, uv, x, y, &d->err));
}

scaf_status scaf_drag_move_chart(scaf_drag_t *d, int chart, double dx, double dy, double angle)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    double cen[2] = {0.0, 0.0};
    if (chart >= 0 && chart < d->at.ncharts && !d->handles.cheld[chart])
        chart_centroid(&d->at, chart, d->at.loop.uv, cen, NULL);
    return handles_changed(
        d, drag_handles_move_chart(&d->handles, chart, d->at.loop.uv, cen, dx, dy, angle, &d->err));
}

scaf_status scaf_drag_clear_vertex(scaf_drag_t *d, int uv)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    st = handles_changed(d, drag_handles_clear_vertex(&d->handles, uv, &d->err));
    if (st == SCAF_OK) drop_hard(d, uv);
    return st;
}

scaf_status scaf_drag_clear_chart(scaf_drag_t *d, int chart)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    return handles_changed(d, drag_handles_clear_chart(&d->handles, chart, &d->err));
}

scaf_status scaf_drag_clear_handles(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    drag_handles_clear(&d->handles);
    d->handles_dirty = 1;
    d->nhard = 0;
    drag_cap_reset(d); /* the drag is over */
    return SCAF_OK;
}

int scaf_drag_handle_count(const scaf_drag_t *d)
{
    return d && d->has_mesh ? drag_handles_count(&d->handles) : 0;
}

/* ---- pins ------------------------------------------------------------------------- */

/* Drop uv's pending hard target, if any. */
static void drop_hard(scaf_drag_t *d, int uv)
{
    for (int i = 0; i < d->nhard; i++)
        if (d->hard_v[i] == uv) {
            d->hard_v[i] = d->hard_v[d->nhard - 1];
            d->hard_xy[2 * i] = d->hard_xy[2 * (d->nhard - 1)];
            d->hard_xy[2 * i + 1] = d->hard_xy[2 * (d->nhard - 1) + 1];
            d->nhard--;
            return;
        }
}

scaf_status scaf_drag_move_vertex_hard(scaf_drag_t *d, int uv, double x, double y)
{
    scaf_status st = scaf_drag_move_vertex(d, uv, x, y);
    if (st != SCAF_OK) return st;
    drop_hard(d, uv);
    if (d->nhard == d->cap_hard) {
        int cap = d->cap_hard ? 2 * d->cap_hard : 8;
        int *v = realloc(d->hard_v, sizeof(int) * (size_t)cap);
        if (v) d->hard_v = v;
        double *p = realloc(d->hard_xy, sizeof(double) * 2 * (size_t)cap);
        if (p) d->hard_xy = p;
        if (!v || !p) {
            drag_handles_clear_vertex(&d->handles, uv, &d->err);
            return err_nomem(&d->err, "hard target");
        }
        d->cap_hard = cap;
    }
    d->hard_v[d->nhard] = uv;
    d->hard_xy[2 * d->nhard] = x;
    d->hard_xy[2 * d->nhard + 1] = y;
    d->nhard++;
    return scaf_loop_pin(&d->at.loop, uv, 0, &d->err); /* pinned once met */
}

int scaf_drag_hard_pending(const scaf_drag_t *d) { return d && d->has_mesh ? d->nhard : 0; }

/* After a step: every pending hard target that can be met exactly now is
 * met and pinned. */
static scaf_status place_hard(scaf_drag_t *d)
{
    for (int i = 0; i < d->nhard;) {
        if (!scaf_loop_place(&d->at.loop, d->hard_v[i], d->hard_xy + 2 * i)) {
            i++;
            continue;
        }
        scaf_status st = scaf_loop_pin(&d->at.loop, d->hard_v[i], 1, &d->err);
        if (st != SCAF_OK) return st;
        drop_hard(d, d->hard_v[i]);
    }
    return SCAF_OK;
}

scaf_status scaf_drag_pin_vertex(scaf_drag_t *d, int uv, int pinned)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (uv < 0 || uv >= d->at.nw)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "vertex %d does not exist: the layout has %d (0..%d)", uv, d->at.nw,
                       d->at.nw - 1);
    if (!pinned) drop_hard(d, uv);
    return scaf_loop_pin(&d->at.loop, uv, pinned != 0, &d->err);
}

int scaf_drag_is_pinned(const scaf_drag_t *d, int uv)
{
    return d && d->has_mesh && scaf_loop_pinned(&d->at.loop, uv);
}

int scaf_drag_pinned_count(const scaf_drag_t *d)
{
    return d && d->has_mesh ? scaf_loop_pinned_count(&d->at.loop) : 0;
}

/* ---- padding ---------------------------------------------------------------- */

double scaf_drag_padding(const scaf_drag_t *d) { return d ? d->opt.padding : NAN; }

scaf_status scaf_drag_set_padding(scaf_drag_t *d, double padding)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (!(padding >= CHART_GAP_EXACT_MIN && padding < 0.5))
        return err_set(&d->err, SCAF_ERR_USAGE, "padding %g must be in [2^-200, 0.5)", padding);
    if (!(d->opt.padding > 0.0))
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "the context was made with padding 0: it has no padding to change");
    /* the test every step passes, at the new padding, on the layout now */
    double keep = d->at.opt.padding, g = INFINITY;
    d->at.opt.padding = padding;
    double need = atlas_padding_need(&d->at, d->at.loop.uv);
    d->at.opt.padding = keep;
    st = chart_gap_min_segments(d->at.loop.uv, d->at.seg, d->at.nseg, need, &g, NULL, &d->err);
    if (st != SCAF_OK) return st;
    if (!(g > need)) {
        double side = atlas_side(&d->at);
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "padding %g is more than the layout keeps now (its smallest chart gap is "
                       "%.6g of the longest side, with the rounding margin): compaction never "
                       "spreads charts; choose at most that",
                       padding, side > 0.0 ? g / side : g);
    }
    d->opt.padding = padding;
    d->at.opt.padding = padding;
    d->out_state = 0; /* the output is certified against the padding */
    return SCAF_OK;
}

/* The term made to match the handle set (targets of chart handles are
 * computed here, from their grab poses). */
static scaf_status sync_handles(scaf_drag_t *d)
{
    if (!d->handles_dirty) return SCAF_OK;
    scaf_status st = drag_handles_build(&d->handles, &d->term, d->opt.weight_ratio,
                                        d->at.loop.total_area, &d->err);
    if (st == SCAF_OK) d->handles_dirty = 0;
    return st;
}

double scaf_drag_max_handle_error(const scaf_drag_t *d)
{
    if (!d || !d->has_mesh) return NAN;
    if (sync_handles((scaf_drag_t *)d) != SCAF_OK) return NAN;
    return opt_handle_term_max_error(&d->term, d->at.loop.uv);
}

/* ---- states: cancel and undo ----------------------------------------------------- */

static void save_state(const scaf_drag_t *d, drag_state *s)
{
    memcpy(s->uv, d->at.loop.uv, sizeof(double) * 2 * (size_t)d->at.nw);
    s->iterations = d->at.loop.iterations;
}

static void restore_state(scaf_drag_t *d, const drag_state *s)
{
    memcpy(d->at.loop.uv, s->uv, sizeof(double) * 2 * (size_t)d->at.nw);
    d->at.loop.iterations = s->iterations;
    d->out_state = 0;
    drag_cap_reset(d); /* a new drag measures from here */
}

scaf_status scaf_drag_cancel(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (!d->has_before)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "nothing to cancel: no step since the mesh was set or the last undo");
    restore_state(d, &d->before);
    return SCAF_OK;
}

/* The current layout pushed on *stack (at most undo_depth, the oldest
 * dropped); on failure nothing changes. */
static scaf_status push_current(scaf_drag_t *d, drag_state **stack, int *n, const char *what)
{
    drag_state s = {malloc(sizeof(double) * 2 * (size_t)d->at.nw), 0};
    if (!s.uv) return err_nomem(&d->err, what);
    save_state(d, &s);
    drag_state *q =
        *n == d->opt.undo_depth ? *stack : realloc(*stack, sizeof *q * (size_t)(*n + 1));
    if (!q) {
        free(s.uv);
        return err_nomem(&d->err, what);
    }
    if (*n == d->opt.undo_depth) { /* full: the oldest goes */
        free(q[0].uv);
        memmove(q, q + 1, sizeof *q * (size_t)(*n - 1));
        (*n)--;
    }
    *stack = q;
    q[(*n)++] = s;
    return SCAF_OK;
}

scaf_status scaf_drag_checkpoint(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    st = push_current(d, &d->stack, &d->nstack, "checkpoint");
    if (st == SCAF_OK) drop_redo(d); /* a new change: what was undone is gone */
    drag_cap_reset(d);
    return st;
}

scaf_status scaf_drag_undo(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (d->nstack == 0)
        return err_set(&d->err, SCAF_ERR_USAGE, "nothing to undo: no checkpoint is left");
    st = push_current(d, &d->redo, &d->nredo, "undo"); /* for scaf_drag_redo */
    if (st != SCAF_OK) return st;
    drag_state *s = &d->stack[--d->nstack];
    restore_state(d, s);
    free(s->uv);
    d->has_before = 0;
    return SCAF_OK;
}

int scaf_drag_undo_count(const scaf_drag_t *d) { return d && d->has_mesh ? d->nstack : 0; }

scaf_status scaf_drag_redo(scaf_drag_t *d)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (d->nredo == 0)
        return err_set(&d->err, SCAF_ERR_USAGE,
                       "nothing to redo: no undo since the last checkpoint or step");
    st = push_current(d, &d->stack, &d->nstack, "redo"); /* undo goes back again */
    if (st != SCAF_OK) return st;
    drag_state *s = &d->redo[--d->nredo];
    restore_state(d, s);
    free(s->uv);
    d->has_before = 0;
    return SCAF_OK;
}

int scaf_drag_redo_count(const scaf_drag_t *d) { return d && d->has_mesh ? d->nredo : 0; }

int scaf_drag_iterations(const scaf_drag_t *d)
{
    return d && d->has_mesh ? d->at.loop.iterations : 0;
}

/* ---- steps ------------------------------------------------------------------------ */

/* n loop iterations (the caller set up the loop and the term); stops
 * early on a zero step, and, with a compaction rule (may be NULL), when E
 * exceeds its limit. */
static scaf_status iterate(scaf_drag_t *d, int n, scaf_param_progress_fn progress, void *user,
                           atlas_compact_rule *rule)
{
    save_state(d, &d->before);
    d->has_before = 1;
    d->out_state = 0;
    drop_redo(d); /* the layout changes: what was undone is gone */
    for (int k = 0; k < n; k++) {
        scaf_iteration_info_t info;
        if (rule) drag_cap_reset(d); /* compaction has its own rule */
        else if (drag_cap_before(d) != SCAF_OK) return d->err.code;
        scaf_status st = scaf_loop_step(&d->at.loop, &info, &d->err);
        if (st != SCAF_OK) {
            if (d->err.code == SCAF_OK) d->err.code = st;
            return st;
        }
        if (!rule && drag_cap_refused(d)) break; /* the iteration is undone */
        if (d->nhard > 0 && (st = place_hard(d)) != SCAF_OK) return st;
        if (progress && progress(&info, user))
            return err_set(&d->err, SCAF_ERR_CANCELLED,
                           "stopped by the progress callback after iteration %d", info.iteration);
        if (rule &&
            atlas_compact_rule_after(
                &d->at, rule, info.energy,
                chart_packing_efficiency(d->at.nw, d->at.loop.uv, d->at.nf, d->at.Fw)))
            break;
        if (!(info.step > 0.0)) break;
    }
    return SCAF_OK;
}

static scaf_status check_count(scaf_drag_t *d, int n)
{
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (n < 1) return err_set(&d->err, SCAF_ERR_USAGE, "iterations: %d must be >= 1", n);
    return SCAF_OK;
}

scaf_status scaf_drag_step(scaf_drag_t *d, int n, scaf_param_progress_fn progress, void *user)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = check_count(d, n);
    if (st == SCAF_OK) st = sync_handles(d);
    if (st != SCAF_OK) return st;
    return iterate(d, n, progress, user, NULL);
}

scaf_status scaf_drag_compact(scaf_drag_t *d, int n, scaf_param_progress_fn progress, void *user)
{
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = check_count(d, n);
    if (st != SCAF_OK) return st;
    /* handles ignored: the term emptied, rebuilt at the next step */
    st = opt_handle_term_set(&d->term, 0, NULL, NULL, 0.0, &d->err);
    if (st != SCAF_OK) return st;
    d->handles_dirty = 1;
    /* the distortion limit of `scaf atlas` (app/atlas: atlas_compact_rule) */
    atlas_compact_rule rule;
    st = atlas_compact_rule_begin(&d->at, &rule, atlas_energy(&d->at), &d->err);
    if (st != SCAF_OK) return st;
    atlas_compact_begin(&d->at);
    int on = d->barrier.on;
    drag_barrier_enable(&d->barrier, 0); /* compaction closes gaps on purpose */
    st = iterate(d, n, progress, user, &rule);
    drag_barrier_enable(&d->barrier, on);
    atlas_compact_end(&d->at);
    /* (a cancelled or failed run keeps its last finished iteration) */
    if (atlas_compact_rule_end(&d->at, &rule, st == SCAF_OK)) d->out_state = 0;
    return st;
}

/* ---- measures ---------------------------------------------------------------------- */

double scaf_drag_energy(const scaf_drag_t *d)
{
    return d && d->has_mesh ? atlas_energy(&d->at) : NAN;
}

double scaf_drag_packing_efficiency(const scaf_drag_t *d)
{
    if (!d || !d->has_mesh) return NAN;
    return chart_packing_efficiency(d->at.nw, d->at.loop.uv, d->at.nf, d->at.Fw);
}

scaf_status scaf_drag_face_energy(const scaf_drag_t *d, double *E)
{
    if (!d) return SCAF_ERR_USAGE;
    scaf_drag_t *m = (scaf_drag_t *)d;
    err_clear(&m->err);
    scaf_status st = need_mesh(m);
    if (st != SCAF_OK) return st;
    if (!E) return err_set(&m->err, SCAF_ERR_USAGE, "E is NULL (give %d doubles)", d->at.nf);
    scaf_loop_face_energy(&d->at.loop, E);
    return SCAF_OK;
}

scaf_status scaf_drag_chart_info(const scaf_drag_t *d, int chart, scaf_drag_chart_info_t *info)
{
    if (!d) return SCAF_ERR_USAGE;
    scaf_drag_t *m = (scaf_drag_t *)d;
    err_clear(&m->err);
    scaf_status st = need_mesh(m);
    if (st != SCAF_OK) return st;
    if (!info) return err_set(&m->err, SCAF_ERR_USAGE, "info is NULL");
    if (chart < 0 || chart >= d->at.ncharts)
        return err_set(&m->err, SCAF_ERR_USAGE,
                       "chart %d does not exist: the layout has %d (0..%d)", chart, d->at.ncharts,
                       d->at.ncharts - 1);
    double *E = malloc(sizeof(double) * (size_t)d->at.ncharts);
    if (!E) return err_nomem(&m->err, "chart info");
    atlas_chart_energy(&d->at, E); /* (all charts: one pass over the faces) */
    memset(info, 0, sizeof *info);
    for (int f = 0; f < d->at.nf; f++) info->faces += d->at.chart[f] == chart;
    info->uvs = d->handles.cstart[chart + 1] - d->handles.cstart[chart];
    chart_centroid(&d->at, chart, d->at.loop.uv, info->centroid, &info->uv_area);
    info->energy = E[chart];
    free(E);
    info->held = d->handles.cheld[chart];
    return SCAF_OK;
}

/* ---- output ------------------------------------------------------------------------ */

scaf_status scaf_drag_get_output(const scaf_drag_t *cd, double *UV, int *FT, int *chart,
                                 double *efficiency, double *gap)
{
    /* const: the layout stays; only the cached certified output and the
     * message are filled */
    scaf_drag_t *d = (scaf_drag_t *)cd;
    if (!d) return SCAF_ERR_USAGE;
    err_clear(&d->err);
    scaf_status st = need_mesh(d);
    if (st != SCAF_OK) return st;
    if (!UV) return err_set(&d->err, SCAF_ERR_USAGE, "UV is NULL (give %d by 2 doubles)", d->at.nw);
    if (d->out_state == 0) {
        err_clear(&d->out_err);
        st = atlas_output_verify(&d->at, d->UVn, &d->out, &d->out_err);
        if (st != SCAF_OK && d->out_err.code == SCAF_OK) d->out_err.code = st;
        d->out_state = st == SCAF_OK ? 1 : -1;
    }
    if (d->out_state < 0) {
        d->err = d->out_err;
        return d->err.code;
    }
    memcpy(UV, d->UVn, sizeof(double) * 2 * (size_t)d->at.nw);
    if (FT) memcpy(FT, d->at.Fw, sizeof(int) * 3 * (size_t)d->at.nf);
    if (chart) memcpy(chart, d->at.chart, sizeof(int) * (size_t)d->at.nf);
    if (efficiency) *efficiency = d->out.efficiency;
    if (gap) *gap = d->out.gap;
    return SCAF_OK;
}
