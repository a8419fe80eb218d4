/* opt/cholmod_solver: sparse Cholesky (CHOLMOD, supernodal) with reuse.
 *
 * One solver object owns one cholmod_common (no global state; two solvers
 * can run in two threads) and the last symbolic analysis. opt_chol_factor
 * compares the matrix pattern with the analyzed one: same pattern ->
 * numerical factorization only (cholmod_factorize); new pattern -> new
 * analysis (fill-reducing ordering + symbolic factorization) first. The
 * ordering is chosen at creation: AMD (cheap, the default for a pattern
 * that changes every iteration), METIS (nested dissection: slower to
 * compute, often less fill on big meshes), or CHOLMOD's default strategy.
 * opt_chol_analyze_given analyzes with a caller permutation
 * (cholmod_analyze_p), e.g. one reused from a previous pattern.
 * Matrices are opt_csc (upper triangle), wrapped without copying.
 * The SCAF loop does not call it: opt/block_solver decides what to ask of
 * it (ordering, reuse, regularization); one-shot solves (opt/embed,
 * opt/cmcf) and the tests and benchmarks use it directly.
 * Errors: SCAF_ERR_NUMERIC with the reason ("not positive definite at
 * column k", CHOLMOD status), SCAF_ERR_NOMEM, SCAF_ERR_USAGE (solve before
 * factor, size mismatch).
 */
#ifndef SCAF_OPT_CHOLMOD_SOLVER_H
#define SCAF_OPT_CHOLMOD_SOLVER_H

#include "opt/csc.h"

typedef enum opt_ordering {
    OPT_ORDER_AMD = 0,
    OPT_ORDER_METIS,
    OPT_ORDER_CHOLMOD_DEFAULT /* CHOLMOD tries AMD, then METIS if fill is high */
} opt_ordering;

typedef struct opt_chol_stats {
    int analyses;       /* symbolic analyses done */
    int block_analyses; /* of which done on the vertex graph and expanded
                              (opt_chol_set_block, opt/block_symbolic) */
    int split_analyses; /* of which reused the fixed part's analysis
                              (opt_chol_set_fixed_part, opt/split_symbolic) */
    int kept_scatters;  /* new patterns whose fixed part's entries kept their
                              places from the last plan (opt/supernodal_plan) */
    int factorizations; /* numerical factorizations done */
    int not_posdef;     /* factorizations that found the matrix not
                              positive definite (the caller's recovery,
                              e.g. a regularized retry, follows them) */
    double t_analyze;   /* seconds in analysis, cumulative */
    double t_factor;    /* seconds in numerical factorization, cumulative */
    double t_solve;     /* seconds in triangular solves, cumulative */
    double nnz_L;       /* nonzeros of the last factor */
    double flops;       /* flop count of the last factorization (CHOLMOD's estimate) */
} opt_chol_stats;

typedef struct opt_chol opt_chol;

/* New solver. Returns NULL on failure with err set. */
opt_chol *opt_chol_create(opt_ordering ordering, scaf_error *err);

/* Free; safe on NULL. */
void opt_chol_destroy(opt_chol *c);

/* Declare that unknowns come in interleaved groups of `block` (the d
 * coordinates of a vertex: unknown k*block + a). New analyses then compute
 * the AMD / METIS ordering on the compressed vertex graph (block^2 times
 * fewer edges) and expand it, which is cheaper and orders each vertex's
 * coordinates together. block = 1 (the default) orders scalars. Ignored
 * for OPT_ORDER_CHOLMOD_DEFAULT and when n is not a multiple of block.
 * The symbolic analysis (supernodal) is then done on the vertex graph too
 * and expanded (opt/block_symbolic: b^2 times fewer entries to analyse),
 * whenever the permutation keeps each vertex's unknowns together; a
 * given permutation that splits them gets the scalar analysis. */
void opt_chol_set_block(opt_chol *c, int block);

/* Declare that the first nfixed unknowns (a multiple of the block size)
 * keep their pattern -- the leading nfixed x nfixed block of every system
 * -- and, in given permutations, their order, while the other unknowns
 * and their couplings change from one analysis to the next (SCAF: mesh,
 * then scaffold). An analysis with a given permutation that orders the
 * fixed unknowns first (by blocks) and the rest in natural order then
 * reuses the fixed part's analysis (opt/split_symbolic) instead of
 * analysing the whole pattern; the rest is ordered after the fixed part
 * (natural order, postordered). The factorization then also keeps where
 * the fixed part's entries of A go in the factor (opt_snum_create_kept)
 * while that part's pattern, order and supernodes stay. 0 (the default)
 * turns it off. */
void opt_chol_set_fixed_part(opt_chol *c, int nfixed);

/* Supernode amalgamation: CHOLMOD's relaxation thresholds (nrelax: merge
 * supernodes below 4 / 16 / 48 columns, within the zero-fraction limits
 * zrelax) multiplied by scale >= 1 (1 = CHOLMOD's default). Bigger
 * supernodes store explicit zeros (more memory) but run BLAS on bigger
 * blocks with less bookkeeping: on the SCAF systems (2x2 vertex blocks)
 * scale 4 factors 25% faster for 60% more stored entries
 * (bench/bench_factor). Takes effect at the next analysis. */
