/* opt/blas_threads: how many threads the dense kernels of the sparse
 * Cholesky factorization (OpenBLAS, called by CHOLMOD) use. Process-wide
 * (OpenBLAS has one setting); scaf_set_threads (include/scaf/scaf.h) is
 * the public face, and sets scaf's own loops (base/parallel) to the same
 * count. */
#ifndef SCAF_OPT_BLAS_THREADS_H
#define SCAF_OPT_BLAS_THREADS_H

/* Whether scaf_set_deterministic asked for the same bits at every thread
 * count (opt/cholmod_solver then plans OPT_SNUM_BINS bins, not one per
 * thread). */
int opt_deterministic(void);

/* Cores this process may run on (its CPU affinity), at least 1. */
int opt_blas_cores(void);

/* The BLAS's current thread count, 0 when it offers none to query. */
int opt_blas_threads(void);

/* For code that runs BLAS in its own threads, or whose results must not
 * depend on the thread count: set the BLAS to one thread (OpenBLAS's
 * threads would spin beside scaf's, and OpenBLAS cuts some kernels, e.g.
 * dpotrf's blocks, by its thread count, so their sums change with it);
 * returns what opt_blas_serial_end restores. */
int opt_blas_serial_begin(void);
void opt_blas_serial_end(int saved);

#endif
