/* app/untangle: flow out, flow back (see untangle.h).
 *
 * check input -> exact check (free: done) -> flow steps, each checked
 * exactly in the input's frame -> volume_deform from the freed surface
 * toward the input, one iteration at a time, until the energy stops
 * decreasing. Every step is logged and reported to the caller.
 */
#include "app/untangle.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "app/inflate.h"
#include "app/surface_flow.h"
#include "geom/self_intersect.h"
#include "mesh/closed_surface.h"
#include "opt/handle_term.h"

#define UNTANGLE_MAX_STEPS 100000

untangle_options untangle_options_default(void)
{
    untangle_options o;
    memset(&o, 0, sizeof o);
    o.delta = 1e-3;
    o.flow_steps = 1000;
    o.iterations = 300;
    o.tolerance = 1e-2;
    o.verify = 0;
    o.anchor_ratio = UNTANGLE_ANCHOR_DEFAULT;
    o.deform = volume_deform_options_default();
    /* measured on leg-intersect.off (bench/RESULTS-untangle.md): SLIM beats
     * Newton here (25 iterations: RMS 0.0146 vs 0.0279 at the same cost).
     * The improvement pass with splits grows the tets from 49.5k to 85k
     * and costs 1.17 s per iteration; without splits (flips, edge and
     * multi-face removal: TetGen's scaffold has no free vertex to smooth)
     * it keeps 40k tets, costs 0.21 s CPU per iteration against 0.17 s
     * with no pass, and ends nearer the input (RMS 0.00805 vs 0.00857) */
    o.deform.solver = SCAF_SOLVER_SLIM;
    o.deform.improve = 1;
    o.deform.improve_opt.ops = TET_OP_ALL & ~(unsigned)TET_OP_SPLIT;
    return o;
}

scaf_status untangle_options_check(const untangle_options *o, scaf_error *err)
{
    if (!(o->delta > 0.0) || !(o->delta <= 1e6))
        return err_set(err, SCAF_ERR_USAGE, "untangle: flow time step %g must be in (0, 1e6]",
                       o->delta);
    if (o->flow_steps < 1 || o->flow_steps > UNTANGLE_MAX_STEPS)
        return err_set(err, SCAF_ERR_USAGE, "untangle: %d flow steps, expected 1..%d",
                       o->flow_steps, UNTANGLE_MAX_STEPS);
    if (o->iterations < 1 || o->iterations > UNTANGLE_MAX_STEPS)
        return err_set(err, SCAF_ERR_USAGE, "untangle: %d iterations, expected 1..%d",
                       o->iterations, UNTANGLE_MAX_STEPS);
    if (!(o->tolerance >= 0.0) || !(o->tolerance < 1.0))
        return err_set(err, SCAF_ERR_USAGE, "untangle: tolerance %g must be in [0, 1)",
                       o->tolerance);
    if (!(o->anchor_ratio >= 0.0) || !(o->anchor_ratio <= 1e12))
        return err_set(err, SCAF_ERR_USAGE, "untangle: anchor weight %g must be in [0, 1e12]",
                       o->anchor_ratio);
    return SCAF_OK;
}

const char *untangle_stop_name(untangle_stop s)
{
    switch (s) {
    case UNTANGLE_ALREADY_FREE: return "already_free";
    case UNTANGLE_CONVERGED: return "converged";
    case UNTANGLE_NO_STEP: return "zero_step";
    case UNTANGLE_ITERATION_LIMIT: return "iteration_limit";
    }
    return "unknown";
}

void untangle_result_free(untangle_result *r)
{
    free(r->flowed);
    free(r->X);
    free(r->log);
    memset(r, 0, sizeof *r);
}

/* RMS and maximum distance of X to X0 (nv by 3), divided by diag. */
static void distances(int nv, const double *X, const double *X0, double diag, double *rms,
                      double *max)
{
    double s = 0.0, m = 0.0;
    for (size_t i = 0; i < (size_t)nv; i++) {
        double d2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double d = X[3 * i + k] - X0[3 * i + k];
            d2 += d * d;
        }
        s += d2;
        if (d2 > m) m = d2;
    }
    double unit = diag > 0.0 ? diag : 1.0;
    *rms = sqrt(s / (nv > 0 ? nv : 1)) / unit;
    *max = sqrt(m) / unit;
}

