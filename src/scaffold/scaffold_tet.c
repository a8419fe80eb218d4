/* scaffold/scaffold_tet: the 3D scaffold provider (see scaffold_tet.h). */
#include "scaffold/scaffold_tet.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/tet_box_mesh.h"
#include "geom/tet_quality.h"

typedef struct tet_provider {
    scaffold_provider base;
    int nf;
    int *F;
    double box_scale;
    int box_cells;
    int built;
    tet_scaffold s;
    double eps;
    double lo[3], hi[3];
    int improve;
    tet_improve_options improve_opt;
    tet_improve_stats stats;
} tet_provider;

/* The first refresh: TetGen around the surface at X. */
static scaf_status build(tet_provider *t, const double *X, scaf_error *err)
{
    int nm = t->base.nmesh;
    tet_box_around(nm, X, t->box_scale, t->lo, t->hi);
    tet_box_mesh m;
    scaf_status st = tet_box_mesh_build(nm, X, t->nf, t->F, t->lo, t->hi, t->box_cells, &m, err);
    if (st != SCAF_OK) return st;
    st = tet_scaffold_from_box_mesh(&t->s, &m, t->nf, t->F, err);
    tet_box_mesh_free(&m);
    if (st != SCAF_OK) err_prefix(err, "tet scaffold");
    return st;
}

static scaf_status tet_refresh(scaffold_provider *p, const double *X, const scaffold_options *o,
                               scaf_error *err)
{
    (void)o;
    tet_provider *t = (tet_provider *)p;
    scaf_status st;
    memset(&t->stats, 0, sizeof t->stats);
    if (!t->built) {
        st = build(t, X, err);
        if (st != SCAF_OK) return st;
        t->built = 1;
        if (t->improve) {
            /* TetGen's tets: many slivers, no free vertex; improve them
             * once thoroughly (tet_improve.h: no budget, up to 20 passes) */
            tet_improve_options thorough = t->improve_opt;
            thorough.max_tries = 0;
            thorough.max_passes = 20;
            st = tet_improve(&t->s, X, &thorough, &t->stats, err);
            if (st != SCAF_OK) {
                err_prefix(err, "tet scaffold improvement");
                return st;
            }
        }
    } else if (t->improve) {
        /* checks every tet exactly at entry and every operation it applies */
        st = tet_improve(&t->s, X, &t->improve_opt, &t->stats, err);
        if (st != SCAF_OK) {
            err_prefix(err, "tet scaffold improvement");
            return st;
        }
    }
    double l2 = INFINITY;
    for (int f = 0; f < t->nf; f++)
        for (int e = 0; e < 3; e++) {
            const double *a = X + 3 * (size_t)t->F[3 * f + e],
                         *b = X + 3 * (size_t)t->F[3 * f + (e + 1) % 3];
            double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
            double q = dx * dx + dy * dy + dz * dz;
            if (q < l2) l2 = q;
        }
    double l = sqrt(l2);
    t->eps = l * l * l / (6.0 * sqrt(6.0));
    return SCAF_OK;
}

static void tet_view(const scaffold_provider *p, scaffold_view *v)
{
    const tet_provider *t = (const tet_provider *)p;
    memset(v, 0, sizeof *v);
    v->d = 3;
    v->nmesh = p->nmesh;
    if (!t->built) return;
    int nm = p->nmesh;
    v->n = t->s.nt;
    v->simplices = t->s.T;
    v->nextra = t->s.nv - nm;
    v->extra = t->s.P + 3 * (size_t)nm; /* the loop writes its steps here */
    v->extra_fixed = t->s.fixed + nm;
    v->eps = t->eps;
    for (int a = 0; a < 3; a++) {
        v->box_lo[a] = t->lo[a];
        v->box_hi[a] = t->hi[a];
    }
}

static void tet_destroy(scaffold_provider *p)
{
    tet_provider *t = (tet_provider *)p;
    if (!t) return;
    tet_scaffold_free(&t->s);
    free(t->F);
    free(t);
}

static const scaffold_provider_ops tet_ops = {tet_refresh, tet_view, tet_destroy};

scaffold_provider *scaffold_tet_create(int nmesh, int nf, const int *F, double box_scale,
                                       int box_cells, scaf_error *err)
{
    if (nmesh < 4 || nf < 4 || !(box_scale > 1.0) || box_cells < 1 || box_cells > 64) {
        err_set(err, SCAF_ERR_USAGE,
                "tet scaffold: %d vertices, %d faces, box scale %g, box cells %d (need >= 4, "
                ">= 4, > 1, 1..64)",
                nmesh, nf, box_scale, box_cells);
        return NULL;
    }
    tet_provider *t = calloc(1, sizeof *t);
    int *Fc = malloc(sizeof(int) * 3 * (size_t)nf);
    if (!t || !Fc) {
        free(t);
        free(Fc);
        err_nomem(err, "tet scaffold");
        return NULL;
    }
    memcpy(Fc, F, sizeof(int) * 3 * (size_t)nf);
    t->base.ops = &tet_ops;
    t->base.d = 3;
    t->base.nmesh = nmesh;
    t->nf = nf;
    t->F = Fc;
    t->box_scale = box_scale;
    t->box_cells = box_cells;
    t->improve = 1;
    tet_improve_options_default(&t->improve_opt);
    return &t->base;
}

void scaffold_tet_set_improve(scaffold_provider *p, int enable, const tet_improve_options *o)
{
    tet_provider *t = (tet_provider *)p;
    t->improve = enable;
    if (o) t->improve_opt = *o;
    else tet_improve_options_default(&t->improve_opt);
}

const tet_improve_stats *scaffold_tet_improve_stats(const scaffold_provider *p)
{
    return &((const tet_provider *)p)->stats;
}

const signed char *scaffold_tet_inside(const scaffold_provider *p)
{
    return ((const tet_provider *)p)->s.region;
}

scaf_status scaffold_tet_quality_stats(const scaffold_view *v, const double *X, double *qmin,
                                       double *qp5, scaf_error *err)
{
    *qmin = *qp5 = 0.0;
    if (v->n <= 0) return SCAF_OK;
    double *q = malloc(sizeof(double) * (size_t)v->n);
    if (!q) return err_nomem(err, "tet quality");
    for (int k = 0; k < v->n; k++) {
        const double *P[4];
        for (int i = 0; i < 4; i++) {
            int id = v->simplices[4 * (size_t)k + i];
            P[i] = id < v->nmesh ? X + 3 * (size_t)id : v->extra + 3 * (size_t)(id - v->nmesh);
        }
        q[k] = tet_quality(P[0], P[1], P[2], P[3]);
    }
    int rc = tet_quality_summary(v->n, q, qmin, qp5);
    free(q);
    return rc == 0 ? SCAF_OK : err_nomem(err, "tet quality");
}
