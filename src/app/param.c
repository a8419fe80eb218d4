/* app/param: the scaf_param_* API (see include/scaf/scaf.h).
 *
 * set_mesh: validates the arrays, finds the charts (mesh/uv_charts: UV
 * charts cut along seams, or components), checks each is a disk or a disk
 * with holes (naming the chart on failure), builds the working mesh (one
 * vertex per (chart, vertex-or-vt) pair), embeds every chart on a circle of
 * its 3D area (opt/embed: opt_embed_chart_best), places the circles on a grid so they do not
 * touch, and sets up the SCAF loop. run: iterates with progress and the
 * stopping rules. Errors leave a message readable by scaf_param_error.
 */
#include "app/param.h"
#include "app/api_options.h"
#include "app/seam_source.h"
#include "app/uv_fans.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"
#include "mesh/degenerate.h"
#include "mesh/mesh.h"
#include "geom/coord_scale.h"
#include "mesh/uv_charts.h"
#include "mesh/vertex_order.h"
#include "opt/convergence.h"
#include "opt/embed.h"
#include "opt/handle_term.h"
#include "scaffold/scaffold_defaults.h"

/* Boundary loops tried as the outer one of a chart with holes (the
 * longest first; see opt_embed_chart_best): on bad/plane_holes.obj (27
 * loops) the best start reaches E <= 50 in 12 iterations instead of 22. */
enum { OUTER_TRIES = 32 };

struct scaf_param {
    scaf_options_t opt;
    scaf_error err;
    int has_mesh;
    int nf;
    int ncharts;
    int nw;      /* working vertices */
    int *Fw;     /* nf by 3 working vertex per corner */
    int pos_exp; /* the loop works on positions / 2^pos_exp (geom/coord_scale) */
    scaf_loop loop;
    scaf_stop_reason stop;   /* why the last run stopped */
    opt_handle_term handles; /* soft positional constraints (scaf_param_set_handles) */
    int handles_added;       /* the term is in the loop */
    scaf_seams seams_used;   /* the seam source set_mesh used */
    char seams_why[200];     /* and why (app/seam_source) */
};

scaf_options_t scaf_options_default(void)
{
    scaf_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.energy = SCAF_ENERGY_SYMMETRIC_DIRICHLET;
    o.init = SCAF_INIT_MVC; /* fewest iterations on every measured mesh: bench/RESULTS-init.md */
    o.max_iterations = 200;
    o.tolerance = 1e-5;
    o.box_scale = SCAFFOLD_DEFAULT_BOX_SCALE;
    o.box_square = 0;
    o.box_points_per_side = SCAFFOLD_DEFAULT_BOX_POINTS_PER_SIDE;
    o.lambda_ratio = 0.01;
    o.min_angle_deg = SCAFFOLD_DEFAULT_MIN_ANGLE_DEG;
    o.step_fraction = 0.8;
    o.solver = SCAF_SOLVER_AUTO;
    return o;
}

scaf_loop_options param_loop_options(const scaf_options_t *o)
{
    scaf_loop_options lo = scaf_loop_options_default();
    lo.energy = (opt_energy)o->energy; /* the same table index (opt/energy_kind.h) */
    lo.lambda_ratio = o->lambda_ratio;
    lo.step_fraction = o->step_fraction;
    lo.solver = o->solver;
    lo.scaffold.box_scale = o->box_scale;
    lo.scaffold.box_square = o->box_square;
    lo.scaffold.box_points_per_side = o->box_points_per_side;
    lo.scaffold.min_angle_deg = o->min_angle_deg;
    return lo;
}

const char *scaf_phase_name(scaf_phase phase)
{
    switch (phase) {
    case SCAF_PHASE_ASSEMBLY: return "assembly";
    case SCAF_PHASE_ANALYSIS: return "analysis";
    case SCAF_PHASE_FACTORIZATION: return "factorization";
    case SCAF_PHASE_SOLVE: return "solve";
    case SCAF_PHASE_LINE_SEARCH: return "line_search";
    case SCAF_PHASE_SCAFFOLD: return "scaffold";
    case SCAF_PHASE_OTHER: return "other";
    case SCAF_PHASE_COUNT: break;
    }
    return "unknown";
}

