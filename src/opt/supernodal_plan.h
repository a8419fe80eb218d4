/* opt/supernodal_plan: how scaf's supernodal Cholesky factorization
 * (opt/supernodal_numeric) and its solves (opt/supernodal_solve) run on
 * the symbolic factor of a CHOLMOD analysis, made once per pattern:
 *   - where each entry of A goes in the factor's supernodes (so that no
 *     factorization transposes or permutes A);
 *   - a cut of the supernodal elimination tree into B bins of whole
 *     subtrees of about equal work (the sum of squared column counts,
 *     longest first), each bin's supernodes in ascending order; the
 *     supernodes above the cut follow, in one thread, which cuts the large
 *     ones into B shares for the threads (top_parallel);
 *   - each bin's (and share's) workspaces.
 * B is the caller's (opt/cholmod_solver: the thread count, or
 * OPT_SNUM_BINS when deterministic), not necessarily the thread count:
 * the bins and shares are worked by however many threads base/parallel
 * has, one bin or share whole in one thread, and every value is computed
 * the same way whichever thread does it. So for a given B the factor and
 * the solves are the same bits for any thread count (the same output
 * on every machine), and one thread runs the same bins one after another.
 * Supernode s holds columns [super[s], super[s+1]) as a dense column-major block of nsrow x nscol
 * values at x + px[s]; its rows are s[pi[s] .. pi[s+1]), its own columns
 * first, then the rows below, ascending. The struct is shared by the
 * factorization and the solve only.
 */
#ifndef SCAF_OPT_SUPERNODAL_PLAN_H
#define SCAF_OPT_SUPERNODAL_PLAN_H

#include <cholmod.h>

#include "opt/csc.h"

typedef struct opt_snum_worker {
    int *map;        /* row -> its place in the supernode being factored */
    int *rel;        /* a descendant's rows -> places in that supernode */
    double *C;       /* a descendant's update */
    int *head;       /* descendants waiting on each supernode */
    int minor;       /* first column found not positive definite, or -1 */
    double *tmp;     /* solve: a supernode's rows below its diagonal block */
    double *acc;     /* solve: this bin's updates of the rows above the cut */
    size_t prefetch; /* backward sweep: the lowest factor value prefetched */
} opt_snum_worker;

typedef struct opt_snum {
    int n, nsuper, bins;
    const int *super, *pi, *px, *s; /* L's structure (not owned) */
    int *col2super;                 /* n */
    int *next, *lpos;               /* nsuper */
    int *aptr, *asrc, *adst;        /* A's entries by supernode: value index, place in the block */
    int nks;                        /* supernodes 0..nks-1 also take the kept entries: */
    const int *kptr, *ksrc;         /* by supernode: value index, */
    const unsigned *kpos;           /* column << 16 | row's place */
    int kept_reused;                /* the kept entries came from an earlier plan */
    int *order, *bptr;     /* bin k: order[bptr[k] .. bptr[k+1]); the rest: above the cut */
    int *toprow;           /* n: a row's index among the rows above the cut, or -1 */
    int ntop;              /* rows above the cut */
    double *y;             /* n: the solve's vector, in the factor's order */
    opt_snum_worker *w;    /* bins (and the top phase's shares) */
    double diag_share_min; /* OPT_SNUM_DIAG_SHARE_MIN (tests may lower it) */
} opt_snum;

/* Supernodes above the cut with at least this many stored entries are
 * cut into shares for the threads (a par_run costs tens of microseconds). */
#define OPT_SNUM_TOP_PARALLEL_MIN 16384.0

/* In a shared supernode's diagonal block, a column block's rows below its
 * triangle go to the threads when they hold at least this many
 * multiply-adds (~150 us at one thread). Below it the extra calls and the
 * wake cost more than they save: with 2^17, aphrodite's 488-column top
 * block took 1.65 ms shared against 1.29 ms in one thread. */
#define OPT_SNUM_DIAG_SHARE_MIN 4194304.0

/* Bins of the deterministic plans of opt/cholmod_solver
 * (scaf_set_deterministic): fixed, so that the factor does not change with
 * the thread count. Threads beyond it do not speed up the factorization;
 * fewer run the bins in turn (one thread pays for the cut and for scaf's
 * small update kernel: bench/RESULTS-param.md, session 16). */
#define OPT_SNUM_BINS 4

/* Plan for matrices with A's pattern (upper, natural order) on L, a
 * supernodal factor of that pattern, cut into `bins` bins. L keeps its
 * structure while the plan lives. NULL when out of memory or when A has
 * an entry outside L's structure. */
opt_snum *opt_snum_create(const cholmod_factor *L, const opt_csc *A, int bins);

void opt_snum_destroy(opt_snum *P);

/* The entries of A's first nfixed columns placed in the factor's blocks,
 * kept from one plan to the next (opt/split_symbolic's systems: a fixed
 * leading part, eliminated first, whose pattern, order and supernodes do
 * not change while the rest does). Placing every entry of A costs random
 * accesses over all of A at each new pattern (aphrodite: ~7 ms, 5% of an
 * iteration); checking that the kept part still holds costs reading the
 * order. 8 bytes per entry, what the plan would hold for them anyway. */
typedef struct opt_snum_kept opt_snum_kept;
void opt_snum_kept_destroy(opt_snum_kept *K);

/* opt_snum_create that takes A's first nfixed columns' entries from *kept
 * when it matches: `pattern`, the caller's name for A's pattern in those
 * columns (equal names: equal patterns; opt_chol counts the changes), the
 * same leading columns in the factor's order, the same supernodes.
 * Otherwise they are placed anew into a new *kept (the old one destroyed).
 * Columns eliminated elsewhere, supernodes of 2^16 columns or rows, or
 * nfixed = 0 keep nothing. The plan borrows *kept: keep it while the plan
 * lives. */
opt_snum *opt_snum_create_kept(const cholmod_factor *L, const opt_csc *A, int bins, int nfixed,
                               long pattern, opt_snum_kept **kept);

/* Whether supernode sn, above the cut, is cut into shares. */
int opt_snum_top_parallel(const opt_snum *P, int sn);

/* How the plan cut the work: bins used (1 when the tree could not be
 * cut), supernodes in the bins, above the cut, and of those the ones cut
 * into shares. */
typedef struct opt_snum_shape {
    int bins, supernodes, in_bins, above, above_parallel;
} opt_snum_shape;
opt_snum_shape opt_snum_get_shape(const opt_snum *P);

#endif /* SCAF_OPT_SUPERNODAL_PLAN_H */
