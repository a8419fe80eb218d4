/* app/volume_api: the public 3D functions of scaf/volume.h (scaf_inflate,
 * scaf_untangle, scaf_flow and their handle) on app/volume_deform,
 * app/inflate, app/untangle, app/surface_flow and geom/tet_box_mesh.
 *
 * Each run: options read up to their struct_size and validated (never
 * replaced) -> arrays validated -> the input checked as the CLI checks it
 * (a closed manifold surface) -> a copy at unit scale (app/unit_scale) ->
 * the work, the caller's progress callback after every step -> results
 * back in the input's units, kept in the handle for the getters.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/api_options.h"
#include "app/inflate.h"
#include "app/surface_flow.h"
#include "app/unit_scale.h"
#include "app/untangle.h"
#include "app/volume_deform.h"
#include "geom/simplex_arrays.h"
#include "geom/tet_box_mesh.h"
#include "mesh/closed_surface.h"
#include "scaf/volume.h"
#include "scaffold/scaffold_tet.h"

#define VOLUME_MAX_STEPS 100000

enum { RESULT_NONE = 0, RESULT_INFLATE, RESULT_UNTANGLE, RESULT_FLOW, RESULT_TET };

struct scaf_volume {
    scaf_error err;
    int kind; /* RESULT_*: which run the results below are of */
    int nv;
    double *X;      /* nv by 3 */
    double *flowed; /* untangle: nv by 3 */
    int tet_nv, nt; /* inflate: the final tets */
    double *P;
    int *T, *label;
    scaf_volume_summary_t sum;
};

scaf_volume_t *scaf_volume_new(void)
{
    scaf_volume_t *h = calloc(1, sizeof *h);
    if (h) err_clear(&h->err);
    return h;
}

static void drop_result(scaf_volume_t *h)
{
    free(h->X);
    free(h->flowed);
    free(h->P);
    free(h->T);
    free(h->label);
    h->X = h->flowed = h->P = NULL;
    h->T = h->label = NULL;
    h->kind = RESULT_NONE;
    h->nv = h->tet_nv = h->nt = 0;
    memset(&h->sum, 0, sizeof h->sum);
}

void scaf_volume_destroy(scaf_volume_t *h)
{
    if (!h) return;
    drop_result(h);
    free(h);
}

const char *scaf_volume_error(const scaf_volume_t *h) { return h ? h->err.message : "no handle"; }

int scaf_volume_vertex_count(const scaf_volume_t *h) { return h ? h->nv : 0; }

scaf_status scaf_volume_get_positions(const scaf_volume_t *h, double *X)
{
    if (!h || !X) return SCAF_ERR_USAGE;
    if (h->kind == RESULT_NONE) return SCAF_ERR_USAGE;
    memcpy(X, h->X, sizeof(double) * 3 * (size_t)h->nv);
    return SCAF_OK;
}

scaf_status scaf_volume_get_flowed(const scaf_volume_t *h, double *X)
{
    if (!h || !X || h->kind != RESULT_UNTANGLE) return SCAF_ERR_USAGE;
    memcpy(X, h->flowed, sizeof(double) * 3 * (size_t)h->nv);
    return SCAF_OK;
}

static int has_tets(const scaf_volume_t *h)
{
    return h && (h->kind == RESULT_INFLATE || h->kind == RESULT_TET);
}

int scaf_volume_tet_vertex_count(const scaf_volume_t *h) { return has_tets(h) ? h->tet_nv : 0; }

int scaf_volume_tet_count(const scaf_volume_t *h) { return has_tets(h) ? h->nt : 0; }

scaf_status scaf_volume_get_tets(const scaf_volume_t *h, double *P, int *T, int *label)
{
    if (!has_tets(h)) return SCAF_ERR_USAGE;
    if (P) memcpy(P, h->P, sizeof(double) * 3 * (size_t)h->tet_nv);
    if (T) memcpy(T, h->T, sizeof(int) * 4 * (size_t)h->nt);
    if (label) memcpy(label, h->label, sizeof(int) * (size_t)h->nt);
    return SCAF_OK;
}

