/* opt/surface_arap_term: spokes-and-rims ARAP of a surface toward a target
 * (see surface_arap_term.h). */
#include "opt/surface_arap_term.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "opt/small_svd.h"

static inline void sub3(const double *a, const double *b, double *o)
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static inline double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Edge e of face f runs from corner e+1 to corner e+2 (opposite corner e). */
static inline void edge_ends(const int *F, int f, int e, int *i, int *j)
{
    *i = F[3 * f + (e + 1) % 3];
    *j = F[3 * f + (e + 2) % 3];
}

void opt_surface_arap_free(opt_surface_arap *s)
{
    free(s->F);
    free(s->target);
    free(s->cot);
    free(s->R);
    free(s->Mdt);
    free(s->pairs);
    free(s->built_dof);
    memset(s, 0, sizeof *s);
}

scaf_status opt_surface_arap_init(opt_surface_arap *s, int nv, int nf, const int *F,
                                  const double *target, double weight_ratio, scaf_error *err)
{
    memset(s, 0, sizeof *s);
    if (nv < 1 || nf < 1 || !(weight_ratio > 0.0) || !isfinite(weight_ratio))
        return err_set(err, SCAF_ERR_USAGE,
                       "surface ARAP term: %d vertices, %d faces, weight ratio %g (need >= 1, "
                       ">= 1, > 0)",
                       nv, nf, weight_ratio);
    for (size_t k = 0; k < 3 * (size_t)nf; k++)
        if (F[k] < 0 || F[k] >= nv)
            return err_set(err, SCAF_ERR_USAGE,
                           "surface ARAP term: face %zu: vertex %d not in [0, %d)", k / 3, F[k],
                           nv);
    size_t n3 = 3 * (size_t)nf;
    s->nv = nv;
    s->nf = nf;
    s->F = malloc(sizeof(int) * n3);
    s->target = malloc(sizeof(double) * 3 * (size_t)nv);
    s->cot = malloc(sizeof(double) * n3);
    s->R = malloc(sizeof(double) * 9 * (size_t)nv);
    s->Mdt = malloc(sizeof(double) * 3 * n3);
    s->pairs = malloc(sizeof(int) * 2 * n3);
    s->built_dof = malloc(sizeof(int) * (size_t)nv);
    if (!s->F || !s->target || !s->cot || !s->R || !s->Mdt || !s->pairs || !s->built_dof) {
        opt_surface_arap_free(s);
        return err_nomem(err, "surface ARAP term");
    }
    memcpy(s->F, F, sizeof(int) * n3);
    memcpy(s->target, target, sizeof(double) * 3 * (size_t)nv);
    double area = 0.0;
    for (int f = 0; f < nf; f++) {
        const double *p[3];
        for (int c = 0; c < 3; c++) p[c] = target + 3 * (size_t)F[3 * f + c];
        double u[3], v[3], n[3];
        sub3(p[1], p[0], u);
        sub3(p[2], p[0], v);
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        double twice = sqrt(dot3(n, n));
        area += 0.5 * twice;
        for (int e = 0; e < 3; e++) {
            /* cot of the angle at corner e: (a . b) / |a x b| */
            double a[3], b[3];
            sub3(p[(e + 1) % 3], p[e], a);
            sub3(p[(e + 2) % 3], p[e], b);
            double c = 0.5 * dot3(a, b) / twice;
            if (!(twice > 0.0) || !isfinite(c)) {
                opt_surface_arap_free(s);
                return err_set(err, SCAF_ERR_MESH,
                               "surface ARAP term: target face %d has zero area (no cotangent "
                               "weights)",
                               f);
            }
            s->cot[3 * f + e] = c;
            edge_ends(F, f, e, &s->pairs[2 * (3 * (size_t)f + e)],
                      &s->pairs[2 * (3 * (size_t)f + e) + 1]);
        }
    }
    s->area = area;
    s->w = weight_ratio / area;
    for (int v = 0; v < nv; v++)
        for (int q = 0; q < 9; q++) s->R[9 * (size_t)v + q] = q % 4 == 0 ? 1.0 : 0.0;
    opt_surface_arap_fit(s, target); /* R = I; Mdt = 3 dt */
    return SCAF_OK;
}