scaf_status param_options_check(const scaf_options_t *o, char *msg, size_t size)
{
    const char *bad = NULL;
    if (!opt_energy_valid((int)o->energy))
        bad = "energy is not a known energy (0 <= energy < scaf_energy_count())";
    else if ((int)o->init < 0 || o->init > SCAF_INIT_MVC)
        bad = "init is not tutte, harmonic or mvc";
    else if (o->max_iterations < 0) bad = "max_iterations must be >= 0";
    else if (!(o->tolerance >= 0.0) || !isfinite(o->tolerance))
        bad = "tolerance must be a finite number >= 0";
    else if (!(o->box_scale >= 1.0) || !(o->box_scale <= 1e6))
        bad = "box_scale must be in [1, 1e6]";
    else if (o->box_points_per_side < 1 || o->box_points_per_side > 100000)
        bad = "box_points_per_side must be in [1, 100000]";
    else if (!(o->lambda_ratio > 0.0) || !isfinite(o->lambda_ratio))
        bad = "lambda_ratio must be > 0";
    else if (!(o->min_angle_deg >= 0.0) || !(o->min_angle_deg <= 30.0))
        bad = "min_angle_deg must be in [0, 30]";
    else if (!(o->step_fraction > 0.0) || !(o->step_fraction < 1.0))
        bad = "step_fraction must be in (0, 1)";
    else if ((int)o->solver < 0 || o->solver > SCAF_SOLVER_NEWTON)
        bad = "solver is not auto, slim or newton";
    else if ((int)o->seams < 0 || o->seams > SCAF_SEAMS_EXTEND)
        bad = "seams is not default, input, auto or extend";
    if (!bad) return SCAF_OK;
    if (msg && size) snprintf(msg, size, "invalid option: %s", bad);
    return SCAF_ERR_USAGE;
}

/* The caller's options into *out (NULL: defaults): SCAF_OK, or
 * SCAF_ERR_USAGE naming the struct_size or the first invalid field. */
static scaf_status options_take(scaf_options_t *out, const scaf_options_t *in, scaf_error *err)
{
    scaf_options_t def = scaf_options_default();
    scaf_status st = api_options_take(out, in, &def, sizeof def, "scaf_options_t", err);
    if (st != SCAF_OK) return st;
    char msg[256];
    if (param_options_check(out, msg, sizeof msg) != SCAF_OK)
        return err_set(err, SCAF_ERR_USAGE, "%s", msg); /* "invalid option: ..." */
    return SCAF_OK;
}

scaf_status scaf_options_check(const scaf_options_t *options, char *message, size_t size)
{
    scaf_error err;
    err_clear(&err);
    scaf_options_t o;
    scaf_status st = options ? options_take(&o, options, &err)
                             : err_set(&err, SCAF_ERR_USAGE, "options is NULL");
    if (message && size) snprintf(message, size, "%s", err.message);
    return st;
}

scaf_param_t *scaf_param_new(const scaf_options_t *options)
{
    scaf_options_t o;
    if (options_take(&o, options, NULL) != SCAF_OK) return NULL;
    scaf_param_t *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->opt = o;
    err_clear(&p->err);
    return p;
}

scaf_status scaf_param_set_options(scaf_param_t *p, const scaf_options_t *options)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    if (!options) return err_set(&p->err, SCAF_ERR_USAGE, "options is NULL");
    scaf_options_t o;
    scaf_status st = options_take(&o, options, &p->err);
    if (st != SCAF_OK) return st;
    p->opt = o;
    if (p->has_mesh) p->loop.opt = param_loop_options(&o);
    return SCAF_OK;
}

static void drop_mesh(scaf_param_t *p)
{
    scaf_loop_free(&p->loop);
    opt_handle_term_free(&p->handles);
    p->handles_added = 0;
    free(p->Fw);
    p->Fw = NULL;
    p->has_mesh = 0;
    p->nf = p->nw = p->ncharts = 0;
    p->stop = SCAF_STOP_NONE;
    p->seams_used = SCAF_SEAMS_DEFAULT;
}

