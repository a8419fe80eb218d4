/* mesh/edges: undirected edge table by bucket sort (see edges.h).
 *
 * Pass 1 counts half-edges per smaller endpoint, pass 2 drops a 64-bit key
 * (larger endpoint << 32 | half-edge id) into each bucket, pass 3 sorts each
 * bucket (insertion sort: buckets hold a vertex's valence, a handful) and
 * numbers the runs of equal endpoints. Fails only on allocation.
 */
#include "mesh/edges.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

static void sort_bucket(uint64_t *k, int n)
{
    if (n > 32) {
        qsort(k, (size_t)n, sizeof *k, cmp_u64);
        return;
    }
    for (int i = 1; i < n; i++) {
        uint64_t x = k[i];
        int j = i - 1;
        while (j >= 0 && k[j] > x) {
            k[j + 1] = k[j];
            j--;
        }
        k[j + 1] = x;
    }
}

void mesh_edges_free(mesh_edges *e)
{
    if (!e) return;
    free(e->ev);
    free(e->he_edge);
    free(e->edge_he_start);
    free(e->edge_he);
    memset(e, 0, sizeof *e);
}

scaf_status mesh_edges_build(int n, int nf, const int *F, mesh_edges *e, scaf_error *err)
{
    memset(e, 0, sizeof *e);
    if (n < 0 || nf < 0 || nf > INT_MAX / 3)
        return err_set(err, SCAF_ERR_MESH, "edge table: %d faces over %d indices is out of range", nf, n);
    size_t nh = 3 * (size_t)nf;
    int *start = calloc((size_t)n + 2, sizeof *start);
    uint64_t *keys = malloc((nh ? nh : 1) * sizeof *keys);
    e->he_edge = malloc((nh ? nh : 1) * sizeof *e->he_edge);
    e->edge_he = malloc((nh ? nh : 1) * sizeof *e->edge_he);
    if (!start || !keys || !e->he_edge || !e->edge_he) goto nomem;

    /* ---- count half-edges per smaller endpoint ---- */
    for (int f = 0; f < nf; f++) {
        if (!face_is_valid(F, f, n)) {
            e->invalid_faces++;
            continue;
        }
        for (int k = 0; k < 3; k++) {
            int a = F[3 * f + k], b = F[3 * f + (k + 1) % 3];
            start[(a < b ? a : b) + 1]++;
        }
    }
    for (int v = 0; v < n; v++) start[v + 1] += start[v];
    size_t nvalid = (size_t)start[n];

    /* ---- fill buckets ---- */
    int *fill = malloc(((size_t)n + 1) * sizeof *fill);
    if (!fill) goto nomem;
    memcpy(fill, start, ((size_t)n + 1) * sizeof *fill);
    for (int f = 0; f < nf; f++) {
        if (!face_is_valid(F, f, n)) {
            for (int k = 0; k < 3; k++) e->he_edge[3 * f + k] = -1;
            continue;
        }
        for (int k = 0; k < 3; k++) {
            int a = F[3 * f + k], b = F[3 * f + (k + 1) % 3];
            int lo = a < b ? a : b, hi = a < b ? b : a;
            keys[fill[lo]++] = ((uint64_t)(uint32_t)hi << 32) | (uint32_t)(3 * f + k);
        }
    }
    free(fill);

    /* ---- sort buckets, number edges ---- */
    int ne = 0;
    for (int v = 0; v < n; v++) {
        int s = start[v], t = start[v + 1];
        sort_bucket(keys + s, t - s);
        for (int i = s; i < t; i++)
            if (i == s || (keys[i] >> 32) != (keys[i - 1] >> 32)) ne++;
    }
    e->ev = malloc(2 * ((size_t)ne ? (size_t)ne : 1) * sizeof *e->ev);
    e->edge_he_start = malloc(((size_t)ne + 1) * sizeof *e->edge_he_start);
    if (!e->ev || !e->edge_he_start) goto nomem;
    int edge = -1;
    for (int v = 0; v < n; v++) {
        int s = start[v], t = start[v + 1];
        for (int i = s; i < t; i++) {
            if (i == s || (keys[i] >> 32) != (keys[i - 1] >> 32)) {
                edge++;
                e->ev[2 * edge] = v;
                e->ev[2 * edge + 1] = (int)(keys[i] >> 32);
                e->edge_he_start[edge] = i;
            }
            int h = (int)(uint32_t)keys[i];
            e->edge_he[i] = h;
            e->he_edge[h] = edge;
        }
    }
    e->edge_he_start[ne] = (int)nvalid;
    e->ne = ne;
    free(start);
    free(keys);
    return SCAF_OK;

nomem:
    free(start);
    free(keys);
    mesh_edges_free(e);
    return err_nomem(err, "edge table");
}
