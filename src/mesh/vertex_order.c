/* mesh/vertex_order: breadth-first vertex numbering (see vertex_order.h). */
#include "mesh/vertex_order.h"

#include <stdlib.h>

/* Breadth first from v over the vertices not marked with `stamp` in seen,
 * marking them; queue gets them in the order reached. start/list: the
 * cells of each vertex. Returns how many were reached. */
static int reach(int nc, const int *idx, const int *start, const int *list, int v, int stamp,
                 int *seen, int *queue)
{
    int head = 0, tail = 0;
    seen[v] = stamp;
    queue[tail++] = v;
    while (head < tail) {
        int u = queue[head++];
        for (int k = start[u]; k < start[u + 1]; k++) {
            const int *ix = idx + (size_t)list[k] * nc;
            for (int i = 0; i < nc; i++)
                if (seen[ix[i]] != stamp) {
                    seen[ix[i]] = stamp;
                    queue[tail++] = ix[i];
                }
        }
    }
    return tail;
}

scaf_status mesh_vertex_order_breadth_first(int nc, int n, const int *idx, int nv, int *rank,
                                            scaf_error *err)
{
    size_t ncorner = (size_t)n * nc;
    int *start = calloc((size_t)nv + 1, sizeof *start);
    int *list = malloc((ncorner ? ncorner : 1) * sizeof *list);
    int *seen = calloc((size_t)nv + 1, sizeof *seen);
    int *queue = malloc(((size_t)nv + 1) * sizeof *queue);
    if (!start || !list || !seen || !queue) {
        free(start);
        free(list);
        free(seen);
        free(queue);
        return err_nomem(err, "vertex order");
    }
    /* The cells of each vertex (a cell repeating a vertex is listed twice:
     * harmless). */
    for (size_t c = 0; c < ncorner; c++) start[idx[c] + 1]++;
    for (int v = 0; v < nv; v++) start[v + 1] += start[v];
    for (size_t c = 0; c < ncorner; c++) list[start[idx[c]]++] = (int)(c / (size_t)nc);
    for (int v = nv; v > 0; v--) start[v] = start[v - 1];
    start[0] = 0;

    /* Each part is reached twice: a probe from its smallest vertex, then
     * the numbering from the last vertex the probe reached; each pass marks
     * with a stamp of its own. */
    for (int v = 0; v < nv; v++) rank[v] = -1;
    int next = 0, stamp = 0;
    for (int v = 0; v < nv; v++) {
        if (rank[v] >= 0) continue;
        if (start[v] == start[v + 1]) { /* in no cell */
            rank[v] = next++;
            continue;
        }
        int far = queue[reach(nc, idx, start, list, v, ++stamp, seen, queue) - 1];
        int m = reach(nc, idx, start, list, far, ++stamp, seen, queue);
        for (int k = 0; k < m; k++) rank[queue[k]] = next++;
    }
    free(start);
    free(list);
    free(seen);
    free(queue);
    return SCAF_OK;
}
