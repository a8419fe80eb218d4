/* app/seam_source: the seams a run cuts along (see the header). */
#include "app/seam_source.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/uv_fans.h"
#include "mesh/chart_segment.h"
#include "mesh/cut_graph.h"
#include "mesh/uv_charts.h"

void seam_plan_free(seam_plan *plan)
{
    if (!plan) return;
    free(plan->UV);
    free(plan->FT);
    memset(plan, 0, sizeof *plan);
}

const char *seam_source_name(scaf_seams s)
{
    switch (s) {
    case SCAF_SEAMS_INPUT: return "input";
    case SCAF_SEAMS_AUTO: return "auto";
    case SCAF_SEAMS_EXTEND: return "extend";
    case SCAF_SEAMS_DEFAULT: break;
    }
    return "default";
}

static int kind_is_disk(mesh_chart_kind k)
{
    return k == MESH_CHART_DISK || k == MESH_CHART_DISK_WITH_HOLES;
}

static int kind_is_broken(mesh_chart_kind k)
{
    return k == MESH_CHART_NON_MANIFOLD || k == MESH_CHART_MISORIENTED ||
        k == MESH_CHART_NON_ORIENTABLE;
}

/* The charts of m (UV charts with UVs, components without): *first_bad
 * gets the first chart that is not a disk (-1 if none) and *kind its
 * kind; *nch the chart count. With fail_broken, a non-manifold,
 * misoriented or non-orientable chart is an error naming where. */
static scaf_status survey(const mesh *m, int fail_broken, int *nch, int *first_bad,
                          mesh_chart_kind *kind, scaf_error *err)
{
    mesh_charts ch;
    scaf_status st = mesh_charts_compute(m, &ch, err);
    if (st != SCAF_OK) return st;
    *first_bad = -1;
    *nch = ch.ncharts;
    for (int c = 0; c < ch.ncharts; c++) {
        mesh_chart_kind k = mesh_chart_classify(&ch, c);
        if (fail_broken && kind_is_broken(k)) {
            st = mesh_chart_check(&ch, c, 1, err);
            if (st == SCAF_OK)
                st = err_set(err, SCAF_ERR_MESH, "chart %d is %s", c, mesh_chart_kind_name(k));
            break;
        }
        if (!kind_is_disk(k) && *first_bad < 0) {
            *first_bad = c;
            *kind = k;
        }
    }
    mesh_charts_free(&ch);
    return st;
}

/* m with its UV indices split into one per fan: *FT2 (nf by 3), *nuv2 and
 * the original index of each (*orig). */
static scaf_status split_uv(const mesh *m, int **FT2, int *nuv2, int **orig, scaf_error *err)
{
    *FT2 = malloc(sizeof(int) * 3 * (size_t)m->nf);
    if (!*FT2) return err_nomem(err, "seams");
    return uv_split_fans(m->nf, m->FT, m->nuv, *FT2, nuv2, orig, err);
}

static void take_cut(seam_plan *plan, cut_graph *g)
{
    plan->changed = 1;
    plan->nuv = g->nsplit;
    plan->FT = g->FT;
    g->FT = NULL;
    plan->cut_edges = g->cut_edges;
    plan->handle_loops = g->handle_loops;
    plan->cones = g->cones;
}

/* Automatic seams on the 3D surface. */
static scaf_status plan_auto(const mesh *m, int segment, seam_plan *plan, scaf_error *err)
{
    mesh m3 = {m->nv, m->V, m->nf, m->F, 0, NULL, NULL};
    int nch = 0, bad = -1;
    mesh_chart_kind kind = MESH_CHART_DISK;
    scaf_status st = survey(&m3, 1, &nch, &bad, &kind, err);
    if (st != SCAF_OK) return st;
    int *label = NULL;
    if (segment) {
        label = malloc(sizeof(int) * (size_t)m->nf);
        if (!label) return err_nomem(err, "seams");
        chart_segment_options so;
        chart_segment_defaults(&so);
        st = chart_segment(m->nv, m->V, m->nf, m->F, &so, label, &plan->segments, err);
        if (st != SCAF_OK) {
            free(label);
            return st;
        }
    }
    cut_graph g;
    st = cut_graph_compute(m->nv, m->V, m->nf, m->F, label, NULL, &g, err);
    free(label);
    if (st != SCAF_OK) return st;
    plan->used = SCAF_SEAMS_AUTO;
    take_cut(plan, &g);
    cut_graph_free(&g);
    plan->UV = calloc(2 * (size_t)(plan->nuv ? plan->nuv : 1), sizeof(double));
    if (!plan->UV) return err_nomem(err, "seams");
    return SCAF_OK;
}

