/* bench/bench_memory: resident memory of a parametrization, per phase.
 *
 * Reads MESH, sets it up (charts, harmonic start) and runs K iterations
 * through the public API, while a sampler thread reads the process's
 * resident set (/proc/self/statm) every millisecond. Each iteration's
 * phase timings (scaf_iteration_info_t) are laid end to end in the order the
 * loop runs them (scaffold, assembly, analysis, factorization, solve, line
 * search, other), ending when the iteration callback runs, and every
 * sample is attributed to the phase whose window holds it: the table gives
 * the highest resident memory seen in each phase (GB), per iteration, with
 * the peak after reading and after the setup, and the kernel's high-water
 * mark VmHWM at the end. The windows are approximate where a phase is
 * split (the loop's "other" time before and after the step, a regularized
 * refactorization after a failed one): a sample is attributed to a
 * neighbouring phase at worst.
 *
 * K = 0 runs to convergence instead (the default tolerance, cap 200
 * iterations), for scale runs; the map is then checked with the exact
 * bijectivity checker (geom/bijectivity) and the verdict printed.
 *
 *   build/bench/bench_memory MESH [K]    (default K = 3; OPENBLAS_NUM_THREADS=1 advised)
 *
 * Exit status 0, 1 when the mesh cannot be read or a step fails.
 */
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "scaf/scaf.h"

enum { MAX_SAMPLES = 1 << 21 };

typedef struct sampler {
    double *t;    /* sample times (monotonic seconds) */
    double *rss;  /* resident set, bytes */
    atomic_int n; /* samples taken */
    atomic_int stop;
} sampler;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double rss_bytes(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long size = 0, res = 0;
    if (f) {
        if (fscanf(f, "%ld %ld", &size, &res) != 2) res = 0;
        fclose(f);
    }
    return (double)res * (double)sysconf(_SC_PAGESIZE);
}

/* VmHWM of /proc/self/status in bytes (0 when unreadable). */
static double hwm_bytes(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    double kb = 0;
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, "VmHWM:", 6) == 0) kb = atof(line + 6);
    if (f) fclose(f);
    return kb * 1024.0;
}

static void *sample_loop(void *arg)
{
    sampler *s = arg;
    while (!atomic_load(&s->stop)) {
        int k = atomic_load(&s->n);
        if (k < MAX_SAMPLES) {
            s->t[k] = now();
            s->rss[k] = rss_bytes();
            atomic_store(&s->n, k + 1);
        }
        struct timespec ts = {0, 1000000};
        nanosleep(&ts, NULL);
    }
    return NULL;
}

/* The highest sample in [t0, t1) (0 when there is none). */
static double window_max(sampler *s, double t0, double t1)
{
    double m = 0;
    int n = atomic_load(&s->n);
    for (int k = 0; k < n; k++)
        if (s->t[k] >= t0 && s->t[k] < t1 && s->rss[k] > m) m = s->rss[k];
    return m;
}

static const int order[SCAF_PHASE_COUNT] = {
    SCAF_PHASE_SCAFFOLD, SCAF_PHASE_ASSEMBLY,    SCAF_PHASE_ANALYSIS, SCAF_PHASE_FACTORIZATION,
    SCAF_PHASE_SOLVE,    SCAF_PHASE_LINE_SEARCH, SCAF_PHASE_OTHER};
static const char *names[SCAF_PHASE_COUNT] = {"assembly",    "analysis", "factorization", "solve",
                                              "line search", "scaffold", "other"};

