/* opt/given_symbolic: see given_symbolic.h. */
#include "opt/given_symbolic.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "opt/cholmod_view.h"
#include "opt/supernodal_check.h"

/* The symbolic analysis of A with the given permutation, as
 * cholmod_analyze_p does it for a supernodal factor (etree, column counts,
 * weighted postorder, supernodes) but with two fewer passes over the
 * matrix: CHOLMOD forms triu(A(p,p)) by two transposes, then, after the
 * postorder, forms it again from A by two more. Here triu(A(p,p)) is built
 * in one pass (columns unsorted: the etree and the supernodal analysis
 * accept that), its transpose (sorted, as cholmod_rowcolcounts wants) by
 * one CHOLMOD transpose, and the postordered matrix by relabelling the
 * first one. Every CHOLMOD routine sees the same patterns as inside
 * cholmod_analyze_p, so the factor (Perm, ColCount, supernodes, row
 * patterns) is the same. Returns NULL with cm->status set when out of
 * memory, or with status OK when perm is not a permutation (the caller
 * then lets CHOLMOD handle and report it). */
cholmod_factor *opt_given_symbolic(cholmod_common *cm, int nn, const int *colptr, const int *rowidx,
                                   const int *perm)
{
    assert(nn >= 0 && colptr[0] == 0);
    size_t n = (size_t)nn, nz = (size_t)colptr[nn];
    int *iw = malloc((8 * n + 2) * sizeof *iw);
    int *si = malloc((nz ? nz : 1) * sizeof *si);
    int *si2 = malloc((nz ? nz : 1) * sizeof *si2);
    cholmod_sparse *F = NULL;
    cholmod_factor *L = NULL;
    if (!iw || !si || !si2) {
        cm->status = CHOLMOD_OUT_OF_MEMORY;
        goto done;
    }
    int *pinv = iw, *parent = iw + n, *post = iw + 2 * n, *colcount = iw + 3 * n;
    int *first = iw + 4 * n, *level = iw + 5 * n, *sp = iw + 6 * n, *sp2 = iw + 7 * n + 1;
    for (size_t k = 0; k < n; k++) pinv[k] = -1;
    for (size_t k = 0; k < n; k++) {
        int v = perm[k];
        if (v < 0 || (size_t)v >= n || pinv[v] >= 0) goto done; /* not a permutation */
        pinv[v] = (int)k;
    }
    /* S = triu(A(p,p)): entry (r, col) of triu(A) goes to column
     * max(pinv r, pinv col), row min (lower entries are ignored, as CHOLMOD
     * does for an upper-stored matrix). */
    memset(sp, 0, (n + 1) * sizeof *sp);
    for (size_t col = 0; col < n; col++) {
        int pc = pinv[col];
        for (int q = colptr[col]; q < colptr[col + 1]; q++) {
            int r = rowidx[q];
            if ((size_t)r > col) continue;
            int pr = pinv[r];
            sp[(pr > pc ? pr : pc) + 1]++;
        }
    }
    for (size_t k = 0; k < n; k++) sp[k + 1] += sp[k];
    memcpy(first, sp, n * sizeof *first); /* fill cursors */
    for (size_t col = 0; col < n; col++) {
        int pc = pinv[col];
        for (int q = colptr[col]; q < colptr[col + 1]; q++) {
            int r = rowidx[q];
            if ((size_t)r > col) continue;
            int pr = pinv[r];
            if (pr > pc) si[first[pr]++] = pc;
            else si[first[pc]++] = pr;
        }
    }
    cholmod_sparse S = opt_cholmod_pattern_view((int)n, sp, si, 0);
    F = cholmod_transpose(&S, 0, cm); /* tril(A(p,p)) by columns, sorted */
    if (!F) goto done;
    if (!cholmod_etree(&S, parent, cm)) goto done;
    if (cholmod_postorder(parent, n, NULL, post, cm) != (long)n) goto done;
    if (!cholmod_rowcolcounts(F, NULL, 0, parent, post, NULL, colcount, first, level, cm))
        goto done;
    double fl = cm->fl, lnz = cm->lnz;
    L = cholmod_allocate_factor(n, cm);
    if (!L) goto done;
    int *lperm = L->Perm, *lcount = L->ColCount;
    cholmod_sparse *T = &S;
    cholmod_sparse S2 = S;
    if (cm->postorder && cholmod_postorder(parent, n, colcount, post, cm) == (long)n) {
        /* combine the permutation with the weighted postorder (as CHOLMOD
         * does) and relabel S accordingly: a postorder keeps every entry
         * upper (its column is an etree ancestor of its row). */
        int *inv = first, *lparent = level;
        for (size_t k = 0; k < n; k++) inv[post[k]] = (int)k;
        sp2[0] = 0;
        for (size_t k = 0; k < n; k++) {
            int o = post[k];
            lperm[k] = perm[o];
            lcount[k] = colcount[o];
            lparent[k] = parent[o] < 0 ? -1 : inv[parent[o]];
            int out = sp2[k];
            for (int q = sp[o]; q < sp[o + 1]; q++) si2[out++] = inv[si[q]];
            sp2[k + 1] = out;
        }
        S2.p = sp2;
        S2.i = si2;
        T = &S2;
        parent = lparent;
    } else {
        memcpy(lperm, perm, n * sizeof *lperm);
        memcpy(lcount, colcount, n * sizeof *lcount);
    }
    L->ordering = CHOLMOD_GIVEN;
    if (!cholmod_super_symbolic(T, NULL, parent, L, cm)) {
        cholmod_free_factor(&L, cm);
        goto done;
    }
    cm->fl = fl;
    cm->lnz = lnz;
done:
    assert(!L || (opt_super_symbolic_valid(L) && L->ordering == CHOLMOD_GIVEN));
    if (F) cholmod_free_sparse(&F, cm);
    free(iw);
    free(si);
    free(si2);
    return L;
}