/* Mdt of every face edge from the current rotations. */
static void update_mdt(opt_surface_arap *s)
{
    for (int f = 0; f < s->nf; f++) {
        double M[9];
        const double *Ra = s->R + 9 * (size_t)s->F[3 * f], *Rb = s->R + 9 * (size_t)s->F[3 * f + 1],
                     *Rc = s->R + 9 * (size_t)s->F[3 * f + 2];
        for (int q = 0; q < 9; q++) M[q] = Ra[q] + Rb[q] + Rc[q];
        for (int e = 0; e < 3; e++) {
            int i, j;
            edge_ends(s->F, f, e, &i, &j);
            double dt[3];
            sub3(s->target + 3 * (size_t)i, s->target + 3 * (size_t)j, dt);
            double *o = s->Mdt + 9 * (size_t)f + 3 * e;
            for (int a = 0; a < 3; a++)
                o[a] = M[3 * a] * dt[0] + M[3 * a + 1] * dt[1] + M[3 * a + 2] * dt[2];
        }
    }
}

void opt_surface_arap_fit(opt_surface_arap *s, const double *X)
{
    /* N_k = sum over the faces around k of sum_e c dx dt^T; R_k its closest
     * rotation (maximizes sum c dx . R dt). The identity rotations before
     * the first fit are only a start. */
    double *N = calloc(9 * (size_t)s->nv, sizeof *N);
    if (!N) { /* keep the rotations: the term stays a valid quadratic */
        update_mdt(s);
        return;
    }
    for (int f = 0; f < s->nf; f++) {
        double C[9] = {0};
        for (int e = 0; e < 3; e++) {
            int i, j;
            edge_ends(s->F, f, e, &i, &j);
            double dx[3], dt[3], c = s->cot[3 * f + e];
            sub3(X + 3 * (size_t)i, X + 3 * (size_t)j, dx);
            sub3(s->target + 3 * (size_t)i, s->target + 3 * (size_t)j, dt);
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) C[3 * a + b] += c * dx[a] * dt[b];
        }
        for (int k = 0; k < 3; k++) {
            double *Nk = N + 9 * (size_t)s->F[3 * f + k];
            for (int q = 0; q < 9; q++) Nk[q] += C[q];
        }
    }
    for (int v = 0; v < s->nv; v++) {
        double U[9], sv[3], V[9];
        svd3_signed(N + 9 * (size_t)v, U, sv, V);
        double *R = s->R + 9 * (size_t)v;
        int finite = 1;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double r =
                    U[3 * a] * V[3 * b] + U[3 * a + 1] * V[3 * b + 1] + U[3 * a + 2] * V[3 * b + 2];
                finite = finite && isfinite(r);
                R[3 * a + b] = r;
            }
        if (!finite) /* a vertex whose faces have no extent: identity */
            for (int q = 0; q < 9; q++) R[q] = q % 4 == 0 ? 1.0 : 0.0;
    }
    free(N);
    update_mdt(s);
}

double opt_surface_arap_energy(const opt_surface_arap *s, const double *X)
{
    double e = 0.0;
    for (int f = 0; f < s->nf; f++)
        for (int k = 0; k < 3; k++) {
            int i, j;
            edge_ends(s->F, f, k, &i, &j);
            double dx[3], dt[3], c = s->cot[3 * f + k];
            sub3(X + 3 * (size_t)i, X + 3 * (size_t)j, dx);
            sub3(s->target + 3 * (size_t)i, s->target + 3 * (size_t)j, dt);
            const double *m = s->Mdt + 9 * (size_t)f + 3 * k;
            e += c * (3.0 * dot3(dx, dx) - 2.0 * dot3(dx, m) + 3.0 * dot3(dt, dt));
        }
    return s->w * e;
}

static double arap_energy(const opt_obj_term *t, const double *X)
{
    return opt_surface_arap_energy(t->self, X);
}

