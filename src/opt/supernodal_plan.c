/* opt/supernodal_plan: see supernodal_plan.h. */
#define _GNU_SOURCE /* qsort_r */
#include "opt/supernodal_plan.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"
#include "opt/supernodal_check.h"

/* A factor whose work (sum of squared column counts) is below this is not
 * cut: waking threads costs more than it saves (a few hundred triangles,
 * e.g. an interactive drag). */
#define CUT_MIN_WORK 1e6

void opt_snum_destroy(opt_snum *P)
{
    if (!P) return;
    if (P->w)
        for (int k = 0; k < P->bins; k++) {
            free(P->w[k].map);
            free(P->w[k].rel);
            free(P->w[k].C);
            free(P->w[k].head);
            free(P->w[k].tmp);
            free(P->w[k].acc);
        }
    free(P->w);
    free(P->col2super);
    free(P->toprow);
    free(P->y);
    free(P->next);
    free(P->lpos);
    free(P->aptr);
    free(P->asrc);
    free(P->adst);
    free(P->order);
    free(P->bptr);
    free(P);
}

/* A's entries of columns [c0, c1) grouped by the supernode whose block
 * holds them (ptr over the supernodes, src: value index, col: column
 * within the supernode, place: row's place in the supernode's rows):
 * counted and bucketed by column chunks (chunk k's entries of a supernode
 * after chunk k-1's: the serial order), then placed supernode by supernode
 * through a row -> place map. */
typedef struct entry_groups {
    int *ptr, *src, *col, *place;
} entry_groups;

static void groups_free(entry_groups *g)
{
    free(g->ptr);
    free(g->src);
    free(g->col);
    free(g->place);
    memset(g, 0, sizeof *g);
}

typedef struct scatter_job {
    const opt_snum *P;
    const opt_csc *A;
    const int *pinv;
    int c0, c1; /* columns */
    int nc;     /* chunks */
    int *cnt;   /* nc x nsuper: entries per chunk and supernode, then fill positions */
    entry_groups *g;
    int **map;  /* per chunk: row -> place */
    int *bad;   /* per chunk: an entry outside L's structure */
    int bucket; /* scatter_pass: count (0) or bucket (1) */
} scatter_job;

/* Chunk k's columns: count its entries per supernode (J->bucket 0), or
 * bucket them at the fill positions left in J->cnt (J->bucket 1; place
 * holds the row for now). */
static void scatter_pass(void *ctx, int k)
{
    scatter_job *J = ctx;
    const opt_snum *P = J->P;
    const opt_csc *A = J->A;
    int *cnt = J->cnt + (size_t)k * (size_t)P->nsuper;
    int c0 = J->c0 + (int)par_chunk_begin((size_t)(J->c1 - J->c0), J->nc, k);
    int c1 = J->c0 + (int)par_chunk_begin((size_t)(J->c1 - J->c0), J->nc, k + 1);
    for (int c = c0; c < c1; c++) {
        int b = J->pinv[c];
        for (int e = A->colptr[c]; e < A->colptr[c + 1]; e++) {
            int a = J->pinv[A->rowidx[e]];
            int lo = a < b ? a : b, hi = a < b ? b : a, sn = P->col2super[lo];
            if (!J->bucket) {
                cnt[sn]++;
                continue;
            }
            int t = cnt[sn]++;
            J->g->src[t] = e;
            J->g->place[t] = hi;
            J->g->col[t] = lo - P->super[sn];
        }
    }
}

static void scatter_place(void *ctx, int k)
{
    scatter_job *J = ctx;
    const opt_snum *P = J->P;
    int *map = J->map[k];
    int s0 = (int)par_chunk_begin((size_t)P->nsuper, J->nc, k);
    int s1 = (int)par_chunk_begin((size_t)P->nsuper, J->nc, k + 1);
    for (int sn = s0; sn < s1; sn++) {
        if (J->g->ptr[sn] == J->g->ptr[sn + 1]) continue;
        const int *rows = P->s + P->pi[sn];
        int nsrow = P->pi[sn + 1] - P->pi[sn];
        for (int i = 0; i < nsrow; i++) map[rows[i]] = i;
        for (int t = J->g->ptr[sn]; t < J->g->ptr[sn + 1]; t++) {
            int r = J->g->place[t], place = map[r];
            if (place < 0 || place >= nsrow || rows[place] != r) J->bad[k] = 1; /* not in L */
            J->g->place[t] = place;
        }
    }
}