/* Intersecting pairs + zero-area faces of the surface X (0: free). */
static scaf_status defects(int nv, const double *X, int nf, const int *F, long long *n,
                           scaf_error *err)
{
    si_report rep;
    scaf_status st = si_check(nv, X, nf, F, &rep, err);
    if (st == SCAF_OK) *n = rep.pairs + rep.degenerate_faces;
    return st;
}

/* Append e to the log and tell the caller: SCAF_ERR_CANCELLED when it
 * asks to stop. */
static scaf_status record(untangle_result *r, int *cap, const untangle_event *e,
                          untangle_progress progress, void *user, scaf_error *err)
{
    if (r->nlog == *cap) {
        int n = *cap ? 2 * *cap : 64;
        untangle_event *g = realloc(r->log, sizeof *g * (size_t)n);
        if (!g) return err_nomem(err, "untangle log");
        r->log = g;
        *cap = n;
    }
    r->log[r->nlog] = *e;
    r->log[r->nlog++].X = NULL;
    if (progress && progress(e, user))
        return err_set(err, SCAF_ERR_CANCELLED, "untangle: cancelled after %s step %d",
                       e->phase == UNTANGLE_FLOW ? "flow" : "iteration", e->step);
    return SCAF_OK;
}

/* The flow's steps as untangle's events (app/surface_flow calls it). */
typedef struct flow_events {
    untangle_result *r;
    int *cap;
    const double *V;
    int nv;
    untangle_progress progress;
    void *user;
    scaf_status status; /* of record(): the reason to stop */
    scaf_error err;
} flow_events;

static int on_flow_step(const surface_flow_event *f, void *user)
{
    flow_events *a = user;
    if (f->step == 0) return 0; /* the input's check: already done in r->input_pairs */
    untangle_event e;
    memset(&e, 0, sizeof e);
    e.phase = UNTANGLE_FLOW;
    e.step = a->r->flow_steps = f->step;
    e.seconds = f->seconds + f->check_seconds;
    e.pairs = f->pairs + f->degenerate_faces;
    e.X = f->X;
    distances(a->nv, f->X, a->V, a->r->diagonal, &e.rms, &e.max);
    a->status = record(a->r, a->cap, &e, a->progress, a->user, &a->err);
    return a->status != SCAF_OK;
}

/* Flow r->flowed (a copy of V) until it is free in V's frame (the one
 * flow-until-free loop, app/surface_flow); r->input_pairs its start. */
static scaf_status flow_out(int nv, const double *V, int nf, const int *F,
                            const untangle_options *o, untangle_progress progress, void *user,
                            untangle_result *r, int *cap, scaf_error *err)
{
    surface_flow_options fo = {o->delta, o->flow_steps, 1, 1};
    flow_events a = {r, cap, V, nv, progress, user, SCAF_OK, {SCAF_OK, ""}};
    surface_flow_result fr;
    scaf_status st = surface_flow_run(nv, V, nf, F, &fo, r->flowed, on_flow_step, &a, &fr, err);
    r->input_pairs = fr.input_defects;
    if (a.status != SCAF_OK) {
        *err = a.err;
        return a.status;
    }
    if (st == SCAF_OK && fr.defects != 0)
        st = err_set(err, SCAF_ERR_NUMERIC,
                     "the flow did not free the surface in %d steps of %g (%lld intersecting "
                     "face pairs left)",
                     o->flow_steps, o->delta, fr.defects);
    return st;
}

/* Pull the surface from r->flowed back toward V; r->X receives the
 * iterate of lowest surface energy. */
