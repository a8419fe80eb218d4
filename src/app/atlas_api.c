/* app/atlas_api: the scaf_atlas_* API (see include/scaf/atlas.h).
 *
 * A thin handle around app/atlas: the public options are copied onto the
 * internal defaults (atlas_options_default, so internal knobs added later
 * keep their defaults), set_mesh checks the arrays (app/param's check)
 * before atlas_init, run adapts the progress callback, and every layout
 * handed out goes through app/atlas_output (normalized, proved bijective,
 * padding certified exactly), the same code the `scaf atlas` program runs
 * before writing. The verified output is computed once per layout and
 * kept until the layout changes. Errors leave a message readable by
 * scaf_atlas_error; no call crashes on NULL or out-of-range arguments.
 */
#include "scaf/atlas.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/api_options.h"
#include "app/atlas.h"
#include "app/atlas_output.h"
#include "app/param.h"
#include "base/error.h"
#include "mesh/mesh.h"

struct scaf_atlas {
    scaf_atlas_options_t opt;
    scaf_error err;
    int has_mesh;
    int ran; /* scaf_atlas_run called on this mesh */
    atlas at;
    /* the verified output of the current layout (out_state: 0 not
     * computed, 1 verified, -1 failed with out_err) */
    int out_state;
    double *UV; /* at.nw by 2 normalized */
    atlas_output out;
    scaf_error out_err;
};

/* ---- options ---------------------------------------------------------------- */

scaf_atlas_options_t scaf_atlas_options_default(void)
{
    atlas_options in = atlas_options_default();
    scaf_atlas_options_t o;
    memset(&o, 0, sizeof o);
    o.struct_size = sizeof o;
    o.padding = 4.0 / 1024.0; /* as `scaf atlas`: mip levels do not bleed */
    o.energy = in.base.energy;
    o.init = in.base.init;
    o.init_input = in.init_input;
    o.settle_iterations = in.settle_iterations;
    o.settle_tolerance = in.settle_tolerance;
    o.compact_iterations = in.compact_iterations;
    o.distortion_tolerance = in.distortion_tolerance;
    o.repack = in.repack;
    o.pack_cells = in.pack_cells;
    o.box_scale = in.base.box_scale;
    o.lambda_ratio = in.base.lambda_ratio;
    o.compact_lambda_ratio = in.compact_lambda_ratio;
    o.seams = in.base.seams;
    return o;
}

static atlas_options to_internal(const scaf_atlas_options_t *o)
{
    atlas_options in = atlas_options_default();
    in.padding = o->padding;
    in.base.energy = o->energy;
    in.base.init = o->init;
    in.init_input = o->init_input;
    in.settle_iterations = o->settle_iterations;
    in.settle_tolerance = o->settle_tolerance;
    in.compact_iterations = o->compact_iterations;
    in.distortion_tolerance = o->distortion_tolerance;
    in.repack = o->repack;
    in.pack_cells = o->pack_cells;
    in.base.box_scale = o->box_scale;
    in.base.lambda_ratio = o->lambda_ratio;
    in.compact_lambda_ratio = o->compact_lambda_ratio;
    in.base.seams = o->seams;
    return in;
}

/* The caller's options into *out (NULL: defaults): SCAF_OK, or
 * SCAF_ERR_USAGE naming the struct_size or the first invalid field (the
 * internal check, app/atlas: one set of ranges for the API and the
 * program). */
static scaf_status options_take(scaf_atlas_options_t *out, const scaf_atlas_options_t *in,
                                scaf_error *err)
{
    scaf_atlas_options_t def = scaf_atlas_options_default();
    scaf_status st = api_options_take(out, in, &def, sizeof def, "scaf_atlas_options_t", err);
    if (st != SCAF_OK) return st;
    atlas_options internal = to_internal(out);
    char msg[256];
    if (atlas_options_check(&internal, msg, sizeof msg) != SCAF_OK)
        return err_set(err, SCAF_ERR_USAGE, "invalid atlas option: %s", msg);
    return SCAF_OK;
}

scaf_status scaf_atlas_options_check(const scaf_atlas_options_t *options, char *message,
                                     size_t size)
{
    scaf_error err;
    err_clear(&err);
    scaf_atlas_options_t o;
    scaf_status st = options ? options_take(&o, options, &err)
                             : err_set(&err, SCAF_ERR_USAGE, "options is NULL");
    if (message && size) snprintf(message, size, "%s", err.message);
    return st;
}

scaf_atlas_t *scaf_atlas_new(const scaf_atlas_options_t *options)
{
    scaf_atlas_options_t o;
    if (options_take(&o, options, NULL) != SCAF_OK) return NULL;
    scaf_atlas_t *a = calloc(1, sizeof *a);
    if (!a) return NULL;
    err_clear(&a->err);
    a->opt = o;
    return a;
}

