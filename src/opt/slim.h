/* opt/slim: one SLIM iteration (local proxy, global solve, safe step).
 *
 * An iteration over an objective made of terms (e.g. chart + scaffold, all
 * of dimension d over one vertex array X):
 *   1. assembly: per simplex the signed SVD of J and the SLIM weights
 *      (opt_slim_proxy); values filled into each term's cached pattern
 *      (opt/proxy_block), blocks summed (opt/proxy_system);
 *   2. analysis (only when the summed pattern changed), factorization,
 *      solve (opt/cholmod_solver): the minimizer y of the proxy with the
 *      fixed vertices (dof = -1) held where they are;
 *   3. line search along D = y - X (opt/line_search): flip-free bound,
 *      Armijo backtracking on the true energy, exact orientation check.
 * The object keeps the per-term patterns, the summed system and the
 * solver between calls. Pass term_changed[k] != 0 when term k's simplices
 * (connectivity) or the dof numbering of their vertices changed since the
 * last call — the scaffold every iteration; the chart's block is then
 * reused as is. When the proxy is numerically indefinite (squared SLIM
 * weights grow like s^-3 for a very compressed simplex), the factorization
 * is retried with the weights capped (1e12, 1e9, 1e6, 1e4), and the level
 * that worked is kept while it is binding. Errors: those of the parts (SCAF_ERR_NUMERIC when the
 * system is not positive definite or the state is invalid, SCAF_ERR_NOMEM,
 * SCAF_ERR_USAGE); on error X is unchanged.
 *
 * Sketch of a SCAF loop on top of it (2D, one chart):
 *
 *   opt_simplices chart;                 // once: rest frames, weight = 3D area
 *   opt_simplices_from_surface(&chart, nv, V, nf, F, err);
 *   opt_embed_chart(nv, V, nf, F, &loops, OPT_EMBED_HARMONIC, UV, NULL, err);
 *   opt_slim *sl = opt_slim_create(NULL, err);
 *   for (it = 0; it < max_iter; it++) {
 *       // X = [chart UV (nv rows) | scaffold-only vertices]; dof: chart
 *       // vertices 0..nv-1 first, scaffold after, box corners -1 (fixed).
 *       build scaffold triangles S_idx over X (kernel's CDT);
 *       opt_simplices scaf;
 *       opt_simplices_from_current(&scaf, 2, nX, X, ns, S_idx, eps, err);
 *       double lambda = opt_term_energy(&chart_term, X) / (100.0 * scaf.n);
 *       for (s...) scaf.weight[s] = lambda;
 *       opt_term terms[2] = {{&chart, energy}, {&scaf, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
 *       int changed[2] = {0, 1};
 *       opt_slim_step(sl, terms, 2, changed, nX, dof, nfree, X, &st, err);
 *       E = opt_term_mean_energy(&terms[0], X);  // the reported energy
 *       opt_simplices_free(&scaf);
 *   }
 *
 * (opt_term_energy uses the chart weights = 3D areas, so lambda above
 * follows the paper's E_M / (100 |S|) with E_M the area-weighted sum; use
 * the mean instead if E_M is meant normalized.)
 */
#ifndef SCAF_OPT_SLIM_H
#define SCAF_OPT_SLIM_H

#include "opt/cholmod_solver.h"
#include "opt/line_search.h"
#include "opt/proxy_system.h"

typedef struct opt_slim_options {
    opt_ordering ordering;  /* fill-reducing ordering for new patterns (AMD) */
    opt_ls_options ls;      /* line search (opt_ls_options_default) */
    double regularization;  /* added to the diagonal of the proxy (0) */
    int block_ordering;     /* order the vertex graph, not scalars (1) */
    int reuse_chart_ordering; /* order term 0 (the chart) once with
                               chart_ordering and extend it to the other
                               terms at each new pattern (opt/ordering_reuse)
                               instead of ordering the whole system from
                               scratch with `ordering` (1) */
    opt_ordering chart_ordering; /* ordering computed once for term 0 (METIS) */
} opt_slim_options;

