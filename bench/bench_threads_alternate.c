/* bench/bench_threads_alternate: one thread against N threads, iteration
 * by iteration in one process.
 *
 * On a shared machine whose speed changes for tens of seconds at a time,
 * two separate runs (bench/threads_phases.py) may fall in different
 * states, and their ratio then measures the host. Here one
 * parametrization (harmonic start, SLIM, tolerance 0) runs its first
 * iteration (the METIS ordering) at one thread, then K more with the
 * thread count switched before each (scaf_set_threads) in the order
 * 1, N, N, 1, 1, N, N, 1, ... so that each count comes as often before
 * as after the other. Consecutive iterations of one run cost nearly the
 * same (same pattern, a scaffold that barely moves), so each adjacent
 * pair (1, N) of that order is a ratio taken within seconds. Prints each
 * iteration's seconds and phases, the per-count medians and their ratios
 * per phase, and the median and range of the pair ratios. Different
 * thread counts sum in another order, so the map differs in its last
 * digits from a run at one count. Timing only: no test depends on it.
 *
 *   build/bench/bench_threads_alternate MESH [K] [N]   (default K = 12, N = 2)
 *
 * Exit status 0, 1 when the mesh cannot be read or a step fails.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_median.h"

#include "mesh/mesh_io.h"
#include "scaf/scaf.h"

static int keep_info(const scaf_iteration_info_t *info, void *user)
{
    *(scaf_iteration_info_t *)user = *info;
    return 0;
}

/* The thread count of counted iteration i: 1, N, N, 1, 1, N, N, 1, ... */
static int threads_at(int i, int nt) { return ((i + 1) / 2) % 2 ? nt : 1; }

/* A table header: `first` (ncols columns), then one column per phase. */
static void phase_header(const char *first, int ncols)
{
    printf("| %s |", first);
    for (int k = 0; k < SCAF_PHASE_COUNT; k++) printf(" %s |", scaf_phase_name((scaf_phase)k));
    printf("\n|");
    for (int k = 0; k < ncols; k++) printf("---|");
    for (int k = 0; k < SCAF_PHASE_COUNT; k++) printf("---|");
    printf("\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_threads_alternate MESH [K] [N]\n");
        return 1;
    }
    int K = argc > 2 ? atoi(argv[2]) : 12, nt = argc > 3 ? atoi(argv[3]) : 2;
    if (K < 2) K = 2;
    if (nt < 2) nt = 2;
    mesh m;
    scaf_error err;
    if (mesh_read(argv[1], &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 1;
    }
    scaf_options_t o = scaf_options_default();
    o.init = SCAF_INIT_HARMONIC;
    o.tolerance = 0;
    o.solver = SCAF_SOLVER_SLIM;
    scaf_set_threads(1);
    scaf_param_t *p = scaf_param_new(&o);
    scaf_iteration_info_t info, *it = malloc(sizeof *it * (size_t)K);
    double *v = malloc(sizeof *v * (size_t)K);
    if (!p || !it || !v || scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL) != SCAF_OK ||
        scaf_param_run(p, 1, keep_info, &info) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], p ? scaf_param_error(p) : "out of memory");
        return 1;
    }
    printf("%s: %d faces; iteration 1 at one thread (%.3f s, not counted), then %d "
           "iterations alternating 1 and %d threads (1, %d, %d, 1, ...)\n\n",
           argv[1], m.nf, info.seconds, K, nt, nt, nt);
    phase_header("iteration | threads | s", 3);
    for (int i = 0; i < K; i++) {
        scaf_set_threads(threads_at(i, nt));
        if (scaf_param_run(p, 1, keep_info, &it[i]) != SCAF_OK) {
            fprintf(stderr, "iteration %d: %s\n", i + 2, scaf_param_error(p));
            return 1;
        }
        printf("| %d | %d | %.4f |", it[i].iteration, threads_at(i, nt), it[i].seconds);
        for (int k = 0; k < SCAF_PHASE_COUNT; k++) printf(" %.4f |", it[i].phase_seconds[k]);
        printf("\n");
        fflush(stdout);
    }
    /* Per count medians, per phase (index SCAF_PHASE_COUNT: the iteration). */
    double med[2][SCAF_PHASE_COUNT + 1];
    for (int c = 0; c < 2; c++)
        for (int k = 0; k <= SCAF_PHASE_COUNT; k++) {
            int n = 0;
            for (int i = 0; i < K; i++)
                if ((threads_at(i, nt) == 1) == (c == 0))
                    v[n++] = k == SCAF_PHASE_COUNT ? it[i].seconds : it[i].phase_seconds[k];
            med[c][k] = bench_median(v, n);
        }
    printf("\n");
    phase_header("threads | iteration", 2);
    for (int c = 0; c < 2; c++) {
        printf("| %d | %.4f |", c ? nt : 1, med[c][SCAF_PHASE_COUNT]);
        for (int k = 0; k < SCAF_PHASE_COUNT; k++) printf(" %.4f |", med[c][k]);
        printf("\n");
    }
    printf("| 1/%d | %.2fx |", nt, med[0][SCAF_PHASE_COUNT] / med[1][SCAF_PHASE_COUNT]);
    for (int k = 0; k < SCAF_PHASE_COUNT; k++)
        printf(" %.2fx |", med[1][k] > 0 ? med[0][k] / med[1][k] : 0.0);
    /* Adjacent pairs of the order, (0, 1), (2, 3), ...: one of each count. */
    int np = 0;
    for (int i = 0; i + 1 < K; i += 2) {
        int one = threads_at(i, nt) == 1 ? i : i + 1, many = one == i ? i + 1 : i;
        v[np++] = it[one].seconds / it[many].seconds;
    }
    double lo = v[0], hi = v[0];
    for (int q = 1; q < np; q++) {
        if (v[q] < lo) lo = v[q];
        if (v[q] > hi) hi = v[q];
    }
    printf("\n\nadjacent pairs (1 thread / %d threads): median %.2fx over %d pairs, range "
           "%.2f-%.2fx; E %.9f\n",
           nt, bench_median(v, np), np, lo, hi, scaf_param_energy(p));
    free(v);
    free(it);
    scaf_param_destroy(p);
    mesh_free(&m);
    return 0;
}
