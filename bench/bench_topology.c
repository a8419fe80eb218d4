/* bench/bench_topology: time of mesh/topology and mesh/uv_charts on the large
 * shared meshes (and a generated one), reading excluded.
 *
 * usage: bench_topology [FILE...]   (default: the three meshes of ../shared/data/large)
 * Prints one line per mesh: faces, read seconds, topology seconds, charts
 * seconds (process CPU time), best of 3 runs each.
 */
#include <stdio.h>
#include <time.h>

#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "mesh/topology.h"
#include "mesh/uv_charts.h"

/* Process CPU time: the code is single-threaded, and on a shared machine
 * CPU time is less disturbed by other jobs than wall time. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void run(const char *name, const mesh *m, double read_s)
{
    double best_t = 1e30, best_c = 1e30;
    scaf_error err;
    for (int rep = 0; rep < 3; rep++) {
        mesh_topology t;
        mesh_charts c;
        double t0 = now();
        if (mesh_topology_compute(m, &t, &err)) {
            fprintf(stderr, "%s: %s\n", name, err.message);
            return;
        }
        double t1 = now();
        if (mesh_charts_compute(m, &c, &err)) {
            fprintf(stderr, "%s: %s\n", name, err.message);
            mesh_topology_free(&t);
            return;
        }
        double t2 = now();
        if (t1 - t0 < best_t) best_t = t1 - t0;
        if (t2 - t1 < best_c) best_c = t2 - t1;
        mesh_charts_free(&c);
        mesh_topology_free(&t);
    }
    printf("%-40s %9d faces  read %6.3f s  topology %6.3f s  charts %6.3f s\n", name, m->nf, read_s,
           best_t, best_c);
}

int main(int argc, char **argv)
{
    static const char *defaults[] = {
        SCAF_DATA_DIR "/large/aphrodite_subdiv16x.obj.gz",
        SCAF_DATA_DIR "/large/nefertiti_subdiv16x.obj.gz",
        SCAF_DATA_DIR "/large/igea.obj",
    };
    int n = argc > 1 ? argc - 1 : 3;
    for (int i = 0; i < n; i++) {
        const char *path = argc > 1 ? argv[i + 1] : defaults[i];
        mesh m;
        scaf_error err;
        double t0 = now();
        if (mesh_read(path, &m, NULL, &err)) {
            fprintf(stderr, "skipped: %s\n", err.message);
            continue;
        }
        run(path, &m, now() - t0);
        mesh_free(&m);
    }
    mesh m;
    scaf_error err;
    if (!mesh_sample_make("cubesphere", 256, &m, &err)) {
        run("generated cubesphere 256 (6 charts)", &m, 0);
        mesh_free(&m);
    }
    return 0;
}
