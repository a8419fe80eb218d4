/* app/param: the scaf_param_* API (see include/scaf/scaf.h).
 *
 * set_mesh: validates the arrays, finds the charts (mesh/uv_charts: UV
 * charts cut along seams, or components), checks each is a disk or a disk
 * with holes (naming the chart on failure), builds the working mesh (one
 * vertex per (chart, vertex-or-vt) pair), embeds every chart on a circle of
 * its 3D area (app/chart_init), places the circles on a grid so they do not
 * touch, and sets up the SCAF loop. run: iterates with progress and the
 * stopping rules. Errors leave a message readable by scaf_param_error.
 */
#include "app/param.h"
#include "app/uv_fans.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "mesh/uv_charts.h"
#include "opt/embed.h"

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
    int nw;          /* working vertices */
    int *Fw;         /* nf by 3 working vertex per corner */
    scaf_loop loop;
    scaf_stop_reason stop; /* why the last run stopped */
};

scaf_options_t scaf_options_default(void)
{
    scaf_options_t o;
    memset(&o, 0, sizeof o);
    o.energy = SCAF_ENERGY_SYMMETRIC_DIRICHLET;
    o.init = SCAF_INIT_MVC; /* fewest iterations on every measured mesh: bench/RESULTS-init.md */
    o.max_iterations = 50;
    o.tolerance = 1e-6;
    o.box_scale = 3.0;
    o.box_square = 0;
    o.box_points_per_side = 5;
    o.lambda_ratio = 0.01;
    o.min_angle_deg = 20.0;
    o.step_fraction = 0.8;
    return o;
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
    if ((int)o->energy < 0 || o->energy > SCAF_ENERGY_CONFORMAL) bad = "energy is not a known energy";
    else if ((int)o->init < 0 || o->init > SCAF_INIT_MVC) bad = "init is not tutte, harmonic or mvc";
    else if (o->max_iterations < 0) bad = "max_iterations must be >= 0";
    else if (!(o->tolerance >= 0.0) || !isfinite(o->tolerance)) bad = "tolerance must be a finite number >= 0";
    else if (!(o->box_scale >= 1.0) || !(o->box_scale <= 1e6)) bad = "box_scale must be in [1, 1e6]";
    else if (o->box_points_per_side < 1 || o->box_points_per_side > 100000)
        bad = "box_points_per_side must be in [1, 100000]";
    else if (!(o->lambda_ratio > 0.0) || !isfinite(o->lambda_ratio)) bad = "lambda_ratio must be > 0";
    else if (!(o->min_angle_deg >= 0.0) || !(o->min_angle_deg <= 30.0))
        bad = "min_angle_deg must be in [0, 30]";
    else if (!(o->step_fraction > 0.0) || !(o->step_fraction < 1.0)) bad = "step_fraction must be in (0, 1)";
    if (!bad) return SCAF_OK;
    if (msg && size) snprintf(msg, size, "invalid option: %s", bad);
    return SCAF_ERR_USAGE;
}

scaf_param_t *scaf_param_new(const scaf_options_t *options)
{
    scaf_param_t *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->opt = options ? *options : scaf_options_default();
    err_clear(&p->err);
    if (param_options_check(&p->opt, p->err.message, sizeof p->err.message) != SCAF_OK) {
        p->err.code = SCAF_ERR_USAGE;
        p->opt = scaf_options_default();
    }
    return p;
}

scaf_status scaf_param_set_options(scaf_param_t *p, const scaf_options_t *options)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    if (!options) return err_set(&p->err, SCAF_ERR_USAGE, "options is NULL");
    scaf_status st = param_options_check(options, p->err.message, sizeof p->err.message);
    if (st != SCAF_OK) return p->err.code = st;
    p->opt = *options;
    if (p->has_mesh) p->loop.opt = *options;
    return SCAF_OK;
}

static void drop_mesh(scaf_param_t *p)
{
    scaf_loop_free(&p->loop);
    free(p->Fw);
    p->Fw = NULL;
    p->has_mesh = 0;
    p->nf = p->nw = p->ncharts = 0;
    p->stop = SCAF_STOP_NONE;
}

void scaf_param_destroy(scaf_param_t *p)
{
    if (!p) return;
    drop_mesh(p);
    free(p);
}

