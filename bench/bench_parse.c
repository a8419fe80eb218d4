/* bench/bench_parse: mesh reader throughput.
 *
 * Usage: bench_parse [-r REPEATS] [FILE...]  (default: the three meshes of
 * SCAF_DATA_DIR/large/). For each file: the uncompressed size, faces, the
 * best-of-REPEATS time of mesh_parse on the bytes already in memory and its
 * MB/s (MB = 10^6 bytes of uncompressed text), and the best time of the
 * whole mesh_read (file read + gunzip for .gz + parse) with its MB/s.
 * The parse is also timed in process CPU seconds (cpu_MB/s), which a busy
 * shared machine disturbs less than the wall clock.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <zlib.h>

#include "mesh/mesh_io.h"

static double clock_s(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double now(void) { return clock_s(CLOCK_MONOTONIC); }
static double cpu(void) { return clock_s(CLOCK_PROCESS_CPUTIME_ID); }

/* Whole file, decompressed if gzip (gzread passes plain files through). */
static char *load(const char *path, size_t *size)
{
    gzFile g = gzopen(path, "rb");
    if (!g) return NULL;
    size_t cap = 1 << 20, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) break;
        if (n == cap) {
            char *b = realloc(buf, cap * 2);
            if (!b) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = b;
            cap *= 2;
        }
        int r = gzread(g, buf + n, (unsigned)(cap - n > (1u << 30) ? (1u << 30) : cap - n));
        if (r <= 0) break;
        n += (size_t)r;
    }
    gzclose(g);
    *size = n;
    return buf;
}

static mesh_format format_of(const char *path)
{
    char name[4096];
    snprintf(name, sizeof name, "%s", path);
    size_t n = strlen(name);
    if (n > 3 && strcasecmp(name + n - 3, ".gz") == 0) name[n -= 3] = '\0';
    if (n > 4 && strcasecmp(name + n - 4, ".off") == 0) return MESH_FORMAT_OFF;
    if (n > 4 && strcasecmp(name + n - 4, ".ply") == 0) return MESH_FORMAT_PLY;
    return MESH_FORMAT_OBJ;
}

int main(int argc, char **argv)
{
    int repeats = 5, first = 1;
    if (argc > 2 && strcmp(argv[1], "-r") == 0) {
        repeats = atoi(argv[2]);
        if (repeats < 1) repeats = 1;
        first = 3;
    }
    static const char *defaults[] = {"large/igea.obj", "large/aphrodite_subdiv16x.obj.gz",
                                     "large/nefertiti_subdiv16x.obj.gz"};
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir || !*dir) dir = SCAF_DATA_DIR;
    int nfiles = argc - first;
    int use_defaults = nfiles <= 0;
    if (use_defaults) nfiles = 3;
    printf("%-30s %7s %9s %8s %10s %8s %9s %9s\n", "file", "MB", "faces", "parse_s", "parse_MB/s",
           "cpu_MB/s", "read_s", "read_MB/s");
    int status = 0;
    for (int i = 0; i < nfiles; i++) {
        char path[4096];
        if (use_defaults) snprintf(path, sizeof path, "%s/%s", dir, defaults[i]);
        else snprintf(path, sizeof path, "%s", argv[first + i]);
        size_t size = 0;
        char *data = load(path, &size);
        if (!data) {
            fprintf(stderr, "%s: cannot read\n", path);
            status = 1;
            continue;
        }
        double best_parse = 1e30, best_read = 1e30, best_cpu = 1e30;
        int nf = 0;
        for (int r = 0; r < repeats; r++) {
            mesh m;
            scaf_error e;
            double c0 = cpu(), t0 = now();
            scaf_status s = mesh_parse(data, size, format_of(path), path, &m, NULL, &e);
            double t1 = now(), c1 = cpu();
            if (c1 - c0 < best_cpu) best_cpu = c1 - c0;
            if (s != SCAF_OK) {
                fprintf(stderr, "%s\n", e.message);
                status = 1;
                break;
            }
            nf = m.nf;
            mesh_free(&m);
            if (t1 - t0 < best_parse) best_parse = t1 - t0;
            t0 = now();
            s = mesh_read(path, &m, NULL, &e);
            t1 = now();
            if (s != SCAF_OK) {
                fprintf(stderr, "%s\n", e.message);
                status = 1;
                break;
            }
            mesh_free(&m);
            if (t1 - t0 < best_read) best_read = t1 - t0;
        }
        const char *base = strrchr(path, '/');
        base = base ? base + 1 : path;
        double mb = (double)size / 1e6;
        printf("%-30s %7.1f %9d %8.3f %10.0f %8.0f %9.3f %9.0f\n", base, mb, nf, best_parse,
               mb / best_parse, mb / best_cpu, best_read, mb / best_read);
        free(data);
    }
    return status;
}
