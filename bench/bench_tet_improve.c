/* bench/bench_tet_improve: the scaffold improvement pass (tet_improve)
 * on the initial TetGen scaffold (3x box, 8 x 8 squares per side) of an
 * icosphere and of closed meshes of ../shared/data:
 *   initial  a thorough improvement of TetGen's output (no budget, up to
 *            20 passes): what a provider does once, when it builds;
 *   again    a pass with the default options right after (nothing moved:
 *            the floor of an iteration's cost);
 *   moved    50 rounds of: random valid moves of every vertex but the
 *            box's (surface included, each toward a random neighbour by
 *            up to 30%, kept when its tets stay positive), as a step of
 *            the loop would, then a default pass. Time is the mean pass,
 *            quality before/after the last round, tets after the first
 *            and the last rounds (growth), operations summed.
 * Time: CPU seconds of the process (the machine is shared: wall time
 * varies 2-3x with the load); initial and again best of 3.
 * Usage: bench_tet_improve [mesh names...] (default bunny.obj armadillo.obj);
 * TET_IMPROVE_GOAL / _TRIES / _PASSES / _OPS override the defaults. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom/tet_box_mesh.h"
#include "geom/tet_orient.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "scaffold/tet_improve.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t rng_next(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return *s >> 11;
}

/* Random valid moves of the vertices that are not fixed, mesh ones
 * included (vertex -> tets lists so it stays linear). */
static void perturb(tet_scaffold *s, double reach, uint64_t seed)
{
    int *start = calloc((size_t)s->nv + 1, sizeof(int));
    int *list = malloc(sizeof(int) * 4 * (size_t)s->nt),
        *fill = malloc(sizeof(int) * (size_t)s->nv);
    if (!start || !list || !fill) exit(1);
    for (int i = 0; i < 4 * s->nt; i++) start[s->T[i] + 1]++;
    for (int v = 0; v < s->nv; v++) start[v + 1] += start[v];
    memcpy(fill, start, sizeof(int) * (size_t)s->nv);
    for (int i = 0; i < 4 * s->nt; i++) list[fill[s->T[i]]++] = i / 4;
    for (int v = 0; v < s->nv; v++) {
        if (s->fixed[v] || start[v] == start[v + 1]) continue;
        int t = list[start[v] + (int)(rng_next(&seed) % (uint64_t)(start[v + 1] - start[v]))];
        int u = s->T[4 * t + (int)(rng_next(&seed) % 4)];
        if (u == v) continue;
        double f = reach * (double)(rng_next(&seed) % 1000) / 1000.0, old[3];
        memcpy(old, s->P + 3 * v, sizeof old);
        for (int k = 0; k < 3; k++) s->P[3 * v + k] += f * (s->P[3 * u + k] - old[k]);
        for (int i = start[v]; i < start[v + 1]; i++) {
            const int *q = s->T + 4 * list[i];
            if (tet_orientation(s->P + 3 * q[0], s->P + 3 * q[1], s->P + 3 * q[2],
                                s->P + 3 * q[3]) <= 0) {
                memcpy(s->P + 3 * v, old, sizeof old);
                break;
            }
        }
    }
    free(start);
    free(list);
    free(fill);
}

static void report(const char *name, const char *what, double secs, const tet_improve_stats *st,
                   int tets_first)
{
    printf("| %s | %s | %.4f | %d -> %d | %.3f -> %.3f | %.3f -> %.3f "
           "| %lld / %lld / %lld / %lld / %lld / %lld / %lld | %lld |\n",
           name, what, secs, tets_first, st->tets_after, st->min_before, st->min_after,
           st->p5_before, st->p5_after, st->flip23, st->flip32, st->edge_removal, st->multi_face,
           st->smooth, st->contract, st->split, st->tries);
}

static void add_counts(tet_improve_stats *sum, const tet_improve_stats *st)
{
    sum->flip23 += st->flip23, sum->flip32 += st->flip32, sum->edge_removal += st->edge_removal;
    sum->multi_face += st->multi_face;
    sum->smooth += st->smooth, sum->contract += st->contract, sum->split += st->split;
    sum->tries += st->tries;
}