void scaf_param_destroy(scaf_param_t *p)
{
    if (!p) return;
    drop_mesh(p);
    free(p);
}

const char *scaf_param_error(const scaf_param_t *p) { return p ? p->err.message : "no context"; }

const scaf_loop *param_loop(const scaf_param_t *p) { return p && p->has_mesh ? &p->loop : NULL; }

int param_working_map(const scaf_param_t *p, param_map *m)
{
    memset(m, 0, sizeof *m);
    if (!p || !p->has_mesh) return 0;
    m->nuv = p->loop.nv;
    m->uv = p->loop.uv;
    m->nf = p->loop.nf;
    m->FT = p->loop.F;
    return 1;
}

int param_face_energy(const scaf_param_t *p, double *E)
{
    if (!p || !p->has_mesh) return 0;
    scaf_loop_face_energy(&p->loop, E);
    return 1;
}

const char *param_seams_why(const scaf_param_t *p) { return p && p->has_mesh ? p->seams_why : ""; }

int param_last_scaffold(const scaf_param_t *p, scaffold_view *v)
{
    memset(v, 0, sizeof *v);
    if (!p || !p->has_mesh) return 0;
    *v = *scaf_loop_scaffold_view(&p->loop);
    return 1;
}

/* ---- set_mesh ------------------------------------------------------------ */

scaf_status param_check_arrays(const double *V, int nv, const int *F, int nf, const double *UV,
                               int nuv, const int *FT, scaf_error *err)
{
    if (nv <= 0 || nf <= 0)
        return err_set(err, SCAF_ERR_USAGE, "the mesh is empty (%d vertices, %d faces)", nv, nf);
    if (!V || !F)
        return err_set(err, SCAF_ERR_USAGE, "%s is NULL (%d vertices, %d faces)", !V ? "V" : "F",
                       nv, nf);
    if (nv > INT_MAX / 3 || nf > INT_MAX / 3 || nuv > INT_MAX / 2)
        return err_set(err, SCAF_ERR_USAGE,
                       "the mesh is too large for int indices (%d vertices, %d faces, %d UVs)", nv,
                       nf, nuv);
    if (nuv < 0 || (nuv > 0 && (!UV || !FT)) || (nuv == 0 && FT))
        return err_set(err, SCAF_ERR_USAGE, "UV and FT must be given together (nuv = %d)", nuv);
    for (int i = 0; i < 3 * nv; i++)
        if (!isfinite(V[i]))
            return err_set(err, SCAF_ERR_MESH, "vertex %d has a non-finite coordinate", i / 3);
    for (int i = 0; i < 3 * nf; i++) {
        if (F[i] < 0 || F[i] >= nv)
            return err_set(err, SCAF_ERR_USAGE,
                           "face %d references vertex %d, but the mesh has %d vertices", i / 3,
                           F[i], nv);
        if (nuv > 0 && (FT[i] < 0 || FT[i] >= nuv))
            return err_set(err, SCAF_ERR_USAGE, "face %d references UV %d, but there are %d UVs",
                           i / 3, FT[i], nuv);
    }
    return SCAF_OK;
}

static double area3(const double *a, const double *b, const double *c)
{
    double u[3], v[3];
    for (int d = 0; d < 3; d++) {
        u[d] = b[d] - a[d];
        v[d] = c[d] - a[d];
    }
    double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
    return 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
}

/* A chart touching itself at a UV vertex (several fans around one vt) is
 * a disk all the same: give each fan its own UV index. m->FT then points
 * to *FTs (nf by 3, freed by the caller) and m->nuv counts the new
 * indices. Nothing to do without UVs. */
static scaf_status split_fans(mesh *m, int **FTs, scaf_error *err)
{
    *FTs = NULL;
    if (m->nuv <= 0) return SCAF_OK;
    *FTs = malloc(sizeof(int) * 3 * (size_t)m->nf);
    if (!*FTs) return err_nomem(err, "UV indices");
    scaf_status st = uv_split_fans(m->nf, m->FT, m->nuv, *FTs, &m->nuv, NULL, err);
    if (st != SCAF_OK) return st;
    m->FT = *FTs;
    return SCAF_OK;
}

