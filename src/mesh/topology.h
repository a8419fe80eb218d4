/* mesh/topology: the topological report of a mesh (what `scaf info` prints).
 *
 * Counts connected components (faces linked through shared vertex
 * indices), edges, boundary edges and loops, Euler characteristic and genus
 * per component, non-manifold edges and vertices, misoriented edges,
 * degenerate, repeated-index and duplicate faces, unreferenced vertices,
 * UV charts and seam edges. The definitions are those of
 * ../shared/data/MANIFEST.md and are spelled out in mesh/complex.h; the
 * per-component arrays and the boundary loops live in `cx` (groups =
 * components, index space = 3D vertices), with ordered loops wherever the
 * boundary is manifold (mesh on the left of the traversal).
 *
 * Fails with SCAF_ERR_MESH when a face references a vertex outside
 * [0, nv) (a reader never produces that), SCAF_ERR_NOMEM on allocation.
 * About 0.5 s for 1.8M faces.
 */
#ifndef SCAF_MESH_TOPOLOGY_H
#define SCAF_MESH_TOPOLOGY_H

#include "base/error.h"
#include "mesh/complex.h"
#include "mesh/mesh.h"

typedef struct mesh_topology {
    int vertices; /* vertices referenced by faces */
    int faces;
    int edges;          /* undirected edges */
    int boundary_edges; /* edges with exactly one face */
    int components;
    int boundary_loops;
    int euler_characteristic; /* V - E + F, summed over components */
    int manifold;             /* 1 iff no non-manifold edge nor vertex */
    int orientable;           /* 1 iff every component is orientable */
    int non_manifold_edges;
    int non_manifold_vertices;
    int misoriented_edges;
    int degenerate_faces;     /* zero 3D area, including repeated-index faces */
    int repeated_index_faces; /* faces using one vertex twice */
    int duplicate_faces;      /* faces on the same vertex set as an earlier face */
    int unreferenced_vertices;
    int has_uv;     /* the mesh has vt indices */
    int uv_charts;  /* charts cut by vt seams; components when !has_uv */
    int seam_edges; /* 2-face edges whose sides use different vt pairs */
    int genus_sum;  /* sum of component genera; -1 if any is undefined */
    tri_complex cx; /* per component: cx.group_*[c]; loops: cx.loop_* */
} mesh_topology;

/* Compute the report of m. On failure *t is left empty. */
scaf_status mesh_topology_compute(const mesh *m, mesh_topology *t, scaf_error *err);

/* Free and reset to empty. Safe on an empty (zeroed) struct. */
void mesh_topology_free(mesh_topology *t);

#endif /* SCAF_MESH_TOPOLOGY_H */
