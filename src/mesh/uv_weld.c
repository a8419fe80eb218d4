/* mesh/uv_weld: see uv_weld.h. Sorting the corners by (vertex, u bits,
 * v bits) puts equal points next to each other; O(c log c) for c corners. */
#include "mesh/uv_weld.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct corner_key {
    int vertex;
    uint64_t u, v; /* the bits of the coordinates: -0 and 0 stay apart, as written */
    int corner;
} corner_key;

static int key_cmp(const void *pa, const void *pb)
{
    const corner_key *a = pa, *b = pb;
    if (a->vertex != b->vertex) return a->vertex < b->vertex ? -1 : 1;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    if (a->v != b->v) return a->v < b->v ? -1 : 1;
    return (a->corner > b->corner) - (a->corner < b->corner);
}

scaf_status uv_weld_corners(mesh *m, scaf_error *err)
{
    if (!mesh_has_uv(m) || m->nf == 0) return SCAF_OK;
    size_t nc = 3 * (size_t)m->nf;
    corner_key *k = malloc(nc * sizeof *k);
    int *first = malloc(nc * sizeof *first); /* per sorted group: its smallest corner */
    double *uv = malloc(nc * 2 * sizeof *uv);
    if (!k || !first || !uv) {
        free(k);
        free(first);
        free(uv);
        return err_nomem(err, "joining per-corner UVs");
    }
    for (size_t c = 0; c < nc; c++) {
        const double *t = m->UV + 2 * (size_t)m->FT[c];
        k[c].vertex = m->F[c];
        memcpy(&k[c].u, &t[0], sizeof(double));
        memcpy(&k[c].v, &t[1], sizeof(double));
        k[c].corner = (int)c;
    }
    qsort(k, nc, sizeof *k, key_cmp);
    /* each corner marked with its group's first corner; the first corners
     * numbered in corner order */
    int *group_first = first;
    for (size_t i = 0; i < nc;) {
        size_t j = i;
        while (j < nc && k[j].vertex == k[i].vertex && k[j].u == k[i].u && k[j].v == k[i].v) j++;
        for (size_t q = i; q < j; q++) group_first[k[q].corner] = k[i].corner;
        i = j;
    }
    int n = 0;
    int *ft = m->FT;
    for (size_t c = 0; c < nc; c++) {
        if ((size_t)group_first[c] == c) {
            const double *t = m->UV + 2 * (size_t)ft[c];
            uv[2 * (size_t)n] = t[0];
            uv[2 * (size_t)n + 1] = t[1];
            group_first[c] = -1 - n; /* the group's new index, told apart from corners */
            n++;
        }
    }
    for (size_t c = 0; c < nc; c++) {
        int g = group_first[c];
        ft[c] = g < 0 ? -1 - g : -1 - group_first[g];
    }
    double *shrunk = realloc(uv, (size_t)(n ? n : 1) * 2 * sizeof *uv);
    free(m->UV);
    m->UV = shrunk ? shrunk : uv;
    m->nuv = n;
    free(k);
    free(first);
    return SCAF_OK;
}