scaf_status scaf_atlas_set_options(scaf_atlas_t *a, const scaf_atlas_options_t *options)
{
    if (!a) return SCAF_ERR_USAGE;
    err_clear(&a->err);
    if (!options) return err_set(&a->err, SCAF_ERR_USAGE, "options is NULL");
    scaf_atlas_options_t o;
    scaf_status st = options_take(&o, options, &a->err);
    if (st != SCAF_OK) return st;
    a->opt = o;
    return SCAF_OK;
}

/* ---- mesh ---------------------------------------------------------------------- */

static void drop_output(scaf_atlas_t *a)
{
    a->out_state = 0;
    err_clear(&a->out_err);
}

static void drop_mesh(scaf_atlas_t *a)
{
    if (a->has_mesh) atlas_free(&a->at);
    memset(&a->at, 0, sizeof a->at);
    free(a->UV);
    a->UV = NULL;
    a->has_mesh = a->ran = 0;
    drop_output(a);
}

void scaf_atlas_destroy(scaf_atlas_t *a)
{
    if (!a) return;
    drop_mesh(a);
    free(a);
}

const char *scaf_atlas_error(const scaf_atlas_t *a)
{
    return a ? a->err.message : "no atlas context (NULL)";
}

scaf_status scaf_atlas_set_mesh(scaf_atlas_t *a, const double *V, int nv, const int *F, int nf,
                                const double *UV, int nuv, const int *FT)
{
    if (!a) return SCAF_ERR_USAGE;
    err_clear(&a->err);
    drop_mesh(a);
    scaf_status st = param_check_arrays(V, nv, F, nf, UV, nuv, FT, &a->err);
    if (st != SCAF_OK) return st;
    if (a->opt.init_input && nuv == 0)
        return err_set(&a->err, SCAF_ERR_USAGE,
                       "init_input is set but no UVs (UV, FT) were given to start from");
    mesh m = {nv,
              (double *)V,
              nf,
              (int *)F,
              nuv,
              nuv > 0 ? (double *)UV : NULL,
              nuv > 0 ? (int *)FT : NULL};
    atlas_options in = to_internal(&a->opt);
    st = atlas_init(&a->at, &m, &in, &a->err);
    if (st != SCAF_OK) {
        memset(&a->at, 0, sizeof a->at);
        return st;
    }
    a->UV = malloc(sizeof(double) * 2 * (size_t)a->at.nw);
    if (!a->UV) {
        atlas_free(&a->at);
        return err_nomem(&a->err, "atlas output");
    }
    a->has_mesh = 1;
    return SCAF_OK;
}

scaf_seams scaf_atlas_seams_used(const scaf_atlas_t *a)
{
    return a && a->has_mesh ? a->at.seams_used : SCAF_SEAMS_DEFAULT;
}

/* ---- verified output ----------------------------------------------------------- */

/* Normalize and verify the current layout once; on failure copy the
 * reason into a->err. */
static scaf_status ensure_output(scaf_atlas_t *a)
{
    if (!a->has_mesh)
        return err_set(&a->err, SCAF_ERR_USAGE, "no mesh: call scaf_atlas_set_mesh first");
    if (a->out_state == 0) {
        err_clear(&a->out_err);
        scaf_status st = atlas_output_verify(&a->at, a->UV, &a->out, &a->out_err);
        if (st != SCAF_OK && a->out_err.code == SCAF_OK) a->out_err.code = st;
        a->out_state = st == SCAF_OK ? 1 : -1;
    }
    if (a->out_state < 0) {
        a->err = a->out_err;
        return a->err.code;
    }
    return SCAF_OK;
}

/* ---- run ----------------------------------------------------------------------- */

typedef struct progress_adapter {
    scaf_atlas_progress_fn fn;
    void *user;
} progress_adapter;

static int on_iteration(const atlas *at, const atlas_iteration *it, void *user)
{
    progress_adapter *pa = user;
    scaf_atlas_iteration_info_t info;
    memset(&info, 0, sizeof info);
    info.phase = it->phase == ATLAS_COMPACT ? SCAF_ATLAS_COMPACT : SCAF_ATLAS_SETTLE;
    /* the phase counters already include this iteration */
    info.iteration = at->settle_done + at->compact_done;
    info.phase_iteration = it->phase == ATLAS_COMPACT ? at->compact_done : at->settle_done;
    info.energy = it->info.energy;
    info.efficiency = it->efficiency;
    info.gap = it->gap;
    info.seconds = it->info.seconds;
    info.loop = it->info;
    return pa->fn(&info, pa->user);
}

