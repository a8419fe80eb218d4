/* opt/split_symbolic: see split_symbolic.h.
 *
 * Positions: the factor's column k holds vertex Perm[k]; the fixed
 * vertices take positions 0..nf-1, the variable ones nf..nv-1. The fixed
 * supernodes are kept as positions; a variable vertex is "reached" by the
 * fixed supernodes on the paths from its fixed neighbours' supernodes to
 * their roots (the standard row-subtree walk, stopping at a supernode
 * already marked for the same vertex). */
#include "opt/split_symbolic.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "opt/given_symbolic.h"
#include "opt/supernodal_check.h"

struct opt_split_symbolic {
    int nf;
    int *cp, *ri, *fperm; /* what it was made for (opt_split_matches) */
    int nsuper;
    int *super, *pi, *s; /* fixed supernodes: first positions, row offsets, rows */
    int *perm, *count;   /* vertex at each position, column counts */
    int *pos;            /* position of each fixed vertex */
    int *smap;           /* supernode of each fixed position */
    int *sparent;        /* supernodal parent, -1 at a root */
};

void opt_split_destroy(opt_split_symbolic *S)
{
    if (!S) return;
    free(S->cp);
    free(S->ri);
    free(S->fperm);
    free(S->super);
    free(S->pi);
    free(S->s);
    free(S->perm);
    free(S->count);
    free(S->pos);
    free(S->smap);
    free(S->sparent);
    free(S);
}

static int *copy_ints(const int *a, size_t n)
{
    int *b = malloc((n ? n : 1) * sizeof *b);
    if (b && n) memcpy(b, a, n * sizeof *b);
    return b;
}

opt_split_symbolic *opt_split_create(cholmod_common *cm, int nf, const int *cp, const int *ri,
                                     const int *fperm)
{
    opt_split_symbolic *S = calloc(1, sizeof *S);
    if (!S) {
        cm->status = CHOLMOD_OUT_OF_MEMORY;
        return NULL;
    }
    /* the fixed columns hold only fixed rows (sorted columns) */
    assert(nf >= 1 && opt_upper_pattern_valid(nf, cp, ri, 0));
    cholmod_factor *L = opt_given_symbolic(cm, nf, cp, ri, fperm);
    if (!L) {
        free(S);
        return NULL;
    }
    size_t n = (size_t)nf, ns = L->nsuper;
    const int *lpi = L->pi;
    S->nf = nf;
    S->nsuper = (int)ns;
    S->cp = copy_ints(cp, n + 1);
    S->ri = copy_ints(ri, (size_t)cp[nf]);
    S->fperm = copy_ints(fperm, n);
    S->super = copy_ints(L->super, ns + 1);
    S->pi = copy_ints(lpi, ns + 1);
    S->s = copy_ints(L->s, (size_t)lpi[ns]);
    S->perm = copy_ints(L->Perm, n);
    S->count = copy_ints(L->ColCount, n);
    S->pos = malloc((n ? n : 1) * sizeof *S->pos);
    S->smap = malloc((n ? n : 1) * sizeof *S->smap);
    S->sparent = malloc((ns ? ns : 1) * sizeof *S->sparent);
    cholmod_free_factor(&L, cm);
    if (!S->cp || !S->ri || !S->fperm || !S->super || !S->pi || !S->s || !S->perm || !S->count ||
        !S->pos || !S->smap || !S->sparent) {
        opt_split_destroy(S);
        cm->status = CHOLMOD_OUT_OF_MEMORY;
        return NULL;
    }
    for (int k = 0; k < nf; k++) S->pos[S->perm[k]] = k;
    for (size_t s = 0; s < ns; s++)
        for (int k = S->super[s]; k < S->super[s + 1]; k++) S->smap[k] = (int)s;
    for (size_t s = 0; s < ns; s++) {
        int below = S->pi[s] + (S->super[s + 1] - S->super[s]); /* first row under the diagonal */
        S->sparent[s] = below < S->pi[s + 1] ? S->smap[S->s[below]] : -1;
    }
    return S;
}

int opt_split_matches(const opt_split_symbolic *S, int nf, const int *cp, const int *ri,
                      const int *fperm, int pattern_known)
{
    return S && S->nf == nf && memcmp(S->fperm, fperm, (size_t)nf * sizeof *fperm) == 0 &&
        (pattern_known ||
         (memcmp(S->cp, cp, ((size_t)nf + 1) * sizeof *cp) == 0 &&
          memcmp(S->ri, ri, (size_t)cp[nf] * sizeof *ri) == 0));
}

/* maxcsize and maxesize of a supernodal pattern, as cholmod_super_symbolic
 * computes them (the largest update matrix a supernode sends to one
 * ancestor; the most rows under a diagonal block). */