scaf_status scaf_volume_get_summary(const scaf_volume_t *h, scaf_volume_summary_t *s)
{
    if (!h || !s || h->kind == RESULT_NONE) return SCAF_ERR_USAGE;
    if (s->struct_size < sizeof(size_t) || s->struct_size > sizeof *s) return SCAF_ERR_USAGE;
    size_t n = s->struct_size;
    scaf_volume_summary_t full = h->sum;
    full.struct_size = n;
    memcpy(s, &full, n);
    return SCAF_OK;
}

const char *scaf_untangle_stop_name(scaf_untangle_stop stop)
{
    switch (stop) {
    case SCAF_UNTANGLE_ALREADY_FREE: return "already_free";
    case SCAF_UNTANGLE_CONVERGED: return "converged";
    case SCAF_UNTANGLE_ZERO_STEP: return "zero_step";
    case SCAF_UNTANGLE_ITERATION_LIMIT: return "iteration_limit";
    }
    return "unknown";
}

/* ---- options ------------------------------------------------------------ */

scaf_inflate_options_t scaf_inflate_options_default(void)
{
    scaf_inflate_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.scale = 2.0;
    o.iterations = 50;
    o.box_scale = volume_deform_options_default().box_scale;
    o.solver = SCAF_SOLVER_NEWTON;
    return o;
}

scaf_untangle_options_t scaf_untangle_options_default(void)
{
    untangle_options d = untangle_options_default();
    scaf_untangle_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.delta = d.delta;
    o.flow_steps = d.flow_steps;
    o.iterations = d.iterations;
    o.tolerance = d.tolerance;
    o.anchor = d.anchor_ratio;
    o.verify = d.verify;
    return o;
}

scaf_tet_options_t scaf_tet_options_default(void)
{
    scaf_tet_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.box_scale = 3.0;
    o.box_cells = 8;
    return o;
}

scaf_flow_options_t scaf_flow_options_default(void)
{
    scaf_flow_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.steps = 10;
    o.delta = 1e-3;
    o.until_free = 0;
    return o;
}

static scaf_status inflate_options_check(const scaf_inflate_options_t *o, scaf_error *err)
{
    scaf_status st = api_check_real(err, "inflate", "scale", o->scale, 0.0, 1e6, API_OPEN_LO);
    if (st == SCAF_OK)
        st = api_check_int(err, "inflate", "iterations", o->iterations, 1, VOLUME_MAX_STEPS);
    if (st == SCAF_OK)
        st = api_check_real(err, "inflate", "box_scale", o->box_scale, 1.0, 1e6, API_OPEN_LO);
    if (st == SCAF_OK && o->solver != SCAF_SOLVER_NEWTON && o->solver != SCAF_SOLVER_SLIM)
        st = err_set(err, SCAF_ERR_USAGE,
                     "inflate: solver %d, expected SCAF_SOLVER_NEWTON or SCAF_SOLVER_SLIM",
                     (int)o->solver);
    return st;
}

static scaf_status tet_options_check(const scaf_tet_options_t *o, scaf_error *err)
{
    scaf_status st = api_check_real(err, "tet", "box_scale", o->box_scale, 1.0, 1e6, API_OPEN_LO);
    if (st == SCAF_OK) st = api_check_int(err, "tet", "box_cells", o->box_cells, 1, 64);
    return st;
}

static untangle_options untangle_internal(const scaf_untangle_options_t *o)
{
    untangle_options u = untangle_options_default();
    u.delta = o->delta;
    u.flow_steps = o->flow_steps;
    u.iterations = o->iterations;
    u.tolerance = o->tolerance;
    u.anchor_ratio = o->anchor;
    u.verify = o->verify;
    return u;
}

static scaf_status untangle_options_valid(const scaf_untangle_options_t *o, scaf_error *err)
{
    if (api_check_int(err, "untangle", "verify", o->verify, 0, 1) != SCAF_OK) return SCAF_ERR_USAGE;
    untangle_options u = untangle_internal(o);
    return untangle_options_check(&u, err);
}

