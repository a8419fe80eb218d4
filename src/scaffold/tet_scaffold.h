/* scaffold/tet_scaffold: the 3D scaffold as a tet mesh that local
 * operations can change (scaffold/tet_improve).
 *
 * The scaffold fills a fixed box around a closed triangle surface, inside
 * and outside it, with positively oriented tetrahedra. Its vertices:
 *   0 .. nmesh-1    the mesh's vertices (the surface): their positions are
 *                   the caller's (tet_improve copies them in), never moved,
 *                   never removed;
 *   nmesh .. nv-1   scaffold-only vertices: the box's (fixed[v] = 1, never
 *                   moved or removed) and the free ones (TetGen's interior
 *                   points, later ones added by edge splits), which
 *                   tet_improve may move, add and remove.
 * This matches scaffold/scaffold_provider's numbering: scaffold-only vertex
 * i is id nmesh + i, its position P + 3 (nmesh + i), its fixed flag
 * fixed[nmesh + i]. Vertex numbering after tet_improve: new vertices are
 * appended, then removed ones are compacted away keeping the survivors in
 * order; vertex_map (nv_before entries) says old id -> new id, -1 for a
 * removed vertex. Mesh vertices keep their ids always. Tet ids are not
 * kept: new tets fill the slots of replaced ones, then the rest close up
 * (per-tet data of the caller does not survive a call).
 *
 * Every tet carries a region label (1 inside the surface, 0 outside) that
 * no operation changes: operations replace tets by tets of one region only.
 * Protected triangles (the surface) are faces that must stay faces,
 * unchanged; no operation removes a protected face or an edge or vertex of
 * one. Faces on the hull (the box) are never removed either.
 *
 * Between calls the arrays are dense (tets 0..nt-1 all live) and the
 * adjacency is consistent; the caller may read T, region, P, fixed and
 * write the positions of free scaffold-only vertices (e.g. the loop's
 * accepted step), provided every tet stays positively oriented.
 */
#ifndef SCAF_SCAFFOLD_TET_SCAFFOLD_H
#define SCAF_SCAFFOLD_TET_SCAFFOLD_H

#include "base/error.h"
#include "geom/tet_box_mesh.h"

typedef struct tet_scaffold {
    int nmesh;            /* vertices below nmesh are mesh vertices */
    int nv;               /* all vertices */
    double *P;            /* nv by 3 positions */
    unsigned char *fixed; /* nv: 1 = never moved or removed (box; mesh vertices
                             are treated as fixed whatever this says) */
    int nt;               /* tetrahedra */
    int *T;               /* nt by 4 vertex ids, positively oriented:
                             det[b - a, c - a, d - a] > 0 */
    signed char *region;  /* nt: 1 inside the surface, 0 outside */

    /* The last tet_improve's renumbering of vertices: nv_before entries,
     * id during the call (the ids before it, then the appended vertices)
     * -> id after it, or -1 (removed). The identity after init. */
    int nv_before;
    int *vertex_map;

    /* Internal (scaffold/tet_ops, scaffold/tet_improve): adjacency and
     * bookkeeping, consistent between calls. Face f of a tet is the one
     * opposite its corner f, its corners tet_face_corner[f] in order seen
     * from outside. */
    int *nbr;               /* 4 nt: 4 t' + f' of the tet across face f of t
                               (t' holds the same face as its face f'), -1
                               on the hull */
    unsigned char *protect; /* nt: bit f set = face f of t is protected */
    int *vtet;              /* nv: one live tet holding the vertex; -1 none,
                               -2 removed (only inside tet_improve) */
    unsigned char *dead;    /* nt: 1 = a free slot (only inside tet_improve) */
    int *free_slots, nfree; /* dead slots, reused last freed first */
    double *q;              /* nt: quality cache (inside tet_improve) */
    int *mark, mark_now;    /* nt: visit stamps of the local searches */
    int cap_v, cap_t;       /* allocated entries */
} tet_scaffold;

/* Build the scaffold from a tet mesh, checking it exactly.
 *   nmesh       vertices 0..nmesh-1 are the mesh's
 *   nv, V       #V by 3 positions of all vertices (copied)
 *   fixed       #V flags, 1 = fixed scaffold-only vertex; NULL: none fixed
 *   nt, T       #T by 4 vertex ids, every tet positively oriented (exact)
 *   region      #T labels (1 inside, 0 outside)
 *   nprot, prot #prot by 3 protected triangles (vertex ids, any order of
 *               corners): each must be a face of the mesh
 * The mesh must be conforming: every face is shared by at most two tets,
 * seen from opposite sides.
 * Errors: SCAF_ERR_USAGE (counts, ids), SCAF_ERR_MESH (a tet not
 * positive, a face with three tets or seen twice from one side, a
 * protected triangle that is no face: the message names it),
 * SCAF_ERR_NOMEM. On failure s is empty (free is still safe). */
scaf_status tet_scaffold_init(tet_scaffold *s, int nmesh, int nv, const double *V,
                              const unsigned char *fixed, int nt, const int *T,
                              const signed char *region, int nprot, const int *prot,
                              scaf_error *err);

/* The same from geom/tet_box_mesh's output: mesh vertices are the surface's
 * (nmesh = m->nsurface), the box vertices fixed, region = m->inside, the
 * surface triangles nf, F (#F by 3, the ones m was built from) protected. */
scaf_status tet_scaffold_from_box_mesh(tet_scaffold *s, const tet_box_mesh *m, int nf, const int *F,
                                       scaf_error *err);

void tet_scaffold_free(tet_scaffold *s);

/* ---- internal editing (scaffold/tet_ops, scaffold/tet_improve) ---- */

/* Corners of face f (opposite corner f) of a positive tet, in the order
 * that makes the face's normal point out of the tet. */
extern const int tet_face_corner[4][3];

/* Room for `tets` more tets and `vertices` more vertices, so the edits
 * that follow cannot fail on memory. */
scaf_status tet_scaffold_reserve(tet_scaffold *s, int tets, int vertices, scaf_error *err);

/* Append a free scaffold-only vertex at p (room reserved); its id. */
int tet_scaffold_add_vertex(tet_scaffold *s, const double p[3]);

/* Replace the nold live tets old[] (one region, a cavity whose boundary
 * faces are exactly those of the nnew tets newT[] (4 nnew ids, positive)
 * not shared among them) by the new tets: adjacency, protected flags of
 * the boundary faces and vertex->tet links follow; the new tets get the
 * region of old[0] and their ids go to ids[] (may be NULL). Room for nnew
 * tets must be reserved. SCAF_ERR_INTERNAL when the faces do not match
 * (nothing changed then). */
scaf_status tet_scaffold_replace(tet_scaffold *s, int nold, const int *old, int nnew,
                                 const int *newT, int *ids, scaf_error *err);

/* Mark vertex v removed (it must be in no live tet any more). */
void tet_scaffold_remove_vertex(tet_scaffold *s, int v);

/* Drop dead tets and removed vertices, renumbering as the header says
 * (vertex_map); dense again. Allocates nothing, cannot fail. */
void tet_scaffold_compact(tet_scaffold *s);

#endif /* SCAF_SCAFFOLD_TET_SCAFFOLD_H */
