/* opt/line_search: a step along a direction that never inverts a simplex.
 *
 * The flip-free bound comes from opt/flip_free_step; energies are barriers
 * (symmetric Dirichlet, conformal) or not (ARAP): in both cases the exact
 * orientation check, not the energy, is what guarantees validity, so it
 * runs on the very doubles that will be stored.
 */
#include "opt/line_search.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"
#include "opt/flip_free_step.h"

void opt_ls_options_default(opt_ls_options *o)
{
    o->safety = 0.8;
    o->max_step = 1.0;
    o->armijo = 1e-4;
    o->shrink = 0.5;
    o->max_backtracks = 64;
}

double opt_terms_energy(const opt_term *terms, int nterms, const double *X)
{
    double e = 0;
    for (int k = 0; k < nterms; k++) e += opt_term_energy(&terms[k], X);
    return e;
}

int opt_terms_oriented(const opt_term *terms, int nterms, const double *X, int *bad_term,
                       int *bad_simplex)
{
    for (int k = 0; k < nterms; k++) {
        const opt_simplices *S = terms[k].s;
        int d = S->d;
        for (int s = 0; s < S->n; s++) {
            const int *ix = S->idx + (size_t)s * (d + 1);
            int ok;
            if (d == 2)
                ok = orient2d(X + 2 * (size_t)ix[0], X + 2 * (size_t)ix[1], X + 2 * (size_t)ix[2]) > 0;
            else /* Shewchuk's orient3d is positive for a negatively oriented tet. */
                ok = orient3d(X + 3 * (size_t)ix[0], X + 3 * (size_t)ix[1], X + 3 * (size_t)ix[2],
                              X + 3 * (size_t)ix[3]) < 0;
            if (!ok) {
                if (bad_term) *bad_term = k;
                if (bad_simplex) *bad_simplex = s;
                return 0;
            }
        }
    }
    return 1;
}

/* E(0) and E'(0) along D in one pass: sum weight * density and
 * sum weight * <dE/dJ, J(D)> (J is linear in positions). */
static double energy_and_slope(const opt_term *terms, int nterms, const double *X, const double *D,
                               double *energy)
{
    double acc = 0, e = 0, J[9], G[9], JD[9];
    for (int k = 0; k < nterms; k++) {
        const opt_simplices *S = terms[k].s;
        int d = S->d;
        for (int s = 0; s < S->n; s++) {
            opt_jacobian(S, s, X, J);
            opt_jacobian(S, s, D, JD);
            double v = opt_density_grad(terms[k].energy, d, J, G);
            double dot = 0;
            for (int q = 0; q < d * d; q++) dot += G[q] * JD[q];
            acc += S->weight[s] * dot;
            e += S->weight[s] * v;
        }
    }
    *energy = e;
    return acc;
}

scaf_status opt_line_search(const opt_term *terms, int nterms, int d, int nv, double *X,
                            const double *D, const opt_ls_options *o, opt_ls_result *res,
                            scaf_error *err)
{
    opt_ls_options def;
    if (!o) { opt_ls_options_default(&def); o = &def; }
    memset(res, 0, sizeof *res);
    size_t n = (size_t)nv * d;
    for (size_t k = 0; k < n; k++)
        if (!isfinite(D[k]))
            return err_set(err, SCAF_ERR_NUMERIC, "line search: direction entry %zu (vertex %zu) is not finite",
                           k, k / d);
    double e0;
    double slope = energy_and_slope(terms, nterms, X, D, &e0);
    res->energy_before = e0;
    res->energy_after = e0;
    if (!isfinite(e0))
        return err_set(err, SCAF_ERR_NUMERIC,
                       "line search: energy at the start is %g (a simplex is inverted or degenerate)", e0);
    double tmax = INFINITY;
    for (int k = 0; k < nterms; k++) {
        double t = opt_max_step(terms[k].s, X, D);
        if (t < tmax) tmax = t;
    }
    res->max_flip_free = tmax;
    res->slope = slope;
    if (!(slope < 0)) return SCAF_OK; /* not a descent direction: no step */
    double t = fmin(o->max_step, o->safety * tmax);
    if (!(t > 0)) return SCAF_OK;
    double *Y = malloc((n ? n : 1) * sizeof *Y);
    if (!Y) return err_nomem(err, "line search trial positions");
    for (int it = 0; it < o->max_backtracks && t > 0; it++) {
        for (size_t k = 0; k < n; k++) Y[k] = X[k] + t * D[k];
        double e = opt_terms_energy(terms, nterms, Y);
        if (!(isfinite(e) && e <= e0 + o->armijo * t * slope)) {
            res->backtracks++;
            t *= o->shrink;
            continue;
        }
        if (!opt_terms_oriented(terms, nterms, Y, NULL, NULL)) {
            res->orientation_rejects++;
            t *= 0.5;
            continue;
        }
        memcpy(X, Y, n * sizeof *X);
        res->step = t;
        res->energy_after = e;
        break;
    }
    free(Y);
    return SCAF_OK;
}
