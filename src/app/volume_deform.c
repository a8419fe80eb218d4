/* app/volume_deform: a surface pulled toward a target inside a box of
 * tets (see volume_deform.h). */
#include "app/volume_deform.h"

#include <string.h>

#include "base/timer.h"
#include "scaffold/scaffold_tet.h"

volume_deform_options volume_deform_options_default(void)
{
    volume_deform_options o;
    memset(&o, 0, sizeof o);
    o.box_scale = 3.76;
    o.box_cells = 8;
    o.lambda_ratio = VOLUME_DEFORM_LAMBDA_RATIO_DEFAULT;
    o.weight_ratio = 1.0;
    o.solver = SCAF_SOLVER_NEWTON;
    o.improve = 1;
    tet_improve_options_default(&o.improve_opt);
    o.improve_opt.max_tries = 1000; /* bunny x30: the growth and quality of
                                       3000, 19 instead of 24 ms CPU per
                                       iteration (bench/RESULTS-inflate.md) */
    return o;
}

void volume_deform_free(volume_deform *vd)
{
    scaf_loop_free(&vd->loop);
    opt_surface_arap_free(&vd->arap);
    memset(vd, 0, sizeof *vd);
}

scaf_status volume_deform_init(volume_deform *vd, int nv, const double *V, int nf, const int *F,
                               const double *target, const volume_deform_options *opt,
                               scaf_error *err)
{
    memset(vd, 0, sizeof *vd);
    volume_deform_options o = opt ? *opt : volume_deform_options_default();
    if (!(o.lambda_ratio > 0.0) || !(o.weight_ratio > 0.0))
        return err_set(err, SCAF_ERR_USAGE,
                       "volume deformation: lambda ratio %g and weight ratio %g must be > 0",
                       o.lambda_ratio, o.weight_ratio);
    vd->nv = nv;
    vd->nf = nf;
    scaf_status st = opt_surface_arap_init(&vd->arap, nv, nf, F, target, o.weight_ratio, err);
    if (st != SCAF_OK) return st;
    scaffold_provider *p = scaffold_tet_create(nv, nf, F, o.box_scale, o.box_cells, err);
    if (!p) {
        opt_surface_arap_free(&vd->arap);
        return err && err->code ? err->code : SCAF_ERR_NOMEM;
    }
    scaffold_tet_set_improve(p, o.improve, &o.improve_opt);
    /* the first refresh: TetGen, so a surface it cannot mesh is refused
     * here, before any iteration */
    st = p->ops->refresh(p, V, NULL, err);
    if (st != SCAF_OK) {
        scaffold_provider_destroy(p);
        opt_surface_arap_free(&vd->arap);
        return st;
    }
    scaf_loop_options lo = scaf_loop_options_default();
    lo.lambda_ratio = o.lambda_ratio;
    lo.solver = o.solver;
    /* the floor: 2d per unit of target area, as symmetric Dirichlet's minimum */
    double floor = 6.0 * vd->arap.w * vd->arap.area;
    st = scaf_loop_init_volume(&vd->loop, nv, V, p, floor, &lo, err);
    if (st == SCAF_OK) {
        vd->scaffold = p;
        opt_surface_arap_fit(&vd->arap, V);
        opt_obj_term t = opt_surface_arap_make(&vd->arap);
        st = scaf_loop_add_term(&vd->loop, &t, err);
    }
    if (st != SCAF_OK) volume_deform_free(vd);
    return st;
}

const scaffold_view *volume_deform_scaffold(const volume_deform *vd)
{
    const scaffold_view *v = scaf_loop_scaffold_view(&vd->loop);
    return v;
}

scaf_status volume_deform_step(volume_deform *vd, volume_deform_iteration *it, scaf_error *err)
{
    double t0 = timer_now();
    scaf_iteration_info_t I;
    scaf_status st = scaf_loop_step(&vd->loop, &I, err);
    if (st != SCAF_OK) return st;
    volume_deform_iteration r;
    memset(&r, 0, sizeof r);
    r.iteration = I.iteration;
    r.energy = I.energy;
    r.step = I.step;
    r.tets = I.scaffold_triangles;
    r.scaffold_vertices = I.scaffold_vertices;
    st = scaffold_tet_quality_stats(scaf_loop_scaffold_view(&vd->loop), vd->loop.uv, &r.quality_min,
                                    &r.quality_p5, err);
    r.seconds = timer_now() - t0;
    if (it) *it = r;
    return st;
}