static void workspace_sizes(cholmod_factor *L, const int *smap)
{
    const int *super = L->super, *pi = L->pi, *s = L->s;
    size_t maxc = 1, maxe = 1;
    for (size_t d = 0; d < L->nsuper; d++) {
        int p = pi[d] + super[d + 1] - super[d], pend = pi[d + 1], plast = p;
        if ((size_t)(pend - p) > maxe) maxe = (size_t)(pend - p);
        int slast = p == pend ? -1 : smap[s[p]];
        for (; p <= pend; p++) {
            int sn = p == pend ? -1 : smap[s[p]];
            if (sn == slast) continue;
            size_t c = (size_t)(p - plast) * (size_t)(pend - plast);
            if (c > maxc) maxc = c;
            plast = p;
            slast = sn;
        }
    }
    L->maxcsize = maxc;
    L->maxesize = maxe;
}

cholmod_factor *opt_split_factor(const opt_split_symbolic *S, cholmod_common *cm, int nv,
                                 const int *cp, const int *ri)
{
    int nf = S->nf, nw = nv - nf, nsf = S->nsuper;
    assert(nw >= 0 && opt_upper_pattern_valid(nv, cp, ri, 0) &&
           memcmp(S->cp, cp, ((size_t)nf + 1) * sizeof *cp) == 0);
    size_t ncouple = (size_t)(cp[nv] - cp[nf]) + 1;
    int *mark = malloc(((size_t)nsf + 1) * sizeof *mark);
    int *cnt = calloc((size_t)nsf + 1, sizeof *cnt);
    int *pairs = malloc(ncouple * sizeof *pairs); /* roots reached, by variable vertex */
    int *jr = malloc(((size_t)nw + 1) * sizeof *jr);
    int *rs = calloc((size_t)nsf + 1, sizeof *rs); /* root sets: offsets, then items */
    int *rsi = malloc(ncouple * sizeof *rsi);
    int *wmark = malloc(((size_t)nw + 1) * sizeof *wmark);
    int *ident = malloc(((size_t)nw + 1) * sizeof *ident);
    int *tcp = malloc(((size_t)nw + 1) * sizeof *tcp), *tri = NULL, *sc = NULL, *scp = NULL;
    int *smap = malloc(((size_t)nv + 1) * sizeof *smap);
    cholmod_factor *LS = NULL, *L = NULL;
    if (!mark || !cnt || !pairs || !jr || !rs || !rsi || !wmark || !ident || !tcp || !smap)
        goto oom;

    /* the fixed supernodes each variable vertex reaches, and its roots */
    for (int s = 0; s < nsf; s++) mark[s] = -1;
    int npairs = 0;
    for (int J = nf; J < nv; J++) {
        jr[J - nf] = npairs;
        for (int q = cp[J]; q < cp[J + 1] && ri[q] < nf; q++) {
            int sn = S->smap[S->pos[ri[q]]], last = -1;
            while (sn >= 0 && mark[sn] != J) {
                mark[sn] = J;
                cnt[sn]++;
                last = sn;
                sn = S->sparent[sn];
            }
            if (sn < 0 && last >= 0) pairs[npairs++] = last;
        }
    }
    jr[nw] = npairs;
    for (int p = 0; p < npairs; p++) rs[pairs[p] + 1]++;
    for (int s = 0; s < nsf; s++) rs[s + 1] += rs[s];
    size_t ntri = ncouple;
    for (int s = 0; s < nsf; s++) {
        size_t k = (size_t)(rs[s + 1] - rs[s]);
        ntri += k * (k + 1) / 2;
    }
    memcpy(mark, rs, (size_t)nsf * sizeof *mark); /* fill cursors */
    for (int j = 0; j < nw; j++)
        for (int p = jr[j]; p < jr[j + 1]; p++) rsi[mark[pairs[p]]++] = j;

    /* the variable block with the fill the fixed block passes on: a clique
     * on the vertices reaching each root */
    tri = malloc(ntri * sizeof *tri);
    if (!tri) goto oom;
    for (int j = 0; j < nw; j++) wmark[j] = -1;
    int out = 0;
    for (int j = 0; j < nw; j++) {
        tcp[j] = out;
        int J = nf + j;
        for (int q = cp[J]; q < cp[J + 1]; q++) {
            int i = ri[q] - nf;
            if (i < 0 || wmark[i] == j) continue;
            wmark[i] = j;
            tri[out++] = i;
        }
        for (int p = jr[j]; p < jr[j + 1]; p++)
            for (int k = rs[pairs[p]]; k < rs[pairs[p] + 1] && rsi[k] <= j; k++) {
                int i = rsi[k];
                if (wmark[i] == j) continue;
                wmark[i] = j;
                tri[out++] = i;
            }
    }
    tcp[nw] = out;
    for (int j = 0; j < nw; j++) ident[j] = j;
    if (nw > 0) {
        LS = opt_given_symbolic(cm, nw, tcp, tri, ident);
        if (!LS) goto fail;
    }
    const int *wperm = LS ? LS->Perm : ident;
    int nsw = LS ? (int)LS->nsuper : 0;

    /* the variable rows of each fixed supernode, ascending by position */
    scp = malloc(((size_t)nsf + 1) * sizeof *scp);
    if (!scp) goto oom;
    scp[0] = 0;
    for (int s = 0; s < nsf; s++) scp[s + 1] = scp[s] + cnt[s];
    sc = malloc(((size_t)scp[nsf] + 1) * sizeof *sc);
    if (!sc) goto oom;
    memcpy(cnt, scp, (size_t)nsf * sizeof *cnt); /* fill cursors */
    for (int s = 0; s < nsf; s++) mark[s] = -1;
    for (int p = 0; p < nw; p++) {
        int J = nf + wperm[p];
        for (int q = cp[J]; q < cp[J + 1] && ri[q] < nf; q++)
            for (int sn = S->smap[S->pos[ri[q]]]; sn >= 0 && mark[sn] != J; sn = S->sparent[sn]) {
                mark[sn] = J;
                sc[cnt[sn]++] = nf + p;
            }
    }

    /* the whole factor: fixed supernodes (their rows, then the variable
     * ones), then the variable block's, shifted by nf */
    L = cholmod_allocate_factor((size_t)nv, cm);
    if (!L) goto fail;
    int *perm = L->Perm, *count = L->ColCount;
    double lnz = 0, fl = 0;
    for (int k = 0; k < nv; k++) {
        int c = k < nf ? S->count[k] + (scp[S->smap[k] + 1] - scp[S->smap[k]])
                       : ((const int *)LS->ColCount)[k - nf];
        perm[k] = k < nf ? S->perm[k] : nf + wperm[k - nf];
        count[k] = c; /* fixed columns: an upper bound (statistics only) */
        lnz += c;
        fl += (double)c * c;
    }
    const int *wsuper = LS ? LS->super : NULL, *wpi = LS ? LS->pi : NULL, *ws = LS ? LS->s : NULL;
    size_t ssize = (size_t)S->pi[nsf] + (size_t)scp[nsf] + (LS ? (size_t)wpi[nsw] : 0), xsize = 0;
    for (int s = 0; s < nsf; s++)
        xsize += (size_t)(S->super[s + 1] - S->super[s]) *
            (size_t)(S->pi[s + 1] - S->pi[s] + scp[s + 1] - scp[s]);
    for (int s = 0; s < nsw; s++)
        xsize += (size_t)(wsuper[s + 1] - wsuper[s]) * (size_t)(wpi[s + 1] - wpi[s]);
    L->ssize = ssize ? ssize : 1;
    L->xsize = xsize ? xsize : 1;
    L->nsuper = (size_t)(nsf + nsw);
    if (!cholmod_change_factor(CHOLMOD_PATTERN, 1, 1, 1, 1, L, cm)) goto fail;
    int *super = L->super, *pi = L->pi, *px = L->px, *ls = L->s, at = 0;
    for (int s = 0; s < nsf; s++) {
        super[s] = S->super[s];
        pi[s] = at;
        int nr = S->pi[s + 1] - S->pi[s];
        memcpy(ls + at, S->s + S->pi[s], (size_t)nr * sizeof *ls);
        at += nr;
        memcpy(ls + at, sc + scp[s], (size_t)(scp[s + 1] - scp[s]) * sizeof *ls);
        at += scp[s + 1] - scp[s];
    }
    for (int s = 0; s < nsw; s++) {
        super[nsf + s] = nf + wsuper[s];
        pi[nsf + s] = at;
        for (int q = wpi[s]; q < wpi[s + 1]; q++) ls[at++] = nf + ws[q];
    }
    super[nsf + nsw] = nv;
    pi[nsf + nsw] = at;
    px[0] = 0;
    for (int s = 0; s < nsf + nsw; s++)
        px[s + 1] = px[s] + (super[s + 1] - super[s]) * (pi[s + 1] - pi[s]);
    for (int s = 0; s < nsf + nsw; s++)
        for (int k = super[s]; k < super[s + 1]; k++) smap[k] = s;
    workspace_sizes(L, smap);
    L->ordering = CHOLMOD_GIVEN;
    cm->lnz = lnz;
    cm->fl = fl;
    /* the fixed vertices first, in the fixed analysis's order */
    assert(opt_super_symbolic_valid(L) &&
           memcmp(L->Perm, S->perm, (size_t)nf * sizeof *S->perm) == 0);
    goto done;
oom:
    cm->status = CHOLMOD_OUT_OF_MEMORY;
fail:
    if (L) cholmod_free_factor(&L, cm);
done:
    if (LS) cholmod_free_factor(&LS, cm);
    free(mark);
    free(cnt);
    free(pairs);
    free(jr);
    free(rs);
    free(rsi);
    free(wmark);
    free(ident);
    free(tcp);
    free(tri);
    free(sc);
    free(scp);
    free(smap);
    return L;
}