/* The charts of m (positions at unit scale, 2^-pos_exp times V_in, the
 * caller's), each checked to be a disk (possibly with holes) with no
 * degenerate triangle; errors name the chart. */
static scaf_status find_charts(const mesh *m, const double *V_in, int pos_exp, mesh_charts *ch,
                               scaf_error *err)
{
    scaf_status st = mesh_charts_compute(m, ch, err);
    if (st != SCAF_OK) return st;
    for (int c = 0; c < ch->ncharts; c++) {
        st = mesh_chart_check(ch, c, 1, err);
        if (st != SCAF_OK) return st;
    }
    const double *V = m->V;
    for (int f = 0; f < m->nf; f++) {
        const int *t = m->F + 3 * f;
        /* degenerate: the one exact definition `scaf info` counts too */
        if (tri3_is_degenerate(V_in + 3 * (size_t)t[0], V_in + 3 * (size_t)t[1],
                               V_in + 3 * (size_t)t[2]))
            return err_set(err, SCAF_ERR_MESH, "chart %d: face %d is degenerate (zero 3D area)",
                           ch->cx.face_group[f], f);
        double a = area3(V + 3 * (size_t)t[0], V + 3 * (size_t)t[1], V + 3 * (size_t)t[2]);
        if (!(a >= DBL_MIN) || !isfinite(a))
            return err_set(err, SCAF_ERR_MESH,
                           "chart %d: face %d is not degenerate, but too small next to the "
                           "mesh's largest coordinate (2^%d) for double precision: its area "
                           "underflows",
                           ch->cx.face_group[f], f, pos_exp);
    }
    return SCAF_OK;
}

/* Working vertices: one per referenced index of IDX (vertex or UV index
 * per corner; each index belongs to one chart: the chart check rejects
 * indices shared by charts), numbered chart by chart so each chart's
 * vertices are contiguous, breadth first within a chart
 * (mesh/vertex_order: whatever the input's numbering, a triangle's
 * corners get close numbers, and the iteration's passes stay in cache).
 * Fw (nf by 3) gets the working vertex of each corner, widx (nidx) the
 * working vertex of each index (-1: unused), *W3 (nw by 3, allocated)
 * their 3D positions. */
static scaf_status working_vertices(const mesh *m, const mesh_charts *ch, const int *IDX, int nidx,
                                    int *widx, int *Fw, int *nw_out, double **W3, scaf_error *err)
{
    for (int i = 0; i < nidx; i++) widx[i] = -1;
    int nw = 0;
    for (int c = 0; c < ch->ncharts; c++)
        for (int k = ch->cx.group_face_start[c]; k < ch->cx.group_face_start[c + 1]; k++) {
            int f = ch->cx.group_faces[k];
            for (int j = 0; j < 3; j++) {
                int i = IDX[3 * f + j];
                if (widx[i] < 0) widx[i] = nw++;
                Fw[3 * f + j] = widx[i];
            }
        }
    /* The charts' vertices are contiguous in this first numbering, so the
     * breadth-first one, part after part by smallest vertex, keeps them so. */
    int *rank = malloc(sizeof(int) * (size_t)(nw ? nw : 1));
    if (!rank) return err_nomem(err, "working mesh");
    scaf_status st = mesh_vertex_order_breadth_first(3, m->nf, Fw, nw, rank, err);
    if (st != SCAF_OK) {
        free(rank);
        return st;
    }
    for (size_t k = 0; k < 3 * (size_t)m->nf; k++) Fw[k] = rank[Fw[k]];
    for (int i = 0; i < nidx; i++)
        if (widx[i] >= 0) widx[i] = rank[widx[i]];
    free(rank);
    *nw_out = nw;
    *W3 = malloc(sizeof(double) * 3 * (size_t)(nw ? nw : 1));
    if (!*W3) return err_nomem(err, "working mesh");
    for (int f = 0; f < m->nf; f++)
        for (int j = 0; j < 3; j++)
            memcpy(*W3 + 3 * (size_t)Fw[3 * f + j], m->V + 3 * (size_t)m->F[3 * f + j],
                   sizeof(double) * 3);
    return SCAF_OK;
}

