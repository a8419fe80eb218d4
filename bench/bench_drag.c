/* bench/bench_drag: milliseconds per drag step (include/scaf/drag.h).
 *
 * The interactive case: the finished atlas of a seams mesh (the drag
 * context with SCAF_DRAG_START_ATLAS; its setup is not timed), then a
 * drag: frame after frame one chart's handle moves a little further
 * toward the middle of the layout (a rigid chart handle, translated and
 * turned) and one scaf_drag_step(1) runs, as an editor does on every
 * mouse move. Reported per mesh: the median CPU time of a step (all
 * threads of the process: on a shared machine the wall time also counts
 * the wait for a core), the median, 10th and 90th percentile of its wall
 * time over all frames, and the median wall time split into the loop's
 * phases (scaf_iteration_info_t.phase_seconds); the load average at the
 * end. Every frame's layout is checked
 * with the exact checker afterwards (not timed). A second run drags a
 * single vertex handle.
 *
 *   build/bench/bench_drag [--frames N] [--mesh PATH] [--box-scale S] [--padding P]
 * Data folder: SCAF_DATA_DIR (env) or the compiled default.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "scaf/scaf.h"

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* CPU seconds of the process (all threads): on a shared, loaded machine
 * the wall time also counts waiting for a core, this does not. */
static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double quantile(const double *x, int n, double q)
{
    double *s = malloc(sizeof(double) * (size_t)n);
    memcpy(s, x, sizeof(double) * (size_t)n);
    qsort(s, (size_t)n, sizeof(double), cmp_double);
    double r = s[(int)floor(q * (n - 1) + 0.5)];
    free(s);
    return r;
}

typedef struct frame_log {
    scaf_iteration_info_t info;
} frame_log;

static int keep_info(const scaf_iteration_info_t *it, void *user)
{
    ((frame_log *)user)->info = *it;
    return 0;
}

static int valid(scaf_drag_t *d)
{
    int nw = scaf_drag_uv_count(d), nf = scaf_drag_face_count(d);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nw);
    int *FT = malloc(sizeof(int) * 3 * (size_t)nf), *chart = malloc(sizeof(int) * (size_t)nf);
    bij_report r;
    int ok = UV && FT && chart && scaf_drag_get_uv(d, UV, FT, chart) == SCAF_OK &&
        bij_check(nw, UV, nf, FT, chart, NULL, &r, NULL) == SCAF_OK && r.bijective;
    free(UV);
    free(FT);
    free(chart);
    return ok;
}

/* One drag of `frames` frames; kind 0: chart handle, 1: vertex handle,
 * 2: rigid motion (scaf_drag_rigid_move: the chart moved rigidly, the
 * others pushed by translations, each frame certified exactly inside the
 * call; no loop phases, the reached fraction in the handle-error column). */
static void drag_run(scaf_drag_t *d, int kind, int frames, const char *name)
{
    int nc = scaf_drag_chart_count(d), nw = scaf_drag_uv_count(d);
    /* the layout's middle, and the smallest chart (moves the most) */
    double *UV = malloc(sizeof(double) * 2 * (size_t)nw);
    scaf_drag_get_uv(d, UV, NULL, NULL);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < nw; v++)
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], UV[2 * v + k]), hi[k] = fmax(hi[k], UV[2 * v + k]);
    double mid[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    int c = 0;
    double amin = INFINITY;
    scaf_drag_chart_info_t ci;
    for (int k = 0; k < nc; k++) {
        scaf_drag_get_uv(d, UV, NULL, NULL);
        scaf_drag_chart_info(d, k, &ci);
        if (ci.uv_area < amin) amin = ci.uv_area, c = k;
    }
    scaf_drag_chart_info(d, c, &ci);
    int *wc = malloc(sizeof(int) * (size_t)nw), v0 = -1;
    scaf_drag_uv_charts(d, wc);
    for (int v = 0; v < nw && v0 < 0; v++)
        if (wc[v] == c) v0 = v;
    double *ms = malloc(sizeof(double) * (size_t)frames);
    double *cpu = malloc(sizeof(double) * (size_t)frames);
    double(*ph)[SCAF_PHASE_COUNT] = malloc(sizeof *ph * (size_t)frames);
    int bad = 0, done = 0;
    double eff0 = scaf_drag_packing_efficiency(d);
    scaf_drag_checkpoint(d);
    if (kind == 2) scaf_drag_rigid_begin(d, &c, 1);
    double reached = 0.0;
    for (int f = 0; f < frames; f++) {
        double t = (double)(f + 1) / frames; /* the mouse goes to the middle */
        double dx = t * (mid[0] - ci.centroid[0]), dy = t * (mid[1] - ci.centroid[1]);
        if (kind == 0) scaf_drag_move_chart(d, c, dx, dy, 0.5 * t);
        else scaf_drag_move_vertex(d, v0, UV[2 * v0] + dx, UV[2 * v0 + 1] + dy);
        frame_log log;
        memset(&log, 0, sizeof log);
        scaf_drag_motion_t mo = scaf_drag_motion_identity();
        mo.dx = dx, mo.dy = dy, mo.angle = 0.5 * t;
        double t0 = now(), c0 = cpu_now();
        scaf_status st = kind == 2 ? scaf_drag_rigid_move(d, &mo, &reached)
                                   : scaf_drag_step(d, 1, keep_info, &log);
        ms[f] = 1e3 * (now() - t0);
        cpu[f] = 1e3 * (cpu_now() - c0);
        for (int p = 0; p < SCAF_PHASE_COUNT; p++) ph[f][p] = 1e3 * log.info.phase_seconds[p];
        if (st != SCAF_OK) {
            fprintf(stderr, "%s: step failed: %s\n", name, scaf_drag_error(d));
            break;
        }
        if (!valid(d)) bad++;
        done++;
    }
    if (done > 0) {
        printf("| %s | %s | %d | %d | %.1f | %.1f | %.1f | %.1f |", name,
               kind == 0       ? "chart"
                   : kind == 1 ? "vertex"
                               : "rigid",
               nc, done, quantile(cpu, done, 0.5), quantile(ms, done, 0.5), quantile(ms, done, 0.1),
               quantile(ms, done, 0.9));
        double *col = malloc(sizeof(double) * (size_t)done);
        for (int p = 0; p < SCAF_PHASE_COUNT; p++) {
            for (int f = 0; f < done; f++) col[f] = ph[f][p];
            printf(" %.1f |", quantile(col, done, 0.5));
        }
        free(col);
        if (kind == 2) printf(" reached %.3f |", reached);
        else printf(" %.3g |", scaf_drag_max_handle_error(d) / side);
        printf(" %.3f -> %.3f | %s |\n", eff0, scaf_drag_packing_efficiency(d), bad ? "NO" : "yes");
    }
    scaf_drag_rigid_end(d);
    scaf_drag_undo(d);
    scaf_drag_clear_handles(d);
    free(UV);
    free(wc);
    free(ms);
    free(cpu);
    free(ph);
}

