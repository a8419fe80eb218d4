/* bench/bench_write: OBJ writer throughput (what `scaf param` and
 * `scaf atlas` spend after the last iteration).
 *
 * Usage: bench_write [-r REPEATS] FILE.obj[.gz] [OUT]  (OUT default
 * /tmp/bench_write.obj). Reads the mesh, gives every corner the UV of its
 * vertex (x, y scaled to [0, 1], so the numbers need 15-17 digits like an
 * optimizer's), then times, best of REPEATS (default 3), in process CPU
 * seconds (a busy shared machine disturbs them less than the wall clock):
 *   - obj_rewrite_uv: the input's text with the new `vt` and `f` lines;
 *   - mesh_write_obj: the mesh written from scratch.
 * Prints faces, seconds and MB/s of output (MB = 10^6 bytes). Exit status
 * 1 when the mesh cannot be read or a write fails.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "mesh/mesh_io.h"
#include "mesh/obj_rewrite.h"

static double cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double file_mb(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (double)st.st_size * 1e-6 : 0.0;
}

int main(int argc, char **argv)
{
    int R = 3, a = 1;
    if (a + 1 < argc && strcmp(argv[a], "-r") == 0) {
        R = atoi(argv[a + 1]);
        a += 2;
    }
    if (a >= argc || R < 1) {
        fprintf(stderr, "usage: bench_write [-r REPEATS] FILE.obj[.gz] [OUT]\n");
        return 1;
    }
    const char *in = argv[a], *out = a + 1 < argc ? argv[a + 1] : "/tmp/bench_write.obj";
    if (strcmp(in, out) == 0) {
        fprintf(stderr, "bench_write: OUT must not be the input (%s)\n", in);
        return 1;
    }
    mesh m;
    scaf_error err;
    if (mesh_read(in, &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", in, err.message);
        return 1;
    }
    /* UVs: each vertex's x, y scaled to [0, 1]; the corners share them */
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int v = 0; v < m.nv; v++)
        for (int k = 0; k < 2; k++) {
            double x = m.V[3 * (size_t)v + k];
            if (x < lo[k]) lo[k] = x;
            if (x > hi[k]) hi[k] = x;
        }
    free(m.UV);
    free(m.FT);
    m.nuv = m.nv;
    m.UV = malloc(2 * (size_t)m.nv * sizeof *m.UV);
    m.FT = malloc(3 * (size_t)m.nf * sizeof *m.FT);
    if (!m.UV || !m.FT) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    for (int v = 0; v < m.nv; v++)
        for (int k = 0; k < 2; k++)
            m.UV[2 * (size_t)v + k] =
                (m.V[3 * (size_t)v + k] - lo[k]) / (hi[k] > lo[k] ? hi[k] - lo[k] : 1.0);
    memcpy(m.FT, m.F, 3 * (size_t)m.nf * sizeof *m.FT);
    double best[2] = {1e300, 1e300};
    for (int r = 0; r < R; r++)
        for (int w = 0; w < 2; w++) {
            double t0 = cpu_s();
            scaf_status st =
                w == 0 ? obj_rewrite_uv(in, out, &m, &err) : mesh_write_obj(out, &m, &err);
            double t = cpu_s() - t0;
            if (st != SCAF_OK) {
                fprintf(stderr, "%s: %s\n", out, err.message);
                return 1;
            }
            if (t < best[w]) best[w] = t;
        }
    double mb_rewrite, mb_write = file_mb(out);
    obj_rewrite_uv(in, out, &m, &err);
    mb_rewrite = file_mb(out);
    printf("%s: %d faces\n", in, m.nf);
    printf("obj_rewrite_uv  %.3f s  %.1f MB/s\n", best[0], mb_rewrite / best[0]);
    printf("mesh_write_obj  %.3f s  %.1f MB/s\n", best[1], mb_write / best[1]);
    remove(out);
    mesh_free(&m);
    return 0;
}