/* The input's seams, cut further where a UV chart is not a disk. */
static scaf_status plan_extend(const mesh *m, seam_plan *plan, scaf_error *err)
{
    int *FT2 = NULL, *orig = NULL, nuv2 = 0;
    double *P = NULL;
    cut_graph g;
    memset(&g, 0, sizeof g);
    scaf_status st = split_uv(m, &FT2, &nuv2, &orig, err);
    if (st != SCAF_OK) goto done;
    mesh m2 = {m->nv, m->V, m->nf, m->F, nuv2, m->UV, FT2};
    /* m2's UV values are not read by the survey: only the indices */
    int nch = 0, bad = -1;
    mesh_chart_kind kind = MESH_CHART_DISK;
    st = survey(&m2, 1, &nch, &bad, &kind, err);
    if (st != SCAF_OK) goto done;
    P = malloc(sizeof(double) * 3 * (size_t)(nuv2 ? nuv2 : 1));
    if (!P) {
        st = err_nomem(err, "seams");
        goto done;
    }
    for (int c = 0; c < 3 * m->nf; c++)
        memcpy(P + 3 * (size_t)FT2[c], m->V + 3 * (size_t)m->F[c], sizeof(double) * 3);
    st = cut_graph_compute(nuv2, P, m->nf, FT2, NULL, NULL, &g, err);
    if (st != SCAF_OK) goto done;
    plan->used = SCAF_SEAMS_EXTEND;
    take_cut(plan, &g);
    plan->UV = malloc(sizeof(double) * 2 * (size_t)(plan->nuv ? plan->nuv : 1));
    if (!plan->UV) {
        st = err_nomem(err, "seams");
        goto done;
    }
    for (int i = 0; i < plan->nuv; i++)
        memcpy(plan->UV + 2 * (size_t)i, m->UV + 2 * (size_t)orig[g.split_vertex[i]],
               sizeof(double) * 2);
done:
    cut_graph_free(&g);
    free(FT2);
    free(orig);
    free(P);
    return st;
}

scaf_status seam_plan_make(const mesh *m, scaf_seams mode, int segment, seam_plan *plan,
                           scaf_error *err)
{
    memset(plan, 0, sizeof *plan);
    if ((int)mode < 0 || mode > SCAF_SEAMS_EXTEND)
        return err_set(err, SCAF_ERR_USAGE, "seams is not default, input, auto or extend");
    int has_uv = mesh_has_uv(m);
    scaf_status st = SCAF_OK;
    if (mode == SCAF_SEAMS_INPUT) {
        plan->used = SCAF_SEAMS_INPUT;
        snprintf(plan->why, sizeof plan->why, "%s",
                 has_uv ? "the input's vt, as asked" : "one chart per component, as asked");
        return SCAF_OK;
    }
    if (mode == SCAF_SEAMS_DEFAULT) {
        int nch = 0, bad = -1;
        mesh_chart_kind kind = MESH_CHART_DISK;
        if (has_uv) {
            int *FT2 = NULL, nuv2 = 0;
            st = split_uv(m, &FT2, &nuv2, NULL, err);
            mesh m2 = {m->nv, m->V, m->nf, m->F, nuv2, m->UV, FT2};
            if (st == SCAF_OK) st = survey(&m2, 0, &nch, &bad, &kind, err);
            free(FT2);
            if (st != SCAF_OK) return st;
            if (bad < 0) {
                plan->used = SCAF_SEAMS_INPUT;
                snprintf(plan->why, sizeof plan->why, "the input's vt cut it into %d disk(s)", nch);
                return SCAF_OK;
            }
            st = plan_auto(m, segment, plan, err);
            if (st == SCAF_OK)
                snprintf(plan->why, sizeof plan->why, "the input's vt chart %d is not a disk (%s)",
                         bad, mesh_chart_kind_name(kind));
            return st;
        }
        mesh m3 = {m->nv, m->V, m->nf, m->F, 0, NULL, NULL};
        st = survey(&m3, 1, &nch, &bad, &kind, err);
        if (st != SCAF_OK) return st;
        if (bad < 0 && !segment) {
            plan->used = SCAF_SEAMS_INPUT;
            snprintf(plan->why, sizeof plan->why, "no vt: one chart per component, each a disk");
            return SCAF_OK;
        }
        st = plan_auto(m, segment, plan, err);
        if (st == SCAF_OK) {
            if (bad >= 0)
                snprintf(plan->why, sizeof plan->why, "no vt, and component %d is not a disk (%s)",
                         bad, mesh_chart_kind_name(kind));
            else snprintf(plan->why, sizeof plan->why, "no vt");
        }
        return st;
    }
    if (mode == SCAF_SEAMS_EXTEND && has_uv) {
        st = plan_extend(m, plan, err);
        if (st == SCAF_OK)
            snprintf(plan->why, sizeof plan->why,
                     "the input's vt and %d edge(s) cut more, as asked", plan->cut_edges);
        return st;
    }
    st = plan_auto(m, segment, plan, err);
    if (st == SCAF_OK)
        snprintf(plan->why, sizeof plan->why, "%s",
                 mode == SCAF_SEAMS_EXTEND ? "no vt to extend" : "as asked");
    return st;
}