int main(int argc, char **argv)
{
    int frames = 40, rigid_only = 0;
    const char *one = NULL;
    scaf_drag_options_t o = scaf_drag_options_default();
    o.start = SCAF_DRAG_START_ATLAS;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--frames") && i + 1 < argc) frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--mesh") && i + 1 < argc) one = argv[++i];
        else if (!strcmp(argv[i], "--box-scale") && i + 1 < argc) o.box_scale = atof(argv[++i]);
        else if (!strcmp(argv[i], "--padding") && i + 1 < argc) o.padding = atof(argv[++i]);
        else if (!strcmp(argv[i], "--rigid-only")) rigid_only = 1;
        else {
            fprintf(stderr,
                    "usage: bench_drag [--frames N] [--mesh PATH] [--box-scale S] [--padding P] "
                    "[--rigid-only]\n");
            return 2;
        }
    }
    if (frames < 1) frames = 1;
    const char *dir = getenv("SCAF_DATA_DIR") ? getenv("SCAF_DATA_DIR") : SCAF_DATA_DIR;
    const char *names[] = {"seams/human_neutral.obj", "seams/spot.obj", "seams/blub.obj"};
    int nmesh = one ? 1 : 3;
    printf("| mesh | handle | charts | frames | median CPU ms | median wall ms | p10 | p90 |");
    for (int p = 0; p < SCAF_PHASE_COUNT; p++) printf(" %s |", scaf_phase_name((scaf_phase)p));
    printf(" handle error / side | packing efficiency | bijective every frame "
           "|\n|---|---|---|---|---|---|---|---|");
    for (int p = 0; p < SCAF_PHASE_COUNT; p++) printf("---|");
    printf("---|---|---|\n");
    for (int k = 0; k < nmesh; k++) {
        char path[4096];
        if (one) snprintf(path, sizeof path, "%s", one);
        else snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        mesh m;
        scaf_error err;
        if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
            fprintf(stderr, "%s: skipped (%s)\n", path, err.message);
            continue;
        }
        scaf_drag_t *d = scaf_drag_new(&o);
        double t0 = now();
        scaf_status st = scaf_drag_set_mesh(d, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
        double setup = now() - t0;
        if (st != SCAF_OK) {
            fprintf(stderr, "%s: %s\n", path, scaf_drag_error(d));
        } else {
            const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
            char label[4352];
            snprintf(label, sizeof label, "%s (%d faces, setup %.1f s)", base, m.nf, setup);
            drag_run(d, 2, frames, label);
            if (!rigid_only) {
                drag_run(d, 0, frames, label);
                drag_run(d, 1, frames, label);
            }
        }
        scaf_drag_destroy(d);
        mesh_free(&m);
    }
    FILE *la = fopen("/proc/loadavg", "r");
    char load[128] = "?";
    if (la) {
        if (!fgets(load, sizeof load, la)) load[0] = 0;
        fclose(la);
    }
    printf("\nload average at the end: %s", load);
    return 0;
}
