/* scaffold/scaffold_frozen: a scaffold built once (see scaffold_frozen.h). */
#include "scaffold/scaffold_frozen.h"

#include <stdlib.h>

#include "geom/predicates.h"

typedef struct frozen_provider {
    scaffold_provider base;
    scaffold_provider *inner;
    int built;
} frozen_provider;

static scaf_status frozen_refresh(scaffold_provider *p, const double *X, const scaffold_options *o,
                                  scaf_error *err)
{
    frozen_provider *f = (frozen_provider *)p;
    if (!f->built) {
        scaf_status st = f->inner->ops->refresh(f->inner, X, o, err);
        f->built = st == SCAF_OK;
        return st;
    }
    if (p->d != 2) return SCAF_OK;
    scaffold_view v;
    f->inner->ops->view(f->inner, &v);
    for (int s = 0; s < v.n; s++) {
        const double *q[3];
        for (int i = 0; i < 3; i++) {
            int id = v.simplices[3 * s + i];
            q[i] = id < v.nmesh ? X + 2 * (size_t)id : v.extra + 2 * (size_t)(id - v.nmesh);
        }
        if (orient2d(q[0], q[1], q[2]) <= 0)
            return err_set(err, SCAF_ERR_INTERNAL,
                           "frozen scaffold: triangle %d is not positively oriented", s);
    }
    return SCAF_OK;
}

static void frozen_view(const scaffold_provider *p, scaffold_view *v)
{
    const frozen_provider *f = (const frozen_provider *)p;
    f->inner->ops->view(f->inner, v);
}

static void frozen_destroy(scaffold_provider *p)
{
    frozen_provider *f = (frozen_provider *)p;
    scaffold_provider_destroy(f->inner);
    free(f);
}

static const scaffold_provider_ops frozen_ops = {frozen_refresh, frozen_view, frozen_destroy};

scaffold_provider *scaffold_frozen_create(scaffold_provider *inner, scaf_error *err)
{
    frozen_provider *f = calloc(1, sizeof *f);
    if (!f) {
        scaffold_provider_destroy(inner);
        err_nomem(err, "frozen scaffold");
        return NULL;
    }
    f->base.ops = &frozen_ops;
    f->base.d = inner->d;
    f->base.nmesh = inner->nmesh;
    f->inner = inner;
    return &f->base;
}
