/* geom/tetgen_call: the C face of TetGen (tetgen_call.cpp, one of the
 * project's two C++ files; src/mesh/gltf_io.cpp is the other), a
 * constrained tetrahedralization of triangle facets.
 *
 * TetGen 1.5 (Debian libtet1.5-dev, Hang Si, AGPL-3.0-or-later; linked
 * into a GPL-3.0-or-later program, which GPLv3 section 13 allows) meshes
 * the volume bounded by the given triangles with the switches
 *   p  the input is a piecewise linear complex (the triangles are facets)
 *   Y  no Steiner point on any input facet: every input triangle stays a
 *      face of the mesh, unsplit
 *   M  no merging of coplanar facets or close vertices (a merged facet
 *      could be re-triangulated, changing the input triangles)
 *   A  region attributes: tets get the attribute of the region seed whose
 *      region (bounded by facets) holds them, 0 elsewhere
 *   z  zero-based indices;  Q  quiet (nothing printed)
 * The input points come back first, at the same indices and bit for bit;
 * points TetGen adds (inside the volume) follow.
 *
 * TetGen reports failure by `throw int`; it is caught here, as is
 * std::bad_alloc, and turned into a status with a message naming the
 * reason (TetGen's codes: 1 out of memory, 2 internal error, 3 facets
 * intersect, 4 an input feature too small for its tolerance, 5 two input
 * facets too close, 10 invalid input). Nothing is thrown to the caller.
 *
 * This is the raw call; geom/tet_box_mesh validates the input and checks
 * the output exactly.
 */
#ifndef SCAF_GEOM_TETGEN_CALL_H
#define SCAF_GEOM_TETGEN_CALL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "base/error.h"

/* What TetGen produced; arrays allocated with malloc (free with
 * tetgen_result_free). */
typedef struct tetgen_result {
    int np;            /* points: the input ones first */
    double *P;         /* #P by 3 */
    int nt;            /* tetrahedra */
    int *T;            /* #T by 4 point indices, in TetGen's vertex order */
    double *attribute; /* #T region attributes (0 outside every seeded region) */
} tetgen_result;

/* Tetrahedralize.
 *   np, P        #P by 3 input points
 *   ntri, tri    #tri by 3 point indices: the facets (closed surfaces)
 *   nseed, seed  #seed by 4: a point (x, y, z) inside a region and the
 *                attribute its tets get (a nonzero number)
 *   out          the mesh, emptied on failure
 * Errors: SCAF_ERR_MESH when TetGen refuses the input (the message says
 * why), SCAF_ERR_NOMEM, SCAF_ERR_INTERNAL for TetGen's internal errors. */
scaf_status tetgen_call(int np, const double *P, int ntri, const int *tri, int nseed,
                        const double *seed, tetgen_result *out, scaf_error *err);

void tetgen_result_free(tetgen_result *r);

#ifdef __cplusplus
}
#endif

#endif /* SCAF_GEOM_TETGEN_CALL_H */
