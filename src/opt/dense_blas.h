/* opt/dense_blas: the BLAS routines (Fortran interface, 32-bit integers:
 * Debian's libblas, OpenBLAS's by default) behind scaf's supernodal
 * factorizations (Cholesky; opt/supernodal_lu's LU) and solves. */
#ifndef SCAF_OPT_DENSE_BLAS_H
#define SCAF_OPT_DENSE_BLAS_H

void dsyrk_(const char *uplo, const char *trans, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *beta, double *c, const int *ldc);
void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k,
            const double *alpha, const double *a, const int *lda, const double *b, const int *ldb,
            const double *beta, double *c, const int *ldc);
void dtrsm_(const char *side, const char *uplo, const char *trans, const char *diag, const int *m,
            const int *n, const double *alpha, const double *a, const int *lda, double *b,
            const int *ldb);
void dtrsv_(const char *uplo, const char *trans, const char *diag, const int *n, const double *a,
            const int *lda, double *x, const int *incx);
void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
            const int *lda, const double *x, const int *incx, const double *beta, double *y,
            const int *incy);

#endif /* SCAF_OPT_DENSE_BLAS_H */