void opt_chol_set_relax(opt_chol *c, int scale);

/* Who computes the numerical factor on CHOLMOD's symbolic analysis:
 * opt/supernodal_numeric (the default; subtrees of the elimination tree
 * in par_threads() threads, base/parallel) or cholmod_factorize (CHOLMOD's
 * own, parallel only inside BLAS). Both give L L^T of the same structure,
 * equal to rounding. */
typedef enum opt_numeric { OPT_NUMERIC_SUPERNODAL = 0, OPT_NUMERIC_CHOLMOD } opt_numeric;
void opt_chol_set_numeric(opt_chol *c, opt_numeric numeric);

/* Factor A (upper CSC, symmetric positive definite): analysis only when the
 * pattern differs from the last analyzed one. */
scaf_status opt_chol_factor(opt_chol *c, const opt_csc *A, scaf_error *err);

/* opt_chol_factor that also prepares the solve with the right-hand side b
 * (n values): scaf's own factorization runs the forward sweep with b as it
 * factors, while each supernode is in cache, so that the next
 * opt_chol_solve of one right-hand side at the same address b only sweeps
 * backward -- one pass over the factor instead of two, the same bits. b's
 * values must not change in between (the solver keeps no copy: it would
 * be n more doubles); another address gets the whole solve. The forward
 * sweep's time counts as factorization time. */
scaf_status opt_chol_factor_rhs(opt_chol *c, const opt_csc *A, const double *b, scaf_error *err);

/* CHOLMOD's int indices: no more unknowns or factor entries than this. */
#define OPT_CHOL_INDEX_MAX 2147483647

/* SCAF_OK when a system of n unknowns and `entries` stored entries (of
 * the upper triangle) is within OPT_CHOL_INDEX_MAX, else SCAF_ERR_MESH saying the
 * problem is too large for the solver, with the numbers (a limit, exit 4,
 * not a numerical failure). The analysis checks it first; a factor that
 * outgrows the indices during the analysis (CHOLMOD_TOO_LARGE) is
 * reported the same way. The analysis also stops at a pending SIGINT /
 * SIGTERM (base/interrupt: SCAF_ERR_CANCELLED). */
scaf_status opt_chol_size_check(double n, double entries, scaf_error *err);

/* Force a new analysis of A's pattern with a given fill-reducing
 * permutation perm (n entries), or the solver's ordering if perm is NULL. */
scaf_status opt_chol_analyze_given(opt_chol *c, const opt_csc *A, const int *perm, scaf_error *err);

/* The same with A's pattern by vertices given: vcolptr (A->n / block + 1)
 * and vrowidx, each vertex column's rows ascending, A being its
 * interleaved expansion (opt_csc_expand_vertex_pattern; what
 * opt/proxy_system keeps). The analysis by vertices then uses it instead
 * of compressing A again. NULL vcolptr: opt_chol_analyze_given. */
scaf_status opt_chol_analyze_vertices(opt_chol *c, const opt_csc *A, const int *vcolptr,
                                      const int *vrowidx, const int *perm, scaf_error *err);

/* opt_chol_factor_rhs for A given by vertices as in
 * opt_chol_analyze_vertices (c's block > 1, A's pattern the expansion of
 * vcolptr, vrowidx; assert()ed), analysed with perm as there when that
 * vertex pattern is not the last analysis's. The pattern is kept and
 * compared by vertices: a quarter of the reads and copies in 2D. */
scaf_status opt_chol_factor_vertices(opt_chol *c, const opt_csc *A, const int *vcolptr,
                                     const int *vrowidx, const int *perm, const double *b,
                                     scaf_error *err);

/* Whether A has exactly the pattern of the last analysis (then
 * opt_chol_factor will not analyse again). */
int opt_chol_pattern_matches(const opt_chol *c, const opt_csc *A);

/* Compute the solver's fill-reducing permutation of A (n entries, block-
 * aware as set by opt_chol_set_block) without analysing: for building
 * orderings of related systems (scaffold/scaf_loop keeps the mesh's). */
scaf_status opt_chol_compute_ordering(opt_chol *c, const opt_csc *A, int *perm, scaf_error *err);

/* Solve A X = B for nrhs right-hand sides. B, X: n by nrhs, column-major
 * (column k at B + k*n); X may equal B. */
scaf_status opt_chol_solve(opt_chol *c, int nrhs, const double *B, double *X, scaf_error *err);

/* The permutation of the last analysis (n entries), NULL before any. */
const int *opt_chol_permutation(const opt_chol *c);

/* Counters and timings. */
opt_chol_stats opt_chol_get_stats(const opt_chol *c);

/* not_posdef summed over every solver of the process (atomic): lets a test
 * see that a recovery path ran without reaching the solver of the code
 * under test. */
long opt_chol_not_posdef_total(void);

#endif /* SCAF_OPT_CHOLMOD_SOLVER_H */