static scaf_status flow_options_check(const scaf_flow_options_t *o, scaf_error *err)
{
    scaf_status st = api_check_int(err, "flow", "steps", o->steps, 1, VOLUME_MAX_STEPS);
    if (st == SCAF_OK)
        st = api_check_real(err, "flow", "delta (the time step)", o->delta, 0.0, 1e6, API_OPEN_LO);
    if (st == SCAF_OK) st = api_check_int(err, "flow", "until_free", o->until_free, 0, 1);
    return st;
}

/* Options first (a bad option is named whatever the arrays), then the
 * arrays; the handle is emptied either way. */
#define OPTIONS_CHECK(type, opt_in, out, def, check)                                               \
    do {                                                                                           \
        if (!h) return SCAF_ERR_USAGE;                                                             \
        drop_result(h);                                                                            \
        err_clear(&h->err);                                                                        \
        type d_ = (def);                                                                           \
        scaf_status s_ = api_options_take(&(out), (opt_in), &d_, sizeof(type), #type, &h->err);    \
        if (s_ == SCAF_OK) s_ = check(&(out), &h->err);                                            \
        if (s_ != SCAF_OK) return s_;                                                              \
    } while (0)

/* The closed-surface check of the CLI (mesh/closed_surface), saying who
 * needs it. */
static scaf_status closed_input(int nv, const double *V, int nf, const int *F, const char *who,
                                scaf_error *err)
{
    mesh m = {nv, (double *)V, nf, (int *)F, 0, NULL, NULL};
    scaf_status st = closed_surface_check(&m, 0, err);
    if (st == SCAF_ERR_MESH) {
        char msg[SCAF_ERROR_MESSAGE_MAX];
        memcpy(msg, err->message, sizeof msg);
        err_set(err, st, "%.900s; %s needs a closed manifold triangle surface", msg, who);
    }
    return st;
}

/* A copy of V at unit scale (*e: the power of two taken away). */
static double *unit_copy(int nv, const double *V, int nf, const int *F, int *e, scaf_error *err)
{
    double *W = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    if (!W) {
        err_nomem(err, "a copy of the surface");
        return NULL;
    }
    if (nv > 0) memcpy(W, V, sizeof(double) * 3 * (size_t)nv); /* V may be NULL without vertices */
    if (unit_scale_down(nv, W, nf, F, e, err) != SCAF_OK) {
        free(W);
        return NULL;
    }
    return W;
}

/* ---- inflate ------------------------------------------------------------ */

/* The final state of vd into h, at unit scale (scaled back by the caller). */
static scaf_status keep_inflated(scaf_volume_t *h, const volume_deform *vd, int nv)
{
    const scaffold_view *v = volume_deform_scaffold(vd);
    const signed char *inside = scaffold_tet_inside(vd->scaffold);
    h->nv = nv;
    h->tet_nv = v->nmesh + v->nextra;
    h->nt = v->n;
    h->X = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    h->P = malloc(sizeof(double) * 3 * (size_t)(h->tet_nv > 0 ? h->tet_nv : 1));
    h->T = malloc(sizeof(int) * 4 * (size_t)(h->nt > 0 ? h->nt : 1));
    h->label = malloc(sizeof(int) * (size_t)(h->nt > 0 ? h->nt : 1));
    if (!h->X || !h->P || !h->T || !h->label) return err_nomem(&h->err, "inflate result");
    memcpy(h->X, volume_deform_positions(vd), sizeof(double) * 3 * (size_t)nv);
    memcpy(h->P, h->X, sizeof(double) * 3 * (size_t)v->nmesh);
    memcpy(h->P + 3 * (size_t)v->nmesh, v->extra, sizeof(double) * 3 * (size_t)v->nextra);
    memcpy(h->T, v->simplices, sizeof(int) * 4 * (size_t)v->n);
    for (int t = 0; t < v->n; t++) {
        h->label[t] = inside[t] ? 1 : 2;
        h->sum.tets_inside += inside[t] ? 1 : 0;
    }
    for (int k = 0; k < 3; k++) {
        h->sum.box_lo[k] = v->box_lo[k];
        h->sum.box_hi[k] = v->box_hi[k];
    }
    h->sum.diagonal_after = inflate_bbox_diagonal(nv, h->X);
    h->kind = RESULT_INFLATE;
    return SCAF_OK;
}

/* Everything of an inflate result back into the input's units. */
static scaf_status inflate_unscale(scaf_volume_t *h, int e)
{
    scaf_error *err = &h->err;
    scaf_status st = unit_scale_up(h->X, 3 * (size_t)h->nv, e, err);
    if (st == SCAF_OK) st = unit_scale_up(h->sum.box_lo, 3, e, err);
    if (st == SCAF_OK) st = unit_scale_up(h->sum.box_hi, 3, e, err);
    if (st == SCAF_OK) st = unit_scale_up(&h->sum.diagonal_before, 1, e, err);
    if (st == SCAF_OK) st = unit_scale_up(&h->sum.diagonal_after, 1, e, err);
    if (st == SCAF_OK) st = unit_scale_up(h->P, 3 * (size_t)h->tet_nv, e, err);
    return st;
}

scaf_status scaf_inflate(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                         const scaf_inflate_options_t *options, scaf_volume_progress_fn progress,
                         void *user)
{
    scaf_inflate_options_t o;
    OPTIONS_CHECK(scaf_inflate_options_t, options, o, scaf_inflate_options_default(),
                  inflate_options_check);
    scaf_error *err = &h->err;
    scaf_status st = simplex_arrays_check(nv, V, nf, F, 3, "face", err);
    if (st == SCAF_OK) st = closed_input(nv, V, nf, F, "inflate", err);
    if (st != SCAF_OK) return st;
    int e = 0;
    double *W = unit_copy(nv, V, nf, F, &e, err);
    if (!W) return err->code;
    double *target = malloc(sizeof(double) * 3 * (size_t)nv);
    if (!target) {
        free(W);
        return err_nomem(err, "inflate target");
    }
    inflate_target(nv, W, nf, F, o.scale, target);
    volume_deform_options vo = volume_deform_options_default();
    vo.box_scale = o.box_scale;
    vo.solver = o.solver;
    volume_deform vd;
    st = volume_deform_init(&vd, nv, W, nf, F, target, &vo, err);
    free(target);
    /* the options were checked above: what init refuses is the surface */
    if (st == SCAF_ERR_USAGE) err->code = st = SCAF_ERR_MESH;
    if (st != SCAF_OK) {
        free(W);
        return st;
    }
    h->sum.diagonal_before = inflate_bbox_diagonal(nv, W);
    h->sum.input_defects = -1;
    free(W);
    int done = 0;
    for (int i = 0; i < o.iterations && st == SCAF_OK; i++) {
        volume_deform_iteration it;
        if ((st = volume_deform_step(&vd, &it, err)) != SCAF_OK) {
            err_prefix(err, "iteration %d", i + 1);
            break;
        }
        done = i + 1;
        scaf_volume_step_info_t info;
        memset(&info, 0, sizeof info);
        info.phase = SCAF_VOLUME_ITERATION;
        info.step = it.iteration;
        info.seconds = it.seconds;
        info.defects = info.pairs = -1;
        info.energy = it.energy;
        info.step_length = it.step;
        info.tets = it.tets;
        info.scaffold_vertices = it.scaffold_vertices;
        info.quality_min = it.quality_min;
        info.quality_p5 = it.quality_p5;
        if (progress && progress(&info, user))
            st = err_set(err, SCAF_ERR_CANCELLED, "inflate: cancelled after iteration %d", done);
    }
    double before = h->sum.diagonal_before;
    if (st == SCAF_OK || st == SCAF_ERR_CANCELLED) {
        scaf_status kept = keep_inflated(h, &vd, nv);
        h->sum.diagonal_before = before;
        h->sum.iterations = done;
        h->sum.input_defects = -1;
        if (kept == SCAF_OK) kept = inflate_unscale(h, e);
        if (kept != SCAF_OK) st = kept;
    }
    volume_deform_free(&vd);
    if (st != SCAF_OK && st != SCAF_ERR_CANCELLED) drop_result(h);
    return st;
}

/* ---- tet ---------------------------------------------------------------- */

scaf_status scaf_tet_mesh(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                          const scaf_tet_options_t *options)
{
    scaf_tet_options_t o;
    OPTIONS_CHECK(scaf_tet_options_t, options, o, scaf_tet_options_default(), tet_options_check);
    scaf_error *err = &h->err;
    scaf_status st = simplex_arrays_check(nv, V, nf, F, 3, "face", err);
    /* the same words as flow, inflate and untangle for an open surface */
    if (st == SCAF_OK) st = closed_input(nv, V, nf, F, "tet", err);
    if (st != SCAF_OK) return st;
    int e = 0;
    double *W = unit_copy(nv, V, nf, F, &e, err);
    if (!W) return err->code;
    double lo[3], hi[3];
    tet_box_around(nv, W, o.box_scale, lo, hi);
    tet_box_mesh tm;
    st = tet_box_mesh_build(nv, W, nf, F, lo, hi, o.box_cells, &tm, err);
    /* the options were checked above: what the mesher refuses is the surface */
    if (st == SCAF_ERR_USAGE) err->code = st = SCAF_ERR_MESH;
    if (st == SCAF_OK) {
        h->nv = nv;
        h->tet_nv = tm.nv;
        h->nt = tm.nt;
        h->X = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
        h->label = malloc(sizeof(int) * (size_t)(tm.nt > 0 ? tm.nt : 1));
        if (!h->X || !h->label) st = err_nomem(err, "tet result");
    }
    if (st == SCAF_OK) {
        memcpy(h->X, V, sizeof(double) * 3 * (size_t)nv);
        h->P = tm.V; /* taken over from tm */
        h->T = tm.T;
        tm.V = NULL;
        tm.T = NULL;
        for (int t = 0; t < tm.nt; t++) h->label[t] = tm.inside[t] ? 1 : 2;
        h->kind = RESULT_TET;
        h->sum.box_vertices = tm.nbox;
        h->sum.tets_inside = tm.ninside;
        h->sum.input_defects = -1;
        h->sum.diagonal_before = inflate_bbox_diagonal(nv, W);
        for (int k = 0; k < 3; k++) {
            h->sum.box_lo[k] = lo[k];
            h->sum.box_hi[k] = hi[k];
        }
        st = unit_scale_up(h->P, 3 * (size_t)h->tet_nv, e, err);
        if (st == SCAF_OK) st = unit_scale_up(h->sum.box_lo, 3, e, err);
        if (st == SCAF_OK) st = unit_scale_up(h->sum.box_hi, 3, e, err);
        if (st == SCAF_OK) st = unit_scale_up(&h->sum.diagonal_before, 1, e, err);
    }
    tet_box_mesh_free(&tm); /* empty after a failure */
    free(W);
    if (st != SCAF_OK) drop_result(h);
    return st;
}

/* ---- untangle ----------------------------------------------------------- */

typedef struct progress_relay {
    scaf_volume_progress_fn progress;
    void *user;
} progress_relay;

static int relay_untangle(const untangle_event *e, void *user)
{
    const progress_relay *r = user;
    if (!r->progress) return 0;
    scaf_volume_step_info_t info;
    memset(&info, 0, sizeof info);
    info.phase = e->phase == UNTANGLE_FLOW ? SCAF_VOLUME_FLOW_STEP : SCAF_VOLUME_ITERATION;
    info.step = e->step;
    info.seconds = e->seconds;
    info.defects = e->pairs;
    info.pairs = -1;
    info.energy = e->energy;
    info.arap = e->arap;
    info.rms = e->rms;
    info.max = e->max;
    info.tets = e->tets;
    info.quality_min = e->quality;
    return r->progress(&info, r->user);
}

scaf_status scaf_untangle(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                          const scaf_untangle_options_t *options, scaf_volume_progress_fn progress,
                          void *user)
{
    scaf_untangle_options_t o;
    OPTIONS_CHECK(scaf_untangle_options_t, options, o, scaf_untangle_options_default(),
                  untangle_options_valid);
    scaf_error *err = &h->err;
    scaf_status st = simplex_arrays_check(nv, V, nf, F, 3, "face", err);
    if (st != SCAF_OK) return st;
    /* at unit scale first: areas overflow at 1e300 and vanish at 1e-300,
     * and untangle_run's own input check measures them */
    int e = 0;
    double *W = unit_copy(nv, V, nf, F, &e, err);
    if (!W) return err->code;
    untangle_options u = untangle_internal(&o);
    progress_relay relay = {progress, user};
    untangle_result r;
    st = untangle_run(nv, W, nf, F, &u, relay_untangle, &relay, &r, err);
    free(W);
    if (st != SCAF_OK) return st;
    h->nv = nv;
    h->X = r.X;
    h->flowed = r.flowed;
    r.X = r.flowed = NULL;
    h->kind = RESULT_UNTANGLE;
    scaf_volume_summary_t *s = &h->sum;
    s->steps = r.flow_steps;
    s->iterations = r.iterations;
    s->input_defects = r.input_pairs;
    s->diagonal_before = ldexp(r.diagonal, e); /* distances are relative to it */
    s->best_iteration = r.best_iteration;
    s->stop = (scaf_untangle_stop)r.stop;
    s->flowed_rms = r.flowed_rms;
    s->flowed_max = r.flowed_max;
    s->rms = r.rms;
    s->max = r.max;
    untangle_result_free(&r);
    size_t n3 = 3 * (size_t)nv;
    st = unit_scale_up(h->X, n3, e, err);
    if (st == SCAF_OK) st = unit_scale_up(h->flowed, n3, e, err);
    if (st != SCAF_OK) drop_result(h);
    return st;
}

/* ---- flow --------------------------------------------------------------- */

static int relay_flow(const surface_flow_event *e, void *user)
{
    const progress_relay *r = user;
    if (!r->progress) return 0;
    scaf_volume_step_info_t info;
    memset(&info, 0, sizeof info);
    info.phase = SCAF_VOLUME_FLOW_STEP;
    info.step = e->step;
    info.seconds = e->seconds;
    info.check_seconds = e->check_seconds;
    info.pairs = e->pairs;
    info.degenerate_faces = e->degenerate_faces;
    info.defects = e->pairs < 0 ? -1 : e->pairs + e->degenerate_faces;
    info.X = e->X;
    return r->progress(&info, r->user);
}

scaf_status scaf_flow(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                      const scaf_flow_options_t *options, scaf_volume_progress_fn progress,
                      void *user)
{
    scaf_flow_options_t o;
    OPTIONS_CHECK(scaf_flow_options_t, options, o, scaf_flow_options_default(), flow_options_check);
    scaf_error *err = &h->err;
    scaf_status st = simplex_arrays_check(nv, V, nf, F, 3, "face", err);
    if (st == SCAF_OK) st = closed_input(nv, V, nf, F, "the flow", err);
    if (st != SCAF_OK) return st;
    int e = 0;
    double *W = unit_copy(nv, V, nf, F, &e, err);
    if (!W) return err->code;
    h->X = malloc(sizeof(double) * 3 * (size_t)nv);
    if (!h->X) {
        free(W);
        return err_nomem(err, "flow result");
    }
    h->nv = nv;
    h->sum.diagonal_before = ldexp(inflate_bbox_diagonal(nv, W), e);
    /* the flow normalizes the surface: the result needs no scaling back */
    surface_flow_options fo = {o.delta, o.steps, o.until_free, 0};
    progress_relay relay = {progress, user};
    surface_flow_result r;
    st = surface_flow_run(nv, W, nf, F, &fo, h->X, relay_flow, &relay, &r, err);
    free(W);
    h->sum.steps = r.steps;
    h->sum.input_defects = r.input_defects;
    h->sum.defects = r.defects;
    if (st == SCAF_OK && o.until_free && r.defects != 0) {
        if (r.degenerate_faces > 0)
            err_set(err, SCAF_ERR_NUMERIC,
                    "the surface still intersects itself after %d steps (%lld intersecting face "
                    "pairs, %d zero-area faces)",
                    o.steps, r.pairs, r.degenerate_faces);
        else
            err_set(err, SCAF_ERR_NUMERIC,
                    "the surface still intersects itself after %d steps (%lld intersecting face "
                    "pairs)",
                    o.steps, r.pairs);
        st = SCAF_ERR_NUMERIC;
    }
    if (st == SCAF_OK || st == SCAF_ERR_CANCELLED || st == SCAF_ERR_NUMERIC) h->kind = RESULT_FLOW;
    else drop_result(h);
    return st;
}
