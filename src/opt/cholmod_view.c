/* opt/cholmod_view: see cholmod_view.h. */
#include "opt/cholmod_view.h"

#include <string.h>

cholmod_sparse opt_cholmod_pattern_view(int n, int *p, int *i, int sorted)
{
    cholmod_sparse S;
    memset(&S, 0, sizeof S);
    S.nrow = S.ncol = (size_t)n;
    S.nzmax = (size_t)p[n];
    S.p = p;
    S.i = i;
    S.stype = 1;
    S.itype = CHOLMOD_INT;
    S.xtype = CHOLMOD_PATTERN;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = sorted;
    S.packed = 1;
    return S;
}

cholmod_sparse opt_csc_cholmod_view(const opt_csc *A)
{
    cholmod_sparse S = opt_cholmod_pattern_view(A->n, A->colptr, A->rowidx, 1);
    S.nzmax = (size_t)A->nnz;
    S.x = A->val;
    S.xtype = CHOLMOD_REAL;
    return S;
}
