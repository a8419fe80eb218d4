/* opt/line_search: a step along a direction that never inverts a simplex.
 *
 * Given positions X (all simplices positively oriented) and a direction D,
 * the search: (1) takes the largest flip-free step over every simplex of
 * every term (mesh and scaffold), t_max = min over simplices; (2) starts at
 * t = min(cap, safety * t_max); (3) backtracks (t *= shrink) until the
 * total energy satisfies Armijo, E(t) <= E(0) + c1 t E'(0); (4) confirms
 * the orientation of EVERY simplex at the exact trial positions with the
 * exact predicates orient2d / orient3d, halving t when any check fails.
 * On success X holds the accepted positions. If no step is acceptable
 * (direction not a descent direction, or the energy cannot decrease within
 * max_backtracks) X is unchanged and result.step = 0: the caller treats
 * that as convergence. Errors: SCAF_ERR_NUMERIC when the energy at X is not
 * finite (X was not a valid, positively oriented state) or D is not
 * finite; SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_LINE_SEARCH_H
#define SCAF_OPT_LINE_SEARCH_H

#include "opt/energy.h"

typedef struct opt_ls_options {
    double safety;      /* fraction of the flip-free step taken first (0.8) */
    double max_step;    /* cap on the step (1: the full SLIM step) */
    double armijo;      /* Armijo sufficient-decrease constant c1 (1e-4) */
    double shrink;      /* backtracking factor (0.5) */
    int max_backtracks; /* give up after this many reductions (64) */
} opt_ls_options;

typedef struct opt_ls_result {
    double step;          /* accepted t; 0 when no step was taken */
    double max_flip_free; /* min over simplices of the flip-free step (may be inf) */
    double energy_before; /* total energy sum_terms sum_s weight * density at X */
    double energy_after;  /* the same after the step */
    double slope;         /* directional derivative E'(0) */
    int backtracks;       /* energy (Armijo) reductions */
    int orientation_rejects; /* reductions forced by the exact orientation check */
} opt_ls_result;

void opt_ls_options_default(opt_ls_options *o);

/* Total energy of the terms at X (#X by d). */
double opt_terms_energy(const opt_term *terms, int nterms, const double *X);

/* Whether every simplex of every term is strictly positively oriented at X,
 * decided exactly. Returns 1 if so, else 0 and *bad_term / *bad_simplex
 * (may be NULL) name the first offender. */
int opt_terms_oriented(const opt_term *terms, int nterms, const double *X, int *bad_term,
                       int *bad_simplex);

/* terms: nterms parts of the objective, all of dimension d over the same
 * nv vertices. X: #X by d positions, in/out. D: #X by d direction (zero
 * rows for fixed vertices). o: options (NULL for defaults). res: out. */
scaf_status opt_line_search(const opt_term *terms, int nterms, int d, int nv, double *X,
                            const double *D, const opt_ls_options *o, opt_ls_result *res,
                            scaf_error *err);

#endif /* SCAF_OPT_LINE_SEARCH_H */
