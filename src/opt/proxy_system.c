/* opt/proxy_system: the sum of several proxy blocks as one sparse system.
 *
 * Union pattern: per vertex column, a k-way merge of the blocks' sorted row
 * lists, recording for every block entry its union position. Scalar layout
 * follows the same interleaved rule as opt/proxy_block, so values are
 * added column by column with offsets (entry - column start) * d. A column
 * only one block has entries in (SCAF: every mesh column away from the
 * chart boundary) is that block's column, pattern and values: runs of
 * them are copied whole, scalar rows and values, instead of merged,
 * expanded, zeroed and added (the values are the same: 0 + x = x).
 */
#include "opt/proxy_system.h"

#include <assert.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

/* A no longer the union: its storage stays for the next rebuild. */
static void release_union(opt_proxy_system *sys)
{
    memset(&sys->A, 0, sizeof sys->A);
    sys->owns = 0;
}

void opt_proxy_system_free(opt_proxy_system *sys)
{
    if (!sys) return;
    free(sys->vcolptr);
    free(sys->vrowidx);
    free(sys->only);
    for (int k = 0; k < OPT_PROXY_MAX_BLOCKS; k++) free(sys->emap[k]);
    free(sys->own_colptr);
    free(sys->own_rowidx);
    free(sys->own_val);
    memset(sys, 0, sizeof *sys);
}

/* *p holds at least `need` elements of `size` bytes: kept when it already
 * does (contents are not needed), else replaced with 1/8 slack so that a
 * scaffold growing a little does not replace it every iteration. Fresh
 * pages are what a rebuild must not pay for: on 1.77M faces, faulting in
 * A's 107 MB of values took 340 ms, the sum into them 9 ms. */
static int reserve(void **p, size_t *cap, size_t need, size_t size)
{
    if (*p && need <= *cap) return 1;
    free(*p);
    size_t n = need + need / 8 + 1;
    *p = malloc(n * size);
    *cap = *p ? n : 0;
    return *p != NULL;
}

/* Scalar CSC of the union's vertex pattern (the interleaved rule of
 * opt_csc_expand_vertex_pattern), runs of single-block columns copied from
 * that block's scalar pattern. Values uninitialized: the sum writes all. */
static scaf_status expand_union(opt_proxy_system *sys, const opt_proxy_block *const *bl,
                                scaf_error *err)
{
    int d = sys->d, nv = sys->nfree, n = nv * d;
    opt_csc *A = &sys->A;
    void *p = sys->own_colptr;
    int ok = reserve(&p, &sys->cap_col, (size_t)n + 1, sizeof(int));
    sys->own_colptr = p;
    if (!ok) return err_nomem(err, "proxy system matrix");
    A->n = n;
    A->colptr = sys->own_colptr;
    A->colptr[0] = 0;
    for (int c = 0; c < nv; c++) {
        int k = sys->only[c];
        if (k >= 0) { /* a run of one block's columns: its starts, shifted */
            int e = c + 1;
            while (e < nv && sys->only[e] == k) e++;
            const int *bc = bl[k]->A.colptr;
            int shift = A->colptr[c * d] - bc[c * d];
            for (int q = c * d + 1; q <= e * d; q++) A->colptr[q] = bc[q] + shift;
            c = e - 1;
            continue;
        }
        int lo = sys->vcolptr[c], hi = sys->vcolptr[c + 1];
        int diag = hi > lo && sys->vrowidx[hi - 1] == c;
        int off = hi - lo - diag;
        for (int a = 0; a < d; a++)
            A->colptr[c * d + a + 1] = A->colptr[c * d + a] + off * d + (diag ? a + 1 : 0);
    }
    A->nnz = A->colptr[n];
    size_t need = (size_t)A->nnz + 1, cap_r = sys->cap_nnz, cap_v = sys->cap_nnz;
    void *r = sys->own_rowidx, *v = sys->own_val;
    ok = reserve(&r, &cap_r, need, sizeof(int)) && reserve(&v, &cap_v, need, sizeof(double));
    sys->own_rowidx = r;
    sys->own_val = v;
    sys->cap_nnz = cap_r < cap_v ? cap_r : cap_v;
    if (!ok) return err_nomem(err, "proxy system matrix");
    A->rowidx = sys->own_rowidx;
    A->val = sys->own_val;
    for (int c = 0; c < nv;) {
        int k = sys->only[c];
        if (k >= 0) {
            int e = c + 1;
            while (e < nv && sys->only[e] == k) e++;
            const opt_csc *B = &bl[k]->A;
            size_t len = (size_t)(B->colptr[e * d] - B->colptr[c * d]);
            memcpy(A->rowidx + A->colptr[c * d], B->rowidx + B->colptr[c * d],
                   len * sizeof *A->rowidx);
            c = e;
            continue;
        }
        int lo = sys->vcolptr[c], hi = sys->vcolptr[c + 1];
        for (int a = 0; a < d; a++) {
            int pos = A->colptr[c * d + a];
            for (int q = lo; q < hi; q++) {
                int r = sys->vrowidx[q];
                int top = r == c ? a : d - 1;
                for (int b = 0; b <= top; b++) A->rowidx[pos++] = r * d + b;
            }
        }
        c++;
    }
    assert(opt_csc_is_upper_sorted(A));
    return SCAF_OK;
}

