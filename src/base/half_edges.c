/* base/half_edges: see half_edges.h.
 *
 * Pass 1 counts half-edges per smaller end, pass 2 drops a 64-bit key
 * (larger end << 32 | half-edge id) into each bucket, pass 3 sorts each
 * bucket and writes the ids out. */
#include "base/half_edges.h"

#include <assert.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort_u64.h"

int half_edges_index_count(int nf, const int *F)
{
    int n = 0;
    for (size_t i = 0; i < 3 * (size_t)(nf > 0 ? nf : 0); i++)
        if (F[i] >= n) n = F[i] + 1;
    return n;
}

scaf_status half_edges_sort(int n, int nf, const int *F, const unsigned char *skip, int *order,
                            int *count, scaf_error *err)
{
    *count = 0;
    if (n < 0 || nf < 0 || nf > INT_MAX / 3)
        return err_set(err, SCAF_ERR_USAGE, "half-edges: %d faces over %d indices is out of range",
                       nf, n);
    size_t nh = 3 * (size_t)nf;
    int *start = calloc((size_t)n + 2, sizeof *start);
    uint64_t *keys = malloc((nh ? nh : 1) * sizeof *keys);
    if (!start || !keys) {
        free(start);
        free(keys);
        return err_nomem(err, "half-edge order");
    }
    for (size_t h = 0; h < nh; h++) {
        if (skip && skip[h / 3]) continue;
        assert(F[h] >= 0 && F[h] < n);
        start[half_edge_lo(F, (int)h) + 1]++;
    }
    for (int v = 0; v < n; v++) start[v + 1] += start[v];
    /* start[lo] walks from the start of bucket lo to its end while
     * filling: afterwards start[v] is where bucket v ends. */
    for (size_t h = 0; h < nh; h++) {
        if (skip && skip[h / 3]) continue;
        int lo = half_edge_lo(F, (int)h), hi = half_edge_hi(F, (int)h);
        keys[start[lo]++] = ((uint64_t)(uint32_t)hi << 32) | (uint32_t)h;
    }
    int done = 0;
    for (int v = 0; v < n; v++) {
        int t = start[v];
        sort_u64(keys + done, t - done);
        for (int i = done; i < t; i++) order[i] = (int)(uint32_t)keys[i];
        done = t;
    }
    *count = done;
    free(start);
    free(keys);
    return SCAF_OK;
}
