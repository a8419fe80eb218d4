/* mesh/mesh_builder: growable mesh arrays for the readers (see mesh_builder.h).
 *
 * Capacity doubles on every growth, so appending n items costs O(n). A
 * failed realloc leaves the old arrays intact (freed by mesh_builder_free).
 */
#include "mesh/mesh_builder.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define BUILDER_MAX_ITEMS ((size_t)INT_MAX - 1)

void mesh_builder_init(mesh_builder *b, int with_ft)
{
    memset(b, 0, sizeof *b);
    b->with_ft = with_ft;
}

void mesh_builder_free(mesh_builder *b)
{
    free(b->V);
    free(b->UV);
    free(b->F);
    free(b->FT);
    int with_ft = b->with_ft;
    mesh_builder_init(b, with_ft);
}

/* Grow *arr (items of `width` doubles/ints of `elem` bytes) to at least `want` items. */
static int grow_to(void **arr, size_t *cap, size_t want, size_t width, size_t elem)
{
    if (want <= *cap) return 0;
    if (want > BUILDER_MAX_ITEMS) return -1;
    size_t n = *cap ? *cap : 1024;
    while (n < want) n = n > BUILDER_MAX_ITEMS / 2 ? BUILDER_MAX_ITEMS : n * 2;
    void *p = realloc(*arr, n * width * elem);
    if (!p) return -1;
    *arr = p;
    *cap = n;
    return 0;
}

int mesh_builder_reserve(mesh_builder *b, size_t nv, size_t nf)
{
    if (grow_to((void **)&b->V, &b->cap_v, nv, 3, sizeof(double))) return -1;
    size_t cap = b->cap_f;
    if (grow_to((void **)&b->F, &cap, nf, 3, sizeof(int))) return -1;
    if (b->with_ft) {
        size_t cap_t = b->cap_f;
        if (grow_to((void **)&b->FT, &cap_t, nf, 3, sizeof(int))) return -1;
    }
    b->cap_f = cap;
    return 0;
}

int mesh_builder_grow_v(mesh_builder *b)
{
    return grow_to((void **)&b->V, &b->cap_v, b->nv + 1, 3, sizeof(double));
}

int mesh_builder_grow_uv(mesh_builder *b)
{
    return grow_to((void **)&b->UV, &b->cap_uv, b->nuv + 1, 2, sizeof(double));
}

int mesh_builder_grow_f(mesh_builder *b)
{
    size_t cap = b->cap_f;
    if (grow_to((void **)&b->F, &cap, b->nf + 1, 3, sizeof(int))) return -1;
    if (b->with_ft) {
        size_t cap_t = b->cap_f;
        if (grow_to((void **)&b->FT, &cap_t, b->nf + 1, 3, sizeof(int))) return -1;
    }
    b->cap_f = cap;
    return 0;
}

/* Shrink an array to n items (at least one, so the pointer is never NULL). */
static void *shrink(void *p, size_t n, size_t bytes_per_item)
{
    void *q = realloc(p, (n ? n : 1) * bytes_per_item);
    return q ? q : p;
}

scaf_status mesh_builder_finish(mesh_builder *b, int keep_uv, mesh *m, scaf_error *err)
{
    memset(m, 0, sizeof *m);
    keep_uv = keep_uv && b->with_ft && b->nuv > 0;
    if (!b->V) b->V = malloc(3 * sizeof(double));
    if (!b->F) b->F = malloc(3 * sizeof(int));
    if (!b->V || !b->F) {
        mesh_builder_free(b);
        return err_nomem(err, "mesh arrays");
    }
    m->nv = (int)b->nv;
    m->V = shrink(b->V, b->nv, 3 * sizeof(double));
    m->nf = (int)b->nf;
    m->F = shrink(b->F, b->nf, 3 * sizeof(int));
    if (keep_uv) {
        m->nuv = (int)b->nuv;
        m->UV = shrink(b->UV, b->nuv, 2 * sizeof(double));
        m->FT = shrink(b->FT, b->nf, 3 * sizeof(int));
    } else {
        free(b->UV);
        free(b->FT);
    }
    int with_ft = b->with_ft;
    memset(b, 0, sizeof *b);
    b->with_ft = with_ft;
    return SCAF_OK;
}