const char *scaf_param_error(const scaf_param_t *p) { return p ? p->err.message : "no context"; }

const scaf_loop *param_loop(const scaf_param_t *p) { return p && p->has_mesh ? &p->loop : NULL; }

/* ---- set_mesh ------------------------------------------------------------ */

scaf_status param_check_arrays(const double *V, int nv, const int *F, int nf, const double *UV, int nuv,
                               const int *FT, scaf_error *err)
{
    if (nv <= 0 || nf <= 0) return err_set(err, SCAF_ERR_USAGE, "the mesh is empty (%d vertices, %d faces)", nv, nf);
    if (!V || !F) return err_set(err, SCAF_ERR_USAGE, "%s is NULL (%d vertices, %d faces)", !V ? "V" : "F", nv, nf);
    if (nv > INT_MAX / 3 || nf > INT_MAX / 3 || nuv > INT_MAX / 2)
        return err_set(err, SCAF_ERR_USAGE, "the mesh is too large for int indices (%d vertices, %d faces, %d UVs)", nv, nf, nuv);
    if (nuv < 0 || (nuv > 0 && (!UV || !FT)) || (nuv == 0 && FT))
        return err_set(err, SCAF_ERR_USAGE, "UV and FT must be given together (nuv = %d)", nuv);
    for (int i = 0; i < 3 * nv; i++)
        if (!isfinite(V[i])) return err_set(err, SCAF_ERR_MESH, "vertex %d has a non-finite coordinate", i / 3);
    for (int i = 0; i < 3 * nf; i++) {
        if (F[i] < 0 || F[i] >= nv)
            return err_set(err, SCAF_ERR_USAGE, "face %d references vertex %d, but the mesh has %d vertices", i / 3, F[i], nv);
        if (nuv > 0 && (FT[i] < 0 || FT[i] >= nuv))
            return err_set(err, SCAF_ERR_USAGE, "face %d references UV %d, but there are %d UVs", i / 3, FT[i], nuv);
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
    double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
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

    mesh m = {nv, (double *)V, nf, (int *)F, nuv, (double *)UV, (int *)FT};
    mesh_charts ch;
    memset(&ch, 0, sizeof ch);
    int *widx = NULL, *local = NULL, *cverts = NULL, *cfaces = NULL, *cloops = NULL, *FTs = NULL;
    double *W3 = NULL, *uv = NULL, *P = NULL, *cuv = NULL, *radius = NULL;
    if (nuv > 0) {
        /* A chart touching itself at a UV vertex (several fans around one
         * vt) is a disk all the same: give each fan its own UV index. */
        FTs = malloc(sizeof(int) * 3 * (size_t)nf);
        if (!FTs) {
            st = err_nomem(err, "UV indices");
            goto fail;
        }
        st = uv_split_fans(nf, FT, nuv, FTs, &m.nuv, NULL, err);
        if (st != SCAF_OK) goto fail;
        m.FT = FTs;
        FT = FTs;
        nuv = m.nuv;
    }
    st = mesh_charts_compute(&m, &ch, err);
    if (st != SCAF_OK) goto fail;
    int nidx = ch.uses_uv ? nuv : nv;
    const int *IDX = ch.uses_uv ? FT : F;
    for (int c = 0; c < ch.ncharts; c++) {
        st = mesh_chart_check(&ch, c, 1, err);
        if (st != SCAF_OK) goto fail;
    }
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        if (!(area3(V + 3 * (size_t)t[0], V + 3 * (size_t)t[1], V + 3 * (size_t)t[2]) > 0.0)) {
            st = err_set(err, SCAF_ERR_MESH, "chart %d: face %d is degenerate (zero 3D area)", ch.cx.face_group[f], f);
            goto fail;
        }
    }

    /* ---- working vertices: one per referenced index (each index belongs
     * to one chart: the chart check rejects indices shared by charts). ---- */
    widx = malloc(sizeof(int) * (size_t)nidx);
    p->Fw = malloc(sizeof(int) * 3 * (size_t)nf);
    if (!widx || !p->Fw) {
        st = err_nomem(err, "working mesh");
        goto fail;
    }
    for (int i = 0; i < nidx; i++) widx[i] = -1;
    int nw = 0;
    /* Number chart by chart so each chart's vertices are contiguous. */
    for (int c = 0; c < ch.ncharts; c++)
        for (int k = ch.cx.group_face_start[c]; k < ch.cx.group_face_start[c + 1]; k++) {
            int f = ch.cx.group_faces[k];
            for (int j = 0; j < 3; j++) {
                int i = IDX[3 * f + j];
                if (widx[i] < 0) widx[i] = nw++;
                p->Fw[3 * f + j] = widx[i];
            }
        }
    W3 = malloc(sizeof(double) * 3 * (size_t)nw);
    uv = malloc(sizeof(double) * 2 * (size_t)nw);
    local = malloc(sizeof(int) * (size_t)nw);
    radius = malloc(sizeof(double) * (size_t)ch.ncharts);
    if (!W3 || !uv || !local || !radius) {
        st = err_nomem(err, "working mesh");
        goto fail;
    }
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) memcpy(W3 + 3 * (size_t)p->Fw[3 * f + j], V + 3 * (size_t)F[3 * f + j], sizeof(double) * 3);

    /* ---- embed each chart ------------------------------------------------ */
    for (int i = 0; i < nw; i++) local[i] = -1;
    for (int c = 0; c < ch.ncharts; c++) {
        int f0 = ch.cx.group_face_start[c], f1 = ch.cx.group_face_start[c + 1], mf = f1 - f0;
        free(cverts); free(cfaces); free(cloops); free(P); free(cuv);
        cverts = malloc(sizeof(int) * 3 * (size_t)mf);
        cfaces = malloc(sizeof(int) * 3 * (size_t)mf);
        int l0 = ch.chart_loop_start[c], l1 = ch.chart_loop_start[c + 1];
        int nlv = 0;
        for (int l = l0; l < l1; l++) {
            int lid = ch.chart_loops[l];
            nlv += ch.cx.loop_start[lid + 1] - ch.cx.loop_start[lid];
        }
        cloops = malloc(sizeof(int) * ((size_t)nlv + (size_t)(l1 - l0) + 1));
        P = malloc(sizeof(double) * 9 * (size_t)mf);
        cuv = malloc(sizeof(double) * 6 * (size_t)mf);
        if (!cverts || !cfaces || !cloops || !P || !cuv) {
            st = err_nomem(err, "chart embedding");
            goto fail;
        }
        int n = 0;
        for (int k = f0; k < f1; k++) {
            int f = ch.cx.group_faces[k];
            for (int j = 0; j < 3; j++) {
                int w = p->Fw[3 * f + j];
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
            int lid = ch.chart_loops[l0 + l];
            lstart[l] = pos;
            for (int h = ch.cx.loop_start[lid]; h < ch.cx.loop_start[lid + 1]; h++) {
                int idx = IDX[ch.cx.loop_he[h]];
                lv[pos++] = local[widx[idx]];
            }
        }
        lstart[nl] = pos;
        opt_chart_loops ol = {nl, lstart, lv, 0};
        /* a chart with holes: the best of up to OUTER_TRIES loops on the circle */
        st = opt_embed_chart_best(n, P, mf, cfaces, &ol,
                                  p->opt.init == SCAF_INIT_HARMONIC ? OPT_EMBED_HARMONIC
                                  : p->opt.init == SCAF_INIT_MVC ? OPT_EMBED_MVC : OPT_EMBED_TUTTE,
                                  OUTER_TRIES, cuv, NULL, NULL, err);
        if (st != SCAF_OK) {
            err_prefix(err, "chart %d", c);
            goto fail;
        }
        double r = 0.0;
        for (int i = 0; i < n; i++) {
            double d = hypot(cuv[2 * i], cuv[2 * i + 1]);
            if (d > r) r = d;
            memcpy(uv + 2 * (size_t)cverts[i], cuv + 2 * i, sizeof(double) * 2);
            local[cverts[i]] = -1;
        }
        radius[c] = r;
    }

    /* ---- grid of non-touching circles ------------------------------------ */
    if (ch.ncharts > 1) {
        double rmax = 0.0;
        for (int c = 0; c < ch.ncharts; c++)
            if (radius[c] > rmax) rmax = radius[c];
        double cell = 2.5 * rmax;
        int cols = (int)ceil(sqrt((double)ch.ncharts));
        int *chart_of_w = local; /* reuse */
        for (int f = 0; f < nf; f++)
            for (int j = 0; j < 3; j++) chart_of_w[p->Fw[3 * f + j]] = ch.cx.face_group[f];
        for (int w = 0; w < nw; w++) {
            int c = chart_of_w[w];
            uv[2 * (size_t)w] += cell * (c % cols);
            uv[2 * (size_t)w + 1] -= cell * (c / cols);
        }
    }

    p->nf = nf;
    p->nw = nw;
    p->ncharts = ch.ncharts;
    st = scaf_loop_init(&p->loop, nw, W3, nf, p->Fw, uv, &p->opt, err);
    if (st != SCAF_OK) goto fail;
    p->has_mesh = 1;
    goto done;
fail:
    free(p->Fw);
    p->Fw = NULL;
    p->nf = p->nw = p->ncharts = 0;
    if (err->code == SCAF_OK) err->code = st;
done:
    mesh_charts_free(&ch);
    free(widx); free(local); free(cverts); free(cfaces); free(cloops); free(FTs);
    free(W3); free(uv); free(P); free(cuv); free(radius);
    return st;
}

