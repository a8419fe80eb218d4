/* app/uv_fans: one UV index per fan (see uv_fans.h).
 *
 * Union-find over face corners: the two faces of a UV edge join the
 * corners of each endpoint; then every class of corners gets an index,
 * the first class of a UV index (in corner order) keeping it.
 */
#include "app/uv_fans.h"

#include <stdlib.h>
#include <string.h>

typedef struct uv_edge {
    int lo, hi;       /* UV indices, lo < hi (lo == hi for invalid faces) */
    int c_lo, c_hi;   /* corners holding lo and hi */
} uv_edge;

static int cmp_edge(const void *a, const void *b)
{
    const uv_edge *x = a, *y = b;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
    return (x->c_lo > y->c_lo) - (x->c_lo < y->c_lo);
}

static int find(int *p, int x)
{
    while (p[x] != x) {
        p[x] = p[p[x]];
        x = p[x];
    }
    return x;
}

static void unite(int *p, int a, int b)
{
    a = find(p, a);
    b = find(p, b);
    if (a != b) p[a < b ? b : a] = a < b ? a : b;
}

scaf_status uv_split_fans(int nf, const int *FT, int nuv, int *FT_out, int *nuv_out, int **orig,
                          scaf_error *err)
{
    size_t nc = 3 * (size_t)(nf > 0 ? nf : 0);
    int *parent = malloc(sizeof(int) * (nc ? nc : 1));
    uv_edge *E = malloc(sizeof(uv_edge) * (nc ? nc : 1));
    int *assigned = malloc(sizeof(int) * (nc ? nc : 1));
    unsigned char *claimed = calloc((size_t)(nuv > 0 ? nuv : 1), 1);
    int *from = malloc(sizeof(int) * ((size_t)nuv + nc + 1));
    if (!parent || !E || !assigned || !claimed || !from) {
        free(parent);
        free(E);
        free(assigned);
        free(claimed);
        free(from);
        return err_nomem(err, "UV fans");
    }
    for (size_t c = 0; c < nc; c++) {
        parent[c] = (int)c;
        assigned[c] = -1;
    }
    for (size_t f = 0; f < (size_t)nf; f++)
        for (int k = 0; k < 3; k++) {
            size_t ca = 3 * f + k, cb = 3 * f + (k + 1) % 3;
            uv_edge *e = &E[3 * f + k];
            int a = FT[ca], b = FT[cb];
            e->lo = a < b ? a : b;
            e->hi = a < b ? b : a;
            e->c_lo = (int)(a < b ? ca : cb);
            e->c_hi = (int)(a < b ? cb : ca);
        }
    qsort(E, nc, sizeof *E, cmp_edge);
    for (size_t i = 0; i < nc;) {
        size_t j = i + 1;
        while (j < nc && E[j].lo == E[i].lo && E[j].hi == E[i].hi) j++;
        if (E[i].lo != E[i].hi)
            for (size_t k = i + 1; k < j; k++) {
                unite(parent, E[i].c_lo, E[k].c_lo);
                unite(parent, E[i].c_hi, E[k].c_hi);
            }
        i = j;
    }
    int n = nuv;
    for (int v = 0; v < nuv; v++) from[v] = v;
    for (size_t c = 0; c < nc; c++) {
        int r = find(parent, (int)c);
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
    }
    *nuv_out = n;
    free(parent);
    free(E);
    free(assigned);
    free(claimed);
    if (orig) *orig = from;
    else free(from);
    return SCAF_OK;
}
