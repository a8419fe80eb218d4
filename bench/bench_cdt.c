/* bench/bench_cdt: speed and quality of the scaffold mesher (geom/cdt).
 *
 * Scaffolds (box = 3x the boundary's bounding box, default 20 degree
 * refinement) around generated wiggly charts with 1k, 10k and 100k boundary
 * vertices, and around the UV chart boundaries of the meshes in the shared
 * data folder that carry UVs (skipped when absent). Prints milliseconds
 * (best of several runs), triangles per second, Steiner points, refused
 * refinements and minimum angles. Usage: bench_cdt [DATA_DIR].
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

typedef struct problem {
    double *pts;
    int np;
    int *seg;
    unsigned char *split, *hole;
    int ns;
} problem;

static void add_box(problem *p)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < p->np; i++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], p->pts[2 * i + k]);
            hi[k] = fmax(hi[k], p->pts[2 * i + k]);
        }
    double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double h = 1.5 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
    double box[8] = {c[0] - h, c[1] - h, c[0] + h, c[1] - h, c[0] + h, c[1] + h, c[0] - h, c[1] + h};
    int b0 = p->np;
    memcpy(p->pts + 2 * p->np, box, sizeof box);
    p->np += 4;
    for (int i = 0; i < 4; i++) {
        p->seg[2 * p->ns] = b0 + i;
        p->seg[2 * p->ns + 1] = b0 + (i + 1) % 4;
        p->split[p->ns] = 1;
        p->hole[p->ns] = 0;
        p->ns++;
    }
}

/* n vertices on a wiggly closed curve (amp = 0: a circle, as after a
 * Tutte embedding: all boundary vertices nearly cocircular) */
static problem wiggly(int n, double amp)
{
    problem p;
    p.pts = malloc((size_t)(n + 4) * 2 * sizeof(double));
    p.seg = malloc((size_t)(n + 4) * 2 * sizeof(int));
    p.split = malloc((size_t)(n + 4));
    p.hole = malloc((size_t)(n + 4));
    p.np = p.ns = 0;
    for (int i = 0; i < n; i++) {
        double t = 2 * 3.14159265358979323846 * i / n;
        double r = 1 + amp * (0.3 * sin(7 * t) + 0.05 * sin(97 * t));
        p.pts[2 * i] = r * cos(t);
        p.pts[2 * i + 1] = r * sin(t);
        p.seg[2 * i] = i;
        p.seg[2 * i + 1] = (i + 1) % n;
        p.split[i] = 0;
        p.hole[i] = 1;
    }
    p.np = p.ns = n;
    add_box(&p);
    return p;
}

/* g x g charts (circles of m vertices, squeezed) on a grid, 0.1 apart */
static problem atlas(int g, int m)
{
    problem p;
    int n = g * g * m;
    p.pts = malloc((size_t)(n + 4) * 2 * sizeof(double));
    p.seg = malloc((size_t)(n + 4) * 2 * sizeof(int));
    p.split = malloc((size_t)(n + 4));
    p.hole = malloc((size_t)(n + 4));
    p.np = p.ns = 0;
    for (int c = 0; c < g * g; c++) {
        double cx = 2.1 * (c % g), cy = 2.1 * (c / g);
        for (int i = 0; i < m; i++) {
            double t = 2 * 3.14159265358979323846 * i / m;
            int v = c * m + i;
            p.pts[2 * v] = cx + cos(t);
            p.pts[2 * v + 1] = cy + (0.5 + 0.1 * (c % 5)) * sin(t);
            p.seg[2 * v] = v;
            p.seg[2 * v + 1] = c * m + (i + 1) % m;
            p.split[v] = 0;
            p.hole[v] = 1;
        }
    }
    p.np = p.ns = n;
    add_box(&p);
    return p;
}

static void problem_free(problem *p)
{
    free(p->pts);
    free(p->seg);
    free(p->split);
    free(p->hole);
}

typedef struct ekey {
    int a, b, face_ccw, lo, hi;
} ekey;

static int cmp_ekey(const void *x, const void *y)
{
    const ekey *p = x, *q = y;
    if (p->lo != q->lo)
        return p->lo < q->lo ? -1 : 1;
    return (p->hi > q->hi) - (p->hi < q->hi);
}

/* The UV boundary of a mesh with UVs: edges of the vt-index triangulation
 * with one incident face, oriented so that the chart is on their left. */
