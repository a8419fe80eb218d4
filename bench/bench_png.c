/* bench/bench_png: cost of the PNG pictures (app/uv_png).
 *
 * For each mesh with UVs (default: the seam meshes of ../shared/data,
 * skipped when absent), the UV layout is drawn at 1024 and 4096 pixels,
 * without and with the 3D checker: one markdown row per case with the
 * seconds of the fill alone (app/uv_raster) and of the whole picture
 * (fill, outline, libpng encoding, atomic write), median of 3 runs, and
 * the file size (checker: 20 squares across the diagonal). The layout need not be bijective: overlapping input UVs
 * are drawn like any others. Usage: bench_png [MESH...].
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>

#include "app/uv_png.h"
#include "app/uv_raster.h"
#include "mesh/mesh_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double median3(double a, double b, double c)
{
    if (a > b) {
        double t = a;
        a = b;
        b = t;
    }
    if (b > c) b = c;
    return a > b ? a : b;
}

static void one(const char *path)
{
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
        printf("| %s | (%s) |\n", path, err.message);
        return;
    }
    if (!mesh_has_uv(&m)) {
        printf("| %s | (no UVs) |\n", path);
        mesh_free(&m);
        return;
    }
    unsigned *col = malloc(sizeof(unsigned) * (size_t)m.nf);
    if (!col) return;
    for (int f = 0; f < m.nf; f++) col[f] = 0x4080c0u + 0x101010u * (unsigned)(f % 8);
    double blo[3] = {1e300, 1e300, 1e300}, bhi[3] = {-1e300, -1e300, -1e300};
    for (int i = 0; i < m.nv; i++)
        for (int k = 0; k < 3; k++) {
            if (m.V[3 * i + k] < blo[k]) blo[k] = m.V[3 * i + k];
            if (m.V[3 * i + k] > bhi[k]) bhi[k] = m.V[3 * i + k];
        }
    double diag =
        sqrt((bhi[0] - blo[0]) * (bhi[0] - blo[0]) + (bhi[1] - blo[1]) * (bhi[1] - blo[1]) +
             (bhi[2] - blo[2]) * (bhi[2] - blo[2]));
    const char *out = "bench_png_out.png";
    int sizes[2] = {1024, 4096};
    for (int s = 0; s < 2; s++)
        for (int chk = 0; chk < 2; chk++) {
            uv_png_options o = uv_png_options_default();
            o.size = sizes[s];
            o.checker = chk ? 20.0 : 0.0;
            double tf[3], tw[3];
            for (int r = 0; r < 3; r++) {
                /* the fill alone, on the fitted frame of the whole UV box */
                double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
                for (int i = 0; i < m.nuv; i++)
                    for (int k = 0; k < 2; k++) {
                        if (m.UV[2 * i + k] < lo[k]) lo[k] = m.UV[2 * i + k];
                        if (m.UV[2 * i + k] > hi[k]) hi[k] = m.UV[2 * i + k];
                    }
                int W, H;
                uv_raster_frame fr = uv_raster_fit(lo, hi, o.size, o.size / 64, &W, &H);
                uv_raster ras;
                if (uv_raster_new(&ras, W, H, &err) != SCAF_OK) return;
                uv_raster_mesh rm = {
                    m.nf, m.UV, m.FT, col, chk ? m.V : NULL, chk ? m.F : NULL, diag / 20.0};
                double t0 = now();
                uv_raster_fill(&ras, &fr, &rm);
                tf[r] = now() - t0;
                uv_raster_free(&ras);
                t0 = now();
                if (uv_png_write(out, m.nuv, m.UV, m.nf, m.FT, col, m.nv, m.V, m.F, &o, &err) !=
                    SCAF_OK) {
                    printf("| %s | %s |\n", path, err.message);
                    return;
                }
                tw[r] = now() - t0;
            }
            struct stat st;
            long bytes = stat(out, &st) == 0 ? (long)st.st_size : -1;
            printf("| %s | %d | %d | %s | %.3f | %.3f | %ld |\n", path, m.nf, sizes[s],
                   chk ? "yes" : "no", median3(tf[0], tf[1], tf[2]), median3(tw[0], tw[1], tw[2]),
                   bytes);
            fflush(stdout);
        }
    remove(out);
    free(col);
    mesh_free(&m);
}

int main(int argc, char **argv)
{
    printf("| mesh | faces | pixels | checker | fill s | picture s | bytes "
           "|\n|---|---|---|---|---|---|---|\n");
    if (argc > 1) {
        for (int i = 1; i < argc; i++) one(argv[i]);
        return 0;
    }
    const char *names[] = {"seams/spot.obj", "seams/human_neutral.obj"};
    for (int i = 0; i < 2; i++) {
        char p[4096];
        snprintf(p, sizeof p, "%s/%s", SCAF_DATA_DIR, names[i]);
        FILE *f = fopen(p, "r");
        if (!f) continue;
        fclose(f);
        one(p);
    }
    return 0;
}
