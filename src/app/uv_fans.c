/* app/uv_fans: one UV index per fan (see uv_fans.h).
 *
 * Union-find over face corners: the faces on one UV edge (a run of
 * base/half_edges) join the corners of each endpoint; then every class of
 * corners gets an index, the first class of a UV index (in corner order)
 * keeping it. A side with both ends at one UV index joins nothing.
 */
#include "app/uv_fans.h"

#include <assert.h>
#include <stdlib.h>

#include "base/half_edges.h"
#include "base/union_find.h"

/* The corner of half-edge h holding its smaller (lo) or larger end. */
static int corner_lo(const int *FT, int h)
{
    int g = half_edge_next(h);
    return FT[h] < FT[g] ? h : g;
}
static int corner_hi(const int *FT, int h)
{
    int g = half_edge_next(h);
    return FT[h] < FT[g] ? g : h;
}

scaf_status uv_split_fans(int nf, const int *FT, int nuv, int *FT_out, int *nuv_out, int **orig,
                          scaf_error *err)
{
    size_t nc = 3 * (size_t)(nf > 0 ? nf : 0);
    int *parent = malloc(sizeof(int) * (nc ? nc : 1));
    int *order = malloc(sizeof(int) * (nc ? nc : 1));
    int *assigned = malloc(sizeof(int) * (nc ? nc : 1));
    unsigned char *claimed = calloc((size_t)(nuv > 0 ? nuv : 1), 1);
    int *from = malloc(sizeof(int) * ((size_t)nuv + nc + 1));
    int nhe = 0;
    scaf_status st = parent && order && assigned && claimed && from
        ? half_edges_sort(nuv, (int)(nc / 3), FT, NULL, order, &nhe, err)
        : SCAF_ERR_NOMEM;
    if (st != SCAF_OK) {
        free(parent);
        free(order);
        free(assigned);
        free(claimed);
        free(from);
        return err_nomem(err, "UV fans");
    }
    uf_init(parent, (int)nc);
    for (size_t c = 0; c < nc; c++) assigned[c] = -1;
    for (int i = 0; i < nhe;) {
        int j = i + 1;
        while (j < nhe && half_edges_same_edge(FT, order[j], order[i])) j++;
        if (half_edge_lo(FT, order[i]) != half_edge_hi(FT, order[i]))
            for (int k = i + 1; k < j; k++) {
                uf_union(parent, corner_lo(FT, order[i]), corner_lo(FT, order[k]));
                uf_union(parent, corner_hi(FT, order[i]), corner_hi(FT, order[k]));
            }
        i = j;
    }
    int n = nuv;
    for (int v = 0; v < nuv; v++) from[v] = v;
    for (size_t c = 0; c < nc; c++) {
        int r = uf_find(parent, (int)c);
        if (assigned[r] < 0) {
            int vt = FT[c];
            if (!claimed[vt]) {
                claimed[vt] = 1;
                assigned[r] = vt;
            } else {
                from[n] = vt;
                assigned[r] = n++;
            }
        }
        FT_out[c] = assigned[r];
        assert(FT_out[c] >= 0 && FT_out[c] < n && from[FT_out[c]] == FT[c]);
    }
    *nuv_out = n;
    free(parent);
    free(order);
    free(assigned);
    free(claimed);
    if (orig) *orig = from;
    else free(from);
    return SCAF_OK;
}
