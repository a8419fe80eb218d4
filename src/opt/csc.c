/* opt/csc: symmetric sparse matrices in compressed-column form (upper part).
 *
 * Triplets are bucketed by column (counting sort), each column's rows
 * sorted by insertion sort (columns are short in mesh matrices), and
 * duplicates summed.
 */
#include "opt/csc.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

void opt_csc_free(opt_csc *A)
{
    if (!A) return;
    free(A->colptr);
    free(A->rowidx);
    free(A->val);
    memset(A, 0, sizeof *A);
}

void opt_csc_symv(const opt_csc *A, const double *x, double *y)
{
    for (int i = 0; i < A->n; i++) y[i] = 0;
    for (int c = 0; c < A->n; c++)
        for (int k = A->colptr[c]; k < A->colptr[c + 1]; k++) {
            int r = A->rowidx[k];
            y[r] += A->val[k] * x[c];
            if (r != c) y[c] += A->val[k] * x[r];
        }
}

int opt_csc_is_upper_sorted(const opt_csc *A)
{
    if (A->n < 0 || !A->colptr || A->colptr[0] != 0 || A->colptr[A->n] != A->nnz) return 0;
    for (int c = 0; c < A->n; c++) {
        if (A->colptr[c + 1] < A->colptr[c]) return 0;
        for (int k = A->colptr[c]; k < A->colptr[c + 1]; k++) {
            int r = A->rowidx[k];
            if (r < 0 || r > c || (k > A->colptr[c] && r <= A->rowidx[k - 1])) return 0;
        }
    }
    return 1;
}

scaf_status opt_csc_from_triplets(opt_csc *A, int n, int nt, const int *I, const int *Jc,
                                  const double *Val, scaf_error *err)
{
    memset(A, 0, sizeof *A);
    for (int k = 0; k < nt; k++)
        if (I[k] < 0 || I[k] >= n || Jc[k] < 0 || Jc[k] >= n)
            return err_set(err, SCAF_ERR_USAGE,
                           "triplet %d: index (%d, %d) outside a %d by %d matrix", k, I[k], Jc[k],
                           n, n);
    int *cp = calloc((size_t)n + 1, sizeof *cp);
    int *rows = malloc(((size_t)nt + 1) * sizeof *rows);
    double *vals = malloc(((size_t)nt + 1) * sizeof *vals);
    if (!cp || !rows || !vals) {
        free(cp);
        free(rows);
        free(vals);
        return err_nomem(err, "sparse matrix");
    }
    for (int k = 0; k < nt; k++) {
        int c = I[k] > Jc[k] ? I[k] : Jc[k];
        cp[c + 1]++;
    }
    for (int c = 0; c < n; c++) cp[c + 1] += cp[c];
    int *next = malloc(((size_t)n + 1) * sizeof *next);
    if (!next) {
        free(cp);
        free(rows);
        free(vals);
        return err_nomem(err, "sparse matrix");
    }
    memcpy(next, cp, ((size_t)n + 1) * sizeof *next);
    for (int k = 0; k < nt; k++) {
        int r = I[k] < Jc[k] ? I[k] : Jc[k], c = I[k] > Jc[k] ? I[k] : Jc[k];
        rows[next[c]] = r;
        vals[next[c]++] = Val[k];
    }
    /* Sort each column by row and sum duplicates, compacting in place. */
    int out = 0;
    for (int c = 0; c < n; c++) {
        int b = cp[c], e = cp[c + 1];
        for (int i = b + 1; i < e; i++) {
            int r = rows[i];
            double v = vals[i];
            int j = i - 1;
            while (j >= b && rows[j] > r) {
                rows[j + 1] = rows[j];
                vals[j + 1] = vals[j];
                j--;
            }
            rows[j + 1] = r;
            vals[j + 1] = v;
        }
        next[c] = out;
        for (int i = b; i < e; i++) {
            if (i > b && rows[i] == rows[i - 1]) {
                vals[out - 1] += vals[i];
            } else {
                rows[out] = rows[i];
                vals[out++] = vals[i];
            }
        }
    }
    next[n] = out;
    free(cp);
    A->n = n;
    A->nnz = out;
    A->colptr = next;
    A->rowidx = rows;
    A->val = vals;
    assert(opt_csc_is_upper_sorted(A));
    return SCAF_OK;
}

scaf_status opt_csc_expand_vertex_pattern(opt_csc *A, int d, int nv, const int *vcolptr,
                                          const int *vrowidx, int zero_values, scaf_error *err)
{
    int n = nv * d;
    A->n = n;
    A->colptr = malloc(((size_t)n + 1) * sizeof *A->colptr);
    if (!A->colptr) return err_nomem(err, "proxy system matrix");
    A->colptr[0] = 0;
    for (int c = 0; c < nv; c++) {
        int lo = vcolptr[c], hi = vcolptr[c + 1];
        int diag = hi > lo && vrowidx[hi - 1] == c;
        int off = hi - lo - diag;
        for (int a = 0; a < d; a++)
            A->colptr[c * d + a + 1] = A->colptr[c * d + a] + off * d + (diag ? a + 1 : 0);
    }
    A->nnz = A->colptr[n];
    A->rowidx = malloc(((size_t)A->nnz + 1) * sizeof *A->rowidx);
    A->val = zero_values ? calloc((size_t)A->nnz + 1, sizeof *A->val)
                         : malloc(((size_t)A->nnz + 1) * sizeof *A->val);
    if (!A->rowidx || !A->val) return err_nomem(err, "proxy system matrix");
    for (int c = 0; c < nv; c++) {
        int lo = vcolptr[c], hi = vcolptr[c + 1];
        for (int a = 0; a < d; a++) {
            int pos = A->colptr[c * d + a];
            for (int k = lo; k < hi; k++) {
                int r = vrowidx[k];
                int top = r == c ? a : d - 1;
                for (int q = 0; q <= top; q++) A->rowidx[pos++] = r * d + q;
            }
        }
    }
    assert(opt_csc_is_upper_sorted(A));
    return SCAF_OK;
}

/* Entries of A's first nvc * d columns when they are the expansion of
 * vertex columns 0..nvc-1, else -1. */
static int expansion_prefix(const opt_csc *A, int d, int nvc, const int *vcolptr,
                            const int *vrowidx)
{
    if (d < 1 || nvc < 0 || A->n < nvc * d || A->colptr[0] != 0) return -1;
    int pos = 0;
    for (int c = 0; c < nvc; c++)
        for (int a = 0; a < d; a++) {
            if (A->colptr[c * d + a] != pos) return -1;
            for (int k = vcolptr[c]; k < vcolptr[c + 1]; k++) {
                int r = vrowidx[k], top = r == c ? a : d - 1;
                for (int q = 0; q <= top; q++)
                    if (pos >= A->nnz || A->rowidx[pos++] != r * d + q) return -1;
            }
        }
    return A->colptr[nvc * d] == pos ? pos : -1;
}

int opt_csc_is_vertex_expansion(const opt_csc *A, int d, int nv, const int *vcolptr,
                                const int *vrowidx)
{
    return A->n == nv * d && expansion_prefix(A, d, nv, vcolptr, vrowidx) == A->nnz;
}

int opt_csc_starts_with_vertex_expansion(const opt_csc *A, int d, int nvc, const int *vcolptr,
                                         const int *vrowidx)
{
    return expansion_prefix(A, d, nvc, vcolptr, vrowidx) >= 0;
}
