/* opt/line_search: a step along a direction that never inverts a simplex.
 *
 * Given positions X (all simplices positively oriented) and a direction D,
 * the search: (1) takes the largest allowed step of every term (for
 * simplices: the flip-free step, min over simplices), t_max = min over
 * terms; (2) starts at
 * t = min(cap, safety * t_max); (3) backtracks (t *= shrink) until the
 * total energy satisfies Armijo, E(t) <= E(0) + c1 t E'(0); (4) confirms
 * every term's exact validity test at the trial positions (simplices:
 * orient2d / orient3d of EVERY simplex), halving t when any check fails.
 * On success X holds the accepted positions. If no step is acceptable
 * (direction not a descent direction, or the energy cannot decrease within
 * max_backtracks) X is unchanged and result.step = 0: the caller treats
 * that as convergence. Errors: SCAF_ERR_NUMERIC when the energy at X is not
 * finite (X was not a valid, positively oriented state) or D is not
 * finite; SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_LINE_SEARCH_H
#define SCAF_OPT_LINE_SEARCH_H

#include "opt/objective.h"

#define OPT_LS_MAX_TERMS 8

typedef struct opt_ls_options {
    double safety;      /* fraction of the flip-free step taken first (0.8) */
    double max_step;    /* cap on the step (1: the full SLIM step) */
    double armijo;      /* Armijo sufficient-decrease constant c1 (1e-4) */
    double shrink;      /* backtracking factor (0.5) */
    int max_backtracks; /* give up after this many reductions (64) */
} opt_ls_options;

typedef struct opt_ls_result {
    double step;             /* accepted t; 0 when no step was taken */
    double max_flip_free;    /* min over simplices of the flip-free step (may be inf) */
    double energy_before;    /* total energy sum_terms sum_s weight * density at X */
    double energy_after;     /* the same after the step */
    double slope;            /* directional derivative E'(0) */
    int backtracks;          /* energy (Armijo) reductions */
    int orientation_rejects; /* reductions forced by the exact orientation check */
    /* When step > 0 and nterms <= OPT_LS_MAX_TERMS: term k's energy at the
     * accepted positions (their sum, in term order, is energy_after), so
     * a caller needs no pass of its own for them; nterm_energy says how
     * many are set (0 otherwise). */
    int nterm_energy;
    double term_energy[OPT_LS_MAX_TERMS];
} opt_ls_result;

void opt_ls_options_default(opt_ls_options *o);

/* terms: nterms terms of the objective (opt/objective), all over the same
 * nv vertices of dimension d. X: #X by d positions, in/out. D: #X by d direction (zero
 * rows for fixed vertices). o: options (NULL for defaults). res: out. */
scaf_status opt_line_search(const opt_obj_term *terms, int nterms, int d, int nv, double *X,
                            const double *D, const opt_ls_options *o, opt_ls_result *res,
                            scaf_error *err);

#endif /* SCAF_OPT_LINE_SEARCH_H */
