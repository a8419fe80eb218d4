/* scaffold/scaffold_tet: the 3D scaffold provider (see scaffold_tet.h). */
#include "scaffold/scaffold_tet.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"
#include "geom/tet_box_mesh.h"

typedef struct tet_provider {
    scaffold_provider base;
    int nf;
    int *F;
    double box_scale;
    int box_cells;
    int built;
    scaffold_tets s;
    double eps;
    double lo[3], hi[3];
    scaffold_tet_improver improve;
    void *improve_user;
} tet_provider;

static void tets_free(scaffold_tets *s)
{
    free(s->T);
    free(s->inside);
    free(s->extra);
    free(s->extra_fixed);
    int nmesh = s->nmesh;
    memset(s, 0, sizeof *s);
    s->nmesh = nmesh;
}

static inline const double *pos(const tet_provider *t, const double *X, int id)
{
    int nm = t->base.nmesh;
    return id < nm ? X + 3 * (size_t)id : t->s.extra + 3 * (size_t)(id - nm);
}

/* The first refresh: TetGen around the surface at X. */
static scaf_status build(tet_provider *t, const double *X, scaf_error *err)
{
    int nm = t->base.nmesh;
    tet_box_around(nm, X, t->box_scale, t->lo, t->hi);
    tet_box_mesh m;
    scaf_status st = tet_box_mesh_build(nm, X, t->nf, t->F, t->lo, t->hi, t->box_cells, &m, err);
    if (st != SCAF_OK) return st;
    scaffold_tets *s = &t->s;
    s->n = s->cap_tets = m.nt;
    s->nextra = s->cap_extra = m.nv - nm;
    s->T = m.T;
    s->inside = m.inside;
    s->extra = malloc(sizeof(double) * 3 * (size_t)(s->nextra ? s->nextra : 1));
    s->extra_fixed = malloc((size_t)(s->nextra ? s->nextra : 1));
    m.T = NULL;
    m.inside = NULL;
    if (!s->extra || !s->extra_fixed) {
        tet_box_mesh_free(&m);
        tets_free(s);
        return err_nomem(err, "tet scaffold");
    }
    memcpy(s->extra, m.V + 3 * (size_t)nm, sizeof(double) * 3 * (size_t)s->nextra);
    /* the box's vertices come right after the surface's; TetGen's own
     * points (if any) after them are free */
    for (int i = 0; i < s->nextra; i++) s->extra_fixed[i] = i < m.nbox;
    tet_box_mesh_free(&m);
    return SCAF_OK;
}

static scaf_status tet_refresh(scaffold_provider *p, const double *X, const scaffold_options *o,
                               scaf_error *err)
{
    (void)o;
    tet_provider *t = (tet_provider *)p;
    scaf_status st;
    if (!t->built) {
        st = build(t, X, err);
        if (st != SCAF_OK) return st;
        t->built = 1;
    } else if (t->improve) {
        st = t->improve(t->improve_user, &t->s, X, err);
        if (st != SCAF_OK) {
            err_prefix(err, "tet scaffold improvement");
            return st;
        }
    }
    /* every tet positive, exactly (Shewchuk's orient3d < 0), after an
     * improvement pass (TetGen's output is checked by tet_box_mesh; the
     * loop's line search checks every tet of an accepted step) */
    for (int k = 0; t->improve && k < t->s.n; k++) {
        const int *q = t->s.T + 4 * (size_t)k;
        if (!(orient3d(pos(t, X, q[0]), pos(t, X, q[1]), pos(t, X, q[2]), pos(t, X, q[3])) < 0))
            return err_set(err, SCAF_ERR_INTERNAL,
                           "tet scaffold: tet %d is not positively oriented", k);
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
    v->n = t->s.n;
    v->simplices = t->s.T;
    v->nextra = t->s.nextra;
    v->extra = t->s.extra;
    v->extra_fixed = t->s.extra_fixed;
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
    tets_free(&t->s);
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
    t->s.nmesh = nmesh;
    return &t->base;
}

void scaffold_tet_set_improver(scaffold_provider *p, scaffold_tet_improver fn, void *user)
{
    tet_provider *t = (tet_provider *)p;
    t->improve = fn;
    t->improve_user = user;
}

const scaffold_tets *scaffold_tet_get(const scaffold_provider *p)
{
    return &((const tet_provider *)p)->s;
}

double scaffold_tet_quality(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        w[k] = d[k] - a[k];
    }
    double vol = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                  u[2] * (v[0] * w[1] - v[1] * w[0])) /
        6.0;
    const double *P[4] = {a, b, c, d};
    double ms = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            for (int k = 0; k < 3; k++) ms += (P[i][k] - P[j][k]) * (P[i][k] - P[j][k]);
    double lrms = sqrt(ms / 6.0);
    return lrms > 0.0 ? 6.0 * sqrt(2.0) * vol / (lrms * lrms * lrms) : 0.0;
}

/* The k-th smallest of q[0..n-1] (0-based; q is reordered). */
static double select_kth(double *q, int n, int k)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        double pivot = q[lo + (hi - lo) / 2];
        int i = lo, j = hi;
        while (i <= j) {
            while (q[i] < pivot) i++;
            while (q[j] > pivot) j--;
            if (i <= j) {
                double x = q[i];
                q[i++] = q[j];
                q[j--] = x;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return q[k];
    }
    return q[k];
}

scaf_status scaffold_tet_quality_stats(const scaffold_view *v, const double *X, double *qmin,
                                       double *qp5, scaf_error *err)
{
    *qmin = *qp5 = 0.0;
    if (v->n <= 0) return SCAF_OK;
    double *q = malloc(sizeof(double) * (size_t)v->n);
    if (!q) return err_nomem(err, "tet quality");
    double lo = INFINITY;
    for (int k = 0; k < v->n; k++) {
        const double *P[4];
        for (int i = 0; i < 4; i++) {
            int id = v->simplices[4 * (size_t)k + i];
            P[i] = id < v->nmesh ? X + 3 * (size_t)id : v->extra + 3 * (size_t)(id - v->nmesh);
        }
        q[k] = scaffold_tet_quality(P[0], P[1], P[2], P[3]);
        if (q[k] < lo) lo = q[k];
    }
    *qmin = lo;
    *qp5 = select_kth(q, v->n, (int)((long long)(v->n - 1) * 5 / 100));
    free(q);
    return SCAF_OK;
}
