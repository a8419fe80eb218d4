/* bench/bench_check: time of the exact bijectivity checker on large maps.
 *
 * Generated layouts of about 1.7M triangles: one jittered n x n grid chart
 * (922 x 922 cells), and 400 separate charts of 46 x 46 cells; plus the
 * seam meshes of ../shared/data when present (read time excluded), and
 * large/aphrodite_subdiv16x.obj.gz (1.77M faces) with its xy projection as
 * the UV map.
 * Reports the best of a few runs of bij_check (seconds) as Markdown.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t seed = 42;
static double unit(void)
{
    seed ^= seed >> 12;
    seed ^= seed << 25;
    seed ^= seed >> 27;
    return (double)((seed * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

/* b x b charts of n x n jittered cells, one cell apart. */
static int layout(int b, int n, double **UV, int **F, int *nuv, int *nf)
{
    int pv = (n + 1) * (n + 1);
    *nuv = b * b * pv;
    *nf = b * b * 2 * n * n;
    *UV = malloc((size_t)*nuv * 2 * sizeof **UV);
    *F = malloc((size_t)*nf * 3 * sizeof **F);
    if (!*UV || !*F) return -1;
    size_t f = 0;
    for (int cy = 0; cy < b; cy++)
        for (int cx = 0; cx < b; cx++) {
            int base = (cy * b + cx) * pv;
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++) {
                    int v = base + j * (n + 1) + i;
                    (*UV)[2 * v] = cx * (n + 1) + i + 0.4 * (unit() - 0.5);
                    (*UV)[2 * v + 1] = cy * (n + 1) + j + 0.4 * (unit() - 0.5);
                }
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    int a = base + j * (n + 1) + i, c = a + n + 2;
                    int *t = *F + 3 * f;
                    t[0] = a, t[1] = a + 1, t[2] = c, t[3] = a, t[4] = c, t[5] = a + n + 1;
                    f += 2;
                }
        }
    return 0;
}

static void time_check(const char *name, int nuv, const double *UV, int nf, const int *F)
{
    double best = 1e30;
    bij_report r;
    for (int k = 0; k < 3; k++) {
        double t0 = now();
        if (bij_check(nuv, UV, nf, F, NULL, NULL, &r, NULL) != SCAF_OK) {
            printf("| %s | failed |\n", name);
            return;
        }
        double t = now() - t0;
        if (t < best) best = t;
    }
    printf("| %s | %d | %d | %d | %s | %.3f |\n", name, nf, r.charts, r.boundary_edges,
           r.bijective ? "yes" : "no", best);
}

int main(void)
{
    printf("| map | triangles | charts | boundary edges | bijective | seconds (best of 3) |\n"
           "|---|---|---|---|---|---|\n");
    double *UV;
    int *F, nuv, nf;
    if (layout(1, 922, &UV, &F, &nuv, &nf) == 0)
        time_check("grid 922x922, 1 chart", nuv, UV, nf, F);
    free(UV);
    free(F);
    if (layout(20, 46, &UV, &F, &nuv, &nf) == 0) time_check("400 charts of 46x46", nuv, UV, nf, F);
    free(UV);
    free(F);
    const char *files[] = {"disk/camel_b.obj",
                           "seams/blub.obj",
                           "seams/spot.obj",
                           "seams/human_neutral.obj",
                           "seams/myles_eight_seamed.obj",
                           NULL};
    for (int i = 0; files[i]; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", SCAF_DATA_DIR, files[i]);
        mesh m;
        if (mesh_read(path, &m, NULL, NULL) != SCAF_OK) continue;
        if (mesh_has_uv(&m)) time_check(files[i], m.nuv, m.UV, m.nf, m.FT);
        mesh_free(&m);
    }
    /* A real 1.77M-face mesh with its xy projection as the UV map
     * (probably not bijective; the time is what counts). */
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", SCAF_DATA_DIR, "large/aphrodite_subdiv16x.obj.gz");
    mesh m;
    if (mesh_read(path, &m, NULL, NULL) == SCAF_OK) {
        double *xy = malloc((size_t)m.nv * 2 * sizeof *xy);
        if (xy) {
            for (int v = 0; v < m.nv; v++) xy[2 * v] = m.V[3 * v], xy[2 * v + 1] = m.V[3 * v + 1];
            time_check("aphrodite_subdiv16x, xy projection", m.nv, xy, m.nf, m.F);
        }
        free(xy);
        mesh_free(&m);
    }
    return 0;
}