/* Group the entries of columns [c0, c1) into g; 0 when one is outside L's
 * structure or memory runs out. */
static int group_entries(const opt_snum *P, const opt_csc *A, const int *pinv, int c0, int c1,
                         entry_groups *g)
{
    int n = P->n, ns = P->nsuper;
    size_t nz = (size_t)(A->colptr[c1] - A->colptr[c0]) + 1;
    int nc = par_chunks(nz);
    if (nc > c1 - c0) nc = c1 - c0 > 0 ? c1 - c0 : 1;
    int *cnt = calloc((size_t)nc * (size_t)ns + 1, sizeof *cnt),
        *bad = calloc((size_t)nc, sizeof *bad);
    int **map = calloc((size_t)nc, sizeof *map);
    g->ptr = calloc((size_t)ns + 1, sizeof *g->ptr);
    g->src = malloc(nz * sizeof *g->src);
    g->col = malloc(nz * sizeof *g->col);
    g->place = malloc(nz * sizeof *g->place);
    int ok = cnt && bad && map && g->ptr && g->src && g->col && g->place;
    for (int k = 0; ok && k < nc; k++) {
        map[k] = malloc((size_t)n * sizeof *map[k]);
        ok = map[k] != NULL;
        if (ok)
            for (int i = 0; i < n; i++) map[k][i] = -1;
    }
    scatter_job J = {P, A, pinv, c0, c1, nc, cnt, g, map, bad, 0};
    if (ok) par_run(nc, scatter_pass, &J);
    /* fill positions: supernode by supernode, chunk by chunk */
    for (int sn = 0, t = 0; ok && sn < ns; sn++) {
        g->ptr[sn] = t;
        for (int k = 0; k < nc; k++) {
            int c = cnt[(size_t)k * (size_t)ns + (size_t)sn];
            cnt[(size_t)k * (size_t)ns + (size_t)sn] = t;
            t += c;
        }
        g->ptr[sn + 1] = t;
    }
    J.bucket = 1;
    if (ok) par_run(nc, scatter_pass, &J);
    if (ok) par_run(nc, scatter_place, &J);
    for (int k = 0; ok && k < nc; k++) ok = !bad[k];
    for (int k = 0; map && k < nc; k++) free(map[k]);
    free(map);
    free(bad);
    free(cnt);
    return ok;
}

/* ---- the leading columns' groups, kept across plans ---------------------- */

struct opt_snum_kept {
    int nf, nsf;   /* leading columns; the supernodes holding exactly them */
    long pattern;  /* the caller's name for A's pattern in them */
    int *perm;     /* nf: the factor's order of them */
    int *super;    /* nsf + 1 */
    int *nrow;     /* nsf: each supernode's rows among them */
    int *ptr;      /* nsf + 1: entries by supernode */
    int *src;      /* value index in A */
    unsigned *pos; /* column within the supernode << 16 | the row's place */
};

void opt_snum_kept_destroy(opt_snum_kept *K)
{
    if (!K) return;
    free(K->perm);
    free(K->super);
    free(K->nrow);
    free(K->ptr);
    free(K->src);
    free(K->pos);
    free(K);
}

/* Supernodes holding exactly the first nf columns of the factor's order
 * when those are A's first nf columns (the fixed part eliminated first)
 * and every such supernode has fewer than 2^16 columns and rows (a
 * column and a place pack into 32 bits); 0 otherwise. */
static int leading_supernodes(const opt_snum *P, const int *perm, int nf)
{
    if (nf <= 0 || nf >= P->n) return 0;
    for (int k = 0; k < nf; k++)
        if (perm[k] >= nf) return 0;
    int nsf = P->col2super[nf - 1] + 1;
    if (P->super[nsf] != nf) return 0;
    for (int sn = 0; sn < nsf; sn++)
        if (P->super[sn + 1] - P->super[sn] >= 65536 || P->pi[sn + 1] - P->pi[sn] >= 65536)
            return 0;
    return nsf;
}

