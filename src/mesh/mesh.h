/* mesh/mesh: the triangle mesh every layer above works on.
 *
 * A mesh is 3D positions, triangles, and optionally UV coordinates with
 * their own per-corner indices (OBJ `f v/vt`), so UV seams survive a round
 * trip: two faces sharing a 3D edge may use different vt indices on it.
 */
#ifndef SCAF_MESH_MESH_H
#define SCAF_MESH_MESH_H

#include <stddef.h>

#include "base/error.h"

typedef struct mesh {
    int nv;     /* number of vertices */
    double *V;  /* #V by 3 positions */
    int nf;     /* number of triangles */
    int *F;     /* #F by 3 vertex indices, 0-based, counter-clockwise */
    int nuv;    /* number of UV coordinates; 0 when the mesh has none */
    double *UV; /* #UV by 2 texture coordinates, NULL when nuv == 0 */
    int *FT;    /* #F by 3 UV indices per corner, NULL when nuv == 0 */
} mesh;

/* Allocate arrays for nv vertices, nf faces and nuv UVs (FT allocated iff
 * nuv > 0). Contents are uninitialized. On failure returns SCAF_ERR_NOMEM
 * and leaves *m empty. */
scaf_status mesh_alloc(mesh *m, int nv, int nf, int nuv, scaf_error *err);

/* Free the arrays and reset to the empty mesh. Safe on an empty mesh. */
void mesh_free(mesh *m);

/* Whether the mesh carries UVs with per-corner indices. */
static inline int mesh_has_uv(const mesh *m) { return m->nuv > 0 && m->FT != NULL; }

#endif /* SCAF_MESH_MESH_H */
