/* bench/bench_atlas: the texture atlas on the seam meshes, packing table.
 *
 * For every mesh of ../shared/data/seams (skipped when absent) and a
 * generated 500-chart mesh: runs the atlas with 4 texels of padding at
 * 1024 (defaults otherwise), verifies the normalized output (exact
 * checker, chart gap), and prints one markdown row: charts, pinched vt
 * split, iterations (settle + compaction), packing efficiency after
 * settling (grid start), after the raster re-placement and after
 * compaction, min chart gap (and whether chart_gap_certify proves it
 * >= the padding exactly), E settled / final, seconds (total, setup,
 * settling iterations, repack and per-iteration measures, compaction
 * iterations, median per iteration), or the error for meshes whose charts
 * are refused. Usage: bench_atlas [--no-rotate] [--settle-check] [MESH...]
 * (default: the seam meshes and the generated ones; --no-rotate: charts
 * turned by multiples of 45 degrees only, no layout turn; --settle-check:
 * also the settle phase run to the end, 1000 iterations with tolerance 0,
 * and how far above that the default settle ended).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/atlas.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/mesh_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct times {
    double sum[64 * 1024];
    int n;
    double phase[2]; /* seconds of the settle / compaction iterations */
} times;

static int on_it(const atlas *a, const atlas_iteration *it, void *user)
{
    (void)a;
    times *t = user;
    if (t->n < 64 * 1024) t->sum[t->n++] = it->info.seconds;
    t->phase[it->phase == ATLAS_COMPACT] += it->info.seconds;
    return 0;
}

static int cmp(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Append an nx x ny grid patch of size sx x sy at x offset ox, bent in z
 * by `bend`, to m (arrays grown). */
static void add_patch(mesh *m, double sx, double sy, int nx, int ny, double ox, double bend)
{
    int v0 = m->nv;
    m->V = realloc(m->V, sizeof(double) * 3 * (size_t)(m->nv + (nx + 1) * (ny + 1)));
    m->F = realloc(m->F, sizeof(int) * 3 * (size_t)(m->nf + 2 * nx * ny));
    if (!m->V || !m->F) abort();
    for (int j = 0; j <= ny; j++)
        for (int i = 0; i <= nx; i++) {
            double *v = m->V + 3 * (size_t)(m->nv++), x = sx * i / nx, y = sy * j / ny;
            v[0] = x + ox;
            v[1] = y;
            v[2] = bend * sin(0.8 * x) * cos(0.5 * y);
        }
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++, m->nf += 2) {
            int a = v0 + j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
            int *t = m->F + 3 * (size_t)m->nf;
            t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
        }
}

static void many_patches(mesh *m, int n)
{
    int r = 2, nvp = 9, nfp = 8;
    m->nv = n * nvp;
    m->nf = n * nfp;
    m->nuv = 0;
    m->UV = NULL;
    m->FT = NULL;
    m->V = malloc(sizeof(double) * 3 * (size_t)m->nv);
    m->F = malloc(sizeof(int) * 3 * (size_t)m->nf);
    int f = 0;
    for (int p = 0; p < n; p++) {
        double s = 0.5 + 0.37 * (p % 7) + 0.11 * (p % 3);
        for (int j = 0; j <= r; j++)
            for (int i = 0; i <= r; i++) {
                double *v = m->V + 3 * (size_t)(p * nvp + j * 3 + i), x = s * i / r, y = s * j / r;
                v[0] = x + 10.0 * p;
                v[1] = y;
                v[2] = 0.3 * s * sin(1.3 * x / s + p) * cos(0.7 * y / s);
            }
        for (int j = 0; j < r; j++)
            for (int i = 0; i < r; i++) {
                int a = p * nvp + j * 3 + i, b = a + 1, c = a + 3, d = c + 1;
                int *t = m->F + 3 * (size_t)f;
                t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
                f += 2;
            }
    }
}

static int no_rotate;    /* --no-rotate: atlas option rotate = 0 */
static int settle_check; /* --settle-check: also settle to the end (see below) */

/* The settle phase alone, run until no step is taken (1000 iterations,
 * tolerance 0): the converged distortion the default settle is compared
 * with. NAN on failure. */
static double settled_to_the_end(mesh *m, int *iterations)
{
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    o.settle_iterations = 1000;
    o.settle_tolerance = 0.0;
    o.compact_iterations = 0;
    o.repack = 0;
    o.rotate = 0;
    atlas a;
    scaf_error err;
    err_clear(&err);
    if (atlas_init(&a, m, &o, &err) != SCAF_OK) return NAN;
    double e = atlas_run(&a, NULL, NULL, &err) == SCAF_OK ? a.settled_energy : NAN;
    *iterations = a.settle_done;
    atlas_free(&a);
    return e;
}

