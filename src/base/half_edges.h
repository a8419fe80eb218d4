/* base/half_edges: the sides of a triangle index list, ordered by
 * undirected edge.
 *
 * Half-edge h = 3f + k of face f goes from F[h] to F[half_edge_next(h)].
 * The order is by (smaller end, larger end, h): the half-edges of one
 * undirected edge form a run, runs come in increasing (lo, hi) order and
 * a run lists its half-edges in increasing h, so every result built on it
 * is deterministic. Counting sort on the smaller end, then a sort of each
 * bucket (a vertex's valence, a handful of keys): linear in practice.
 *
 * The one grouping of face sides that the edge table (mesh/edges), the
 * bijectivity checker, chart boundary segments, boundary loops of charts
 * and the UV fan splitter share. Half-edges whose two ends are equal (a
 * face with a repeated index) are listed like the others, as runs with
 * lo == hi: callers that must ignore them skip those runs.
 */
#ifndef SCAF_BASE_HALF_EDGES_H
#define SCAF_BASE_HALF_EDGES_H

#include "base/error.h"

/* The half-edge after h in its face. */
static inline int half_edge_next(int h) { return h - h % 3 + (h % 3 + 1) % 3; }

/* Smaller and larger end of half-edge h of F. */
static inline int half_edge_lo(const int *F, int h)
{
    int a = F[h], b = F[half_edge_next(h)];
    return a < b ? a : b;
}
static inline int half_edge_hi(const int *F, int h)
{
    int a = F[h], b = F[half_edge_next(h)];
    return a < b ? b : a;
}

/* Whether half-edges g and h of F lie on the same undirected edge. */
static inline int half_edges_same_edge(const int *F, int g, int h)
{
    return half_edge_lo(F, g) == half_edge_lo(F, h) && half_edge_hi(F, g) == half_edge_hi(F, h);
}

/* Sort the half-edges of nf triangles F over the indices 0..n-1.
 *   skip   optional (NULL: none): faces f with skip[f] != 0 contribute no
 *          half-edges (their indices are not read)
 *   order  out: room for 3 nf half-edge ids; gets the sorted ones
 *   count  out: how many (3 nf minus 3 per skipped face)
 * Every index of a face not skipped must be in [0, n). Fails only with
 * SCAF_ERR_NOMEM (or SCAF_ERR_USAGE on a negative n or nf). */
scaf_status half_edges_sort(int n, int nf, const int *F, const unsigned char *skip, int *order,
                            int *count, scaf_error *err);

/* One past the largest index of F (0 for no faces): n for
 * half_edges_sort when the caller does not know it. */
int half_edges_index_count(int nf, const int *F);

#endif /* SCAF_BASE_HALF_EDGES_H */
