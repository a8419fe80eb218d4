/* opt/fill_split: per-batch column ranges of a parallel fill.
 *
 * A batch's writes are counted per column in SPLIT_BUCKETS buckets over
 * the span of the dofs it touches; the cuts go to the bucket bounds nearest
 * to equal shares. A corner of rank r among its simplex's free corners
 * (ascending dof) owns r + 1 blocks of the upper pattern (the pairs whose
 * larger dof it is, its diagonal among them) and one rhs entry; its weight
 * is r + 2. The counts only balance the threads: any cut gives the same
 * values.
 */
#include "opt/fill_split.h"

#include <assert.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define SPLIT_BUCKETS 1024

int opt_fill_split_touches(const opt_simplices *S, int s, const int *dof, int lo, int hi)
{
    const int *ix = S->idx + (size_t)s * (S->d + 1);
    for (int i = 0; i <= S->d; i++)
        if (dof[ix[i]] >= lo && dof[ix[i]] < hi) return 1;
    return 0;
}

void opt_fill_split_free(opt_fill_split *f)
{
    if (!f) return;
    free(f->cb);
    memset(f, 0, sizeof *f);
}

/* Cut the batch [s0, s1) into nc ranges of about equal weight (cb: nc + 1). */
static void split_batch(const opt_simplices *S, const int *dof, size_t s0, size_t s1, int nc,
                        int *cb, long long *hist)
{
    int nv = S->d + 1, lo = INT_MAX, hi = -1;
    for (size_t s = s0; s < s1; s++)
        for (int i = 0; i < nv; i++) {
            int di = dof[S->idx[s * nv + i]];
            if (di < 0) continue;
            if (di < lo) lo = di;
            if (di > hi) hi = di;
        }
    cb[0] = 0;
    cb[nc] = INT_MAX;
    if (hi < 0) { /* nothing free: any cut */
        for (int k = 1; k < nc; k++) cb[k] = 0;
        return;
    }
    long long width = ((long long)hi - lo) / SPLIT_BUCKETS + 1, total = 0;
    memset(hist, 0, SPLIT_BUCKETS * sizeof *hist);
    for (size_t s = s0; s < s1; s++) {
        const int *ix = S->idx + s * nv;
        for (int i = 0; i < nv; i++) {
            int di = dof[ix[i]];
            if (di < 0) continue;
            int rank = 0;
            for (int j = 0; j < nv; j++) {
                int dj = dof[ix[j]];
                rank += dj >= 0 && (dj < di || (dj == di && j < i));
            }
            hist[(di - lo) / width] += rank + 2;
            total += rank + 2;
        }
    }
    long long cum = 0;
    int q = 0;
    for (int k = 1; k < nc; k++) {
        long long target = total * k / nc;
        while (q < SPLIT_BUCKETS && cum + hist[q] < target) cum += hist[q++];
        /* Cut before bucket q or after it, whichever is nearer the target. */
        int after = q < SPLIT_BUCKETS && cum + hist[q] - target < target - cum;
        long long cut = lo + (q + after) * width;
        if (after) cum += hist[q++];
        cb[k] = cut > INT_MAX - 1 ? INT_MAX - 1 : (int)cut;
        if (cb[k] < cb[k - 1]) cb[k] = cb[k - 1];
    }
}

int opt_fill_split_prepare(opt_fill_split *f, const opt_simplices *S, const int *dof, int nc,
                           size_t batch)
{
    size_t n = (size_t)S->n;
    if (f->nc == nc && f->batch == batch && f->n == n && f->cb) return 0;
    opt_fill_split_free(f);
    size_t nbatch = (n + batch - 1) / batch;
    int *cb = malloc((nbatch ? nbatch : 1) * (size_t)(nc + 1) * sizeof *cb);
    long long *hist = malloc(SPLIT_BUCKETS * sizeof *hist);
    if (!cb || !hist) {
        free(cb);
        free(hist);
        return -1;
    }
    for (size_t b = 0; b < nbatch; b++) {
        size_t s0 = b * batch, s1 = s0 + batch < n ? s0 + batch : n;
        split_batch(S, dof, s0, s1, nc, cb + b * (size_t)(nc + 1), hist);
    }
    free(hist);
#ifndef NDEBUG /* each batch's ranges: from 0, ascending, to INT_MAX */
    for (size_t b = 0; b < nbatch; b++) {
        const int *r = cb + b * (size_t)(nc + 1);
        assert(r[0] == 0 && r[nc] == INT_MAX);
        for (int k = 0; k < nc; k++) assert(r[k] <= r[k + 1]);
    }
#endif
    *f = (opt_fill_split){.nc = nc, .batch = batch, .n = n, .cb = cb};
    return 0;
}