typedef struct opt_slim_stats {
    double t_assemble;   /* proxy weights + value fill + block sum */
    double t_pattern;    /* pattern (re)builds of blocks and union */
    double t_analyze;    /* symbolic analysis (0 when reused) */
    double t_factor;     /* numerical factorization */
    double t_solve;      /* triangular solves */
    double t_line_search;
    int analyzed;        /* 1 if this iteration needed a new analysis */
    int blocks_rebuilt;  /* terms whose pattern was rebuilt this iteration */
    int cap_retries;     /* factorizations redone with tighter weight caps
                            (Newton: with a larger diagonal shift) */
    double weight_cap;   /* cap on squared SLIM weights used (INFINITY: none) */
    double max_weight2;  /* largest uncapped squared SLIM weight (SLIM only) */
    int clamped;         /* Newton: simplices whose Hessian had a negative
                            eigenvalue clamped to 0 */
    double shift;        /* Newton: diagonal shift that made H factorable (0) */
    int exact;           /* Newton: 1 if the exact (unprojected) Hessian was used */
    int exact_rejected;  /* Newton: 1 if it was tried first but was not
                            positive definite (the projected one was used) */
    opt_ls_result ls;    /* step, energies before/after, backtracks */
} opt_slim_stats;

typedef struct opt_slim opt_slim;

void opt_slim_options_default(opt_slim_options *o);

/* New iteration driver; o may be NULL for defaults. NULL on failure. */
opt_slim *opt_slim_create(const opt_slim_options *o, scaf_error *err);

/* Free; safe on NULL. */
void opt_slim_destroy(opt_slim *sl);

/* One iteration. terms: nterms (<= OPT_PROXY_MAX_BLOCKS) parts of the
 * objective, all dimension d. term_changed: nterms flags or NULL (NULL =
 * nothing changed; the first call builds every pattern anyway). nv: rows of
 * X. dof: nv entries, a free index in [0, nfree) or -1 for fixed vertices.
 * X: #X by d, in/out. st: timings and line-search result (may be NULL). */
scaf_status opt_slim_step(opt_slim *sl, const opt_term *terms, int nterms,
                          const int *term_changed, int nv, const int *dof, int nfree, double *X,
                          opt_slim_stats *st, scaf_error *err);

/* One projected Newton iteration with the same object, arguments and
 * machinery: the system is the sum of the terms' PSD-projected Hessians
 * (opt/newton_fill) in the SLIM proxy's pattern — switching between
 * opt_slim_step and opt_newton_step needs no new symbolic analysis — its
 * solution p is the direction (H p = -g, fixed vertices do not move), and
 * the line search is the same (flip-free bound, Armijo, exact orientation
 * check; a full step is t = 1, o.ls.max_step). Every term must be
 * symmetric Dirichlet (SCAF_ERR_USAGE otherwise). After a full step
 * (t = max_step) the next step first tries the exact Hessian: near a
 * strict minimum it is positive definite and converges quadratically,
 * while the per-simplex projection, active at the minimum of a curved
 * surface (stretched simplices have negative twists there), converges only
 * linearly. When the exact one is not positive definite (or gives no
 * descent) the projected one is used; that one is semidefinite, and when
 * CHOLMOD finds it not positive definite the factorization is retried
 * with a diagonal shift (1e-10 .. 1e-4 of its largest diagonal entry),
 * reported in st->shift. From far away SLIM steps are usually better. */
scaf_status opt_newton_step(opt_slim *sl, const opt_term *terms, int nterms,
                            const int *term_changed, int nv, const int *dof, int nfree, double *X,
                            opt_slim_stats *st, scaf_error *err);

/* The solver inside (statistics, permutation). */
const opt_chol *opt_slim_solver(const opt_slim *sl);

/* Number the free vertices: fixed[v] != 0 marks vertex v fixed (fixed may
 * be NULL: none). dof gets nv entries; returns the number of free ones. */
int opt_dof_numbering(int nv, const unsigned char *fixed, int *dof);

#endif /* SCAF_OPT_SLIM_H */
