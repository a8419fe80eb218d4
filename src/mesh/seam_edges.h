/* mesh/seam_edges: the seams of a UV topology, as 3D edges, and their
 * length.
 *
 * A seam edge is an edge of the 3D mesh with two faces whose UV indices
 * (FT) differ on it: the edges a texture is cut along. The length is
 * reported as the measure, total 3D seam length / sqrt(total 3D
 * area), so meshes of any size and unit compare (xatlas's automatic
 * charts: 9.8 on closed/bunny). Edges are listed once, as (smaller,
 * larger) vertex index, in increasing order; deterministic.
 *
 * Fails with SCAF_ERR_NOMEM only (or SCAF_ERR_USAGE on bad arguments).
 */
#ifndef SCAF_MESH_SEAM_EDGES_H
#define SCAF_MESH_SEAM_EDGES_H

#include "base/error.h"

typedef struct seam_edges {
    int n;             /* seam edges */
    int *ab;           /* n by 2 vertex indices, ab[2i] < ab[2i+1] */
    double length;     /* total 3D length */
    double area;       /* total 3D area of the mesh */
    double normalized; /* length / sqrt(area) (0 without area) */
} seam_edges;

/* input: nv, V (#V by 3), nf, F (#F by 3 over [0, nv)), FT (#F by 3 UV
 * indices, any non-negative ints). On failure *s is empty. */
scaf_status seam_edges_find(int nv, const double *V, int nf, const int *F, const int *FT,
                            seam_edges *s, scaf_error *err);

void seam_edges_free(seam_edges *s);

#endif /* SCAF_MESH_SEAM_EDGES_H */
