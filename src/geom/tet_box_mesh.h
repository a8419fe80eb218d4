/* geom/tet_box_mesh: the initial 3D scaffold, a closed surface inside a
 * box, tetrahedralized by TetGen (geom/tetgen_call) and checked exactly.
 *
 * The box is given by its corners and made of facets: each of its six
 * sides an n x n grid of squares cut into two triangles (the authors of
 * SCAF use 8 x 8). TetGen meshes the box with the surface as a constraint
 * and no Steiner point on the surface or the box. Before TetGen the input
 * is refused with a message naming the reason when it cannot be meshed:
 * an index out of range or a coordinate not finite, a vertex not strictly
 * inside the box, an open surface (an edge with one face), a non-manifold
 * edge (more than two faces), a zero-area face or two faces intersecting
 * (geom/self_intersect, exact). After TetGen, every claim is checked
 * exactly, or the call fails with SCAF_ERR_INTERNAL:
 *   - the surface and box vertices are unchanged, at their indices;
 *   - every tet is positively oriented (geom/tet_orient: orient3d);
 *   - every input triangle is a face of exactly two tets, one inside the
 *     surface and one outside; every box triangle a face of one tet; no
 *     other face lies on the hull and no face has three or more tets;
 *   - inside/outside labels: a walk over the tets from the box (outside)
 *     flips the label at every surface triangle and must never meet a
 *     contradiction, so nested shells are labelled right (the cavity of a
 *     hollow ball is outside); TetGen's region attribute, seeded between
 *     the box and the surface's bounding box, must agree on its region.
 */
#ifndef SCAF_GEOM_TET_BOX_MESH_H
#define SCAF_GEOM_TET_BOX_MESH_H

#include "base/error.h"

typedef struct tet_box_mesh {
    int nv;    /* vertices: the surface's nsurface first, then
                              the box's nbox, then points TetGen added */
    double *V; /* #V by 3 */
    int nsurface, nbox;
    int nt;              /* tetrahedra */
    int *T;              /* #T by 4 vertex indices, positively oriented:
                              det[b - a, c - a, d - a] > 0 */
    signed char *inside; /* #T: 1 inside the surface, 0 between it and the box */
    int ninside;         /* tets with inside == 1 */
    int nbox_faces;      /* triangles of the box (12 n^2) */
    int *box_F;          /* #box_faces by 3, outward, indices into V */
} tet_box_mesh;

/* A box around the surface: its bounding box scaled by `scale` (> 1)
 * about its centre, each side at least (scale - 1) times the largest
 * extent away so a flat surface still gets a box. */
void tet_box_around(int nv, const double *V, double scale, double lo[3], double hi[3]);

/* Tetrahedralize the box lo..hi around the closed surface.
 *   nv, V       #V by 3 surface vertex positions
 *   nf, F       #F by 3 surface triangles (orientation does not matter)
 *   lo, hi      box corners; every vertex strictly inside
 *   box_cells   n, squares per box side edge, 1..64
 *   out         the mesh (free with tet_box_mesh_free); empty on failure
 * Errors: SCAF_ERR_USAGE (bad arguments, box), SCAF_ERR_MESH (the surface
 * cannot be meshed: the message names the face, edge or vertex),
 * SCAF_ERR_NOMEM, SCAF_ERR_INTERNAL (TetGen's output failed a check). */
scaf_status tet_box_mesh_build(int nv, const double *V, int nf, const int *F, const double lo[3],
                               const double hi[3], int box_cells, tet_box_mesh *out,
                               scaf_error *err);

void tet_box_mesh_free(tet_box_mesh *m);

#endif /* SCAF_GEOM_TET_BOX_MESH_H */
