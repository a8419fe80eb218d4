/* opt/ordering_reuse: extend a fixed ordering of the chart to chart + scaffold.
 *
 * Keys: chart vertex v -> its rank in the chart ordering; scaffold vertices
 * in breadth-first layers from the chart get key = max key of their
 * neighbours placed in earlier layers plus a small offset, so they sort
 * just after that neighbour (and after the earlier layers). Vertices the search does
 * not reach (a scaffold part not touching the chart) come last. Sorting by
 * key gives the vertex order, expanded to interleaved scalar unknowns.
 */
#include "opt/ordering_reuse.h"

#include <math.h>
#include <stdlib.h>

typedef struct keyed { double key; int v; } keyed;

static int cmp_keyed(const void *pa, const void *pb)
{
    const keyed *a = pa, *b = pb;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    return (a->v > b->v) - (a->v < b->v);
}

scaf_status opt_ordering_extend(const opt_csc *A, int d, int nlead, const int *lead_perm,
                                int *perm, scaf_error *err)
{
    if (d < 1 || A->n % d != 0 || nlead < 0 || nlead * d > A->n)
        return err_set(err, SCAF_ERR_USAGE, "ordering extension: n=%d, d=%d, %d leading vertices",
                       A->n, d, nlead);
    int nv = A->n / d;
    /* Symmetric vertex adjacency from the upper scalar pattern (last column
     * of each vertex holds all its row groups). */
    int *deg = calloc((size_t)nv + 1, sizeof *deg);
    double *key = malloc((size_t)nv * sizeof *key);
    keyed *ks = malloc((size_t)nv * sizeof *ks);
    int *queue = malloc((size_t)nv * sizeof *queue);
    if (!deg || !key || !ks || !queue) {
        free(deg); free(key); free(ks); free(queue);
        return err_nomem(err, "ordering extension");
    }
    for (int J = 0; J < nv; J++) {
        int col = J * d + d - 1, prev = -1;
        for (int k = A->colptr[col]; k < A->colptr[col + 1]; k++) {
            int I = A->rowidx[k] / d;
            if (I != prev && I != J) { deg[I + 1]++; deg[J + 1]++; }
            prev = I;
        }
    }
    for (int v = 0; v < nv; v++) deg[v + 1] += deg[v];
    int *adj = malloc(((size_t)deg[nv] + 1) * sizeof *adj);
    int *pos = malloc(((size_t)nv + 1) * sizeof *pos);
    if (!adj || !pos) {
        free(deg); free(key); free(ks); free(queue); free(adj); free(pos);
        return err_nomem(err, "ordering extension");
    }
    for (int v = 0; v < nv; v++) pos[v] = deg[v];
    for (int J = 0; J < nv; J++) {
        int col = J * d + d - 1, prev = -1;
        for (int k = A->colptr[col]; k < A->colptr[col + 1]; k++) {
            int I = A->rowidx[k] / d;
            if (I != prev && I != J) { adj[pos[I]++] = J; adj[pos[J]++] = I; }
            prev = I;
        }
    }
    /* Chart ranks from the order lead_perm visits the chart's vertices. */
    for (int v = 0; v < nv; v++) key[v] = NAN;
    int rank = 0;
    for (int k = 0; k < nlead * d; k++) {
        int v = lead_perm[k] / d;
        if (v >= 0 && v < nlead && isnan(key[v])) key[v] = rank++;
    }
    for (int v = 0; v < nlead; v++)
        if (isnan(key[v])) key[v] = rank++; /* a chart vertex lead_perm missed */
    /* Breadth-first layers into the scaffold. */
    int head = 0, tail = 0, layer_start = 0;
    double eps = 1.0 / (4.0 * (nv + 1));
    for (int v = nlead; v < nv; v++) {
        for (int k = deg[v]; k < deg[v + 1]; k++)
            if (adj[k] < nlead) { queue[tail++] = v; break; }
    }
    while (head < tail) {
        int layer_end = tail;
        /* Keys of this layer from neighbours placed before it. */
        for (int q = layer_start; q < layer_end; q++) {
            int v = queue[q];
            double best = -1;
            for (int k = deg[v]; k < deg[v + 1]; k++) {
                int u = adj[k];
                if (!isnan(key[u]) && key[u] > best) best = key[u];
            }
            ks[q].key = best; /* stash; assign after the whole layer */
        }
        /* Just after that neighbour; eps * layers stays below 1/4, so a
         * key never passes the next chart rank. */
        for (int q = layer_start; q < layer_end; q++) key[queue[q]] = ks[q].key + eps;
        /* Next layer: unplaced neighbours, each once. */
        for (int q = layer_start; q < layer_end; q++) {
            int v = queue[q];
            for (int k = deg[v]; k < deg[v + 1]; k++) {
                int u = adj[k];
                if (isnan(key[u])) {
                    key[u] = INFINITY; /* mark as queued */
                    queue[tail++] = u;
                }
            }
        }
        for (int q = layer_end; q < tail; q++) key[queue[q]] = NAN;
        head = layer_end;
        layer_start = layer_end;
    }
    for (int v = 0; v < nv; v++) {
        ks[v].key = isnan(key[v]) ? INFINITY : key[v];
        ks[v].v = v;
    }
    qsort(ks, (size_t)nv, sizeof *ks, cmp_keyed);
    for (int k = 0; k < nv; k++)
        for (int a = 0; a < d; a++) perm[k * d + a] = ks[k].v * d + a;
    free(deg); free(key); free(ks); free(queue); free(adj); free(pos);
    return SCAF_OK;
}