/* Embed chart c on a circle of its 3D area (opt_embed_chart_best: with
 * holes, the best of up to OUTER_TRIES loops on the circle) and store its
 * UV in uv (working vertices) and the circle's radius in *radius. local
 * (nw entries, all -1) is scratch, left all -1. */
static scaf_status embed_chart(const mesh_charts *ch, int c, const int *IDX, const int *widx,
                               const int *Fw, const double *W3, opt_embed_method method, int *local,
                               double *uv, double *radius, scaf_error *err)
{
    int f0 = ch->cx.group_face_start[c], f1 = ch->cx.group_face_start[c + 1], mf = f1 - f0;
    int l0 = ch->chart_loop_start[c], l1 = ch->chart_loop_start[c + 1];
    int nlv = 0;
    for (int l = l0; l < l1; l++) {
        int lid = ch->chart_loops[l];
        nlv += ch->cx.loop_start[lid + 1] - ch->cx.loop_start[lid];
    }
    int *cverts = malloc(sizeof(int) * 3 * (size_t)mf);
    int *cfaces = malloc(sizeof(int) * 3 * (size_t)mf);
    int *cloops = malloc(sizeof(int) * ((size_t)nlv + (size_t)(l1 - l0) + 1));
    double *P = malloc(sizeof(double) * 9 * (size_t)mf);
    double *cuv = malloc(sizeof(double) * 6 * (size_t)mf);
    scaf_status st = SCAF_OK;
    if (!cverts || !cfaces || !cloops || !P || !cuv) {
        st = err_nomem(err, "chart embedding");
        goto done;
    }
    /* the chart's own vertices, faces and boundary loops */
    int n = 0;
    for (int k = f0; k < f1; k++) {
        int f = ch->cx.group_faces[k];
        for (int j = 0; j < 3; j++) {
            int w = Fw[3 * f + j];
            if (local[w] < 0) {
                local[w] = n;
                cverts[n] = w;
                memcpy(P + 3 * (size_t)n, W3 + 3 * (size_t)w, sizeof(double) * 3);
                n++;
            }
            cfaces[3 * (k - f0) + j] = local[w];
        }
    }
    int nl = l1 - l0;
    int *lstart = cloops, *lv = cloops + nl + 1;
    int pos = 0;
    for (int l = 0; l < nl; l++) {
        int lid = ch->chart_loops[l0 + l];
        lstart[l] = pos;
        for (int h = ch->cx.loop_start[lid]; h < ch->cx.loop_start[lid + 1]; h++) {
            int idx = IDX[ch->cx.loop_he[h]];
            lv[pos++] = local[widx[idx]];
        }
    }
    lstart[nl] = pos;
    opt_chart_loops ol = {nl, lstart, lv, 0};
    st = opt_embed_chart_best(n, P, mf, cfaces, &ol, method, OUTER_TRIES, cuv, NULL, NULL, err);
    if (st != SCAF_OK) {
        err_prefix(err, "chart %d", c);
        for (int i = 0; i < n; i++) local[cverts[i]] = -1;
        goto done;
    }
    double r = 0.0;
    for (int i = 0; i < n; i++) {
        double d = hypot(cuv[2 * i], cuv[2 * i + 1]);
        if (d > r) r = d;
        memcpy(uv + 2 * (size_t)cverts[i], cuv + 2 * i, sizeof(double) * 2);
        local[cverts[i]] = -1;
    }
    *radius = r;
done:
    free(cverts);
    free(cfaces);
    free(cloops);
    free(P);
    free(cuv);
    return st;
}

/* Several charts: move chart c's circle (radius up to the largest) to
 * cell c of a grid of 2.5 * rmax cells, so the circles do not touch.
 * chart_of_w (nw) is scratch. */
