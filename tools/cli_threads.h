/* tools/cli_threads: the `--threads N` option of `scaf param` and `scaf
 * atlas`: threads of scaf's own loops over simplices (energies, assembly,
 * line search: base/parallel) and of the dense kernels of the sparse
 * Cholesky factorization (scaf_set_threads).
 *
 * Results are deterministic for a given N (OpenBLAS splits each product
 * by output blocks that depend only on N and the sizes, never on timing;
 * scaf's sums are cut into chunks by N and added in chunk order) and N = 1
 * gives the numbers of the one-thread program of before. They may differ
 * between two values of N (the sums then run in another order). CHOLMOD's
 * own OpenMP loops stay at one thread whatever N (they only move data;
 * opt/cholmod_solver.c says why that pays). */
#ifndef SCAF_TOOLS_CLI_THREADS_H
#define SCAF_TOOLS_CLI_THREADS_H

/* Set the thread count: `requested` >= 1 (from --threads), or 0 for the
 * default: OPENBLAS_NUM_THREADS if set (OpenBLAS read it at start; a
 * number there sets scaf's loops too), else every core the process may run
 * on. */
void cli_threads_apply(int requested);

#endif
