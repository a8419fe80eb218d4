/* scaffold/scaffold_cdt: the 2D scaffold provider (see scaffold_cdt.h). */
#include "scaffold/scaffold_cdt.h"

#include <stdlib.h>
#include <string.h>

typedef struct cdt_provider {
    scaffold_provider base;
    int nedges;
    int *edges;  /* nedges by 2 */
    scaffold sc; /* the current scaffold (empty before the first refresh) */
} cdt_provider;

static scaf_status cdt_refresh(scaffold_provider *p, const double *X, const scaffold_options *o,
                               scaf_error *err)
{
    cdt_provider *c = (cdt_provider *)p;
    scaffold_free(&c->sc);
    double box[4];
    scaffold_box(X, p->nmesh, o->box_scale, o->box_square, box);
    return scaffold_build(X, p->nmesh, c->edges, c->nedges, box, o, &c->sc, err);
}

static void cdt_view(const scaffold_provider *p, scaffold_view *v)
{
    const cdt_provider *c = (const cdt_provider *)p;
    const scaffold *sc = &c->sc;
    memset(v, 0, sizeof *v);
    v->d = 2;
    v->nmesh = p->nmesh;
    v->n = sc->ntri;
    v->simplices = sc->T;
    v->nextra = sc->nextra;
    v->extra = sc->extra_uv;
    v->extra_fixed = sc->extra_fixed;
    v->eps = sc->eps;
    v->box_lo[0] = sc->box[0];
    v->box_lo[1] = sc->box[1];
    v->box_hi[0] = sc->box[2];
    v->box_hi[1] = sc->box[3];
}

static void cdt_destroy(scaffold_provider *p)
{
    cdt_provider *c = (cdt_provider *)p;
    scaffold_free(&c->sc);
    free(c->edges);
    free(c);
}

static const scaffold_provider_ops cdt_ops = {cdt_refresh, cdt_view, cdt_destroy};

scaffold_provider *scaffold_cdt_create(int nmesh, const int *edges, int nedges, scaf_error *err)
{
    cdt_provider *c = calloc(1, sizeof *c);
    int *e = malloc(sizeof(int) * 2 * (size_t)(nedges > 0 ? nedges : 1));
    if (!c || !e) {
        free(c);
        free(e);
        err_nomem(err, "2D scaffold");
        return NULL;
    }
    memcpy(e, edges, sizeof(int) * 2 * (size_t)nedges);
    c->base.ops = &cdt_ops;
    c->base.d = 2;
    c->base.nmesh = nmesh;
    c->nedges = nedges;
    c->edges = e;
    return &c->base;
}
