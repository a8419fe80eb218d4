/* opt/proxy_system: the sum of several proxy blocks as one sparse system.
 *
 * SCAF's system is chart block + scaffold block over one numbering of free
 * vertices. The system keeps the union pattern and, per block, a map from
 * the block's vertex-level entries into it. opt_proxy_system_sum rebuilds
 * the union only when some block's pattern version changed since the last
 * call (the scaffold, every iteration), re-deriving only the small
 * per-block entry maps; the chart block's own simplex map is never redone.
 * Then it sums values (one pass over each block's nonzeros). With a single
 * block the union is that block's matrix (no copy of the pattern).
 * The resulting A (upper CSC) feeds opt/cholmod_solver; `version` changes
 * exactly when A's pattern changes, so the solver can keep its analysis.
 */
#ifndef SCAF_OPT_PROXY_SYSTEM_H
#define SCAF_OPT_PROXY_SYSTEM_H

#include "opt/proxy_block.h"

#define OPT_PROXY_MAX_BLOCKS 8

typedef struct opt_proxy_system {
    int d, nfree; /* nfree: max over blocks; A is nfree*d square */
    int nblocks;
    int *vcolptr, *vrowidx;              /* union vertex-level pattern */
    int *emap[OPT_PROXY_MAX_BLOCKS];     /* block entry -> union entry */
    int *only;                           /* per vertex column: the one block
                                            with entries there (its column is
                                            the union's: values copied), -1
                                            when several or none */
    unsigned seen[OPT_PROXY_MAX_BLOCKS]; /* block versions merged */
    const opt_proxy_block *blk[OPT_PROXY_MAX_BLOCKS];
    opt_csc A; /* union matrix (owned when nblocks > 1) */
    int owns;  /* whether A's arrays are the ones below */
    /* The union's storage and the capacities of the arrays above, kept
     * across rebuilds (the scaffold's pattern changes every iteration): a
     * rebuild refills memory already in use instead of new pages. */
    int *own_colptr, *own_rowidx;
    double *own_val;
    size_t cap_vcol, cap_vrow, cap_col, cap_nnz, cap_emap[OPT_PROXY_MAX_BLOCKS];
    unsigned version; /* bumped whenever A's pattern changes */
} opt_proxy_system;

/* Free everything; safe on a zeroed system. */
void opt_proxy_system_free(opt_proxy_system *sys);

/* Sum blocks[0..nblocks) (same d, nblocks <= OPT_PROXY_MAX_BLOCKS) into
 * sys->A, of dimension max(block nfree) * d (a block with a smaller nfree
 * covers the leading unknowns). Blocks must stay alive and unmoved while
 * sys->A is used. The values are summed in base/parallel's threads, each
 * over its own columns, block after block: the serial sums for any count. */
scaf_status opt_proxy_system_sum(opt_proxy_system *sys, const opt_proxy_block *const *blocks,
                                 int nblocks, scaf_error *err);

#endif /* SCAF_OPT_PROXY_SYSTEM_H */
