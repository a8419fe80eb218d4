/* opt/handle_term: soft positional constraints (see handle_term.h). */
#include "opt/handle_term.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double opt_handle_weight(double weight_ratio, double total_area, int nhandles)
{
    if (nhandles <= 0 || !(total_area > 0.0)) return 0.0;
    double l2 = total_area; /* characteristic length sqrt(A), squared */
    return weight_ratio * total_area / ((double)nhandles * l2);
}

void opt_handle_term_init(opt_handle_term *h, int d, int nverts)
{
    memset(h, 0, sizeof *h);
    h->d = d;
    h->nverts = nverts;
}

scaf_status opt_handle_term_set(opt_handle_term *h, int n, const int *vertex, const double *target,
                                double w, scaf_error *err)
{
    return opt_handle_term_set_scaled(h, n, vertex, target, NULL, w, err);
}

scaf_status opt_handle_term_set_scaled(opt_handle_term *h, int n, const int *vertex,
                                       const double *target, const double *scale, double w,
                                       scaf_error *err)
{
    if (n < 0) return err_set(err, SCAF_ERR_USAGE, "handles: negative count %d", n);
    if (!isfinite(w) || w < 0.0)
        return err_set(err, SCAF_ERR_USAGE, "handles: weight %g is not a finite value >= 0", w);
    for (int i = 0; i < n; i++) {
        if (vertex[i] < 0 || vertex[i] >= h->nverts)
            return err_set(err, SCAF_ERR_USAGE, "handle %d: vertex %d is not in [0, %d)", i,
                           vertex[i], h->nverts);
        for (int a = 0; a < h->d; a++)
            if (!isfinite(target[(size_t)h->d * i + a]))
                return err_set(err, SCAF_ERR_USAGE, "handle %d: target coordinate %d is not finite",
                               i, a);
        if (scale && (!isfinite(scale[i]) || scale[i] < 0.0))
            return err_set(err, SCAF_ERR_USAGE,
                           "handle %d: weight factor %g is not a finite value >= 0", i, scale[i]);
    }
    if (n > h->cap) {
        int *v = malloc(sizeof(int) * (size_t)n);
        int *bd = malloc(sizeof(int) * (size_t)n);
        double *t = malloc(sizeof(double) * (size_t)h->d * (size_t)n);
        double *sc = malloc(sizeof(double) * (size_t)n);
        if (!v || !bd || !t || !sc) {
            free(v);
            free(bd);
            free(t);
            free(sc);
            return err_nomem(err, "handles");
        }
        free(h->vertex);
        free(h->built_dof);
        free(h->target);
        free(h->scale);
        h->vertex = v;
        h->built_dof = bd;
        h->target = t;
        h->scale = sc;
        h->cap = n;
        h->built = 0;
    }
    if (n != h->n) h->built = 0;
    for (int i = 0; i < n; i++) {
        if (h->built && h->vertex[i] != vertex[i]) h->built = 0;
        h->vertex[i] = vertex[i];
    }
    if (n > 0) memcpy(h->target, target, sizeof(double) * (size_t)h->d * (size_t)n);
    for (int i = 0; i < n; i++) h->scale[i] = scale ? scale[i] : 1.0;
    h->n = n;
    h->w = w;
    return SCAF_OK;
}

double opt_handle_term_max_error(const opt_handle_term *h, const double *X)
{
    double worst = 0.0;
    for (int i = 0; i < h->n; i++) {
        double s = 0.0;
        for (int a = 0; a < h->d; a++) {
            double e = X[(size_t)h->d * h->vertex[i] + a] - h->target[(size_t)h->d * i + a];
            s += e * e;
        }
        if (sqrt(s) > worst) worst = sqrt(s);
    }
    return worst;
}

void opt_handle_term_free(opt_handle_term *h)
{
    free(h->vertex);
    free(h->target);
    free(h->built_dof);
    free(h->scale);
    memset(h, 0, sizeof *h);
}

