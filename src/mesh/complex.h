/* mesh/complex: topology of a triangle list split into face groups.
 *
 * The common core of mesh/topology (3D vertex indices, groups = connected
 * components) and mesh/uv_charts (UV indices, groups = charts). Given the
 * faces F over an index space 0..n-1 and a group label per face, it
 * computes per group: referenced indices, edges, boundary loops, Euler
 * characteristic, non-manifold edges and vertices, misoriented edges,
 * orientability and genus; and the boundary loops themselves, ordered as
 * cycles (mesh on the left) wherever the boundary is manifold.
 *
 * Definitions (those of ../shared/data/MANIFEST.md):
 * - boundary edge: exactly one incident face; non-manifold edge: more than 2.
 * - boundary loop: a connected component of the boundary-edge graph,
 *   restricted to one group (loops of different groups never merge).
 * - non-manifold vertex: its incident faces form more than one fan, where
 *   two faces are in one fan when linked through edges incident to the
 *   vertex (any edge, also a non-manifold one). A vertex used by two
 *   groups therefore always counts (one fan per group at least).
 * - misoriented edge: a DIRECTED edge used by two or more faces; an edge
 *   used twice in each direction counts twice.
 * - chi = V - E + F per group, V = indices referenced by the group's faces.
 * - orientable: faces can be flipped to agree on every 2-face edge.
 * - genus = (2 - chi - b) / 2 when the group is manifold (no non-manifold
 *   edge or vertex) and orientable; -1 ("undefined") otherwise.
 * Invalid faces (index out of range or repeated, see mesh/edges.h) count in
 * F of their group but add no edges, corners or vertices.
 */
#ifndef SCAF_MESH_COMPLEX_H
#define SCAF_MESH_COMPLEX_H

#include "base/error.h"
#include "mesh/edges.h"

typedef struct tri_complex {
    int n;            /* size of the index space */
    int nf;           /* number of faces */
    mesh_edges edges; /* edge table of F (see mesh/edges.h) */

    /* ---- groups ---- */
    int ngroups;
    int *face_group;       /* #F group of each face (copy of the input) */
    int *group_face_start; /* ngroups+1: faces of group g are            */
    int *group_faces;      /*   group_faces[start[g] .. start[g+1]-1], ascending */

    /* ---- per group, each ngroups long ---- */
    int *group_vertices; /* referenced indices */
    int *group_edges;
    int *group_loops; /* boundary loops */
    int *group_euler; /* V - E + F */
    int *group_nm_edges;
    int *group_nm_vertices;
    int *group_misoriented;
    int *group_orientable; /* 1 / 0 */
    int *group_genus;      /* -1 when undefined */
    int *group_bad_edge;   /* first non-manifold edge of the group or -1 */
    int *group_bad_vertex; /* first non-manifold vertex or -1 */
    int *group_bad_orient; /* first misoriented edge or -1 */

    /* ---- totals over all groups ---- */
    int referenced; /* indices used by at least one valid face */
    int boundary_edges;
    int nm_edges, nm_vertices, misoriented;

    /* ---- boundary loops ---- */
    int nloops;
    int *loop_group;   /* #loops group of each loop */
    int *loop_ordered; /* #loops 1 if the loop is a simple cycle */
    int *loop_start;   /* #loops+1: half-edges of loop l are             */
    int *loop_he;      /*   loop_he[loop_start[l] .. loop_start[l+1]-1]  */
    /* For an ordered loop the half-edges are in traversal order: each one
     * ends where the next starts, the faces lie on their left, and the loop
     * starts at its smallest half-edge id. Otherwise they are ascending.
     * Vertex i of an ordered loop is F[loop_he[loop_start[l] + i]]. */
} tri_complex;

/* Analyze F (#F by 3 indices into 0..n-1) with face_group (#F labels in
 * 0..ngroups-1; every group non-empty; faces sharing an edge must be in
 * one group, as connected components and UV charts are: an edge is counted
 * in the group of its first face). On failure (out of memory, bad
 * label) returns the status and leaves *c empty. */
scaf_status tri_complex_build(int n, int nf, const int *F, int ngroups, const int *face_group,
                              tri_complex *c, scaf_error *err);

/* Free and reset to empty. Safe on an empty (zeroed) struct. */
void tri_complex_free(tri_complex *c);

/* Label faces by connected component, faces linked through shared indices
 * (valid or not). face_comp: #F output; components are numbered in order
 * of their first face. Returns the number of components, or -1 when out
 * of memory (err set). */
int tri_components(int n, int nf, const int *F, int *face_comp, scaf_error *err);

#endif /* SCAF_MESH_COMPLEX_H */
