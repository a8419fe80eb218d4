/* opt/cmcf: conformalized mean curvature flow (see the header). */
#include "opt/cmcf.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "opt/cotan_laplacian.h"

scaf_status cmcf_frame(int nv, const double *U, int nf, const int *F, double centre[3],
                       double *area, scaf_error *err)
{
    (void)nv;
    double A = 0, c[3] = {0, 0, 0};
    for (int f = 0; f < nf; f++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = U + 3 * (size_t)F[3 * f + k];
        double a = opt_tri_area3(p[0], p[1], p[2]);
        A += a;
        for (int d = 0; d < 3; d++) c[d] += a * (p[0][d] + p[1][d] + p[2][d]) / 3;
    }
    if (!(A > 0) || !isfinite(A))
        return err_set(err, SCAF_ERR_NUMERIC, "the surface has area %g: cannot normalize it", A);
    for (int d = 0; d < 3; d++) centre[d] = c[d] / A;
    *area = A;
    return SCAF_OK;
}

scaf_status cmcf_normalize(int nv, double *U, int nf, const int *F, scaf_error *err)
{
    double c[3], area;
    scaf_status st = cmcf_frame(nv, U, nf, F, c, &area, err);
    if (st != SCAF_OK) return st;
    double s = 1 / sqrt(area);
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) U[3 * (size_t)v + d] = (U[3 * (size_t)v + d] - c[d]) * s;
    return SCAF_OK;
}

void cmcf_free(cmcf *f)
{
    opt_csc_free(&f->L);
    opt_csc_free(&f->A);
    free(f->diag);
    free(f->mass);
    free(f->rhs);
    free(f->next);
    opt_chol_destroy(f->chol);
    memset(f, 0, sizeof *f);
}

scaf_status cmcf_init(cmcf *f, int nv, const double *V, int nf, const int *F, double delta,
                      scaf_error *err)
{
    memset(f, 0, sizeof *f);
    if (!(delta > 0) || !isfinite(delta))
        return err_set(err, SCAF_ERR_USAGE, "flow time step %g: it must be positive and finite",
                       delta);
    if (nv < 3 || nf < 1)
        return err_set(err, SCAF_ERR_USAGE, "flow of a surface with %d vertices and %d faces", nv,
                       nf);
    f->nv = nv;
    f->nf = nf;
    f->F = F;
    f->delta = delta;
    scaf_status st = opt_cotan_laplacian(nv, V, nf, F, &f->L, err);
    if (st != SCAF_OK) goto fail;
    opt_csc *A = &f->A, *L = &f->L;
    A->n = L->n;
    A->nnz = L->nnz;
    A->colptr = malloc(((size_t)nv + 1) * sizeof *A->colptr);
    A->rowidx = malloc((size_t)L->nnz * sizeof *A->rowidx);
    A->val = malloc((size_t)L->nnz * sizeof *A->val);
    f->diag = malloc((size_t)nv * sizeof *f->diag);
    f->mass = malloc((size_t)nv * sizeof *f->mass);
    f->rhs = malloc(3 * (size_t)nv * sizeof *f->rhs);
    f->next = malloc(3 * (size_t)nv * sizeof *f->next);
    if (!A->colptr || !A->rowidx || !A->val || !f->diag || !f->mass || !f->rhs || !f->next) {
        st = err_nomem(err, "flow system");
        goto fail;
    }
    memcpy(A->colptr, L->colptr, ((size_t)nv + 1) * sizeof *A->colptr);
    memcpy(A->rowidx, L->rowidx, (size_t)L->nnz * sizeof *A->rowidx);
    /* upper part, rows ascending: the diagonal closes each column (the
     * Laplacian stores every one) */
    for (int j = 0; j < nv; j++) f->diag[j] = L->colptr[j + 1] - 1;
    f->chol = opt_chol_create(OPT_ORDER_AMD, err);
    if (!f->chol) {
        st = err ? err->code : SCAF_ERR_NOMEM;
        goto fail;
    }
    return SCAF_OK;
fail:
    cmcf_free(f);
    return st;
}

scaf_status cmcf_step(cmcf *f, double *U, scaf_error *err)
{
    int nv = f->nv;
    opt_mass_barycentric(nv, U, f->nf, f->F, f->mass);
    for (int k = 0; k < f->L.nnz; k++) f->A.val[k] = -f->delta * f->L.val[k];
    for (int v = 0; v < nv; v++) {
        f->A.val[f->diag[v]] += f->mass[v];
        for (int d = 0; d < 3; d++) f->rhs[(size_t)d * nv + v] = f->mass[v] * U[3 * (size_t)v + d];
    }
    /* same pattern every step: only the first factorization analyses */
    scaf_status st = opt_chol_factor(f->chol, &f->A, err);
    if (st == SCAF_OK) st = opt_chol_solve(f->chol, 3, f->rhs, f->rhs, err);
    if (st != SCAF_OK) {
        err_prefix(err, "flow step %d", f->steps + 1);
        return st;
    }
    for (size_t k = 0; k < 3 * (size_t)nv; k++)
        if (!isfinite(f->rhs[k]))
            return err_set(err, SCAF_ERR_NUMERIC,
                           "flow step %d: vertex %d got a non-finite position", f->steps + 1,
                           (int)(k % (size_t)nv));
    /* normalize a copy: U stays unchanged on failure */
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) f->next[3 * (size_t)v + d] = f->rhs[(size_t)d * nv + v];
    st = cmcf_normalize(nv, f->next, f->nf, f->F, err);
    if (st != SCAF_OK) {
        err_prefix(err, "flow step %d", f->steps + 1);
        return st;
    }
    memcpy(U, f->next, 3 * (size_t)nv * sizeof *U);
    f->steps++;
    return st;
}