static void bench(const char *name, mesh *m)
{
    atlas_options o = atlas_options_default();
    o.padding = 4.0 / 1024.0;
    if (no_rotate) o.rotate = 0;
    atlas a;
    scaf_error err;
    err_clear(&err);
    static times t;
    t.n = 0;
    t.phase[0] = t.phase[1] = 0.0;
    double t0 = now();
    if (atlas_init(&a, m, &o, &err) != SCAF_OK) {
        printf("| %s | refused: %s |\n", name, err.message);
        return;
    }
    double t1 = now();
    if (atlas_run(&a, on_it, &t, &err) != SCAF_OK) {
        printf("| %s | failed: %s |\n", name, err.message);
        atlas_free(&a);
        return;
    }
    double t2 = now();
    double *UV = malloc(sizeof(double) * 2 * (size_t)a.nw);
    atlas_normalized_uv(&a, UV);
    bij_report r;
    double gap = INFINITY;
    bij_check(a.nw, UV, a.nf, a.Fw, a.chart, NULL, &r, &err);
    chart_gap_min(a.nw, UV, a.nf, a.Fw, a.chart, 0.0, &gap, NULL, &err);
    int cert = 0;
    if (chart_gap_certify(UV, a.seg, a.nseg, o.padding, &cert, NULL, &err) != SCAF_OK) cert = -1;
    double eff = chart_packing_efficiency(a.nw, UV, a.nf, a.Fw);
    double iters = 0.0;
    for (int i = 0; i < t.n; i++) iters += t.sum[i];
    qsort(t.sum, (size_t)t.n, sizeof(double), cmp);
    double med = t.n ? t.sum[t.n / 2] : 0.0;
    printf("| %s | %d | %d | %d+%d | %.3f | %.3f | %.3f | %.5f%s | %s | %.4f / %.4f | %.2f | %.2f "
           "| %.2f | %.2f | %.2f | "
           "%.3f |\n",
           name, a.ncharts, a.split_uvs, a.settle_done, a.compact_done, a.eff_before, a.eff_packed,
           eff, gap,
           a.ncharts < 2   ? ""
               : cert == 1 ? " (exact >= P)"
               : cert == 0 ? " (NOT >= P)"
                           : " (not certifiable)",
           r.bijective ? "yes" : "NO", a.settled_energy, scaf_loop_energy(&a.loop), t2 - t0,
           t1 - t0, t.phase[0], (t2 - t1) - iters, t.phase[1], med);
    if (settle_check) {
        int its = 0;
        double ref = settled_to_the_end(m, &its);
        printf("| %s: settle to the end | %d iterations | E %.6f | default settle %.6f (%d its, "
               "%s) is %.2e above |\n",
               name, its, ref, a.settled_energy, a.settle_done,
               scaf_stop_reason_name(a.settle_stop), (a.settled_energy - ref) / ref);
    }
    fflush(stdout);
    free(UV);
    atlas_free(&a);
}

int main(int argc, char **argv)
{
    while (argc > 1 && (!strcmp(argv[1], "--no-rotate") || !strcmp(argv[1], "--settle-check"))) {
        if (!strcmp(argv[1], "--no-rotate")) no_rotate = 1;
        else settle_check = 1;
        argv[1] = argv[0];
        argv++;
        argc--;
    }
    const char *seams[] = {"seams/spot.obj", "seams/blub.obj", "seams/human_neutral.obj",
                           "seams/myles_knot1_seamed.obj", "seams/myles_eight_seamed.obj"};
    printf("| mesh | charts | split vt | iterations | eff. settled (grid) | eff. re-placed | eff. "
           "final | "
           "min gap | bijective | E settled / final | total s | setup s | settle s | repack+checks "
           "s | compaction s | "
           "median s/it |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    int n = argc > 1 ? argc - 1 : (int)(sizeof seams / sizeof *seams);
    for (int i = 0; i < n; i++) {
        char path[4096];
        if (argc > 1) snprintf(path, sizeof path, "%s", argv[i + 1]);
        else snprintf(path, sizeof path, "%s/%s", SCAF_DATA_DIR, seams[i]);
        mesh m;
        scaf_error err;
        if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
            printf("| %s | skipped: %s |\n", argc > 1 ? path : seams[i], err.message);
            continue;
        }
        bench(argc > 1 ? path : seams[i], &m);
        mesh_free(&m);
    }
    if (argc <= 1) {
        mesh m;
        many_patches(&m, 500);
        bench("generated: 500 patches", &m);
        mesh_free(&m);
        memset(&m, 0, sizeof m);
        add_patch(&m, 8.0, 1.0, 96, 12, 0.0, 0.3);
        bench("generated: 8 x 1 strip", &m);
        mesh_free(&m);
        /* one large square (settles at 45 degrees from its Tutte circle)
         * and 50 small ones */
        memset(&m, 0, sizeof m);
        add_patch(&m, 10.0, 10.0, 10, 10, 0.0, 0.0);
        for (int p = 0; p < 50; p++)
            add_patch(&m, 0.6 + 0.05 * (p % 5), 0.6, 2, 2, 20.0 + 3.0 * p, 0.05);
        bench("generated: 1 large + 50 small squares", &m);
        mesh_free(&m);
    }
    return 0;
}
