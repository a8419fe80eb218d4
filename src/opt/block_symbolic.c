/* opt/block_symbolic: see block_symbolic.h. */
#include "opt/block_symbolic.h"

#include <assert.h>
#include <limits.h>
#include <stdlib.h>

#include "opt/supernodal_check.h"

int opt_block_graph(const opt_csc *A, int b, int **cp_out, int **ri_out)
{
    int nb = A->n / b;
    int *cp = malloc(((size_t)nb + 1) * sizeof *cp);
    int *ri = malloc(((size_t)A->nnz + 1) * sizeof *ri);
    int *mark = malloc(((size_t)nb + 1) * sizeof *mark);
    if (!cp || !ri || !mark) {
        free(cp);
        free(ri);
        free(mark);
        return 0;
    }
    for (int I = 0; I < nb; I++) mark[I] = -1;
    int out = 0;
    for (int J = 0; J < nb; J++) {
        cp[J] = out;
        /* the last column of the group usually holds every row group;
         * the others add any it lacks (then the column is re-sorted) */
        int added = 0;
        for (int a = b - 1; a >= 0; a--) {
            int col = J * b + a;
            for (int k = A->colptr[col]; k < A->colptr[col + 1]; k++) {
                int I = A->rowidx[k] / b;
                if (mark[I] == J) continue;
                mark[I] = J;
                ri[out++] = I;
                added += a < b - 1;
            }
        }
        if (added) /* insertion sort: a handful of late rows */
            for (int k = cp[J] + 1; k < out; k++)
                for (int q = k; q > cp[J] && ri[q - 1] > ri[q]; q--) {
                    int t = ri[q];
                    ri[q] = ri[q - 1];
                    ri[q - 1] = t;
                }
    }
    cp[nb] = out;
    assert(opt_upper_pattern_valid(nb, cp, ri, 0));
    free(mark);
    *cp_out = cp;
    *ri_out = ri;
    return 1;
}

int opt_block_perm_compress(int n, int b, const int *perm, int *vperm)
{
    if (b < 1 || n % b) return 0;
    for (int k = 0; k < n / b; k++) {
        int first = perm[k * b];
        if (first < 0 || first % b) return 0;
        for (int a = 1; a < b; a++)
            if (perm[k * b + a] != first + a) return 0;
        vperm[k] = first / b;
    }
    assert(opt_is_permutation(n / b, vperm));
    return 1;
}

cholmod_factor *opt_block_expand_symbolic(const cholmod_factor *Lv, int b, cholmod_common *cm)
{
    assert(b >= 1 && opt_super_symbolic_valid(Lv));
    size_t nv = Lv->n, n = nv * (size_t)b, ns = Lv->nsuper, bb = (size_t)b * (size_t)b;
    if (Lv->xsize > (size_t)INT_MAX / bb || Lv->ssize > (size_t)INT_MAX / (size_t)b) {
        cm->status = CHOLMOD_TOO_LARGE; /* CHOLMOD's int indices */
        return NULL;
    }
    cholmod_factor *L = cholmod_allocate_factor(n, cm);
    if (!L) return NULL;
    const int *vperm = Lv->Perm, *vcount = Lv->ColCount;
    int *perm = L->Perm, *count = L->ColCount;
    double lnz = 0.0, fl = 0.0;
    for (size_t k = 0; k < nv; k++)
        for (int a = 0; a < b; a++) {
            size_t j = k * (size_t)b + (size_t)a;
            perm[j] = vperm[k] * b + a;
            count[j] = vcount[k] * b - a; /* the block's rows below and at a */
            lnz += count[j];
            fl += (double)count[j] * count[j];
        }
    /* sizes first: cholmod_change_factor allocates super, pi, px, s from them */
    L->ssize = Lv->ssize * (size_t)b;
    L->xsize = Lv->xsize * bb;
    L->nsuper = ns;
    if (!cholmod_change_factor(CHOLMOD_PATTERN, 1, 1, 1, 1, L, cm)) {
        cholmod_free_factor(&L, cm);
        return NULL;
    }
    const int *vsuper = Lv->super, *vpi = Lv->pi, *vs = Lv->s;
    int *super = L->super, *pi = L->pi, *px = L->px, *s = L->s;
    px[0] = 0;
    for (size_t k = 0; k <= ns; k++) {
        super[k] = vsuper[k] * b;
        pi[k] = vpi[k] * b;
        if (k > 0) px[k] = px[k - 1] + (super[k] - super[k - 1]) * (pi[k] - pi[k - 1]);
    }
    for (int q = 0; q < vpi[ns]; q++)
        for (int a = 0; a < b; a++) s[(size_t)q * (size_t)b + (size_t)a] = vs[q] * b + a;
    /* an update matrix is ndrow2 x ndrow1 rows of a supernode, both b
     * times as many; the solve's workspace counts rows */
    L->maxcsize = Lv->maxcsize * bb;
    L->maxesize = Lv->maxesize * (size_t)b;
    L->ordering = Lv->ordering;
    cm->lnz = lnz;
    cm->fl = fl;
    assert(opt_super_symbolic_valid(L));
    return L;
}
