/* app/deform: planar deformation with soft handles (see deform.h). */
#include "app/deform.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"
#include "mesh/vertex_order.h"
#include "opt/handle_term.h"
#include "scaffold/scaf_loop.h"
#include "scaffold/scaffold_cdt.h"
#include "scaffold/scaffold_frozen.h"

deform_options deform_options_default(void)
{
    deform_options o;
    memset(&o, 0, sizeof o);
    o.iterations = 100;
    o.tolerance = 1e-12;
    o.weight_ratio = OPT_HANDLE_WEIGHT_RATIO_DEFAULT;
    o.frame_iterations = 4;
    o.stall_iterations = 20;
    return o;
}

static scaf_status rest_is_ccw(int nv, const double *P, int nf, const int *F, scaf_error *err)
{
    for (int f = 0; f < nf; f++) {
        for (int i = 0; i < 3; i++)
            if (F[3 * f + i] < 0 || F[3 * f + i] >= nv)
                return err_set(err, SCAF_ERR_MESH, "triangle %d: vertex %d out of range", f + 1,
                               F[3 * f + i] + 1);
        if (orient2d(P + 2 * (size_t)F[3 * f], P + 2 * (size_t)F[3 * f + 1],
                     P + 2 * (size_t)F[3 * f + 2]) <= 0)
            return err_set(err, SCAF_ERR_MESH,
                           "triangle %d is not counter-clockwise in the plane (flipped or "
                           "degenerate): the rest "
                           "shape must be a planar embedding",
                           f + 1);
    }
    return SCAF_OK;
}

/* Before any work: pins in range and not handles, and every triangle
 * whose three corners are held (pinned at rest, or a hard handle at its
 * target) positively oriented there; otherwise no bijective map holds
 * them (r->infeasible = 1). */
static scaf_status held_check(int nv, const double *P, int nf, const int *F, int nh, const int *hv,
                              const double *ht, const deform_options *o, deform_result *r,
                              scaf_error *err)
{
    if (o->npins < 0 || (o->npins > 0 && !o->pins))
        return err_set(err, SCAF_ERR_USAGE, "deform: %d pins but no pin array", o->npins);
    if (!o->hard && o->npins == 0) return SCAF_OK;
    double *H = malloc(sizeof(double) * 2 * (size_t)(nv > 0 ? nv : 1));
    signed char *why = calloc((size_t)(nv > 0 ? nv : 1), 1); /* 1 pin, 2 hard handle */
    if (!H || !why) {
        free(H);
        free(why);
        return err_nomem(err, "deform");
    }
    scaf_status st = SCAF_OK;
    for (int i = 0; i < o->npins && st == SCAF_OK; i++) {
        int v = o->pins[i];
        if (v < 0 || v >= nv)
            st = err_set(err, SCAF_ERR_USAGE, "pin %d: vertex %d is not in [0, %d)", i, v, nv);
        else {
            why[v] = 1;
            H[2 * v] = P[2 * v], H[2 * v + 1] = P[2 * v + 1];
        }
    }
    for (int i = 0; i < nh && st == SCAF_OK; i++) {
        if (why[hv[i]] == 1)
            st = err_set(err, SCAF_ERR_USAGE,
                         "vertex %d is pinned and handle %d: a pinned vertex has no target", hv[i],
                         i);
        else if (o->hard && o->hard[i]) {
            why[hv[i]] = 2;
            H[2 * hv[i]] = ht[2 * i], H[2 * hv[i] + 1] = ht[2 * i + 1];
        }
    }
    for (int f = 0; f < nf && st == SCAF_OK; f++) {
        const int *t = F + 3 * f;
        if (!why[t[0]] || !why[t[1]] || !why[t[2]]) continue;
        if (orient2d(H + 2 * (size_t)t[0], H + 2 * (size_t)t[1], H + 2 * (size_t)t[2]) > 0.0)
            continue;
        r->infeasible = 1;
        st = err_set(err, SCAF_ERR_MESH,
                     "infeasible: triangle %d has all three corners held (vertices %d, %d, %d: "
                     "%s, %s, %s) and is flipped or degenerate at those positions: no bijective "
                     "map holds them",
                     f + 1, t[0], t[1], t[2], why[t[0]] == 1 ? "pinned" : "hard target",
                     why[t[1]] == 1 ? "pinned" : "hard target",
                     why[t[2]] == 1 ? "pinned" : "hard target");
    }
    free(H);
    free(why);
    return st;
}

