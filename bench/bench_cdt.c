/* bench/bench_cdt: speed and quality of the scaffold mesher (geom/cdt).
 *
 * Scaffolds (box = 3x the boundary's bounding box, default 20 degree
 * refinement) around generated wiggly charts with 1k, 10k and 100k boundary
 * vertices, and around the UV chart boundaries of the meshes in the shared
 * data folder that carry UVs (skipped when absent). Prints milliseconds
 * (best of several runs), triangles per second, Steiner points, refused
 * refinements and minimum angles. Usage: bench_cdt [DATA_DIR], or, for
 * instruction counts under callgrind, bench_cdt --one circle|wiggly N
 * ANGLE: one triangulation of that input (ANGLE 0 = CDT only).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom/cdt.h"
#include "geom/predicates.h"
#include "mesh/mesh_io.h"

/* the tests' builder (cb_*), box, UV boundary and angle helpers */
#include "../tests/geom/cdt_check.h"
#include "../tests/geom/cdt_uv_boundary.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* CPU time of this process: on a shared machine it leaves out the time
 * the process waited for a core */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* n vertices on a wiggly closed curve (amp = 0: a circle, as after a
 * Tutte embedding: all boundary vertices nearly cocircular), then the box */
static void wiggly_input(cdt_builder *b, int n, double amp)
{
    double *xy = malloc((size_t)n * 2 * sizeof(double));
    if (!xy) {
        fprintf(stderr, "bench_cdt: out of memory\n");
        exit(1);
    }
    for (int i = 0; i < n; i++) {
        double t = 2 * 3.14159265358979323846 * i / n;
        double r = 1 + amp * (0.3 * sin(7 * t) + 0.05 * sin(97 * t));
        xy[2 * i] = r * cos(t);
        xy[2 * i + 1] = r * sin(t);
    }
    cb_init(b);
    cb_loop(b, xy, n);
    free(xy);
    cb_box(b, 3.0, NULL);
}

/* g x g charts (circles of m vertices, squeezed) on a grid, 0.1 apart */
static void atlas_input(cdt_builder *b, int g, int m)
{
    double *xy = malloc((size_t)m * 2 * sizeof(double));
    if (!xy) {
        fprintf(stderr, "bench_cdt: out of memory\n");
        exit(1);
    }
    cb_init(b);
    for (int c = 0; c < g * g; c++) {
        double cx = 2.1 * (c % g), cy = 2.1 * (c / g);
        for (int i = 0; i < m; i++) {
            double t = 2 * 3.14159265358979323846 * i / m;
            xy[2 * i] = cx + cos(t);
            xy[2 * i + 1] = cy + (0.5 + 0.1 * (c % 5)) * sin(t);
        }
        cb_loop(b, xy, m);
    }
    free(xy);
    cb_box(b, 3.0, NULL);
}

static void run(const char *name, const cdt_builder *p, int reps, double min_angle_deg)
{
    cdt_input in = cb_input(p);
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = min_angle_deg;
    double best = 1e30, best_cpu = 1e30;
    cdt_output out;
    scaf_error err;
    for (int r = 0; r < reps; r++) {
        double t0 = now(), c0 = cpu_now();
        scaf_status s = cdt_triangulate(&in, &opt, &out, &err);
        double dt = now() - t0, dc = cpu_now() - c0;
        if (dc < best_cpu) best_cpu = dc;
        if (s != SCAF_OK) {
            printf("| %s | %d | error: %s |\n", name, p->np - 4, err.message);
            return;
        }
        if (dt < best) best = dt;
        if (r + 1 < reps) cdt_output_free(&out);
    }
    /* quality: all triangles, and those touching no chart vertex */
    unsigned char *chart = calloc((size_t)out.npoints, 1);
    for (int s = 0; s < p->ns; s++)
        if (!p->split[s]) chart[p->seg[2 * s]] = chart[p->seg[2 * s + 1]] = 1;
    double amin = 180, afree = 180;
    long nfree = 0, below = 0, nbelow_all = 0;
    for (int t = 0; t < out.ntriangles; t++) {
        const int *v = out.triangles + 3 * t;
        double a =
            tri_min_angle(out.points + 2 * v[0], out.points + 2 * v[1], out.points + 2 * v[2]);
        amin = fmin(amin, a);
        if (a < min_angle_deg - 1e-9) nbelow_all++;
        if (!chart[v[0]] && !chart[v[1]] && !chart[v[2]]) {
            nfree++;
            afree = fmin(afree, a);
            if (a < min_angle_deg - 1e-9) below++;
        }
    }
    printf("| %s | %d | %.2f | %.2f | %d | %d | %.2f M | %d | %.2f | %.1f%% | %.2f (%ld of %ld "
           "below) |\n",
           name, p->np - 4, best_cpu * 1e3, best * 1e3, out.ntriangles, out.nsteiner,
           out.ntriangles / best_cpu * 1e-6, out.nrejected, amin,
           100.0 * (out.ntriangles - nbelow_all) / (out.ntriangles ? out.ntriangles : 1), afree,
           below, nfree);
    fflush(stdout);
    free(chart);
    cdt_output_free(&out);
}

int main(int argc, char **argv)
{
    if (argc == 5 && !strcmp(argv[1], "--one")) {
        int n = atoi(argv[3]);
        if (n < 3 || n > 10000000) {
            fprintf(stderr, "usage: bench_cdt --one circle|wiggly N ANGLE\n");
            return 2;
        }
        cdt_builder p;
        wiggly_input(&p, n, strcmp(argv[2], "circle") ? 1 : 0);
        run(argv[2], &p, 1, atof(argv[4]));
        cb_free(&p);
        return 0;
    }
    const char *dir = argc > 1 ? argv[1] : SCAF_DATA_DIR;
    printf("| input | boundary vertices | CPU ms (best) | wall ms (best) | triangles | Steiner | "
           "triangles/s (CPU) | refused | min angle (all) | triangles >= bound | min angle away "
           "from chart vertices |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    int sizes[3] = {1000, 10000, 100000}, reps[3] = {30, 10, 3};
    for (int i = 0; i < 3; i++) {
        cdt_builder p;
        wiggly_input(&p, sizes[i], 1);
        char name[64];
        snprintf(name, sizeof name, "wiggly %d, CDT only", sizes[i]);
        run(name, &p, reps[i], 0);
        snprintf(name, sizeof name, "wiggly %d, 20 deg", sizes[i]);
        run(name, &p, reps[i], 20);
        cb_free(&p);
        wiggly_input(&p, sizes[i], 0);
        snprintf(name, sizeof name, "circle %d, 20 deg", sizes[i]);
        run(name, &p, reps[i], 20);
        cb_free(&p);
    }
    cdt_builder a;
    atlas_input(&a, 10, 100);
    run("atlas 10x10 charts x 100", &a, 10, 20);
    cb_free(&a);
    atlas_input(&a, 30, 12);
    run("atlas 30x30 charts x 12", &a, 10, 20);
    cb_free(&a);
    const char *files[] = {"disk/camel_b.obj", "seams/blub.obj", "seams/spot.obj",
                           "seams/myles_knot1_seamed.obj"};
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        mesh m;
        scaf_error err;
        memset(&m, 0, sizeof m);
        if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
            printf("| %s | skipped: %s |\n", files[i], err.message);
            continue;
        }
        if (!mesh_has_uv(&m)) {
            mesh_free(&m);
            continue;
        }
        cdt_builder p;
        if (cb_uv_boundary(&m, &p)) {
            run(files[i], &p, 10, 20);
            cb_free(&p);
        }
        mesh_free(&m);
    }
    return 0;
}
