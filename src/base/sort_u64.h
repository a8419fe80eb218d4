/* base/sort_u64: ascending sort of 64-bit keys, tuned for short runs.
 *
 * The topology code sorts many tiny buckets (a vertex's valence, a
 * handful of keys): insertion sort there, qsort beyond 32 keys. */
#ifndef SCAF_BASE_SORT_U64_H
#define SCAF_BASE_SORT_U64_H

#include <stdint.h>

/* Sort k[0..n-1] ascending in place. */
void sort_u64(uint64_t *k, int n);

#endif