scaf_status scaf_atlas_run(scaf_atlas_t *a, scaf_atlas_progress_fn progress, void *user)
{
    if (!a) return SCAF_ERR_USAGE;
    err_clear(&a->err);
    if (!a->has_mesh)
        return err_set(&a->err, SCAF_ERR_USAGE, "no mesh: call scaf_atlas_set_mesh first");
    if (a->ran)
        return err_set(&a->err, SCAF_ERR_USAGE,
                       "scaf_atlas_run was already called for this mesh: call scaf_atlas_set_mesh "
                       "to start over");
    a->ran = 1;
    drop_output(a);
    progress_adapter pa = {progress, user};
    scaf_status st = atlas_run(&a->at, progress ? on_iteration : NULL, &pa, &a->err);
    if (st != SCAF_OK) {
        if (a->err.code == SCAF_OK) a->err.code = st;
        return st;
    }
    /* certify now, so a failing certificate shows up here too */
    return ensure_output(a);
}

/* ---- results ------------------------------------------------------------------- */

int scaf_atlas_chart_count(const scaf_atlas_t *a) { return a && a->has_mesh ? a->at.ncharts : 0; }
int scaf_atlas_uv_count(const scaf_atlas_t *a) { return a && a->has_mesh ? a->at.nw : 0; }

int scaf_atlas_iterations(const scaf_atlas_t *a, scaf_atlas_phase phase)
{
    if (!a || !a->has_mesh) return 0;
    if (phase == SCAF_ATLAS_SETTLE) return a->at.settle_done;
    if (phase == SCAF_ATLAS_COMPACT) return a->at.compact_done;
    return 0;
}

scaf_stop_reason scaf_atlas_stop_reason(const scaf_atlas_t *a, scaf_atlas_phase phase)
{
    if (!a || !a->has_mesh) return SCAF_STOP_NONE;
    if (phase == SCAF_ATLAS_SETTLE) return a->at.settle_stop;
    if (phase == SCAF_ATLAS_COMPACT) return a->at.compact_stop;
    return SCAF_STOP_NONE;
}

double scaf_atlas_energy(const scaf_atlas_t *a)
{
    return a && a->has_mesh ? scaf_loop_energy(&a->at.loop) : NAN;
}

/* The getters below take a const handle: they leave the layout as it is
 * and only fill the handle's cache of the certified output and its
 * message, which are not part of its observable state. */
static scaf_atlas_t *cache_of(const scaf_atlas_t *a) { return (scaf_atlas_t *)a; }

scaf_status scaf_atlas_get_uv(const scaf_atlas_t *ca, double *UV, int *FT, int *chart)
{
    scaf_atlas_t *a = cache_of(ca);
    if (!a) return SCAF_ERR_USAGE;
    err_clear(&a->err);
    if (!UV)
        return err_set(&a->err, SCAF_ERR_USAGE, "UV is NULL (give %d by 2 doubles)",
                       scaf_atlas_uv_count(a));
    scaf_status st = ensure_output(a);
    if (st != SCAF_OK) return st;
    memcpy(UV, a->UV, sizeof(double) * 2 * (size_t)a->at.nw);
    if (FT) memcpy(FT, a->at.Fw, sizeof(int) * 3 * (size_t)a->at.nf);
    if (chart) memcpy(chart, a->at.chart, sizeof(int) * (size_t)a->at.nf);
    return SCAF_OK;
}

double scaf_atlas_packing_efficiency(const scaf_atlas_t *ca)
{
    scaf_atlas_t *a = cache_of(ca);
    if (!a) return NAN;
    err_clear(&a->err);
    return ensure_output(a) == SCAF_OK ? a->out.efficiency : NAN;
}

double scaf_atlas_min_chart_gap(const scaf_atlas_t *ca)
{
    scaf_atlas_t *a = cache_of(ca);
    if (!a) return NAN;
    err_clear(&a->err);
    return ensure_output(a) == SCAF_OK ? a->out.gap : NAN;
}

scaf_status scaf_atlas_chart_distortion(const scaf_atlas_t *ca, double *E)
{
    scaf_atlas_t *a = cache_of(ca);
    if (!a) return SCAF_ERR_USAGE;
    err_clear(&a->err);
    if (!a->has_mesh)
        return err_set(&a->err, SCAF_ERR_USAGE, "no mesh: call scaf_atlas_set_mesh first");
    if (!E) return err_set(&a->err, SCAF_ERR_USAGE, "E is NULL (give %d doubles)", a->at.ncharts);
    atlas_chart_energy(&a->at, E);
    /* atlas_chart_energy writes NAN everywhere when its scratch memory
     * cannot be allocated; chart areas are positive otherwise */
    for (int c = 0; c < a->at.ncharts; c++)
        if (isnan(E[c])) return err_nomem(&a->err, "per-chart distortion");
    return SCAF_OK;
}