/* The end of the run of columns from c on that block `only` alone has
 * entries in. */
static int single_run_end(const opt_proxy_block *const *bl, int nb, int only, int c, int nfree)
{
    const opt_proxy_block *b = bl[only];
    int e = c + 1;
    for (; e < nfree && e < b->nfree && b->vcolptr[e] < b->vcolptr[e + 1]; e++) {
        int other = 0;
        for (int k = 0; k < nb && !other; k++)
            other = k != only && e < bl[k]->nfree && bl[k]->vcolptr[e] < bl[k]->vcolptr[e + 1];
        if (other) break;
    }
    return e;
}

static scaf_status build_union(opt_proxy_system *sys, const opt_proxy_block *const *bl, int nb,
                               scaf_error *err)
{
    int nfree = sys->nfree;
    release_union(sys);
    size_t cap = 0;
    for (int k = 0; k < nb; k++) cap += (size_t)bl[k]->vcolptr[bl[k]->nfree];
    size_t cap_vcol = sys->cap_vcol, cap_only = sys->cap_vcol;
    void *vc = sys->vcolptr, *vr = sys->vrowidx, *on = sys->only;
    int ok = reserve(&vc, &cap_vcol, (size_t)nfree + 1, sizeof(int)) &&
        reserve(&on, &cap_only, (size_t)nfree + 1, sizeof(int)) &&
        reserve(&vr, &sys->cap_vrow, cap + 1, sizeof(int));
    sys->vcolptr = vc;
    sys->only = on;
    sys->vrowidx = vr;
    sys->cap_vcol = cap_vcol < cap_only ? cap_vcol : cap_only;
    if (!ok) return err_nomem(err, "proxy system union pattern");
    for (int k = 0; k < nb; k++) {
        void *em = sys->emap[k];
        ok = reserve(&em, &sys->cap_emap[k], (size_t)bl[k]->vcolptr[bl[k]->nfree] + 1, sizeof(int));
        sys->emap[k] = em;
        if (!ok) return err_nomem(err, "proxy system union map");
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
        sys->only[c] = nonempty == 1 ? only : -1;
        if (nonempty == 1) {
            /* the run of columns only this block has entries in: its
             * pattern shifted, in whole-array loops (aphrodite: the union
             * 0.95 -> 0.4 ms an iteration) */
            int e = single_run_end(bl, nb, only, c, nfree);
            const opt_proxy_block *b = bl[only];
            int b0 = b->vcolptr[c], b1 = b->vcolptr[e], shift = out - b0;
            for (int q = c + 1; q < e; q++) sys->vcolptr[q] = b->vcolptr[q] + shift;
            for (int q = c + 1; q < e; q++) sys->only[q] = only;
            for (int q = b0; q < b1; q++) sys->emap[only][q] = q + shift;
            memcpy(sys->vrowidx + out, b->vrowidx + b0, (size_t)(b1 - b0) * sizeof *sys->vrowidx);
            out += b1 - b0;
            c = e - 1;
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
    sys->only[nfree] = -1; /* ends the last run */
    sys->owns = 1;
    return expand_union(sys, bl, err);
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
    for (int c = c0; c < c1;) {
        int k = sys->only[c];
        if (k >= 0) { /* a run of one block's columns: its values */
            int e = c + 1;
            while (e < c1 && sys->only[e] == k) e++;
            const opt_csc *B = &j->bl[k]->A;
            memcpy(A->val + A->colptr[c * d], B->val + B->colptr[c * d],
                   (size_t)(B->colptr[e * d] - B->colptr[c * d]) * sizeof *A->val);
            c = e;
            continue;
        }
        memset(A->val + A->colptr[c * d], 0,
               (size_t)(A->colptr[(c + 1) * d] - A->colptr[c * d]) * sizeof *A->val);
        for (int k2 = 0; k2 < j->nb; k2++) {
            const opt_proxy_block *b = j->bl[k2];
            if (c >= b->nfree) continue;
            for (int e = b->vcolptr[c]; e < b->vcolptr[c + 1]; e++) {
                int u = sys->emap[k2][e];
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
        c++;
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