/* The largest distance of a hard handle not reached yet to its target
 * (working positions X); 0 when none is left. */
static double hard_missing_error(int nh, const int *hw, const double *ht, const unsigned char *hard,
                                 const unsigned char *done, const double *X)
{
    double m = 0.0;
    for (int i = 0; i < nh; i++)
        if (hard[i] && !done[i]) {
            double e =
                hypot(X[2 * (size_t)hw[i]] - ht[2 * i], X[2 * (size_t)hw[i] + 1] - ht[2 * i + 1]);
            if (e > m) m = e;
        }
    return m;
}

/* out (input numbering) from X (working numbering), nv by 2. */
static void to_input(int nv, const int *rank, const double *X, double *out)
{
    for (int v = 0; v < nv; v++) {
        out[2 * v] = X[2 * (size_t)rank[v]];
        out[2 * v + 1] = X[2 * (size_t)rank[v] + 1];
    }
}

scaf_status deform_run(int nv, const double *P, int nf, const int *F, int nh, const int *hv,
                       const double *ht, int nframes, const double *frames, deform_options *o,
                       double *out, deform_result *r, scaf_error *err)
{
    deform_options def = deform_options_default();
    if (!o) o = &def;
    memset(r, 0, sizeof *r);
    memcpy(out, P, sizeof(double) * 2 * (size_t)nv);
    if (nframes < 0 || (nframes > 0 && o->frame_iterations < 1))
        return err_set(err, SCAF_ERR_USAGE,
                       "deform: a drag needs at least one iteration per waypoint");
    if (o->iterations < 0 || !(o->weight_ratio >= 0.0) || !isfinite(o->weight_ratio) ||
        !(o->tolerance >= 0.0))
        return err_set(err, SCAF_ERR_USAGE,
                       "deform: iterations >= 0, a finite weight ratio >= 0 and a tolerance >= 0 "
                       "are needed");
    scaf_status st = rest_is_ccw(nv, P, nf, F, err);
    if (st != SCAF_OK) return st;
    for (int i = 0; i < nh; i++) /* checked here: the loop sees other numbers */
        if (hv[i] < 0 || hv[i] >= nv)
            return err_set(err, SCAF_ERR_USAGE, "handle %d: vertex %d is not in [0, %d)", i, hv[i],
                           nv);
    st = held_check(nv, P, nf, F, nh, hv, ht, o, r, err);
    if (st != SCAF_OK) return st;
    for (int i = 0; o->hard && i < nh; i++) r->hard += o->hard[i] != 0;
    /* The loop runs on the vertices numbered breadth first, as scaf
     * param's working mesh (mesh/vertex_order): a triangle's corners get
     * close numbers whatever the input's order, so the iteration's passes
     * stay in cache. rank[v]: input vertex v's working number. */
    size_t nv1 = (size_t)(nv > 0 ? nv : 1);
    int *rank = malloc(sizeof(int) * nv1),
        *Fw = malloc(sizeof(int) * 3 * (size_t)(nf > 0 ? nf : 1));
    int *hw = malloc(sizeof(int) * (size_t)(nh > 0 ? nh : 1));
    unsigned char *done = calloc((size_t)(nh > 0 ? nh : 1), 1); /* hard target reached */
    double *V3 = malloc(sizeof(double) * 3 * nv1), *Pw = malloc(sizeof(double) * 2 * nv1);
    if (!rank || !Fw || !hw || !done || !V3 || !Pw) st = err_nomem(err, "deform");
    if (st == SCAF_OK) st = mesh_vertex_order_breadth_first(3, nf, F, nv, rank, err);
    if (st != SCAF_OK) {
        free(rank);
        free(Fw);
        free(hw);
        free(done);
        free(V3);
        free(Pw);
        return st;
    }
    for (size_t k = 0; k < 3 * (size_t)nf; k++) Fw[k] = rank[F[k]];
    for (int i = 0; i < nh; i++) hw[i] = rank[hv[i]];
    for (int v = 0; v < nv; v++) {
        int r = rank[v];
        Pw[2 * r] = P[2 * v];
        Pw[2 * r + 1] = P[2 * v + 1];
        V3[3 * r] = P[2 * v];
        V3[3 * r + 1] = P[2 * v + 1];
        V3[3 * r + 2] = 0.0;
    }
    scaf_loop L;
    opt_handle_term h;
    opt_handle_term_init(&h, 2, nv);
    st = scaf_loop_init(&L, nv, V3, nf, Fw, Pw, NULL, err);
    free(V3);
    free(Pw);
    free(Fw);
    if (st != SCAF_OK) {
        free(rank);
        free(hw);
        free(done);
        return st;
    }
    hv = hw;
    for (int i = 0; i < o->npins && st == SCAF_OK; i++)
        st = scaf_loop_pin(&L, rank[o->pins[i]], 1, err);
    double w = opt_handle_weight(o->weight_ratio, L.total_area, nh);
    st = opt_handle_term_set(&h, nh, hv, nframes > 0 ? frames : ht, w, err);
    if (st == SCAF_OK) {
        opt_obj_term t = opt_handle_term_make(&h);
        st = scaf_loop_add_term(&L, &t, err);
    }
    if (st == SCAF_OK && o->no_remesh) {
        scaffold_provider *cdt = scaffold_cdt_create(L.nv, L.bedges, L.nbedges, err);
        scaffold_provider *fz = cdt ? scaffold_frozen_create(cdt, err) : NULL;
        st = fz ? scaf_loop_set_scaffold_provider(&L, fz, err) : SCAF_ERR_NOMEM;
        if (st != SCAF_OK) scaffold_provider_destroy(fz);
    }
    r->stop = SCAF_STOP_ITERATIONS;
    int stalled = 0;
    double best_missing = INFINITY;
    for (int it = 0; st == SCAF_OK && it < o->iterations; it++) {
        int frame = it / (o->frame_iterations > 0 ? o->frame_iterations : 1);
        int dragging = frame < nframes;
        if (it > 0 && it % o->frame_iterations == 0 && frame <= nframes) {
            st = opt_handle_term_set(
                &h, nh, hv, dragging ? frames + 2 * (size_t)frame * (size_t)nh : ht, w, err);
            if (st != SCAF_OK) break;
        }
        scaf_iteration_info_t info;
        st = scaf_loop_step(&L, &info, err);
        if (st != SCAF_OK) {
            r->stop = SCAF_STOP_ERROR;
            break;
        }
        /* hard targets: placed exactly where that flips nothing, then
         * pinned (once the drag's waypoints are done) */
        int reached = 0;
        for (int i = 0; o->hard && !dragging && i < nh; i++)
            if (o->hard[i] && !done[i] && scaf_loop_place(&L, hv[i], ht + 2 * (size_t)i)) {
                st = scaf_loop_pin(&L, hv[i], 1, err);
                if (st != SCAF_OK) break;
                done[i] = 1;
                reached++;
            }
        if (st != SCAF_OK) break;
        r->hard_reached += reached;
        int missing = r->hard_reached < r->hard;
        if (missing && !dragging) {
            double e = hard_missing_error(nh, hv, ht, o->hard, done, L.uv);
            stalled = reached > 0 || e < (1.0 - 1e-3) * best_missing ? 0 : stalled + 1;
            if (e < best_missing) best_missing = e;
        }
        to_input(nv, rank, L.uv, out);
        r->iterations = L.iterations;
        if (o->progress) {
            o->current = out;
            int stop = o->progress(&info, o->user);
            o->current = NULL;
            if (stop) {
                r->stop = SCAF_STOP_CANCELLED;
                break;
            }
        }
        if (dragging) continue;
        /* hard targets left: placements may still come while the map
         * moves or one was just made; a bounded stall ends the run */
        if (missing && o->stall_iterations > 0 && stalled >= o->stall_iterations) {
            r->stop = SCAF_STOP_TOLERANCE;
            break;
        }
        if (missing && reached > 0) continue;
        if (!(info.step > 0.0)) {
            r->stop = SCAF_STOP_ZERO_STEP;
            break;
        }
        if (o->tolerance > 0.0 &&
            info.total_before - info.total_after < o->tolerance * fabs(info.total_before)) {
            r->stop = SCAF_STOP_TOLERANCE;
            break;
        }
    }
    if (st == SCAF_OK && r->hard_reached < r->hard) r->infeasible = 2;
    if (o->iterations == 0) r->stop = SCAF_STOP_NONE;
    r->energy = scaf_loop_energy(&L);
    r->max_handle_error = opt_handle_term_max_error(&h, L.uv);
    r->iterations = L.iterations;
    scaf_loop_free(&L);
    opt_handle_term_free(&h);
    free(rank);
    free(hw);
    free(done);
    return st;
}
