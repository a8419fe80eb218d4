/* tools/cli_threads: the `--threads N` option of `scaf param` and `scaf
 * atlas`, i.e. how many threads the dense kernels of the sparse Cholesky
 * factorization (OpenBLAS, called by CHOLMOD) may use.
 *
 * Results are deterministic for a given N (OpenBLAS splits each product
 * by output blocks that depend only on N and the sizes, never on timing)
 * and N = 1 gives the numbers of the one-thread program of before. They
 * may differ between two values of N (the kernels then sum in another
 * order). CHOLMOD's own OpenMP loops stay at one thread whatever N (they
 * only move data; opt/cholmod_solver.c says why that pays). */
#ifndef SCAF_TOOLS_CLI_THREADS_H
#define SCAF_TOOLS_CLI_THREADS_H

/* Cores this process may run on (its CPU affinity), at least 1. */
int cli_threads_available(void);

/* Set the solver's thread count: `requested` >= 1 (from --threads), or 0
 * for the default: OPENBLAS_NUM_THREADS if set (OpenBLAS read it at
 * start), else cli_threads_available(). Returns the count now in effect
 * (0 when no OpenBLAS is linked: nothing to set). */
int cli_threads_apply(int requested);

#endif
