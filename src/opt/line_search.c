/* opt/line_search: a step along a direction that never inverts a simplex.
 *
 * The bound and the checks come from the terms (opt/objective: for
 * simplices opt/flip_free_step and the exact predicates); energies are
 * barriers (symmetric Dirichlet, conformal) or not (ARAP): in both cases
 * the exact validity check, not the energy, is what guarantees validity,
 * so it runs on the very doubles that will be stored.
 */
#include "opt/line_search.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void opt_ls_options_default(opt_ls_options *o)
{
    o->safety = 0.8;
    o->max_step = 1.0;
    o->armijo = 1e-4;
    o->shrink = 0.5;
    o->max_backtracks = 64;
}

scaf_status opt_line_search(const opt_obj_term *terms, int nterms, int d, int nv, double *X,
                            const double *D, const opt_ls_options *o, opt_ls_result *res,
                            scaf_error *err)
{
    opt_ls_options def;
    if (!o) {
        opt_ls_options_default(&def);
        o = &def;
    }
    memset(res, 0, sizeof *res);
    size_t n = (size_t)nv * d;
    for (size_t k = 0; k < n; k++)
        if (!isfinite(D[k]))
            return err_set(err, SCAF_ERR_NUMERIC,
                           "line search: direction entry %zu (vertex %zu) is not finite", k, k / d);
    double e0 = 0, slope = 0;
    for (int k = 0; k < nterms; k++) terms[k].ops->energy_slope(&terms[k], X, D, &e0, &slope);
    res->energy_before = e0;
    res->energy_after = e0;
    if (!isfinite(e0))
        return err_set(err, SCAF_ERR_NUMERIC,
                       "line search: energy at the start is %g (a simplex is inverted or "
                       "degenerate)",
                       e0);
    double tmax = INFINITY;
    for (int k = 0; k < nterms; k++) {
        if (!terms[k].ops->max_step) continue;
        double t = terms[k].ops->max_step(&terms[k], X, D);
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
        /* opt_obj_energy's sum, each term's share kept (res->term_energy) */
        double e = 0;
        for (int k = 0; k < nterms; k++) {
            double ek = terms[k].ops->energy(&terms[k], Y);
            if (k < OPT_LS_MAX_TERMS) res->term_energy[k] = ek;
            e += ek;
        }
        if (!(isfinite(e) && e <= e0 + o->armijo * t * slope)) {
            res->backtracks++;
            t *= o->shrink;
            continue;
        }
        if (!opt_obj_valid(terms, nterms, Y)) {
            res->orientation_rejects++;
            t *= 0.5;
            continue;
        }
        memcpy(X, Y, n * sizeof *X);
        res->step = t;
        res->energy_after = e;
        res->nterm_energy = nterms <= OPT_LS_MAX_TERMS ? nterms : 0;
        break;
    }
    free(Y);
    assert(res->step == 0.0 || opt_obj_valid(terms, nterms, X)); /* accepted: every term valid */
    return SCAF_OK;
}