static void place_on_grid(const mesh_charts *ch, int nf, const int *Fw, int nw,
                          const double *radius, int *chart_of_w, double *uv)
{
    if (ch->ncharts <= 1) return;
    double rmax = 0.0;
    for (int c = 0; c < ch->ncharts; c++)
        if (radius[c] > rmax) rmax = radius[c];
    double cell = 2.5 * rmax;
    int cols = (int)ceil(sqrt((double)ch->ncharts));
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) chart_of_w[Fw[3 * f + j]] = ch->cx.face_group[f];
    for (int w = 0; w < nw; w++) {
        int c = chart_of_w[w];
        uv[2 * (size_t)w] += cell * (c % cols);
        uv[2 * (size_t)w + 1] -= cell * (c / cols);
    }
}

static opt_embed_method embed_method(scaf_init init)
{
    return init == SCAF_INIT_HARMONIC ? OPT_EMBED_HARMONIC
        : init == SCAF_INIT_MVC       ? OPT_EMBED_MVC
                                      : OPT_EMBED_TUTTE;
}

scaf_status scaf_param_set_mesh(scaf_param_t *p, const double *V, int nv, const int *F, int nf,
                                const double *UV, int nuv, const int *FT)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    drop_mesh(p);
    scaf_error *err = &p->err;
    scaf_status st = param_check_arrays(V, nv, F, nf, UV, nuv, FT, err);
    if (st != SCAF_OK) return st;
    /* Work at unit scale, exactly (geom/coord_scale): the result does
     * not depend on the input's units; UVs go back to them in get_uv. */
    p->pos_exp = coord_scale_exponent(V, 3, 3 * (size_t)nf, F);
    const double *V_in = V;
    double *Vs = malloc(sizeof(double) * 3 * (size_t)nv);
    if (!Vs) return err_nomem(err, "scaled positions");
    coord_scale_apply(Vs, V, 3, nv, 3 * (size_t)nf, F, p->pos_exp);
    V = Vs;

    mesh m = {nv, (double *)V, nf, (int *)F, nuv, (double *)UV, (int *)FT};
    mesh_charts ch;
    memset(&ch, 0, sizeof ch);
    int *FTs = NULL, *widx = NULL, *local = NULL, nw = 0;
    double *W3 = NULL, *uv = NULL, *radius = NULL;
    /* the seams: the input's, or cut automatically where a chart is not
     * a disk (app/seam_source); the UV values are not used here */
    seam_plan plan;
    st = seam_plan_make(&m, p->opt.seams, 0, &plan, err);
    if (st != SCAF_OK) goto fail;
    if (plan.changed) {
        m.nuv = plan.nuv;
        m.UV = plan.UV;
        m.FT = plan.FT;
    }
    st = split_fans(&m, &FTs, err);
    if (st == SCAF_OK) st = find_charts(&m, V_in, p->pos_exp, &ch, err);
    if (st != SCAF_OK) goto fail;
    int nidx = ch.uses_uv ? m.nuv : nv;
    const int *IDX = ch.uses_uv ? m.FT : F;

    widx = malloc(sizeof(int) * (size_t)nidx);
    p->Fw = malloc(sizeof(int) * 3 * (size_t)nf);
    if (!widx || !p->Fw) {
        st = err_nomem(err, "working mesh");
        goto fail;
    }
    st = working_vertices(&m, &ch, IDX, nidx, widx, p->Fw, &nw, &W3, err);
    if (st != SCAF_OK) goto fail;
    uv = malloc(sizeof(double) * 2 * (size_t)nw);
    local = malloc(sizeof(int) * (size_t)nw);
    radius = malloc(sizeof(double) * (size_t)ch.ncharts);
    if (!uv || !local || !radius) {
        st = err_nomem(err, "working mesh");
        goto fail;
    }
    for (int i = 0; i < nw; i++) local[i] = -1;
    for (int c = 0; c < ch.ncharts; c++) {
        /* a million charts take seconds here: listen for SIGINT / SIGTERM */
        if (c % 1024 == 0 &&
            (st = interrupt_check(c ? NULL : "setup", "setting up the charts", err)) != SCAF_OK)
            goto fail;
        st = embed_chart(&ch, c, IDX, widx, p->Fw, W3, embed_method(p->opt.init), local, uv,
                         &radius[c], err);
        if (st != SCAF_OK) goto fail;
    }
    if ((st = interrupt_check(NULL, "setting up the charts", err)) != SCAF_OK) goto fail;
    place_on_grid(&ch, nf, p->Fw, nw, radius, local, uv);

    p->nf = nf;
    p->nw = nw;
    p->ncharts = ch.ncharts;
    scaf_loop_options lo = param_loop_options(&p->opt);
    st = scaf_loop_init(&p->loop, nw, W3, nf, p->Fw, uv, &lo, err);
    if (st != SCAF_OK) goto fail;
    if ((st = interrupt_check(NULL, "setting up the scaffold", err)) != SCAF_OK) {
        scaf_loop_free(&p->loop);
        goto fail;
    }
    p->has_mesh = 1;
    p->seams_used = plan.used;
    snprintf(p->seams_why, sizeof p->seams_why, "%s", plan.why);
    goto done;
