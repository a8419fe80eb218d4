/* opt/blas_threads: how many threads the dense kernels of the sparse
 * Cholesky factorization (OpenBLAS, called by CHOLMOD) use. Process-wide
 * (OpenBLAS has one setting); scaf_set_threads (include/scaf/scaf.h) is
 * the public face, and sets scaf's own loops (base/parallel) to the same
 * count. */
#ifndef SCAF_OPT_BLAS_THREADS_H
#define SCAF_OPT_BLAS_THREADS_H

/* Cores this process may run on (its CPU affinity), at least 1. */
int opt_blas_cores(void);

/* The BLAS's current thread count, 0 when it offers none to query. */
int opt_blas_threads(void);

/* For code that runs BLAS in its own threads: set the BLAS to one thread
 * when T > 1 (OpenBLAS's threads would spin beside them); returns what
 * opt_blas_serial_end restores. */
int opt_blas_serial_begin(int T);
void opt_blas_serial_end(int saved);

#endif
