/* app/surface_flow: see surface_flow.h.
 *
 * normalize a copy (and keep the input's frame) -> check the start (with
 * until_free: free means done) -> cmcf from the input -> per step: solve,
 * map into the chosen frame, check, tell the caller. */
#include "app/surface_flow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "geom/self_intersect.h"
#include "opt/cmcf.h"

/* The exact check of X into e. */
static scaf_status check(int nv, const double *X, int nf, const int *F, surface_flow_event *e,
                         scaf_error *err)
{
    double t0 = timer_now();
    si_report rep;
    scaf_status st = si_check(nv, X, nf, F, &rep, err);
    e->check_seconds = timer_now() - t0;
    if (st != SCAF_OK) return st;
    e->pairs = rep.pairs;
    e->degenerate_faces = rep.degenerate_faces;
    return SCAF_OK;
}

static void note(surface_flow_result *r, const surface_flow_event *e)
{
    r->pairs = e->pairs;
    r->degenerate_faces = e->degenerate_faces;
    r->defects = e->pairs < 0 ? -1 : e->pairs + e->degenerate_faces;
}

scaf_status surface_flow_run(int nv, const double *V, int nf, const int *F,
                             const surface_flow_options *o, double *X,
                             surface_flow_progress progress, void *user, surface_flow_result *r,
                             scaf_error *err)
{
    memset(r, 0, sizeof *r);
    r->input_defects = r->defects = r->pairs = -1;
    size_t n3 = 3 * (size_t)nv;
    double c[3] = {0.0, 0.0, 0.0}, area = 1.0;
    scaf_status st = SCAF_OK;
    double *U = malloc(sizeof(double) * (n3 > 0 ? n3 : 1));
    if (!U) return err_nomem(err, "flow positions");
    memcpy(U, V, sizeof(double) * n3);
    if (o->input_frame) st = cmcf_frame(nv, V, nf, F, c, &area, err);
    if (st == SCAF_OK) st = cmcf_normalize(nv, U, nf, F, err);
    if (st != SCAF_OK) {
        free(U);
        return st;
    }
    double s = sqrt(area);
    /* the start: the input itself in its own frame, else normalized */
    memcpy(X, o->input_frame ? V : U, sizeof(double) * n3);
    surface_flow_event e;
    memset(&e, 0, sizeof e);
    e.pairs = -1;
    e.X = X;
    if (o->until_free && (st = check(nv, X, nf, F, &e, err)) == SCAF_OK) {
        note(r, &e);
        r->input_defects = r->defects;
    }
    if (st == SCAF_OK && progress && progress(&e, user))
        st = err_set(err, SCAF_ERR_CANCELLED, "flow: cancelled at the start");
    if (st != SCAF_OK || r->defects == 0) {
        free(U);
        return st;
    }
    cmcf f;
    if ((st = cmcf_init(&f, nv, V, nf, F, o->delta, err)) != SCAF_OK) {
        free(U);
        return st;
    }
    for (int step = 1; step <= o->steps; step++) {
        memset(&e, 0, sizeof e);
        e.pairs = -1;
        e.X = X;
        e.step = step;
        double t0 = timer_now();
        if ((st = cmcf_step(&f, U, err)) != SCAF_OK) break;
        e.seconds = timer_now() - t0;
        if (o->input_frame)
            for (size_t i = 0; i < n3; i++) X[i] = c[i % 3] + s * U[i];
        else memcpy(X, U, sizeof(double) * n3);
        if (o->until_free && (st = check(nv, X, nf, F, &e, err)) != SCAF_OK) break;
        r->steps = step;
        note(r, &e);
        if (progress && progress(&e, user)) {
            st = err_set(err, SCAF_ERR_CANCELLED, "flow: cancelled after step %d", step);
            break;
        }
        if (o->until_free && r->defects == 0) break;
    }
    cmcf_free(&f);
    free(U);
    return st;
}