typedef struct run {
    sampler *s;
} run;

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    run *r = user;
    double t1 = now(), t = t1 - info->seconds;
    printf("| %d | %.3f |", info->iteration, info->seconds);
    for (int q = 0; q < SCAF_PHASE_COUNT; q++) {
        int ph = order[q];
        double end = q == SCAF_PHASE_COUNT - 1 ? t1 : t + info->phase_seconds[ph];
        double m = window_max(r->s, t, end);
        if (m > 0) printf(" %.2f |", m / 1e9);
        else printf(" - |");
        t = end;
    }
    printf(" %.2f |\n", hwm_bytes() / 1e9);
    fflush(stdout);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_memory MESH [K]\n");
        return 1;
    }
    int K = argc > 2 ? atoi(argv[2]) : 3;
    if (K < 0) K = 3;
    sampler s = {malloc(sizeof(double) * MAX_SAMPLES), malloc(sizeof(double) * MAX_SAMPLES), 0, 0};
    if (!s.t || !s.rss) return 1;
    pthread_t th;
    if (pthread_create(&th, NULL, sample_loop, &s) != 0) return 1;
    double t_start = now();
    mesh m;
    scaf_error err;
    if (mesh_read(argv[1], &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 1;
    }
    double t_read = now(), hwm_read = hwm_bytes();
    scaf_options_t o = scaf_options_default();
    o.init = SCAF_INIT_HARMONIC;
    if (K > 0) o.tolerance = 0;
    else o.max_iterations = 200;
    scaf_param_t *p = scaf_param_new(&o);
    scaf_status st =
        p ? scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL) : SCAF_ERR_NOMEM;
    double t_setup = now(), hwm_setup = hwm_bytes();
    printf("%s: %d vertices, %d faces; resident memory, GB (sampled every ms; VmHWM: the kernel's "
           "high-water mark)\n\n",
           argv[1], m.nv, m.nf);
    printf("read: %.1f s, peak %.2f GB (VmHWM %.2f); setup (charts, harmonic start): %.1f s, peak "
           "%.2f GB (VmHWM %.2f)\n\n",
           t_read - t_start, window_max(&s, t_start, t_read) / 1e9, hwm_read / 1e9,
           t_setup - t_read, window_max(&s, t_read, t_setup) / 1e9, hwm_setup / 1e9);
    printf("| iteration | s |");
    for (int q = 0; q < SCAF_PHASE_COUNT; q++) printf(" %s |", names[order[q]]);
    printf(" VmHWM after |\n|---|---|");
    for (int q = 0; q < SCAF_PHASE_COUNT; q++) printf("---|");
    printf("---|\n");
    run r = {&s};
    if (st == SCAF_OK) st = scaf_param_run(p, K, on_iteration, &r);
    if (st != SCAF_OK) fprintf(stderr, "failed: %s\n", p ? scaf_param_error(p) : "out of memory");
    if (st == SCAF_OK) {
        printf("\n%d iterations, E = %.9f, stop reason %s, %.1f s since the start\n",
               scaf_param_iterations(p), scaf_param_energy(p),
               scaf_stop_reason_name(scaf_param_stop_reason(p)), now() - t_start);
        fflush(stdout);
    }
    if (st == SCAF_OK && K == 0) {
        int nuv = scaf_param_uv_count(p);
        double *UV = malloc(sizeof(double) * 2 * (size_t)nuv);
        int *FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
        bij_report rep;
        scaf_error e2;
        if (!UV || !FT || scaf_param_get_uv(p, UV, FT) != SCAF_OK ||
            bij_check(nuv, UV, m.nf, FT, NULL, NULL, &rep, &e2) != SCAF_OK)
            st = SCAF_ERR_NOMEM;
        else
            printf("exact check: %s (%lld flipped, %lld degenerate, %lld crossings)\n",
                   rep.bijective ? "bijective" : "NOT bijective", (long long)rep.flipped,
                   (long long)rep.degenerate, rep.boundary_crossings);
        free(UV);
        free(FT);
    }
    atomic_store(&s.stop, 1);
    pthread_join(th, NULL);
    printf("\nVmHWM at the end: %.2f GB\n", hwm_bytes() / 1e9);
    scaf_param_destroy(p);
    mesh_free(&m);
    free(s.t);
    free(s.rss);
    return st == SCAF_OK ? 0 : 1;
}
