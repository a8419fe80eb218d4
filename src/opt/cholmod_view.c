/* opt/cholmod_view: see cholmod_view.h. */
#include "opt/cholmod_view.h"

#include <string.h>

cholmod_sparse opt_csc_cholmod_view(const opt_csc *A)
{
    cholmod_sparse S;
    memset(&S, 0, sizeof S);
    S.nrow = S.ncol = (size_t)A->n;
    S.nzmax = (size_t)A->nnz;
    S.p = A->colptr;
    S.i = A->rowidx;
    S.x = A->val;
    S.stype = 1;
    S.itype = CHOLMOD_INT;
    S.xtype = CHOLMOD_REAL;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = 1;
    S.packed = 1;
    return S;
}
