/* bench/bench_param: seconds per SCAF iteration and where they go.
 *
 * Runs the parametrization (harmonic start, as the reference numbers were
 * measured) on disk/camel_b.obj (50 iterations), disk/camelhead.off (50),
 * disk/aphrodite.obj (10) and, with --large, large/aphrodite_subdiv16x.obj.gz
 * (100 iterations, or --large-iterations N). Prints a Markdown table: E
 * reached, median wall seconds per iteration, process CPU seconds per
 * iteration, the phase split (summed over iterations), the median
 * factorization time and the ratio iteration / factorization (how close an
 * iteration is to its floor, one CHOLMOD factorization), and the peak
 * resident memory. Run with OPENBLAS_NUM_THREADS=1 for single-threaded
 * numbers. No ratio against libigl here: a reference timing written down
 * once is only comparable with a run in the same minutes, so speed against
 * libigl is measured by bench/side_by_side.py (both programs interleaved).
 * The reference energies printed are libigl's E after the same number of
 * iterations from the same harmonic start (deterministic). Data folder:
 * SCAF_DATA_DIR (env) or the compiled default; missing files are skipped.
 *
 *   build/bench/bench_param [--large] [--large-iterations N] > bench/RESULTS-param.md
 */
#include <stdio.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include "bench_median.h"

#include "mesh/mesh_io.h"
#include "scaf/scaf.h"

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif

typedef struct run_log {
    int n, cap;
    scaf_iteration_info_t *it;
    double *cpu;
    double cpu_last;
} run_log;

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    run_log *r = user;
    if (r->n == r->cap) {
        r->cap = r->cap ? 2 * r->cap : 64;
        r->it = realloc(r->it, sizeof *r->it * (size_t)r->cap);
        r->cpu = realloc(r->cpu, sizeof *r->cpu * (size_t)r->cap);
        if (!r->it || !r->cpu) return 1;
    }
    double c = cpu_now();
    r->it[r->n] = *info;
    r->cpu[r->n] = c - r->cpu_last;
    r->cpu_last = c;
    r->n++;
    fprintf(stderr, "\r  iteration %d  E = %.5f  %.3f s   ", info->iteration, info->energy,
            info->seconds);
    return 0;
}

static void bench(const char *rel, int iterations, const char *ref_energy)
{
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir || !*dir) dir = SCAF_DATA_DIR;
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    struct stat st;
    if (stat(path, &st) != 0) {
        printf("| %s | (missing) | | | | | | | |\n", rel);
        return;
    }
    fprintf(stderr, "%s\n", rel);
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
        printf("| %s | read failed: %s | | | | | | | |\n", rel, err.message);
        return;
    }
    scaf_options_t o = scaf_options_default();
    o.init = SCAF_INIT_HARMONIC;
    o.tolerance = 0;
    scaf_param_t *p = scaf_param_new(&o);
    scaf_status s = scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
    run_log r = {0};
    if (s == SCAF_OK) {
        r.cpu_last = cpu_now();
        s = scaf_param_run(p, iterations, on_iteration, &r);
    }
    fprintf(stderr, "\n");
    if (s != SCAF_OK) {
        printf("| %s | failed: %s | | | | | | | |\n", rel, scaf_param_error(p));
        scaf_param_destroy(p);
        mesh_free(&m);
        return;
    }
    double *w = malloc(sizeof(double) * (size_t)r.n), *f = malloc(sizeof(double) * (size_t)r.n);
    double phase[SCAF_PHASE_COUNT] = {0}, total = 0;
    for (int i = 0; i < r.n; i++) {
        w[i] = r.it[i].seconds;
        f[i] = r.it[i].phase_seconds[SCAF_PHASE_FACTORIZATION];
        total += r.it[i].seconds;
        for (int k = 0; k < SCAF_PHASE_COUNT; k++) phase[k] += r.it[i].phase_seconds[k];
    }
    double mw = bench_median(w, r.n), mf = bench_median(f, r.n), mc = bench_median(r.cpu, r.n);
    int dom = 0;
    for (int k = 1; k < SCAF_PHASE_COUNT; k++)
        if (phase[k] > phase[dom]) dom = k;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    char split[512];
    int len = 0;
    for (int k = 0; k < SCAF_PHASE_COUNT; k++)
        len += snprintf(split + len, sizeof split - (size_t)len, "%s%s %.0f%%", k ? ", " : "",
                        scaf_phase_name((scaf_phase)k), total > 0 ? 100 * phase[k] / total : 0.0);
    printf("| %s | %d | %d | %.5f (ref %s) | %.4f | %.4f | %s | %.4f (%.2fx) | %.0f MB |\n", rel,
           m.nf, r.n, scaf_param_energy(p), ref_energy, mw, mc, split, mf, mf > 0 ? mw / mf : 0.0,
           ru.ru_maxrss / 1024.0);
    printf("<!-- %s: dominant phase %s; total %.2f s -->\n", rel, scaf_phase_name((scaf_phase)dom),
           total);
    fflush(stdout);
    free(w);
    free(f);
    free(r.it);
    free(r.cpu);
    scaf_param_destroy(p);
    mesh_free(&m);
}

int main(int argc, char **argv)
{
    int large = 0, large_its = 100;
#ifdef __GLIBC__
    /* as the scaf program does (tools/main.c): reuse freed factor memory */
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1); /* never give the heap back */
#endif
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--large")) large = 1;
        else if (!strcmp(argv[i], "--large-iterations") && i + 1 < argc)
            large_its = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_param [--large] [--large-iterations N]\n");
            return 2;
        }
    }
    printf("| mesh | faces | iterations | E reached | median s/it (wall) | median s/it (CPU) | "
           "phase split | median factorization s (it / fact) | peak RSS |\n");
    printf("|---|---|---|---|---|---|---|---|---|\n");
    bench("disk/camel_b.obj", 50, "4.10928 @50");
    bench("disk/camelhead.off", 50, "7.44660 @50");
    bench("disk/aphrodite.obj", 10, "6.37446 @10");
    if (large) bench("large/aphrodite_subdiv16x.obj.gz", large_its, "-");
    return 0;
}