fail:
    free(p->Fw);
    p->Fw = NULL;
    p->nf = p->nw = p->ncharts = 0;
    if (err->code == SCAF_OK) err->code = st;
done:
    seam_plan_free(&plan);
    mesh_charts_free(&ch);
    free(widx);
    free(local);
    free(FTs);
    free(W3);
    free(uv);
    free(radius);
    free(Vs);
    return st;
}

/* ---- run and results ----------------------------------------------------- */

scaf_status scaf_param_run(scaf_param_t *p, int iterations, scaf_param_progress_fn progress,
                           void *user)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    if (!p->has_mesh)
        return err_set(&p->err, SCAF_ERR_USAGE, "no mesh: call scaf_param_set_mesh first");
    p->loop.opt = param_loop_options(&p->opt);
    int n = iterations > 0 ? iterations : p->opt.max_iterations;
    p->stop =
        n > 0 ? SCAF_STOP_ITERATIONS : SCAF_STOP_NONE; /* unless a rule below stops it first */
    /* The criterion judges the energy being minimized (the mesh term's
     * own: symmetric Dirichlet, ARAP or conformal); the objective of one
     * iteration also holds its re-rested scaffold (opt/convergence). */
    opt_convergence conv;
    opt_convergence_reset(&conv);
    /* ARAP is 0 at a rotation: relative to E alone a map near an isometry
     * never looks converged (hilbert, planar: criterion 0.087 after 200
     * iterations while E crept by 1e-7). It is judged relative to E + 1
     * (opt_energy_scale_offset), as its scaffold weight is. */
    double shift = opt_energy_scale_offset(p->loop.opt.energy);
    double e_mesh = scaf_loop_mesh_energy(&p->loop);
    for (int it = 0; it < n; it++) {
        scaf_iteration_info_t info;
        scaf_status st = scaf_loop_step(&p->loop, &info, &p->err);
        if (st != SCAF_OK) {
            p->stop = SCAF_STOP_ERROR;
            return st;
        }
        double e_next = p->loop.opt.energy == OPT_ENERGY_SYMMETRIC_DIRICHLET
            ? info.energy
            : scaf_loop_mesh_energy(&p->loop);
        double dec = info.decrement; /* relative to the iteration's objective */
        if (shift > 0.0 && dec > 0.0)
            dec *= info.total_before / ((e_mesh + shift) * p->loop.total_area);
        info.criterion = opt_convergence_update(&conv, e_mesh + shift, e_next + shift, dec);
        e_mesh = e_next;
        if (progress && progress(&info, user)) {
            p->stop = SCAF_STOP_CANCELLED;
            return err_set(&p->err, SCAF_ERR_CANCELLED,
                           "stopped by the progress callback after iteration %d", info.iteration);
        }
        if (info.step == 0.0) { /* no descent left */
            p->stop = SCAF_STOP_ZERO_STEP;
            break;
        }
        /* converged: the estimated relative distance to the minimum (the
         * larger of the Newton decrement and the linear tail of the last
         * decreases) is below the tolerance */
        if (p->opt.tolerance > 0.0 && info.criterion < p->opt.tolerance) {
            p->stop = SCAF_STOP_CONVERGED;
            break;
        }
    }
    return SCAF_OK;
}

