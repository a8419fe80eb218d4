/* tools/cli_threads: the `--threads N` option of `scaf param` and `scaf
 * atlas`: threads of the dense kernels of the sparse Cholesky
 * factorization (scaf_set_threads).
 *
 * Results are deterministic for a given N (OpenBLAS splits each product
 * by output blocks that depend only on N and the sizes, never on timing)
 * and N = 1 gives the numbers of the one-thread program of before. They
 * may differ between two values of N (the kernels then sum in another
 * order). CHOLMOD's own OpenMP loops stay at one thread whatever N (they
 * only move data; opt/cholmod_solver.c says why that pays). */
#ifndef SCAF_TOOLS_CLI_THREADS_H
#define SCAF_TOOLS_CLI_THREADS_H

/* Set the thread count: `requested` >= 1 (from --threads), or 0 for the
 * default: OPENBLAS_NUM_THREADS if set (OpenBLAS read it at start), else
 * every core the process may run on. */
void cli_threads_apply(int requested);

#endif
