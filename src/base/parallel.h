/* base/parallel: the thread count of scaf's own loops over simplices
 * (energies, the line search's bound and checks, the proxy and Newton
 * fills), how such a loop is cut into chunks, and the threads that run
 * the chunks.
 *
 * Results must not depend on the thread count nor on scheduling, so that
 * a run gives the same bytes on every machine (asset pipelines cache by
 * content hash): a reduction over n items (par_sum, par_min) is cut into
 * par_sum_chunks(n) contiguous chunks, a function of n only; each chunk's
 * partial result is kept apart and the partials are combined in chunk
 * order, whatever threads ran the chunks. par_chunks(n), which does depend
 * on the thread count, only cuts work whose result does not depend on the
 * cut (fills where each value receives its terms in the serial order).
 *
 * The threads are a small pool of POSIX threads, started on first use and
 * kept; idle, they sleep on a condition variable. Not OpenMP: libgomp's
 * idle threads spin (its wait policy is fixed when the library loads), and
 * spinning threads took the cores from the serial parts and from OpenBLAS
 * on a busy 2-core machine (assembly 3x slower at two threads,
 * bench/RESULTS-param.md, session 6). One loop runs in the pool at a time;
 * a loop started while another runs (two handles in two threads) runs its
 * chunks in its own thread, with the same results.
 */
#ifndef SCAF_BASE_PARALLEL_H
#define SCAF_BASE_PARALLEL_H

#include <stddef.h>

/* Fewer items than this per chunk are not worth a thread (waking one costs
 * tens of microseconds; a simplex costs ~0.1-1 us). The default of
 * par_min_chunk. */
#define PAR_MIN_CHUNK 4096
/* At most this many chunks (partials live in arrays of this size). */
#define PAR_MAX_CHUNKS 64

/* Process-wide; n < 1 counts as 1. Until set: 1. */
void par_set_threads(int n);
int par_threads(void);

/* Items per chunk below which a loop is not cut (process-wide; n < 1
 * counts as 1; until set: PAR_MIN_CHUNK). Only tests lower it (the
 * program's SCAF_MIN_CHUNK), so that small inputs take the parallel paths;
 * reductions then group their sums differently, the same for every thread
 * count. */
void par_set_min_chunk(size_t n);
size_t par_min_chunk(void);

/* Chunks for a loop of n items: min(threads, n / par_min_chunk(),
 * PAR_MAX_CHUNKS), at least 1. Only for loops whose result does not
 * depend on the cut. */
int par_chunks(size_t n);

/* Chunks of a reduction over n items: min(n / par_min_chunk(),
 * PAR_MAX_CHUNKS), at least 1, whatever the thread count (the partials'
 * grouping then never changes with it). */
int par_sum_chunks(size_t n);

/* First item of chunk k of nc over n items (chunk k is [begin(k), begin(k+1))). */
static inline size_t par_chunk_begin(size_t n, int nc, int k)
{
    return (size_t)((unsigned long long)n * (unsigned long long)k / (unsigned long long)nc);
}

/* Run fn(ctx, k) for every k in [0, nc), in up to min(nc, threads) threads
 * (the caller's among them); returns when all have returned. fn must not
 * depend on which thread runs it. */
typedef void (*par_fn)(void *ctx, int k);
void par_run(int nc, par_fn fn, void *ctx);

/* A loop over n items whose result is range(ctx, lo, hi) of its items
 * [lo, hi), run over par_sum_chunks(n) chunks with par_run: par_sum adds
 * the chunks' results in chunk order (from 0), par_min takes their
 * minimum. One chunk: range(ctx, 0, n). The same bits for any thread
 * count. */
typedef double (*par_range_fn)(const void *ctx, size_t lo, size_t hi);
double par_sum(size_t n, par_range_fn range, const void *ctx);
double par_min(size_t n, par_range_fn range, const void *ctx);

#endif /* SCAF_BASE_PARALLEL_H */