static void arap_energy_slope(const opt_obj_term *t, const double *X, const double *D, double *e,
                              double *slope)
{
    const opt_surface_arap *s = t->self;
    double g = 0.0;
    for (int f = 0; f < s->nf; f++)
        for (int k = 0; k < 3; k++) {
            int i, j;
            edge_ends(s->F, f, k, &i, &j);
            double dx[3], dd[3], c = s->cot[3 * f + k];
            sub3(X + 3 * (size_t)i, X + 3 * (size_t)j, dx);
            sub3(D + 3 * (size_t)i, D + 3 * (size_t)j, dd);
            const double *m = s->Mdt + 9 * (size_t)f + 3 * k;
            double r[3] = {3.0 * dx[0] - m[0], 3.0 * dx[1] - m[1], 3.0 * dx[2] - m[2]};
            g += c * dot3(r, dd);
        }
    *e += opt_surface_arap_energy(s, X);
    *slope += 2.0 * s->w * g;
}

/* Rebuilt only when a vertex's dof differs from the one it was built for. */
static scaf_status arap_pattern(opt_obj_term *t, const int *dof, int nfree, scaf_error *err)
{
    opt_surface_arap *s = t->self;
    int same = s->built;
    for (int v = 0; same && v < s->nv; v++) same = s->built_dof[v] == dof[v];
    if (same) return SCAF_OK;
    s->built = 0;
    scaf_status st =
        opt_proxy_block_pattern_pairs(&t->blk, 3, 3 * s->nf, s->pairs, dof, nfree, err);
    if (st != SCAF_OK) return st;
    memcpy(s->built_dof, dof, sizeof(int) * (size_t)s->nv);
    s->built = 1;
    return SCAF_OK;
}

/* The quadratic at the fitted rotations: scale 1 (SLIM: half Hessian,
 * rhs = half the negative gradient at 0 plus fixed couplings) or Newton
 * (twice the matrix, rhs = -gradient at X). */
static void arap_fill_any(opt_obj_term *t, const int *dof, const double *X, double *rhs, int newton)
{
    opt_surface_arap *s = t->self;
    opt_surface_arap_fit(s, X);
    if (t->blk.A.nnz > 0) memset(t->blk.A.val, 0, sizeof(double) * (size_t)t->blk.A.nnz);
    double scale = newton ? 2.0 : 1.0;
    for (int f = 0; f < s->nf; f++)
        for (int k = 0; k < 3; k++) {
            int i, j, pk = 3 * f + k;
            edge_ends(s->F, f, k, &i, &j);
            double wc = s->w * s->cot[pk], h = scale * 3.0 * wc;
            int di = dof[i], dj = dof[j];
            if (di >= 0) opt_proxy_block_add_diagonal(&t->blk, di, h);
            if (dj >= 0) opt_proxy_block_add_diagonal(&t->blk, dj, h);
            opt_proxy_block_add_pair(&t->blk, pk, dof, s->pairs, -h);
            const double *m = s->Mdt + 9 * (size_t)f + 3 * k;
            const double *xi = X + 3 * (size_t)i, *xj = X + 3 * (size_t)j;
            for (int a = 0; a < 3; a++) {
                double ri, rj;
                if (newton) { /* -gradient at X */
                    ri = -2.0 * wc * (3.0 * (xi[a] - xj[a]) - m[a]);
                    rj = -ri;
                } else { /* the fixed end's coupling joins the free one's side */
                    ri = wc * m[a] + (dj < 0 ? 3.0 * wc * xj[a] : 0.0);
                    rj = -wc * m[a] + (di < 0 ? 3.0 * wc * xi[a] : 0.0);
                }
                if (di >= 0) rhs[3 * (size_t)di + a] += ri;
                if (dj >= 0) rhs[3 * (size_t)dj + a] += rj;
            }
        }
}

static void arap_fill(opt_obj_term *t, const int *dof, const double *X, double *rhs)
{
    arap_fill_any(t, dof, X, rhs, 0);
}

/* Exact (the term is quadratic at fixed rotations): project changes nothing. */
static scaf_status arap_hessian_fill(opt_obj_term *t, const int *dof, const double *X, int project,
                                     double *rhs, scaf_error *err)
{
    (void)project;
    (void)err;
    arap_fill_any(t, dof, X, rhs, 1);
    return SCAF_OK;
}

static const opt_obj_term_ops arap_ops = {
    arap_energy, arap_energy_slope, arap_pattern, arap_fill, NULL, NULL, arap_hessian_fill};

opt_obj_term opt_surface_arap_make(opt_surface_arap *s)
{
    opt_obj_term t = {&arap_ops, s, {0}};
    return t;
}