/* ---- run and results ----------------------------------------------------- */

scaf_status scaf_param_run(scaf_param_t *p, int iterations, scaf_param_progress_fn progress, void *user)
{
    if (!p) return SCAF_ERR_USAGE;
    err_clear(&p->err);
    if (!p->has_mesh) return err_set(&p->err, SCAF_ERR_USAGE, "no mesh: call scaf_param_set_mesh first");
    p->loop.opt = p->opt;
    int n = iterations > 0 ? iterations : p->opt.max_iterations;
    p->stop = n > 0 ? SCAF_STOP_ITERATIONS : SCAF_STOP_NONE; /* unless a rule below stops it first */
    for (int it = 0; it < n; it++) {
        scaf_iteration_info_t info;
        scaf_status st = scaf_loop_step(&p->loop, &info, &p->err);
        if (st != SCAF_OK) {
            p->stop = SCAF_STOP_ERROR;
            return st;
        }
        if (progress && progress(&info, user)) {
            p->stop = SCAF_STOP_CANCELLED;
            return err_set(&p->err, SCAF_ERR_CANCELLED, "stopped by the progress callback after iteration %d",
                           info.iteration);
        }
        if (info.step == 0.0) { /* no descent left */
            p->stop = SCAF_STOP_ZERO_STEP;
            break;
        }
        /* Converged when the objective (mesh + scaffold, the energy being
         * minimized) or the reported E stops decreasing noticeably. */
        double dec = (info.energy_before - info.energy) / info.energy_before;
        double tdec = (info.total_before - info.total_after) / info.total_before;
        if (p->opt.tolerance > 0.0 && ((dec >= 0.0 && dec < p->opt.tolerance) || tdec < p->opt.tolerance)) {
            p->stop = SCAF_STOP_TOLERANCE;
            break;
        }
    }
    return SCAF_OK;
}

double scaf_param_energy(const scaf_param_t *p) { return p && p->has_mesh ? scaf_loop_energy(&p->loop) : NAN; }
int scaf_param_chart_count(const scaf_param_t *p) { return p ? p->ncharts : 0; }
int scaf_param_iterations(const scaf_param_t *p) { return p && p->has_mesh ? p->loop.iterations : 0; }
scaf_stop_reason scaf_param_stop_reason(const scaf_param_t *p) { return p ? p->stop : SCAF_STOP_NONE; }
int scaf_param_uv_count(const scaf_param_t *p) { return p ? p->nw : 0; }

scaf_status scaf_param_get_uv(const scaf_param_t *p, double *UV, int *FT)
{
    if (!p || !p->has_mesh || !UV) return SCAF_ERR_USAGE;
    memcpy(UV, p->loop.uv, sizeof(double) * 2 * (size_t)p->nw);
    if (FT) memcpy(FT, p->Fw, sizeof(int) * 3 * (size_t)p->nf);
    return SCAF_OK;
}