scaf_status scaf_param_set_handles(scaf_param_t *p, int n, const int *idx, const double *targets,
                                   double weight_ratio)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    if (!p->has_mesh)
        return err_set(&p->err, SCAF_ERR_USAGE, "no mesh: call scaf_param_set_mesh first");
    if (n < 0 || (n > 0 && (!idx || !targets)))
        return err_set(&p->err, SCAF_ERR_USAGE,
                       "handles: n >= 0 and, when n > 0, idx and targets are needed");
    if (!(weight_ratio >= 0.0) || !isfinite(weight_ratio))
        return err_set(&p->err, SCAF_ERR_USAGE,
                       "handles: the weight ratio must be a finite number >= 0");
    /* targets in the loop's units (positions / 2^pos_exp, see set_mesh) */
    double *t = malloc(sizeof(double) * 2 * (size_t)(n > 0 ? n : 1));
    if (!t) return err_nomem(&p->err, "handles");
    for (size_t i = 0; i < 2 * (size_t)n; i++) t[i] = ldexp(targets[i], -p->pos_exp);
    if (!p->handles_added) opt_handle_term_init(&p->handles, 2, p->nw);
    scaf_status st = opt_handle_term_set(
        &p->handles, n, idx, t, opt_handle_weight(weight_ratio, p->loop.total_area, n), &p->err);
    free(t);
    if (st != SCAF_OK || p->handles_added) return st;
    opt_obj_term term = opt_handle_term_make(&p->handles);
    st = scaf_loop_add_term(&p->loop, &term, &p->err);
    p->handles_added = st == SCAF_OK;
    if (st != SCAF_OK) opt_handle_term_free(&p->handles);
    return st;
}

double scaf_param_energy(const scaf_param_t *p)
{
    return p && p->has_mesh ? scaf_loop_energy(&p->loop) : NAN;
}
int scaf_param_chart_count(const scaf_param_t *p) { return p ? p->ncharts : 0; }
scaf_seams scaf_param_seams_used(const scaf_param_t *p)
{
    return p ? p->seams_used : SCAF_SEAMS_DEFAULT;
}
int scaf_param_iterations(const scaf_param_t *p)
{
    return p && p->has_mesh ? p->loop.iterations : 0;
}
scaf_stop_reason scaf_param_stop_reason(const scaf_param_t *p)
{
    return p ? p->stop : SCAF_STOP_NONE;
}
int scaf_param_uv_count(const scaf_param_t *p) { return p ? p->nw : 0; }

scaf_status scaf_param_get_uv(const scaf_param_t *p, double *UV, int *FT)
{
    if (!p || !p->has_mesh || !UV) return SCAF_ERR_USAGE;
    /* back to the input's units: exact unless a coordinate would overflow
     * or fall into the subnormal range (then the map proved bijective
     * would not be the one given) */
    size_t bad = SIZE_MAX;
    for (size_t i = 0; i < 2 * (size_t)p->nw; i++) {
        UV[i] = ldexp(p->loop.uv[i], p->pos_exp);
        if (bad == SIZE_MAX && ldexp(UV[i], -p->pos_exp) != p->loop.uv[i]) bad = i;
    }
    if (FT) memcpy(FT, p->Fw, sizeof(int) * 3 * (size_t)p->nf);
    if (bad == SIZE_MAX) return SCAF_OK;
    /* the context is the caller's heap object: its message may change even
     * through this const pointer, so scaf_param_error says why */
    return err_set(&((scaf_param_t *)p)->err, SCAF_ERR_NUMERIC,
                   "UV %zu cannot be written exactly in the mesh's units (2^%d times %g would %s); "
                   "scale the "
                   "mesh by a power of 2",
                   bad / 2, p->pos_exp, p->loop.uv[bad],
                   p->pos_exp > 0 ? "overflow" : "be subnormal");
}
