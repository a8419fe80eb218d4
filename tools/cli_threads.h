/* tools/cli_threads: the `--threads N` option of `scaf param` and `scaf
 * atlas`: threads of scaf's own loops over simplices (energies, assembly,
 * line search: base/parallel) and of the dense kernels of the sparse
 * Cholesky factorization (scaf_set_threads).
 *
 * Results are the same bits for any N (so the same command gives the
 * same file on every machine, whatever its cores): scaf's reductions are
 * cut into chunks by their size only and added in chunk order
 * (base/parallel), the factorization's tree is cut into a fixed number of
 * bins that N threads work (opt/supernodal_plan), and OpenBLAS runs
 * one-threaded inside scaf's kernels (its split of a product changes with
 * its thread count). CHOLMOD's
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
