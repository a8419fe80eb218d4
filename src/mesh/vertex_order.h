/* mesh/vertex_order: a numbering of a mesh's vertices that keeps
 * neighbours close.
 *
 * The SCAF iteration's passes over triangles gather their corners'
 * positions and scatter into the matrix columns of their vertices: with
 * neighbours numbered close, a run of triangles touches a narrow band of
 * both, which stays in cache. A mesh's own numbering need not be so: one
 * subdivided 1-to-4 numbers every edge midpoint after all the old
 * vertices, and a triangle's corners then lie far apart (443k faces:
 * median spread 95,513 against 1,368 breadth first).
 */
#ifndef SCAF_MESH_VERTEX_ORDER_H
#define SCAF_MESH_VERTEX_ORDER_H

#include "base/error.h"

/* Breadth first (Cuthill-McKee without the degree sort) over the vertex
 * adjacency of n cells of nc corners (idx: n by nc vertex ids in [0, nv)),
 * each connected part from a far vertex (the last one reached from the
 * part's smallest vertex), the parts in the order of their smallest
 * vertex; a vertex no cell uses keeps its place among the parts. rank gets
 * nv entries, a permutation of 0..nv-1: vertex v's new number.
 * Deterministic. Fails with SCAF_ERR_NOMEM. */
scaf_status mesh_vertex_order_breadth_first(int nc, int n, const int *idx, int nv, int *rank,
                                            scaf_error *err);

#endif /* SCAF_MESH_VERTEX_ORDER_H */
