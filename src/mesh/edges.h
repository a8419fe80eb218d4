/* mesh/edges: the undirected edges of a triangle list, with their
 * incident half-edges.
 *
 * Half-edge h = 3*f + k of face f goes from corner k to corner (k+1)%3,
 * i.e. from F[3f+k] to F[3f+(k+1)%3]; for a counter-clockwise face the face
 * lies on the left of its half-edges. Edges are numbered in increasing
 * (smaller endpoint, larger endpoint) order, so the table is deterministic.
 * Built by a counting sort on the smaller endpoint followed by a small sort
 * inside each bucket: linear time in practice (about 0.2 s for 1.8M faces).
 *
 * Works on any index space: 3D vertex indices (mesh.F) or UV indices
 * (mesh.FT). A face with an index outside [0, n) or with a repeated index
 * is "invalid" here: it contributes no half-edges (he_edge = -1).
 */
#ifndef SCAF_MESH_EDGES_H
#define SCAF_MESH_EDGES_H

#include "base/error.h"

typedef struct mesh_edges {
    int ne;             /* number of undirected edges */
    int *ev;            /* #E by 2 endpoints, ev[2e] < ev[2e+1] */
    int *he_edge;       /* #F*3: edge of half-edge h, -1 for invalid faces */
    int *edge_he_start; /* #E+1: half-edges of edge e are            */
    int *edge_he;       /*   edge_he[edge_he_start[e] .. start[e+1]-1], ascending */
    int invalid_faces;  /* faces skipped (out-of-range or repeated index) */
} mesh_edges;

/* Build the edge table of nf triangles F (#F by 3 indices into 0..n-1).
 * On failure (out of memory) returns the status and leaves *e empty. */
scaf_status mesh_edges_build(int n, int nf, const int *F, mesh_edges *e, scaf_error *err);

/* Free and reset to empty. Safe on an empty (zeroed) table. */
void mesh_edges_free(mesh_edges *e);

/* Number of half-edges (incident face sides) of edge e. */
static inline int mesh_edge_valence(const mesh_edges *e, int edge)
{
    return e->edge_he_start[edge + 1] - e->edge_he_start[edge];
}

/* Start / end index of half-edge h in the index array F. */
static inline int he_from(const int *F, int h) { return F[h]; }
static inline int he_to(const int *F, int h) { return F[3 * (h / 3) + (h % 3 + 1) % 3]; }

/* Whether face f of F is valid in an index space of size n (see above). */
static inline int face_is_valid(const int *F, int f, int n)
{
    int a = F[3 * f], b = F[3 * f + 1], c = F[3 * f + 2];
    return a >= 0 && b >= 0 && c >= 0 && a < n && b < n && c < n && a != b && b != c && a != c;
}

#endif /* SCAF_MESH_EDGES_H */
