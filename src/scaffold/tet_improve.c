/* scaffold/tet_improve: the improvement pass (see the header): check the
 * scaffold at entry, visit the tets below the quality goal worst first,
 * try the local operations of scaffold/tet_ops on each, repeat while a
 * pass changed something, compact. */
#include "scaffold/tet_improve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/tet_orient.h"
#include "geom/tet_quality.h"
#include "scaffold/tet_ops.h"

void tet_improve_options_default(tet_improve_options *o)
{
    o->quality_goal = 0.2;
    o->max_passes = 3;
    o->max_tries = 3000;
    o->ops = TET_OP_ALL;
}

typedef struct bad_tet {
    double q;
    int t;
} bad_tet;

static int cmp_bad(const void *pa, const void *pb)
{
    const bad_tet *a = pa, *b = pb;
    if (a->q != b->q) return a->q < b->q ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

/* Worst quality, 5th percentile and count below goal of the live tets. */
static int summarize(const tet_scaffold *s, double goal, double *min, double *p5, int *below)
{
    double *q = malloc(sizeof *q * (size_t)(s->nt > 0 ? s->nt : 1));
    if (!q) return -1;
    int n = 0;
    *below = 0;
    for (int t = 0; t < s->nt; t++)
        if (!s->dead[t]) {
            q[n++] = s->q[t];
            *below += s->q[t] < goal;
        }
    int r = tet_quality_summary(n, q, min, p5);
    free(q);
    return r;
}

scaf_status tet_improve(tet_scaffold *s, const double *X, const tet_improve_options *o,
                        tet_improve_stats *stats, scaf_error *err)
{
    tet_improve_options def;
    if (!o) {
        tet_improve_options_default(&def);
        o = &def;
    }
    if (!isfinite(o->quality_goal) || (o->ops & ~(unsigned)TET_OP_ALL))
        return err_set(err, SCAF_ERR_USAGE,
                       "tet_improve: quality goal %g must be finite, ops %#x within %#x",
                       o->quality_goal, o->ops, (unsigned)TET_OP_ALL);
    tet_improve_stats local;
    tet_improve_stats *st = stats ? stats : &local;
    memset(st, 0, sizeof *st);
    st->tets_before = s->nt, st->vertices_before = s->nv;

    /* check every tet at the new mesh positions before anything changes */
    double *saved = NULL;
    if (X && s->nmesh > 0) {
        saved = malloc(sizeof(double) * 3 * (size_t)s->nmesh);
        if (!saved) return err_nomem(err, "scaffold mesh positions");
        memcpy(saved, s->P, sizeof(double) * 3 * (size_t)s->nmesh);
        memcpy(s->P, X, sizeof(double) * 3 * (size_t)s->nmesh);
    }
    for (int t = 0; t < s->nt; t++) {
        const int *q = s->T + 4 * (size_t)t;
        const double *a = s->P + 3 * (size_t)q[0], *b = s->P + 3 * (size_t)q[1],
                     *c = s->P + 3 * (size_t)q[2], *d = s->P + 3 * (size_t)q[3];
        if (tet_orientation(a, b, c, d) <= 0) {
            if (saved) memcpy(s->P, saved, sizeof(double) * 3 * (size_t)s->nmesh);
            free(saved);
            return err_set(err, SCAF_ERR_MESH,
                           "scaffold tet %d (%d, %d, %d, %d) is not positively oriented", t, q[0],
                           q[1], q[2], q[3]);
        }
        s->q[t] = tet_quality(a, b, c, d);
    }
    free(saved);
    if (summarize(s, o->quality_goal, &st->min_before, &st->p5_before, &st->below_goal_before))
        return err_nomem(err, "scaffold quality summary");

    /* the passes */
    tet_ops c = {s, st, o->max_tries, SCAF_OK, err};
    bad_tet *bad = NULL;
    for (int pass = 0; pass < o->max_passes && !tet_ops_exhausted(&c); pass++) {
        bad_tet *nb = realloc(bad, sizeof *bad * (size_t)(s->nt > 0 ? s->nt : 1));
        if (!nb) {
            c.status = err_nomem(err, "scaffold worklist");
            break;
        }
        bad = nb;
        int nbad = 0;
        for (int t = 0; t < s->nt; t++)
            if (!s->dead[t] && s->q[t] < o->quality_goal) bad[nbad].q = s->q[t], bad[nbad++].t = t;
        if (nbad == 0) break;
        /* with a budget only the worst few can be visited: sort those (the
         * tets at or below the k-th worst quality, k the tries left) */
        long long left = o->max_tries > 0 ? o->max_tries - st->tries : nbad;
        if (left < nbad / 2) {
            double *x = malloc(sizeof *x * (size_t)nbad);
            if (!x) {
                c.status = err_nomem(err, "scaffold worklist");
                break;
            }
            for (int i = 0; i < nbad; i++) x[i] = bad[i].q;
            double qk = tet_quality_kth(x, nbad, (int)left);
            free(x);
            int keep = 0;
            for (int i = 0; i < nbad; i++)
                if (bad[i].q <= qk) bad[keep++] = bad[i];
            nbad = keep;
        }
        qsort(bad, (size_t)nbad, sizeof *bad, cmp_bad);
        st->passes++;
        int applied = 0;
        for (int i = 0; i < nbad && !tet_ops_exhausted(&c); i++) {
            int t = bad[i].t;
            /* a slot freed or refilled since, by a better tet: skip */
            if (t >= s->nt || s->dead[t] || !(s->q[t] < o->quality_goal)) continue;
            applied += tet_ops_improve_tet(&c, t, o->ops);
        }
        if (!applied) break;
    }
    free(bad);

    tet_scaffold_compact(s);
    if (c.status) return c.status;
    st->tets_after = s->nt, st->vertices_after = s->nv;
    if (summarize(s, o->quality_goal, &st->min_after, &st->p5_after, &st->below_goal_after))
        return err_nomem(err, "scaffold quality summary");
    return SCAF_OK;
}
