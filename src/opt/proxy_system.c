/* opt/proxy_system: the sum of several proxy blocks as one sparse system.
 *
 * Union pattern: per vertex column, a k-way merge of the blocks' sorted row
 * lists, recording for every block entry its union position. Scalar layout
 * follows the same interleaved rule as opt/proxy_block, so values are
 * added column by column with offsets (entry - column start) * d.
 */
#include "opt/proxy_system.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

static void release_union(opt_proxy_system *sys)
{
    free(sys->vcolptr);
    free(sys->vrowidx);
    sys->vcolptr = sys->vrowidx = NULL;
    for (int k = 0; k < OPT_PROXY_MAX_BLOCKS; k++) {
        free(sys->emap[k]);
        sys->emap[k] = NULL;
    }
    if (sys->owns) opt_csc_free(&sys->A);
    memset(&sys->A, 0, sizeof sys->A);
    sys->owns = 0;
}

void opt_proxy_system_free(opt_proxy_system *sys)
{
    if (!sys) return;
    release_union(sys);
    memset(sys, 0, sizeof *sys);
}

static scaf_status build_union(opt_proxy_system *sys, const opt_proxy_block *const *bl, int nb,
                               scaf_error *err)
{
    int nfree = sys->nfree, d = sys->d;
    release_union(sys);
    size_t cap = 0;
    for (int k = 0; k < nb; k++) cap += (size_t)bl[k]->vcolptr[bl[k]->nfree];
    sys->vcolptr = malloc(((size_t)nfree + 1) * sizeof *sys->vcolptr);
    sys->vrowidx = malloc((cap + 1) * sizeof *sys->vrowidx);
    if (!sys->vcolptr || !sys->vrowidx) return err_nomem(err, "proxy system union pattern");
    for (int k = 0; k < nb; k++) {
        sys->emap[k] = malloc(((size_t)bl[k]->vcolptr[bl[k]->nfree] + 1) * sizeof *sys->emap[k]);
        if (!sys->emap[k]) return err_nomem(err, "proxy system union map");
    }
    int out = 0, cur[OPT_PROXY_MAX_BLOCKS];
    for (int c = 0; c < nfree; c++) {
        sys->vcolptr[c] = out;
        int end[OPT_PROXY_MAX_BLOCKS];
        int only = -1, nonempty = 0;
        for (int k = 0; k < nb; k++) {
            int has = c < bl[k]->nfree;
            cur[k] = has ? bl[k]->vcolptr[c] : 0;
            end[k] = has ? bl[k]->vcolptr[c + 1] : 0;
            if (cur[k] < end[k]) {
                only = k;
                nonempty++;
            }
        }
        if (nonempty == 1) { /* most columns: one block's rows, copied */
            for (int e = cur[only]; e < end[only]; e++) {
                sys->emap[only][e] = out;
                sys->vrowidx[out++] = bl[only]->vrowidx[e];
            }
            continue;
        }
        for (;;) {
            int r = INT_MAX;
            for (int k = 0; k < nb; k++)
                if (cur[k] < end[k] && bl[k]->vrowidx[cur[k]] < r) r = bl[k]->vrowidx[cur[k]];
            if (r == INT_MAX) break;
            for (int k = 0; k < nb; k++)
                if (cur[k] < end[k] && bl[k]->vrowidx[cur[k]] == r) sys->emap[k][cur[k]++] = out;
            sys->vrowidx[out++] = r;
        }
    }
    sys->vcolptr[nfree] = out;
    /* Scalar expansion, same rule as the blocks. */
    sys->owns = 1;
    return opt_csc_expand_vertex_pattern(&sys->A, d, nfree, sys->vcolptr, sys->vrowidx, 0,
                                         err); /* summed values overwrite */
}

typedef struct sum_job {
    opt_proxy_system *sys;
    const opt_proxy_block *const *bl;
    int nb, nc;
    int cb[PAR_MAX_CHUNKS + 1]; /* vertex columns of each range */
} sum_job;

