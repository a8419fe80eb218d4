/* opt/simplices: a "simplex soup" with rest shapes — what the optimizer sees.
 *
 * The optimizer works on sets of d-simplices (triangles for d = 2,
 * tetrahedra for d = 3) over one shared vertex array X (#X by d current
 * positions). Each simplex carries its rest shape only through a gradient
 * operator G (d+1 by d) with J = sum_i x_i G[i]^T, i.e. the affine Jacobian
 * of rest -> current is J[a][b] = sum_i X[idx_i][a] G[i][b]; a rest volume;
 * and an energy weight (the simplex contributes weight * density(J)).
 * Builders here make the two kinds SCAF needs:
 *   - a 3D surface chart: each triangle laid flat isometrically in its own
 *     2D frame, weight = its 3D area (so sum weight * density / sum weight
 *     is the reported energy E);
 *   - a scaffold: rest shape = current shape, weight = 1 (the caller sets
 *     lambda), with the paper's degeneracy guard (a rest simplex smaller
 *     than min_vol is replaced by a regular one of volume min_vol).
 * Builders fail with SCAF_ERR_MESH naming the simplex when a rest shape is
 * degenerate or non-finite, SCAF_ERR_USAGE on bad indices, SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_SIMPLICES_H
#define SCAF_OPT_SIMPLICES_H

#include <stddef.h>

#include "base/error.h"

typedef struct opt_simplices {
    int d;          /* dimension: 2 (triangles) or 3 (tetrahedra) */
    int n;          /* number of simplices */
    int *idx;       /* n by (d+1) vertex indices into the shared X */
    double *grad;   /* n by (d+1) by d gradient operators: grad[(s*(d+1)+i)*d + b] */
    double *vol;    /* n rest areas / volumes, > 0 */
    double *weight; /* n energy weights, >= 0 (caller may overwrite) */
} opt_simplices;

/* Allocate room for n simplices of dimension d (contents uninitialized).
 * On failure *s is left empty. */
scaf_status opt_simplices_alloc(opt_simplices *s, int d, int n, scaf_error *err);

/* Free and reset to empty; safe on an empty (zeroed) set. */
void opt_simplices_free(opt_simplices *s);

/* Lay the 3D triangle p0 p1 p2 flat isometrically: q (3 by 2) gets
 * (0,0), (|p1-p0|, 0) and the third corner with positive y. */
void opt_flatten_triangle(const double p0[3], const double p1[3], const double p2[3], double q[6]);

/* Gradient operator of one rest simplex. rest: (d+1) by d rest corner
 * coordinates. grad: (d+1) by d out. vol: signed rest volume out.
 * Returns 0 when the rest simplex is degenerate (grad then undefined). */
int opt_gradient_operator(int d, const double *rest, double *grad, double *vol);

/* Jacobian of simplex s of set S at positions X (#X by d): J d by d out. */
void opt_jacobian_general(const opt_simplices *S, int s, const double *X, double *J);
static inline void opt_jacobian(const opt_simplices *S, int s, const double *X, double *J)
{
    if (S->d != 2) {
        opt_jacobian_general(S, s, X, J);
        return;
    }
    /* Inline: the hot case, run per triangle by the energy, line search
     * and proxy loops in other files. */
    const int *ix = S->idx + (size_t)s * 3;
    const double *G = S->grad + (size_t)s * 6;
    const double *x0 = X + 2 * (size_t)ix[0], *x1 = X + 2 * (size_t)ix[1],
                 *x2 = X + 2 * (size_t)ix[2];
    for (int a = 0; a < 2; a++) {
        J[2 * a] = x0[a] * G[0] + x1[a] * G[2] + x2[a] * G[4];
        J[2 * a + 1] = x0[a] * G[1] + x1[a] * G[3] + x2[a] * G[5];
    }
}

/* Pull a d by d matrix M (a derivative w.r.t. J, or a direction in J
 * space) back to the simplex's corners through its gradient operator G
 * ((d+1) by d): out[i*d + a] = sum_b M[a][b] G[i][b]. This is the chain
 * rule dJ/dx^T: the corner gradient of f(J) is the pull-back of df/dJ. */
static inline void opt_pullback(int d, const double *G, const double *M, double *out)
{
    for (int i = 0; i <= d; i++)
        for (int a = 0; a < d; a++) {
            double acc = 0;
            for (int b = 0; b < d; b++) acc += M[a * d + b] * G[i * d + b];
            out[i * d + a] = acc;
        }
}

/* Surface chart: nv vertices V (#V by 3), nf triangles F (#F by 3).
 * Builds d = 2 simplices with idx = F, flattened rest frames, vol = weight
 * = 3D area. Fails on a zero-area or non-finite triangle (SCAF_ERR_MESH). */
scaf_status opt_simplices_from_surface(opt_simplices *out, int nv, const double *V, int nf,
                                       const int *F, scaf_error *err);

/* Reorder S in place: simplex k becomes the old simplex order[k] (order:
 * a permutation of 0..n-1). Fails with SCAF_ERR_NOMEM (S unchanged). */
scaf_status opt_simplices_permute(opt_simplices *S, const int *order, scaf_error *err);

/* The order of S's simplices by their largest vertex index, ties kept in
 * their order (a counting sort over nv vertices): order gets n entries.
 * In this order a scatter into one matrix column per vertex walks the
 * columns nearly in sequence, and a pass over the corners reads X nearly
 * in sequence. */
scaf_status opt_simplices_order_by_last_vertex(const opt_simplices *S, int nv, int *order,
                                               scaf_error *err);

/* Rest shape = current shape: d = 2 or 3, X (#X by d) with nv rows,
 * n simplices S (n by (d+1)). A simplex of signed volume below min_vol uses
 * a regular simplex of volume min_vol as rest shape instead (the paper's
 * eps = l^2/4 guard; pass 0 to disable); for d = 2, a triangle of area
 * between min_vol / 4 and 2 min_vol gets its own shape blended towards
 * that regular one (smoothly in log area), so the rest shape is a
 * continuous function of the current shape. Weight is set to 1. Fails with
 * SCAF_ERR_MESH on a simplex of volume <= 0 when min_vol <= 0. */
scaf_status opt_simplices_from_current(opt_simplices *out, int d, int nv, const double *X, int n,
                                       const int *S, double min_vol, scaf_error *err);

/* Signed volume of simplex s at positions X (plain floating point;
 * use the exact predicates for decisions). */
double opt_signed_volume(const opt_simplices *S, int s, const double *X);

#endif /* SCAF_OPT_SIMPLICES_H */