static double handle_energy(const opt_obj_term *t, const double *X)
{
    const opt_handle_term *h = t->self;
    double s = 0.0;
    for (int i = 0; i < h->n; i++)
        for (int a = 0; a < h->d; a++) {
            double e = X[(size_t)h->d * h->vertex[i] + a] - h->target[(size_t)h->d * i + a];
            s += h->scale[i] * (e * e); /* scale 1: the bits of the plain sum */
        }
    return h->w * s;
}

static void handle_energy_slope(const opt_obj_term *t, const double *X, const double *D, double *e,
                                double *slope)
{
    const opt_handle_term *h = t->self;
    double s = 0.0, g = 0.0;
    for (int i = 0; i < h->n; i++)
        for (int a = 0; a < h->d; a++) {
            size_t k = (size_t)h->d * h->vertex[i] + a;
            double r = X[k] - h->target[(size_t)h->d * i + a];
            s += h->scale[i] * (r * r);
            g += h->scale[i] * r * D[k];
        }
    *e += h->w * s;
    *slope += 2.0 * h->w * g;
}

/* Rebuilt only when a handle's dof is not the one the pattern has. */
static scaf_status handle_pattern(opt_obj_term *t, const int *dof, int nfree, scaf_error *err)
{
    opt_handle_term *h = t->self;
    int same = h->built;
    for (int i = 0; same && i < h->n; i++) same = h->built_dof[i] == dof[h->vertex[i]];
    if (same) return SCAF_OK;
    h->built = 0;
    scaf_status st =
        opt_proxy_block_pattern_vertices(&t->blk, h->d, h->n, h->vertex, dof, nfree, err);
    if (st != SCAF_OK) return st;
    for (int i = 0; i < h->n; i++) h->built_dof[i] = dof[h->vertex[i]];
    h->built = 1;
    return SCAF_OK;
}

static void handle_fill(opt_obj_term *t, const int *dof, const double *X, double *rhs)
{
    (void)X;
    const opt_handle_term *h = t->self;
    if (t->blk.A.nnz > 0) memset(t->blk.A.val, 0, sizeof(double) * (size_t)t->blk.A.nnz);
    for (int i = 0; i < h->n; i++) {
        int k = dof[h->vertex[i]];
        if (k < 0) continue; /* a fixed vertex: nothing to move */
        double wi = h->w * h->scale[i];
        opt_proxy_block_add_diagonal(&t->blk, k, wi);
        for (int a = 0; a < h->d; a++)
            rhs[(size_t)h->d * k + a] += wi * h->target[(size_t)h->d * i + a];
    }
}

/* Newton: the term is quadratic, its Hessian 2w I exact (project changes
 * nothing) and its negative gradient -2w (x - t). */
static scaf_status handle_hessian_fill(opt_obj_term *t, const int *dof, const double *X,
                                       int project, double *rhs, scaf_error *err)
{
    (void)project;
    (void)err;
    const opt_handle_term *h = t->self;
    if (t->blk.A.nnz > 0) memset(t->blk.A.val, 0, sizeof(double) * (size_t)t->blk.A.nnz);
    for (int i = 0; i < h->n; i++) {
        int k = dof[h->vertex[i]];
        if (k < 0) continue;
        double wi = h->w * h->scale[i];
        opt_proxy_block_add_diagonal(&t->blk, k, 2.0 * wi);
        for (int a = 0; a < h->d; a++) {
            size_t v = (size_t)h->d * h->vertex[i] + a;
            rhs[(size_t)h->d * k + a] -= 2.0 * wi * (X[v] - h->target[(size_t)h->d * i + a]);
        }
    }
    return SCAF_OK;
}

static const opt_obj_term_ops handle_ops = {
    handle_energy, handle_energy_slope, handle_pattern, handle_fill, NULL,
    NULL,          handle_hessian_fill};

opt_obj_term opt_handle_term_make(opt_handle_term *h)
{
    opt_obj_term t = {&handle_ops, h, {0}};
    return t;
}
