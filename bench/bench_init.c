/* bench/bench_init: the three starting embeddings compared (tutte,
 * harmonic, mvc).
 *
 * For every mesh: the start's wall time (scaf_param_set_mesh, which also
 * finds the charts; the difference between inits is the embedding), the
 * energy E of the start and after 1, 10 and the last iteration, and the
 * number of iterations each init needs to reach 1.05 times the lowest E
 * any of the three reached (tolerance 0, so every run does all
 * iterations). Disk meshes and bad/plane_holes are one chart each (no
 * UVs passed); the seams meshes pass their UVs so the charts are the seam
 * charts, as the atlas starts them. When harmonic's start energy equals
 * mvc's or tutte's bit for bit, harmonic fell back on every chart
 * (column "fallback"). Data folder: SCAF_DATA_DIR (env) or the compiled
 * default; missing files are skipped. Iterations: 30 (10 above 60k faces,
 * 60 for plane_holes), or --iterations N for all. A second table runs the
 * whole default atlas pipeline on the seams meshes with each init: start
 * E, settle and compact iterations, final E, packing efficiency, seconds.
 * A third table times the embedding alone (opt_embed_chart, best of 5) on
 * the one-chart meshes, with whether it fell back.
 *
 *   OPENBLAS_NUM_THREADS=1 build/bench/bench_init > bench/RESULTS-init.md
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "opt/embed.h"
#include "scaf/atlas.h"
#include "scaf/scaf.h"

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif

#define NINIT 3
#define MAXIT 200

static const char *init_name[NINIT] = {"tutte", "harmonic", "mvc"};
static const scaf_init init_value[NINIT] = {SCAF_INIT_TUTTE, SCAF_INIT_HARMONIC, SCAF_INIT_MVC};

typedef struct run {
    int ok, n;
    double start_s, e0, e[MAXIT];
} run;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    run *r = user;
    if (r->n < MAXIT) r->e[r->n++] = info->energy;
    return 0;
}

static void bench_mesh(const char *dir, const char *rel, int with_uv, int iterations)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    struct stat st;
    if (stat(path, &st) != 0) {
        printf("| %s | (missing) | | | | | | | | |\n", rel);
        return;
    }
    fprintf(stderr, "%s\n", rel);
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
        printf("| %s | read failed: %s | | | | | | | | |\n", rel, err.message);
        return;
    }
    if (iterations > MAXIT) iterations = MAXIT;
    run r[NINIT];
    memset(r, 0, sizeof r);
    const char *msg[NINIT] = {""};
    for (int k = 0; k < NINIT; k++) {
        scaf_options_t o = scaf_options_default();
        o.init = init_value[k];
        o.tolerance = 0;
        scaf_param_t *p = scaf_param_new(&o);
        if (!p) continue;
        double t0 = now();
        scaf_status s = with_uv && m.nuv > 0
            ? scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT)
            : scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
        r[k].start_s = now() - t0;
        if (s == SCAF_OK) {
            r[k].e0 = scaf_param_energy(p);
            s = scaf_param_run(p, iterations, on_iteration, &r[k]);
        }
        r[k].ok = s == SCAF_OK;
        if (!r[k].ok) {
            msg[k] = "failed";
            fprintf(stderr, "%s %s: %s\n", rel, init_name[k], scaf_param_error(p));
        }
        scaf_param_destroy(p);
    }
    double best = INFINITY;
    for (int k = 0; k < NINIT; k++)
        for (int i = 0; r[k].ok && i < r[k].n; i++)
            if (r[k].e[i] < best) best = r[k].e[i];
    const char *fallback = !r[1].ok ? "?"
        : r[1].e0 == r[2].e0        ? "to mvc"
        : r[1].e0 == r[0].e0        ? "to tutte"
                                    : "no";
    for (int k = 0; k < NINIT; k++) {
        if (!r[k].ok) {
            printf("| %s | %s | %s | | | | | | | |\n", rel, init_name[k], msg[k]);
            continue;
        }
        int reach = -1;
        for (int i = 0; i < r[k].n && reach < 0; i++)
            if (r[k].e[i] <= 1.05 * best) reach = i + 1;
        int n = r[k].n;
        char reach_s[32];
        if (reach > 0) snprintf(reach_s, sizeof reach_s, "%d", reach);
        else snprintf(reach_s, sizeof reach_s, "> %d", n);
        printf("| %s | %s | %.4f | %.4g | %.4g | %.4g | %.4g (it %d) | %s | %s |\n", rel,
               init_name[k], r[k].start_s, r[k].e0, n >= 1 ? r[k].e[0] : NAN,
               n >= 10 ? r[k].e[9] : NAN, n ? r[k].e[n - 1] : NAN, n, reach_s,
               k == 1 ? fallback : "");
        fflush(stdout);
    }
    mesh_free(&m);
}

static void bench_atlas(const char *dir, const char *rel)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    struct stat st;
    if (stat(path, &st) != 0) {
        printf("| %s | (missing) | | | | | | |\n", rel);
        return;
    }
    fprintf(stderr, "atlas %s\n", rel);
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
        printf("| %s | read failed: %s | | | | | | |\n", rel, err.message);
        return;
    }
    for (int k = 0; k < NINIT; k++) {
        scaf_atlas_options_t o = scaf_atlas_options_default();
        o.init = init_value[k];
        scaf_atlas_t *a = scaf_atlas_new(&o);
        if (!a) continue;
        double t0 = now();
        scaf_status s = scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT);
        double t1 = now(), e0 = s == SCAF_OK ? scaf_atlas_energy(a) : NAN;
        if (s == SCAF_OK) s = scaf_atlas_run(a, NULL, NULL);
        double t2 = now();
        if (s != SCAF_OK)
            printf("| %s | %s | failed: %s | | | | | |\n", rel, init_name[k], scaf_atlas_error(a));
        else
            printf("| %s | %s | %.4f | %.4g | %d | %d | %.4f | %.3f | %.2f |\n", rel, init_name[k],
                   t1 - t0, e0, scaf_atlas_iterations(a, SCAF_ATLAS_SETTLE),
                   scaf_atlas_iterations(a, SCAF_ATLAS_COMPACT), scaf_atlas_energy(a),
                   scaf_atlas_packing_efficiency(a), t2 - t0);
        fflush(stdout);
        scaf_atlas_destroy(a);
    }
    mesh_free(&m);
}

static void bench_embed(const char *dir, const char *rel)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    struct stat st;
    if (stat(path, &st) != 0) return;
    mesh m;
    mesh_topology t;
    memset(&t, 0, sizeof t);
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) return;
    if (mesh_topology_compute(&m, &t, &err) != SCAF_OK || t.components != 1) {
        mesh_free(&m);
        mesh_topology_free(&t);
        return;
    }
    int nl = t.cx.nloops;
    int *verts = malloc(((size_t)t.cx.loop_start[nl] + 1) * sizeof *verts);
    double *UV = malloc(2 * (size_t)m.nv * sizeof *UV);
    if (verts && UV) {
        for (int k = 0; k < t.cx.loop_start[nl]; k++) verts[k] = m.F[t.cx.loop_he[k]];
        opt_chart_loops L = {nl, t.cx.loop_start, verts, -1};
        static const opt_embed_method meth[NINIT] = {OPT_EMBED_TUTTE, OPT_EMBED_HARMONIC,
                                                     OPT_EMBED_MVC};
        printf("| %s | %d |", rel, m.nf);
        for (int k = 0; k < NINIT; k++) {
            double best = INFINITY;
            int fb = 0;
            scaf_status s = SCAF_OK;
            for (int r = 0; r < 5 && s == SCAF_OK; r++) {
                double t0 = now();
                s = opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, meth[k], UV, &fb, &err);
                double dt = now() - t0;
                if (dt < best) best = dt;
            }
            if (s != SCAF_OK) printf(" failed |");
            else printf(" %.4f%s |", best, fb ? " (fell back)" : "");
        }
        printf("\n");
        fflush(stdout);
    }
    free(verts);
    free(UV);
    mesh_topology_free(&t);
    mesh_free(&m);
}

int main(int argc, char **argv)
{
    int iterations = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--iterations") && i + 1 < argc) iterations = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_init [--iterations N]\n");
            return 2;
        }
    }
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir) dir = SCAF_DATA_DIR;
    static const struct {
        const char *rel;
        int uv, it;
    } meshes[] = {
        {"disk/aphrodite.obj", 0, 10},
        {"disk/bull_1.obj", 0, 30},
        {"disk/camel_b.obj", 0, 30},
        {"disk/camelhead.off", 0, 30},
        {"disk/hand_lowres.obj", 0, 30},
        {"disk/hilbert.obj", 0, 30},
        {"disk/mountain.obj", 0, 30},
        {"bad/plane_holes.obj", 0, 60},
        {"seams/blub.obj", 1, 30},
        {"seams/spot.obj", 1, 30},
        {"seams/human_neutral.obj", 1, 30},
        {"seams/myles_eight_seamed.obj", 1, 30},
        {"seams/myles_knot1_seamed.obj", 1, 30},
    };
    printf("| mesh | init | start s | E start | E it 1 | E it 10 | E last | iterations to 1.05 x "
           "best | harmonic fell back |\n");
    printf("|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; i++)
        bench_mesh(dir, meshes[i].rel, meshes[i].uv, iterations > 0 ? iterations : meshes[i].it);
    printf("\nEmbedding alone (opt_embed_chart, seconds, best of 5):\n\n");
    printf("| mesh | faces | tutte | harmonic | mvc |\n|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; i++)
        if (!meshes[i].uv) bench_embed(dir, meshes[i].rel);
    printf("\nAtlas (default options, seams meshes):\n\n");
    printf("| mesh | init | set_mesh s | E start | settle its | compact its | E final | efficiency "
           "| total s |\n");
    printf("|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; i++)
        if (meshes[i].uv) bench_atlas(dir, meshes[i].rel);
    return 0;
}
