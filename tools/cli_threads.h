/* tools/cli_threads: the `--threads N` option of `scaf param` and `scaf
 * atlas`: threads of scaf's own loops over simplices (energies, assembly,
 * line search: base/parallel) and of the dense kernels of the sparse
 * Cholesky factorization (scaf_set_threads).
 *
 * Every sum over simplices is the same bits for any N (cut into chunks by
 * its size only, added in chunk order: base/parallel), and OpenBLAS runs
 * one-threaded inside scaf's kernels (its split of a product changes with
 * its thread count); the factorization's tree is cut into N bins, so
 * outputs for different N may differ in the last bits, unless
 * --deterministic (scaf_set_deterministic) fixes the bins at
 * OPT_SNUM_BINS: then the same bytes for any N, at a cost per iteration
 * (bench/RESULTS-param.md, session 16). The same N gives the same bytes
 * run after run. CHOLMOD's
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