static scaf_status flow_back(int nv, const double *V, int nf, const int *F,
                             const untangle_options *o, untangle_progress progress, void *user,
                             untangle_result *r, int *cap, scaf_error *err)
{
    volume_deform vd;
    scaf_status st = volume_deform_init(&vd, nv, r->flowed, nf, F, V, &o->deform, err);
    if (st != SCAF_OK) return st;
    /* the anchor: every vertex pulled toward its input position */
    opt_handle_term anchor;
    opt_handle_term_init(&anchor, 3, nv);
    int *all = malloc(sizeof(int) * (size_t)nv);
    if (!all) st = err_nomem(err, "untangle anchor");
    for (int i = 0; i < nv && all; i++) all[i] = i;
    if (st == SCAF_OK && o->anchor_ratio > 0.0) {
        st = opt_handle_term_set(&anchor, nv, all, V, o->anchor_ratio / (nv * vd.arap.area), err);
        opt_obj_term t = opt_handle_term_make(&anchor);
        if (st == SCAF_OK) st = scaf_loop_add_term(&vd.loop, &t, err);
    }
    free(all);
    if (st != SCAF_OK) {
        volume_deform_free(&vd);
        opt_handle_term_free(&anchor);
        return st;
    }
    /* lowest[k]: the lowest energy after k iterations (0: the start) */
    double *lowest = malloc(sizeof(double) * ((size_t)o->iterations + 1));
    if (!lowest) {
        volume_deform_free(&vd);
        opt_handle_term_free(&anchor);
        return err_nomem(err, "untangle energies");
    }
    lowest[0] = scaf_loop_energy(&vd.loop);
    r->stop = UNTANGLE_ITERATION_LIMIT;
    for (int it = 1; it <= o->iterations; it++) {
        volume_deform_iteration vi;
        st = volume_deform_step(&vd, &vi, err);
        if (st != SCAF_OK) break;
        const double *X = volume_deform_positions(&vd);
        r->iterations = it;
        untangle_event e;
        memset(&e, 0, sizeof e);
        e.phase = UNTANGLE_BACK;
        e.step = it;
        e.energy = vi.energy;
        e.arap = opt_surface_arap_energy(&vd.arap, X);
        e.tets = vi.tets;
        e.quality = vi.quality_min;
        e.pairs = -1;
        e.X = X;
        e.seconds = vi.seconds; /* the loop's time, without the check below */
        distances(nv, X, V, r->diagonal, &e.rms, &e.max);
        if (o->verify) {
            if ((st = defects(nv, X, nf, F, &e.pairs, err)) != SCAF_OK) break;
            if (e.pairs != 0) {
                st = err_set(err, SCAF_ERR_INTERNAL,
                             "untangle: the surface intersects itself after iteration %d (%lld "
                             "face pairs) although every tet stayed positive",
                             it, e.pairs);
                break;
            }
        }
        lowest[it] = lowest[it - 1];
        if (vi.energy < lowest[it] || r->best_iteration == 0) {
            /* a new lowest energy: the result so far */
            lowest[it] = vi.energy;
            r->best_iteration = it;
            memcpy(r->X, X, sizeof(double) * 3 * (size_t)nv);
        }
        if ((st = record(r, cap, &e, progress, user, err)) != SCAF_OK) break;
        if (!(vi.step > 0.0)) {
            r->stop = UNTANGLE_NO_STEP;
            break;
        }
        int w = it - UNTANGLE_WINDOW;
        if (w >= 0 && lowest[w] - lowest[it] <= o->tolerance * lowest[w]) {
            r->stop = UNTANGLE_CONVERGED;
            break;
        }
    }
    free(lowest);
    volume_deform_free(&vd);
    opt_handle_term_free(&anchor);
    return st;
}

scaf_status untangle_run(int nv, const double *V, int nf, const int *F, const untangle_options *o,
                         untangle_progress progress, void *user, untangle_result *r,
                         scaf_error *err)
{
    memset(r, 0, sizeof *r);
    untangle_options d = untangle_options_default();
    if (!o) o = &d;
    scaf_status st = untangle_options_check(o, err);
    if (st != SCAF_OK) return st;
    mesh m = {nv, (double *)V, nf, (int *)F, 0, NULL, NULL};
    if ((st = closed_surface_check(&m, 1, err)) != SCAF_OK) return st;
    r->flowed = malloc(sizeof(double) * 3 * (size_t)nv);
    r->X = malloc(sizeof(double) * 3 * (size_t)nv);
    if (!r->flowed || !r->X) {
        untangle_result_free(r);
        return err_nomem(err, "untangle result");
    }
    memcpy(r->flowed, V, sizeof(double) * 3 * (size_t)nv);
    memcpy(r->X, V, sizeof(double) * 3 * (size_t)nv);
    r->diagonal = inflate_bbox_diagonal(nv, V);
    int cap = 0;
    st = flow_out(nv, V, nf, F, o, progress, user, r, &cap, err);
    if (st == SCAF_OK && r->input_pairs == 0) {
        r->stop = UNTANGLE_ALREADY_FREE;
        return SCAF_OK;
    }
    if (st == SCAF_OK) {
        distances(nv, r->flowed, V, r->diagonal, &r->flowed_rms, &r->flowed_max);
        memcpy(r->X, r->flowed, sizeof(double) * 3 * (size_t)nv);
        st = flow_back(nv, V, nf, F, o, progress, user, r, &cap, err);
    }
    if (st == SCAF_OK) distances(nv, r->X, V, r->diagonal, &r->rms, &r->max);
    else untangle_result_free(r);
    return st;
}
