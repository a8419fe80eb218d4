/* mesh/mesh_builder: growable arrays the readers fill, then hand over as a mesh.
 *
 * Internal to src/mesh. Positions, UVs and triangles are appended one at a
 * time (amortized doubling); `mesh_builder_finish` moves the arrays into a
 * `mesh` without copying. Counts are kept below INT_MAX so they fit the
 * mesh's int fields; exceeding that, or running out of memory, is reported
 * by the append functions returning non-zero (the reader names the line).
 */
#ifndef SCAF_MESH_MESH_BUILDER_H
#define SCAF_MESH_MESH_BUILDER_H

#include <stddef.h>

#include "base/error.h"
#include "mesh/mesh.h"

typedef struct mesh_builder {
    double *V; /* nv by 3 */
    size_t nv, cap_v;
    double *UV; /* nuv by 2 */
    size_t nuv, cap_uv;
    int *F;  /* nf by 3 */
    int *FT; /* nf by 3, only when with_ft; -1 marks a corner without vt */
    size_t nf, cap_f;
    int with_ft;
} mesh_builder;

/* Empty builder; with_ft says whether triangles carry UV indices (OBJ). */
void mesh_builder_init(mesh_builder *b, int with_ft);
void mesh_builder_free(mesh_builder *b);

/* Reserve room for at least nv vertices / nf triangles (a hint; 0 on success). */
int mesh_builder_reserve(mesh_builder *b, size_t nv, size_t nf);

/* Append; return 0 on success, -1 when out of memory or over INT_MAX items. */
int mesh_builder_grow_v(mesh_builder *b);
int mesh_builder_grow_uv(mesh_builder *b);
int mesh_builder_grow_f(mesh_builder *b);

static inline int mesh_builder_add_v(mesh_builder *b, double x, double y, double z)
{
    if (b->nv == b->cap_v && mesh_builder_grow_v(b)) return -1;
    double *v = b->V + 3 * b->nv++;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return 0;
}

static inline int mesh_builder_add_uv(mesh_builder *b, double u, double v)
{
    if (b->nuv == b->cap_uv && mesh_builder_grow_uv(b)) return -1;
    double *t = b->UV + 2 * b->nuv++;
    t[0] = u;
    t[1] = v;
    return 0;
}

/* ta..tc are ignored unless with_ft. */
static inline int mesh_builder_add_f(mesh_builder *b, int a, int bb, int c, int ta, int tb, int tc)
{
    if (b->nf == b->cap_f && mesh_builder_grow_f(b)) return -1;
    int *f = b->F + 3 * b->nf;
    f[0] = a;
    f[1] = bb;
    f[2] = c;
    if (b->with_ft) {
        int *t = b->FT + 3 * b->nf;
        t[0] = ta;
        t[1] = tb;
        t[2] = tc;
    }
    b->nf++;
    return 0;
}

/* Move the arrays into *m (shrunk to size). keep_uv: keep UV and FT (needs
 * with_ft, nuv > 0); otherwise the mesh has no UVs. The builder is left
 * empty. Returns SCAF_ERR_NOMEM only if an allocation for an empty array fails. */
scaf_status mesh_builder_finish(mesh_builder *b, int keep_uv, mesh *m, scaf_error *err);

#endif /* SCAF_MESH_MESH_BUILDER_H */
