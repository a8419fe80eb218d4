/* bench/disk_mesh: read a disk mesh for the opt benchmarks.
 *
 * The mesh goes into a polar_disk (tests/opt/polar_disk.h) so benchmarks
 * treat generated and real disks alike; its single boundary loop is found
 * from the directed edges whose reverse is absent. Header-only.
 */
#ifndef SCAF_BENCH_DISK_MESH_H
#define SCAF_BENCH_DISK_MESH_H

#include <stdio.h>
#include <stdlib.h>

#include "../tests/opt/polar_disk.h"
#include "mesh/mesh_io.h"
#include "opt/simplices.h"

static inline int disk_mesh_cmp_ll(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = *(const long long *)b;
    return (x > y) - (x < y);
}

/* Read a mesh with the library's reader (any format, .gz ok) and find its
 * single boundary loop (the topology module is not used here). */
static inline int disk_mesh_load(const char *path, polar_disk *m)
{
    mesh in = {0};
    scaf_error err;
    if (mesh_read(path, &in, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return -1;
    }
    m->nv = in.nv;
    m->nf = in.nf;
    m->V = in.V;
    m->F = in.F;
    free(in.UV);
    free(in.FT);
    /* Boundary half-edges: directed edges whose reverse is absent. */
    int *next = malloc((size_t)m->nv * sizeof *next);
    long long *keys = malloc(3 * (size_t)m->nf * sizeof *keys);
    if (!next || !keys) return -1;
    for (int v = 0; v < m->nv; v++) next[v] = -1;
    for (int t = 0; t < m->nf; t++)
        for (int k = 0; k < 3; k++)
            keys[3 * t + k] = (long long)m->F[3 * t + k] * m->nv + m->F[3 * t + (k + 1) % 3];
    qsort(keys, 3 * (size_t)m->nf, sizeof *keys, disk_mesh_cmp_ll);
    int start = -1, nb = 0;
    for (size_t k = 0; k < 3 * (size_t)m->nf; k++) {
        long long a = keys[k] / m->nv, b = keys[k] % m->nv, rev = b * m->nv + a;
        if (!bsearch(&rev, keys, 3 * (size_t)m->nf, sizeof *keys, disk_mesh_cmp_ll)) { next[a] = (int)b; start = (int)a; nb++; }
    }
    free(keys);
    m->loops = malloc(((size_t)nb + 1) * sizeof *m->loops);
    if (start < 0 || !m->loops) return -1;
    int len = 0, v = start;
    do { m->loops[len++] = v; v = next[v]; } while (v != start && v >= 0 && len < nb);
    free(next);
    if (len != nb) { fprintf(stderr, "%s: %d boundary edges, first loop has %d (not one loop)\n", path, nb, len); return -1; }
    m->nloops = 1;
    m->start[0] = 0;
    m->start[1] = len;
    return 0;
}

/* fixed (m->nv flags, zeroed by the caller) gets the outer boundary loop
 * and the unreferenced vertices (no simplex: keep them out of the system).
 * Returns 0, or -1 when out of memory. */
static inline int disk_mesh_fixed(const polar_disk *m, unsigned char *fixed)
{
    for (int k = 0; k < m->start[1]; k++) fixed[m->loops[k]] = 1;
    unsigned char *used = calloc((size_t)m->nv, 1);
    if (!used) return -1;
    for (int k = 0; k < 3 * m->nf; k++) used[m->F[k]] = 1;
    for (int v = 0; v < m->nv; v++)
        if (!used[v]) fixed[v] = 1;
    free(used);
    return 0;
}

/* The chart's simplices (rest frames of the 3D triangles, weight = area)
 * and the sum of their weights. Returns 0, or -1 with a message. */
static inline int disk_mesh_chart(const polar_disk *m, opt_simplices *S, double *wsum)
{
    scaf_error err;
    if (opt_simplices_from_surface(S, m->nv, m->V, m->nf, m->F, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return -1;
    }
    *wsum = 0;
    for (int s = 0; s < S->n; s++) *wsum += S->weight[s];
    return 0;
}

#endif /* SCAF_BENCH_DISK_MESH_H */
