/* base/min_heap: a binary min-heap of (key, id) pairs, ties broken by the
 * smaller id, so every Dijkstra-style growth over it is deterministic
 * (the cut graph's shortest paths, the segmentation's chart growth).
 *
 * Lazy deletion is the caller's: push a pair again with a smaller key and
 * skip popped pairs whose key is stale. Zero-initialize, push, pop while
 * n > 0, then min_heap_free. Fails only on allocation (push returns 0).
 */
#ifndef SCAF_BASE_MIN_HEAP_H
#define SCAF_BASE_MIN_HEAP_H

typedef struct min_heap_item {
    double key;
    int id;
} min_heap_item;

typedef struct min_heap {
    min_heap_item *a;
    int n, cap;
} min_heap;

/* Add (key, id); 0 when out of memory (the heap is then unchanged). */
int min_heap_push(min_heap *h, double key, int id);

/* Remove and return the smallest pair; h->n must be > 0. */
min_heap_item min_heap_pop(min_heap *h);

/* Release the storage (the heap is then empty and reusable). */
void min_heap_free(min_heap *h);

#endif /* SCAF_BASE_MIN_HEAP_H */