/* Rows of supernode sn below nf (its rows ascend: they come first). */
static int rows_below(const opt_snum *P, int sn, int nf)
{
    const int *rows = P->s + P->pi[sn];
    int lo = 0, hi = P->pi[sn + 1] - P->pi[sn];
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (rows[mid] < nf) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* Whether K was made for these leading columns: the same pattern of A in
 * them, the same order and the same supernodes. The rows of a supernode
 * among them then follow (the union of its columns' patterns in the
 * leading block's own factor); their counts are compared as a check. */
static int kept_matches(const opt_snum_kept *K, const opt_snum *P, const int *perm, int nf, int nsf,
                        long pattern)
{
    if (!K || K->nf != nf || K->nsf != nsf || K->pattern != pattern) return 0;
    if (memcmp(K->perm, perm, (size_t)nf * sizeof *perm) ||
        memcmp(K->super, P->super, ((size_t)nsf + 1) * sizeof *K->super))
        return 0;
    for (int sn = 0; sn < nsf; sn++)
        if (K->nrow[sn] != rows_below(P, sn, nf)) return 0;
    return 1;
}

static opt_snum_kept *kept_build(const opt_snum *P, const opt_csc *A, const int *perm,
                                 const int *pinv, int nf, int nsf, long pattern)
{
    opt_snum_kept *K = calloc(1, sizeof *K);
    if (!K) return NULL;
    K->nf = nf;
    K->nsf = nsf;
    K->pattern = pattern;
    K->perm = malloc((size_t)nf * sizeof *K->perm);
    K->super = malloc(((size_t)nsf + 1) * sizeof *K->super);
    K->nrow = malloc(((size_t)nsf + 1) * sizeof *K->nrow);
    entry_groups g = {0};
    /* entries of the leading columns all lie in the leading supernodes */
    int ok = K->perm && K->super && K->nrow && group_entries(P, A, pinv, 0, nf, &g);
    if (ok) {
        memcpy(K->perm, perm, (size_t)nf * sizeof *perm);
        memcpy(K->super, P->super, ((size_t)nsf + 1) * sizeof *K->super);
        for (int sn = 0; sn < nsf; sn++) K->nrow[sn] = rows_below(P, sn, nf);
        /* pack each place into the column array's room */
        unsigned *pos = (unsigned *)g.col;
        for (int t = 0; t < g.ptr[nsf]; t++)
            pos[t] = (unsigned)g.col[t] << 16 | (unsigned)g.place[t];
        K->ptr = g.ptr;
        K->src = g.src;
        K->pos = pos;
        g.ptr = g.src = g.col = NULL;
    }
    groups_free(&g);
    if (!ok) {
        opt_snum_kept_destroy(K);
        return NULL;
    }
    return K;
}

/* The scatter of A: the leading columns' groups kept in *kept (made anew
 * when they do not match), the other columns' grouped here with their
 * places in the blocks (adst). 0 when A has an entry outside L's structure
 * or memory runs out. */
static int build_scatter(opt_snum *P, const opt_csc *A, const int *perm, int nfixed, long pattern,
                         opt_snum_kept **kept)
{
    int n = P->n;
    int *pinv = malloc((size_t)n * sizeof *pinv);
    if (!pinv) return 0;
    for (int k = 0; k < n; k++) pinv[perm[k]] = k;
    int nf = 0, nsf = kept ? leading_supernodes(P, perm, nfixed) : 0, ok = 1;
    if (nsf > 0) {
        nf = nfixed;
        P->kept_reused = kept_matches(*kept, P, perm, nf, nsf, pattern);
        if (!P->kept_reused) {
            opt_snum_kept_destroy(*kept);
            *kept = NULL; /* its memory back before the new one */
            *kept = kept_build(P, A, perm, pinv, nf, nsf, pattern);
            if (!*kept) nf = nsf = 0; /* all of A below */
        }
    }
    if (nsf > 0) {
        const opt_snum_kept *K = *kept;
        P->nks = nsf;
        P->kptr = K->ptr;
        P->ksrc = K->src;
        P->kpos = K->pos;
    }
    entry_groups g = {0};
    ok = group_entries(P, A, pinv, nf, n, &g);
    if (ok) {
        for (int sn = 0; sn < P->nsuper; sn++) {
            int nsrow = P->pi[sn + 1] - P->pi[sn];
            for (int t = g.ptr[sn]; t < g.ptr[sn + 1]; t++)
                g.col[t] = g.col[t] * nsrow + g.place[t];
        }
        P->aptr = g.ptr;
        P->asrc = g.src;
        P->adst = g.col;
        g.ptr = g.src = g.col = NULL;
    }
    groups_free(&g);
    free(pinv);
    return ok;
}

/* Largest update buffer: a descendant's rows from one supernode's range
 * times its rows from there down. */
static size_t max_update(const opt_snum *P)
{
    size_t most = 1;
    for (int d = 0; d < P->nsuper; d++) {
        int nscol = P->super[d + 1] - P->super[d];
        const int *rows = P->s + P->pi[d];
        int nsrow = P->pi[d + 1] - P->pi[d];
        for (int p = nscol; p < nsrow;) {
            int sn = P->col2super[rows[p]], q = p;
            while (q < nsrow && P->col2super[rows[q]] == sn) q++;
            size_t c = (size_t)(q - p) * (size_t)(nsrow - p);
            if (c > most) most = c;
            p = q;
        }
    }
    return most;
}

static int cmp_work_desc(const void *a, const void *b, void *wv)
{
    const double *W = wv;
    double x = W[*(const int *)a], y = W[*(const int *)b];
    if (x != y) return x < y ? 1 : -1;
    return *(const int *)a - *(const int *)b;
}

/* Longest-first assignment of the candidate subtrees to T bins; returns the
 * heaviest bin's work, bin[i] the bin of cand[i] (cand sorted by work). */
static double assign_bins(int *cand, int nc, const double *W, int T, int *bin)
{
    qsort_r(cand, (size_t)nc, sizeof *cand, cmp_work_desc, (void *)W);
    double load[PAR_MAX_CHUNKS] = {0};
    for (int i = 0; i < nc; i++) {
        int best = 0;
        for (int k = 1; k < T; k++)
            if (load[k] < load[best]) best = k;
        load[best] += W[cand[i]];
        bin[i] = best;
    }
    double most = 0;
    for (int k = 0; k < T; k++)
        if (load[k] > most) most = load[k];
    return most;
}

/* Cut the supernodal tree into subtrees for T bins (order, bptr); the
 * supernodes above the cut follow in ascending order. Returns the bins
 * used (1: no cut, everything runs above it). */
static int plan_bins(opt_snum *P, int T)
{
    int ns = P->nsuper;
    P->order = malloc(((size_t)ns + 1) * sizeof *P->order);
    P->bptr = calloc((size_t)T + 2, sizeof *P->bptr);
    if (!P->order || !P->bptr) return 0;
    for (int k = 0; k < ns; k++) P->order[k] = k;
    if (T < 2 || ns < 2 * T) return 1;
    int *parent = malloc((size_t)ns * sizeof *parent), *chead = malloc((size_t)ns * sizeof *chead);
    int *cnext = malloc((size_t)ns * sizeof *cnext), *cand = malloc((size_t)ns * sizeof *cand);
    int *bin = malloc((size_t)ns * sizeof *bin), *owner = malloc((size_t)ns * sizeof *owner);
    double *W = malloc((size_t)ns * sizeof *W);
    int used = 1;
    if (!parent || !chead || !cnext || !cand || !bin || !owner || !W) goto done;
    for (int sn = 0; sn < ns; sn++) {
        int nscol = P->super[sn + 1] - P->super[sn], nsrow = P->pi[sn + 1] - P->pi[sn];
        double w = 0;
        for (int c = 0; c < nscol; c++) w += (double)(nsrow - c) * (double)(nsrow - c);
        W[sn] = w;
        chead[sn] = -1;
        parent[sn] = nsrow > nscol ? P->col2super[P->s[P->pi[sn] + nscol]] : -1;
    }
    double total = 0;
    for (int sn = 0; sn < ns; sn++) total += W[sn];
    if (total < CUT_MIN_WORK) goto done; /* too small to be worth threads */
    for (int sn = 0; sn < ns; sn++) {
        int p = parent[sn];
        if (p < 0) continue;
        if (p <= sn) goto done; /* a parent before its child: no cut */
        W[p] += W[sn];
    }
    for (int sn = ns - 1; sn >= 0; sn--)
        if (parent[sn] >= 0) {
            cnext[sn] = chead[parent[sn]];
            chead[parent[sn]] = sn;
        }
    int nc = 0;
    for (int sn = 0; sn < ns; sn++)
        if (parent[sn] < 0) cand[nc++] = sn;
    /* split the heaviest subtree until the bins are within 3% of even, or
     * the work above the cut would pass a quarter of the whole */
    double above = 0;
    for (int iter = 0; iter < ns; iter++) {
        double most = assign_bins(cand, nc, W, T, bin), sum = 0;
        for (int i = 0; i < nc; i++) sum += W[cand[i]];
        if (most <= 1.03 * sum / T) break;
        int i = 0;
        while (i < nc && chead[cand[i]] < 0) i++;
        if (i == nc) break;
        int c = cand[i];
        double own = W[c];
        for (int ch = chead[c]; ch >= 0; ch = cnext[ch]) own -= W[ch];
        if (above + own > 0.5 * total) break;
        above += own;
        cand[i] = cand[--nc];
        for (int ch = chead[c]; ch >= 0; ch = cnext[ch]) cand[nc++] = ch;
    }
    assign_bins(cand, nc, W, T, bin);
    /* a supernode belongs to the bin of its candidate ancestor; parents
     * come after their children, so a descending sweep sees them first */
    for (int sn = 0; sn < ns; sn++) owner[sn] = -2;
    for (int i = 0; i < nc; i++) owner[cand[i]] = bin[i];
    for (int sn = ns - 1; sn >= 0; sn--)
        if (owner[sn] == -2) owner[sn] = parent[sn] >= 0 ? owner[parent[sn]] : -1;
    int pos = 0;
    for (int k = 0; k < T; k++) {
        P->bptr[k] = pos;
        for (int sn = 0; sn < ns; sn++)
            if (owner[sn] == k) P->order[pos++] = sn;
    }
    P->bptr[T] = pos;
    for (int sn = 0; sn < ns; sn++)
        if (owner[sn] < 0) P->order[pos++] = sn;
    used = T;
done:
    if (used == 1) memset(P->bptr, 0, ((size_t)T + 2) * sizeof *P->bptr);
    free(parent);
    free(chead);
    free(cnext);
    free(cand);
    free(bin);
    free(owner);
    free(W);
    return used;
}

#ifndef NDEBUG
/* The plan's invariants (for the assert above): every supernode in
 * exactly one bin or above the cut, ascending within each bin; each
 * column in its supernode; each entry of A (those of the kept part
 * excepted) placed inside its supernode's block; the rows above the cut
 * numbered 0..ntop-1. */
static int plan_valid(const opt_snum *P, const cholmod_factor *L, const opt_csc *A)
{
    int n = P->n, ns = P->nsuper, T = P->bins, top = P->bptr[T > 1 ? T : 0];
    if (!opt_is_permutation(ns, P->order) || P->bptr[0] != 0 || top > ns) return 0;
    for (int k = 0; k < T && T > 1; k++) {
        if (P->bptr[k + 1] < P->bptr[k]) return 0;
        for (int i = P->bptr[k] + 1; i < P->bptr[k + 1]; i++)
            if (P->order[i] <= P->order[i - 1]) return 0;
    }
    for (int c = 0; c < n; c++) {
        int sn = P->col2super[c];
        if (sn < 0 || sn >= ns || c < P->super[sn] || c >= P->super[sn + 1]) return 0;
    }
    for (int sn = 0; sn < ns; sn++) {
        long size = (long)(P->pi[sn + 1] - P->pi[sn]) * (P->super[sn + 1] - P->super[sn]);
        for (int q = P->aptr[sn]; q < P->aptr[sn + 1]; q++)
            if (P->asrc[q] < 0 || P->asrc[q] >= A->nnz || P->adst[q] < 0 || P->adst[q] >= size)
                return 0;
    }
    int ntop = 0;
    for (int c = 0; c < n; c++)
        if (P->toprow[c] >= 0 && P->toprow[c] != ntop++) return 0;
    (void)L;
    return ntop == P->ntop;
}
#endif

opt_snum *opt_snum_create(const cholmod_factor *L, const opt_csc *A, int bins)
{
    return opt_snum_create_kept(L, A, bins, 0, 0, NULL);
}

opt_snum *opt_snum_create_kept(const cholmod_factor *L, const opt_csc *A, int bins, int nfixed,
                               long pattern, opt_snum_kept **kept)
{
    if (!L->is_super || L->itype != CHOLMOD_INT || (int)L->n != A->n) return NULL;
    assert(opt_super_symbolic_valid(L) && opt_csc_is_upper_sorted(A));
    if (bins < 1) bins = 1;
    if (bins > PAR_MAX_CHUNKS) bins = PAR_MAX_CHUNKS;
    opt_snum *P = calloc(1, sizeof *P);
    if (!P) return NULL;
    P->n = A->n;
    P->nsuper = (int)L->nsuper;
    P->super = L->super;
    P->pi = L->pi;
    P->px = L->px;
    P->s = L->s;
    int n = P->n, ns = P->nsuper;
    P->col2super = malloc(((size_t)n + 1) * sizeof *P->col2super);
    P->next = malloc(((size_t)ns + 1) * sizeof *P->next);
    P->lpos = malloc(((size_t)ns + 1) * sizeof *P->lpos);
    if (!P->col2super || !P->next || !P->lpos) goto fail;
    for (int sn = 0; sn < ns; sn++)
        for (int k = P->super[sn]; k < P->super[sn + 1]; k++) P->col2super[k] = sn;
    if (!build_scatter(P, A, L->Perm, nfixed, pattern, kept)) goto fail;
    int T = plan_bins(P, bins);
    if (T < 1) goto fail;
    P->bins = T;
    P->diag_share_min = OPT_SNUM_DIAG_SHARE_MIN;
    P->toprow = malloc(((size_t)n + 1) * sizeof *P->toprow);
    P->y = malloc(((size_t)n + 1) * sizeof *P->y);
    if (!P->toprow || !P->y) goto fail;
    for (int k = 0; k < n; k++) P->toprow[k] = -1;
    for (int i = P->bptr[T > 1 ? T : 0]; i < ns && T > 1; i++)
        for (int k = P->super[P->order[i]]; k < P->super[P->order[i] + 1]; k++)
            P->toprow[k] = P->ntop++;
    size_t csize = max_update(P);
    int maxrow = 1;
    for (int sn = 0; sn < ns; sn++)
        if (P->pi[sn + 1] - P->pi[sn] > maxrow) maxrow = P->pi[sn + 1] - P->pi[sn];
    P->w = calloc((size_t)T, sizeof *P->w);
    if (!P->w) goto fail;
    for (int k = 0; k < T; k++) {
        opt_snum_worker *wk = &P->w[k];
        wk->map = malloc(((size_t)n + 1) * sizeof *wk->map);
        wk->rel = malloc((size_t)maxrow * sizeof *wk->rel);
        wk->C = malloc(csize * sizeof *wk->C);
        wk->head = malloc(((size_t)ns + 1) * sizeof *wk->head);
        wk->tmp = malloc((size_t)maxrow * sizeof *wk->tmp);
        wk->acc = malloc(((size_t)P->ntop + 1) * sizeof *wk->acc);
        if (!wk->map || !wk->rel || !wk->C || !wk->head || !wk->tmp || !wk->acc) goto fail;
    }
    assert(plan_valid(P, L, A));
    return P;
fail:
    opt_snum_destroy(P);
    return NULL;
}

int opt_snum_top_parallel(const opt_snum *P, int sn)
{
    return P->bins > 1 &&
        (double)(P->pi[sn + 1] - P->pi[sn]) * (double)(P->super[sn + 1] - P->super[sn]) >=
        OPT_SNUM_TOP_PARALLEL_MIN;
}

opt_snum_shape opt_snum_get_shape(const opt_snum *P)
{
    int T = P->bins, first_above = P->bptr[T > 1 ? T : 0];
    opt_snum_shape sh = {T, P->nsuper, first_above, P->nsuper - first_above, 0};
    for (int i = first_above; i < P->nsuper; i++)
        sh.above_parallel += opt_snum_top_parallel(P, P->order[i]);
    return sh;
}
