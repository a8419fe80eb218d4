/* opt/objective: the terms of the objective a SLIM iteration minimizes.
 *
 * An objective is a list of terms over one vertex array X (#X by d). Each
 * term answers, at positions X (and a direction D, #X by d):
 *   energy        its value; +INFINITY where it forbids X (a barrier);
 *   energy_slope  its value and its derivative along D, ADDED to *e and
 *                 *slope (running sums: a list of terms is summed in one
 *                 order, whatever the terms);
 *   pattern       (re)build its share of the SLIM system, an
 *                 opt_proxy_block (t->blk), for the numbering dof (one entry
 *                 per vertex of X: a free index in [0, nfree) or -1 =
 *                 fixed). Called every iteration before fill; a term whose
 *                 couplings and dofs did not change may keep its pattern;
 *   fill          its convex proxy around X: values into t->blk, and its
 *                 right-hand side ADDED to rhs (nfree*d). The minimizer of
 *                 the summed proxies is the iteration's target;
 *   max_step      optional (NULL: no bound): the largest t such that X + t'D
 *                 is allowed for every 0 <= t' < t — a flip-free bound, a
 *                 per-vertex trust region...; the line search starts from
 *                 a fraction of the minimum over the terms;
 *   valid         optional (NULL: always): decides exactly whether X is
 *                 allowed (simplex orientations by exact predicates);
 *   hessian_fill  optional (NULL: no Newton step with this term): its
 *                 Hessian at X into t->blk (the pattern of `pattern`; each
 *                 simplex's projected PSD when project != 0, the exact one
 *                 otherwise) and its NEGATIVE gradient ADDED to rhs. The
 *                 solution of the summed system is the Newton step itself.
 *                 Fails with SCAF_ERR_USAGE when the term's energy has no
 *                 Hessian here (the loop then takes a SLIM step).
 * The line search (opt/line_search) uses energy, energy_slope, max_step
 * and valid; the assembly (scaffold/scaf_loop) pattern and fill (SLIM) or
 * hessian_fill (projected Newton). A term
 * with no proxy (pattern/fill NULL) adds nothing to the system.
 *
 * opt_simplex_term is the implementation for a set of simplices with a
 * distortion energy (the mesh term, the scaffold term): SLIM proxy blocks,
 * the flip-free bound and exact orientation checks. Other terms (soft
 * positional constraints, surface terms in 3D) implement the same ops.
 */
#ifndef SCAF_OPT_OBJECTIVE_H
#define SCAF_OPT_OBJECTIVE_H

#include "opt/energy.h"
#include "opt/proxy_block.h"

typedef struct opt_obj_term opt_obj_term;

typedef struct opt_obj_term_ops {
    double (*energy)(const opt_obj_term *t, const double *X);
    void (*energy_slope)(const opt_obj_term *t, const double *X, const double *D, double *e,
                         double *slope);
    scaf_status (*pattern)(opt_obj_term *t, const int *dof, int nfree, scaf_error *err);
    void (*fill)(opt_obj_term *t, const int *dof, const double *X, double *rhs);
    double (*max_step)(const opt_obj_term *t, const double *X, const double *D);
    int (*valid)(const opt_obj_term *t, const double *X);
    scaf_status (*hessian_fill)(opt_obj_term *t, const int *dof, const double *X, int project,
                                double *rhs, scaf_error *err);
} opt_obj_term_ops;

struct opt_obj_term {
    const opt_obj_term_ops *ops;
    void *self;          /* the implementation's data (owned by whoever made the term) */
    opt_proxy_block blk; /* its block of the system (owned: opt_obj_term_free) */
};

/* Free the term's block; self is left alone. Safe on a zeroed term. */
void opt_obj_term_free(opt_obj_term *t);

/* Sum of the terms' energies at X, term by term. */
double opt_obj_energy(const opt_obj_term *terms, int nterms, const double *X);

/* Whether every term with a validity test accepts X (exact). */
int opt_obj_valid(const opt_obj_term *terms, int nterms, const double *X);

/* Simplices S with energy `energy` (weights S->weight). The proxy uses
 * proxy_weight (S->n values) instead of S->weight when it is not NULL (the
 * SCAF scaffold: a softer proxy, the true energy in the line search); its
 * Newton fill (opt/newton_fill, symmetric Dirichlet only) always uses the
 * true weights S->weight.
 * keep_pattern: S's simplices and the dofs of their vertices never change
 * once the pattern is built (the mesh term: mesh vertices keep their dofs
 * in every iteration), so it is built once. */
typedef struct opt_simplex_term {
    const opt_simplices *S;
    opt_energy energy;
    const double *proxy_weight;
    int keep_pattern;
} opt_simplex_term;

/* A term over st (which must outlive it). */
opt_obj_term opt_simplex_term_make(opt_simplex_term *st);

#endif /* SCAF_OPT_OBJECTIVE_H */
