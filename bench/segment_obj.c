/* bench/segment_obj: the automatic charts of mesh/chart_segment as UV
 * seams, for looking at them and for running `scaf atlas --init tutte` on
 * them before the cut graph is wired into the program.
 *
 *   segment_obj IN OUT.obj [target_charts]
 *
 * Writes IN with one vt per (vertex, chart) pair (the coordinates are the
 * vertex's x and y: a placeholder, replaced by any --init), so the UV
 * charts are exactly the segmentation's charts; prints the chart count,
 * the seam length over sqrt(area) and the time as one JSON line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/timer.h"
#include "mesh/chart_segment.h"
#include "mesh/mesh_io.h"

static int pair_cmp(const void *p, const void *q)
{
    const long long *a = p, *b = q;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s IN OUT.obj [target_charts]\n", argv[0]);
        return 2;
    }
    scaf_error err;
    err_clear(&err);
    mesh m = {0};
    if (mesh_read(argv[1], &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    chart_segment_options o;
    chart_segment_defaults(&o);
    if (argc > 3) o.target_charts = atoi(argv[3]);
    int *chart = malloc(sizeof(int) * (size_t)(m.nf > 0 ? m.nf : 1));
    int n = 0;
    double t0 = timer_now();
    if (!chart || chart_segment(m.nv, m.V, m.nf, m.F, &o, chart, &n, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    double seconds = timer_now() - t0;
    /* one vt per (vertex, chart): a key table per vertex of the charts seen */
    int *first = malloc(sizeof(int) * (size_t)m.nv);
    int *next = malloc(sizeof(int) * 3 * (size_t)m.nf);
    int *key_chart = malloc(sizeof(int) * 3 * (size_t)m.nf);
    int *key_vertex = malloc(sizeof(int) * 3 * (size_t)m.nf);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    if (!first || !next || !key_chart || !key_vertex || !FT) return 1;
    for (int v = 0; v < m.nv; v++) first[v] = -1;
    int nuv = 0;
    for (int h = 0; h < 3 * m.nf; h++) {
        int v = m.F[h], c = chart[h / 3], id = first[v];
        while (id >= 0 && key_chart[id] != c) id = next[id];
        if (id < 0) {
            id = nuv++;
            key_chart[id] = c;
            key_vertex[id] = v;
            next[id] = first[v];
            first[v] = id;
        }
        FT[h] = id;
    }
    double *UV = malloc(sizeof(double) * 2 * (size_t)(nuv > 0 ? nuv : 1));
    if (!UV) return 1;
    for (int i = 0; i < nuv; i++) {
        UV[2 * i] = m.V[3 * key_vertex[i]];
        UV[2 * i + 1] = m.V[3 * key_vertex[i] + 1];
    }
    /* seam length: sides whose face and neighbour lie in different charts
     * (each seam edge seen twice), over sqrt(area) */
    double seam = 0.0, area = 0.0;
    for (int f = 0; f < m.nf; f++) {
        const double *a = m.V + 3 * m.F[3 * f], *b = m.V + 3 * m.F[3 * f + 1],
                     *c = m.V + 3 * m.F[3 * f + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2],
               z = u[0] * w[1] - u[1] * w[0];
        area += 0.5 * sqrt(x * x + y * y + z * z);
    }
    /* an edge is a seam when its two faces lie in different charts: the
     * half-edges sorted by (smaller end, larger end) put them side by side */
    {
        long long *pair = malloc(sizeof(long long) * 2 * 3 * (size_t)m.nf);
        if (!pair) return 1;
        for (int h = 0; h < 3 * m.nf; h++) {
            int a = m.F[h], b = m.F[h - h % 3 + (h % 3 + 1) % 3];
            int lo = a < b ? a : b, hi = a < b ? b : a;
            pair[2 * h] = (long long)lo * m.nv + hi;
            pair[2 * h + 1] = h;
        }
        qsort(pair, 3 * (size_t)m.nf, 2 * sizeof(long long), pair_cmp);
        for (int i = 0; i + 1 < 3 * m.nf; i++) {
            if (pair[2 * i] != pair[2 * i + 2]) continue;
            int g = (int)pair[2 * i + 1], h = (int)pair[2 * i + 3];
            if (chart[g / 3] != chart[h / 3]) {
                const double *a = m.V + 3 * m.F[g], *b = m.V + 3 * m.F[g - g % 3 + (g % 3 + 1) % 3];
                seam += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                             (a[2] - b[2]) * (a[2] - b[2]));
            }
        }
        free(pair);
    }
    mesh out = m;
    out.nuv = nuv;
    out.UV = UV;
    out.FT = FT;
    if (mesh_write_obj(argv[2], &out, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    printf("{\"input\": \"%s\", \"faces\": %d, \"charts\": %d, \"seam_length\": %.3f, "
           "\"seconds\": %.3f}\n",
           argv[1], m.nf, n, seam / sqrt(area), seconds);
    free(UV);
    free(FT);
    free(first);
    free(next);
    free(key_chart);
    free(key_vertex);
    free(chart);
    mesh_free(&m);
    return 0;
}