/* The first column c with vcolptr[c] >= target (nfree if none). */
static int column_at(const int *vcolptr, int nfree, long long target)
{
    int lo = 0, hi = nfree;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (vcolptr[mid] < target) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* Sum the blocks' values into columns [cb[r], cb[r+1]) of the union, block
 * after block: each value gets its terms in block order whatever the
 * ranges, so any thread count gives the serial sums. */
static void sum_range(void *ctx, int r)
{
    sum_job *j = ctx;
    opt_proxy_system *sys = j->sys;
    int d = sys->d, c0 = j->cb[r], c1 = j->cb[r + 1];
    opt_csc *A = &sys->A;
    size_t v0 = (size_t)A->colptr[c0 * d], v1 = (size_t)A->colptr[c1 * d];
    memset(A->val + v0, 0, (v1 - v0) * sizeof *A->val);
    for (int k = 0; k < j->nb; k++) {
        const opt_proxy_block *b = j->bl[k];
        int end = c1 < b->nfree ? c1 : b->nfree;
        for (int c = c0; c < end; c++)
            for (int e = b->vcolptr[c]; e < b->vcolptr[c + 1]; e++) {
                int u = sys->emap[k][e];
                int kb = e - b->vcolptr[c], ku = u - sys->vcolptr[c];
                int top = b->vrowidx[e] == c;
                for (int a2 = 0; a2 < d; a2++) {
                    const double *src = b->A.val + b->A.colptr[c * d + a2] + kb * d;
                    double *dst = A->val + A->colptr[c * d + a2] + ku * d;
                    int m = top ? a2 + 1 : d;
                    for (int a = 0; a < m; a++) dst[a] += src[a];
                }
            }
    }
}

scaf_status opt_proxy_system_sum(opt_proxy_system *sys, const opt_proxy_block *const *bl, int nb,
                                 scaf_error *err)
{
    if (nb < 1 || nb > OPT_PROXY_MAX_BLOCKS)
        return err_set(err, SCAF_ERR_USAGE, "proxy system: %d blocks (1..%d allowed)", nb,
                       OPT_PROXY_MAX_BLOCKS);
    int nfree = 0;
    for (int k = 0; k < nb; k++) {
        if (bl[k]->d != bl[0]->d)
            return err_set(err, SCAF_ERR_USAGE, "proxy system: block %d has d=%d, block 0 d=%d", k,
                           bl[k]->d, bl[0]->d);
        if (bl[k]->nfree > nfree) nfree = bl[k]->nfree;
    }
    int changed = nb != sys->nblocks || bl[0]->d != sys->d || nfree != sys->nfree;
    for (int k = 0; k < nb && !changed; k++)
        changed = bl[k] != sys->blk[k] || bl[k]->version != sys->seen[k];
    if (nb == 1) {
        /* Alias the block's matrix; its pattern version is ours. */
        if (changed) {
            release_union(sys);
            sys->version++;
        }
        sys->A = bl[0]->A;
        sys->owns = 0;
    } else if (changed) {
        sys->d = bl[0]->d;
        sys->nfree = nfree;
        scaf_status st = build_union(sys, bl, nb, err);
        if (st != SCAF_OK) {
            release_union(sys);
            sys->nblocks = 0;
            return st;
        }
        sys->version++;
    }
    sys->d = bl[0]->d;
    sys->nfree = nfree;
    sys->nblocks = nb;
    for (int k = 0; k < nb; k++) {
        sys->blk[k] = bl[k];
        sys->seen[k] = bl[k]->version;
    }
    if (nb == 1) return SCAF_OK;
    sum_job j = {sys, bl, nb, par_chunks((size_t)sys->vcolptr[nfree]), {0}};
    for (int k = 0; k <= j.nc; k++) /* column ranges of about equal entries */
        j.cb[k] = k == j.nc
            ? nfree
            : column_at(sys->vcolptr, nfree, (long long)sys->vcolptr[nfree] * k / j.nc);
    par_run(j.nc, sum_range, &j);
    return SCAF_OK;
}