static int uv_boundary(const mesh *m, problem *p)
{
    int nf = m->nf;
    ekey *e = malloc((size_t)nf * 3 * sizeof *e);
    int *map = malloc((size_t)m->nuv * sizeof(int));
    if (!e || !map)
        return -1;
    for (int f = 0; f < nf; f++) {
        const int *t = m->FT + 3 * f;
        double o = orient2d(m->UV + 2 * t[0], m->UV + 2 * t[1], m->UV + 2 * t[2]);
        for (int k = 0; k < 3; k++) {
            ekey *q = e + 3 * f + k;
            q->a = t[k];
            q->b = t[(k + 1) % 3];
            q->face_ccw = o >= 0;
            q->lo = q->a < q->b ? q->a : q->b;
            q->hi = q->a < q->b ? q->b : q->a;
        }
    }
    qsort(e, (size_t)nf * 3, sizeof *e, cmp_ekey);
    for (int i = 0; i < m->nuv; i++)
        map[i] = -1;
    int nb = 0;
    for (int i = 0; i < 3 * nf;) {
        int j = i;
        while (j < 3 * nf && e[j].lo == e[i].lo && e[j].hi == e[i].hi)
            j++;
        if (j - i == 1)
            e[nb++] = e[i];
        i = j;
    }
    p->pts = malloc((size_t)(nb + 4) * 2 * sizeof(double));
    p->seg = malloc((size_t)(nb + 4) * 2 * sizeof(int));
    p->split = malloc((size_t)(nb + 4));
    p->hole = malloc((size_t)(nb + 4));
    p->np = p->ns = 0;
    for (int i = 0; i < nb; i++) {
        int ends[2] = {e[i].face_ccw ? e[i].a : e[i].b, e[i].face_ccw ? e[i].b : e[i].a};
        for (int k = 0; k < 2; k++) {
            if (map[ends[k]] < 0) {
                map[ends[k]] = p->np;
                p->pts[2 * p->np] = m->UV[2 * ends[k]];
                p->pts[2 * p->np + 1] = m->UV[2 * ends[k] + 1];
                p->np++;
            }
        }
        p->seg[2 * p->ns] = map[ends[0]];
        p->seg[2 * p->ns + 1] = map[ends[1]];
        p->split[p->ns] = 0;
        p->hole[p->ns] = 1;
        p->ns++;
    }
    free(e);
    free(map);
    add_box(p);
    return 0;
}

static double min_angle(const double *a, const double *b, const double *c)
{
    const double *p[3] = {a, b, c};
    double best = 180;
    for (int i = 0; i < 3; i++) {
        const double *o = p[i], *u = p[(i + 1) % 3], *w = p[(i + 2) % 3];
        double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
        double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / 3.14159265358979323846;
        best = fmin(best, ang);
    }
    return best;
}

static void run(const char *name, const problem *p, int reps, double min_angle_deg)
{
    cdt_input in = {p->np, p->pts, p->ns, p->seg, p->split, p->hole, 0, NULL};
    cdt_options opt = cdt_default_options();
    opt.min_angle_deg = min_angle_deg;
    double best = 1e30, best_cpu = 1e30;
    cdt_output out;
    scaf_error err;
    for (int r = 0; r < reps; r++) {
        double t0 = now(), c0 = cpu_now();
        scaf_status s = cdt_triangulate(&in, &opt, &out, &err);
        double dt = now() - t0, dc = cpu_now() - c0;
        if (dc < best_cpu)
            best_cpu = dc;
        if (s != SCAF_OK) {
            printf("| %s | %d | error: %s |\n", name, p->np - 4, err.message);
            return;
        }
        if (dt < best)
            best = dt;
        if (r + 1 < reps)
            cdt_output_free(&out);
    }
    /* quality: all triangles, and those touching no chart vertex */
    unsigned char *chart = calloc((size_t)out.npoints, 1);
    for (int s = 0; s < p->ns; s++)
        if (!p->split[s])
            chart[p->seg[2 * s]] = chart[p->seg[2 * s + 1]] = 1;
    double amin = 180, afree = 180;
    long nfree = 0, below = 0, nbelow_all = 0;
    for (int t = 0; t < out.ntriangles; t++) {
        const int *v = out.triangles + 3 * t;
        double a = min_angle(out.points + 2 * v[0], out.points + 2 * v[1], out.points + 2 * v[2]);
        amin = fmin(amin, a);
        if (a < min_angle_deg - 1e-9)
            nbelow_all++;
        if (!chart[v[0]] && !chart[v[1]] && !chart[v[2]]) {
            nfree++;
            afree = fmin(afree, a);
            if (a < min_angle_deg - 1e-9)
                below++;
        }
    }
    printf("| %s | %d | %.2f | %.2f | %d | %d | %.2f M | %d | %.2f | %.1f%% | %.2f (%ld of %ld below) |\n",
           name, p->np - 4, best_cpu * 1e3, best * 1e3, out.ntriangles, out.nsteiner,
           out.ntriangles / best_cpu * 1e-6,
           out.nrejected, amin, 100.0 * (out.ntriangles - nbelow_all) / (out.ntriangles ? out.ntriangles : 1),
           afree, below, nfree);
    fflush(stdout);
    free(chart);
    cdt_output_free(&out);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : SCAF_DATA_DIR;
    printf("| input | boundary vertices | CPU ms (best) | wall ms (best) | triangles | Steiner | "
           "triangles/s (CPU) | refused | min angle (all) | triangles >= bound | min angle away "
           "from chart vertices |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    int sizes[3] = {1000, 10000, 100000}, reps[3] = {30, 10, 3};
    for (int i = 0; i < 3; i++) {
        problem p = wiggly(sizes[i], 1);
        char name[64];
        snprintf(name, sizeof name, "wiggly %d, CDT only", sizes[i]);
        run(name, &p, reps[i], 0);
        snprintf(name, sizeof name, "wiggly %d, 20 deg", sizes[i]);
        run(name, &p, reps[i], 20);
        problem_free(&p);
        p = wiggly(sizes[i], 0);
        snprintf(name, sizeof name, "circle %d, 20 deg", sizes[i]);
        run(name, &p, reps[i], 20);
        problem_free(&p);
    }
    problem a = atlas(10, 100);
    run("atlas 10x10 charts x 100", &a, 10, 20);
    problem_free(&a);
    a = atlas(30, 12);
    run("atlas 30x30 charts x 12", &a, 10, 20);
    problem_free(&a);
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
        problem p;
        if (uv_boundary(&m, &p) == 0) {
            run(files[i], &p, 10, 20);
            problem_free(&p);
        }
        mesh_free(&m);
    }
    return 0;
}