static void run(const char *name, const mesh *m, const tet_improve_options *o)
{
    double lo[3], hi[3];
    tet_box_mesh tm;
    tet_box_around(m->nv, m->V, 3, lo, hi);
    if (tet_box_mesh_build(m->nv, m->V, m->nf, m->F, lo, hi, 8, &tm, NULL) != SCAF_OK) return;
    tet_improve_options thorough = *o;
    thorough.max_tries = 0, thorough.max_passes = 20;
    double best[2] = {1e30, 1e30};
    tet_improve_stats st[2];
    tet_scaffold s;
    for (int rep = 0; rep < 3; rep++) {
        if (tet_scaffold_from_box_mesh(&s, &tm, m->nf, m->F, NULL) != SCAF_OK) exit(1);
        for (int k = 0; k < 2; k++) {
            double t0 = cpu_now();
            if (tet_improve(&s, NULL, k ? o : &thorough, &st[k], NULL) != SCAF_OK) exit(1);
            double t1 = cpu_now();
            if (t1 - t0 < best[k]) best[k] = t1 - t0;
        }
        if (rep < 2) tet_scaffold_free(&s);
    }
    report(name, "initial", best[0], &st[0], st[0].tets_before);
    report(name, "again", best[1], &st[1], st[1].tets_before);
    tet_improve_stats sum, one;
    memset(&sum, 0, sizeof sum);
    double total = 0;
    int first = 0;
    const int rounds = 50;
    for (int r = 0; r < rounds; r++) {
        perturb(&s, 0.3, 1000 + (uint64_t)r);
        double t0 = cpu_now();
        if (tet_improve(&s, NULL, o, &one, NULL) != SCAF_OK) exit(1);
        total += cpu_now() - t0;
        if (r == 0) first = one.tets_after;
        add_counts(&sum, &one);
    }
    sum.tets_after = one.tets_after, sum.min_before = one.min_before;
    sum.min_after = one.min_after, sum.p5_before = one.p5_before, sum.p5_after = one.p5_after;
    report(name, "moved x50", total / rounds, &sum, first);
    tet_scaffold_free(&s);
    tet_box_mesh_free(&tm);
}

int main(int argc, char **argv)
{
    tet_improve_options o;
    tet_improve_options_default(&o);
    const char *env = getenv("TET_IMPROVE_OPS");
    if (env) o.ops = (unsigned)atoi(env);
    if ((env = getenv("TET_IMPROVE_GOAL"))) o.quality_goal = atof(env);
    if ((env = getenv("TET_IMPROVE_TRIES"))) o.max_tries = atoll(env);
    if ((env = getenv("TET_IMPROVE_PASSES"))) o.max_passes = atoi(env);
    printf("options: goal %.2f, passes %d, tries %lld, ops %u\n\n", o.quality_goal, o.max_passes,
           o.max_tries, o.ops);
    printf("| mesh | scaffold | CPU s per pass | tets | min quality | 5th percentile | 2-3 / 3-2 / "
           "edge removal / multi-face / smooth / contract / split | tries "
           "|\n|---|---|---|---|---|---|---|---|\n");
    mesh m;
    if (mesh_sample_make("icosphere", 10, &m, NULL) == SCAF_OK) {
        run("icosphere 10", &m, &o);
        mesh_free(&m);
    }
    static const char *deflt[] = {"bunny.obj", "armadillo.obj"};
    int n = argc > 1 ? argc - 1 : 2;
    for (int i = 0; i < n; i++) {
        const char *f = argc > 1 ? argv[i + 1] : deflt[i];
        char path[1024];
        snprintf(path, sizeof path, "%s/closed/%s", SCAF_DATA_DIR, f);
        mesh_read_info info;
        if (mesh_read(path, &m, &info, NULL) != SCAF_OK) continue;
        run(f, &m, &o);
        mesh_free(&m);
    }
    return 0;
}
