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
    /* The loop runs on the vertices numbered breadth first, as scaf
     * param's working mesh (mesh/vertex_order): a triangle's corners get
     * close numbers whatever the input's order, so the iteration's passes
     * stay in cache. rank[v]: input vertex v's working number. */
    size_t nv1 = (size_t)(nv > 0 ? nv : 1);
    int *rank = malloc(sizeof(int) * nv1),
        *Fw = malloc(sizeof(int) * 3 * (size_t)(nf > 0 ? nf : 1));
    int *hw = malloc(sizeof(int) * (size_t)(nh > 0 ? nh : 1));
    double *V3 = malloc(sizeof(double) * 3 * nv1), *Pw = malloc(sizeof(double) * 2 * nv1);
    if (!rank || !Fw || !hw || !V3 || !Pw) st = err_nomem(err, "deform");
    if (st == SCAF_OK) st = mesh_vertex_order_breadth_first(3, nf, F, nv, rank, err);
    if (st != SCAF_OK) {
        free(rank);
        free(Fw);
        free(hw);
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
        return st;
    }
    hv = hw;
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
    if (o->iterations == 0) r->stop = SCAF_STOP_NONE;
    r->energy = scaf_loop_energy(&L);
    r->max_handle_error = opt_handle_term_max_error(&h, L.uv);
    r->iterations = L.iterations;
    scaf_loop_free(&L);
    opt_handle_term_free(&h);
    free(rank);
    free(hw);
    return st;
}
