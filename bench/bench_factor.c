/* bench/bench_factor: one SCAF system against its factorization (the floor).
 *
 * Runs K SCAF iterations (harmonic start) on a single-disk mesh, keeps the
 * last assembled system and then times, on that very matrix, interleaved
 * (so machine load hits every variant alike), median of R repetitions:
 * the symbolic analysis with the loop's own permutation and the numerical
 * factorization, for CHOLMOD's default supernode relaxation and looser
 * ones, for an alternative placement of the scaffold unknowns (those not
 * next to the chart first), with one or two OpenBLAS threads. Prints n,
 * nnz(A), the stored factor entries, the flops of the exact factor, the
 * supernode count, the time of one solve with one right-hand side (what a
 * SLIM step adds to the factorization; it reads the stored factor twice,
 * so relaxation that helps the factorization costs the solve), and the
 * median iteration time of the run for the ratio iteration / factorization. A missing or non-disk mesh, or a failing
 * step, prints the reason and exits with status 1.
 *
 * With T = 1 the variants are timed in process CPU seconds (a loaded
 * machine's waits excluded; the iteration time stays wall-clock).
 * The variants with T BLAS threads run (T = 1 by default; after a
 * two-thread call OpenBLAS's second thread keeps spinning for a while, so
 * mixing thread counts in one run would slow the one-thread variants).
 *
 *   build/bench/bench_factor [MESH.obj|.off] [K] [R] [T]   (default camelhead, 5, 5, 1)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cholmod.h>

#include "bench_median.h"

#include "base/timer.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "opt/cholmod_view.h"
#include "opt/embed.h"
#include "scaffold/scaf_loop.h"

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif

extern void openblas_set_num_threads(int) __attribute__((weak));
extern int omp_get_max_active_levels(void) __attribute__((weak));
extern void omp_set_max_active_levels(int) __attribute__((weak));

static int cmp_ll(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = *(const long long *)b;
    return (x > y) - (x < y);
}

/* The boundary loop of a single-boundary disk, in order (mesh/topology's
 * ordered loop: faces on its left), or 0. */
static int boundary_loop(const mesh *m, int *loop)
{
    mesh_topology t;
    scaf_error e;
    if (mesh_topology_compute(m, &t, &e) != SCAF_OK) return 0;
    int n = 0;
    if (t.cx.nloops == 1 && t.cx.loop_ordered[0])
        for (; n < t.cx.loop_start[1]; n++) loop[n] = m->F[t.cx.loop_he[n]];
    mesh_topology_free(&t);
    return n;
}

/* The clock of the variants: with one thread the process's CPU seconds
 * (waiting for a core on a loaded machine excluded), else wall seconds. */
static int use_cpu_clock;

static double clock_now(void)
{
    if (!use_cpu_clock) return timer_now();
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Factor A (upper CSC wrapper) with the analysis Lsym's relaxation, time. */
static double time_factor(cholmod_sparse *A, cholmod_factor *L, cholmod_common *cm)
{
    double t0 = clock_now();
    int lv = omp_get_max_active_levels ? omp_get_max_active_levels() : -1;
    if (lv >= 0) omp_set_max_active_levels(0);
    cholmod_factorize(A, L, cm);
    if (lv >= 0) omp_set_max_active_levels(lv);
    return clock_now() - t0;
}

/* One solve with one right-hand side (a SLIM step's), time; the result
 * and workspaces are allocated before the clock starts, as the solver
 * keeps them. */
static double time_solve(cholmod_factor *L, cholmod_common *cm)
{
    cholmod_dense *B = cholmod_ones(L->n, 1, CHOLMOD_REAL, cm), *X = NULL, *Y = NULL, *E = NULL;
    int lv = omp_get_max_active_levels ? omp_get_max_active_levels() : -1;
    if (lv >= 0) omp_set_max_active_levels(0);
    cholmod_solve2(CHOLMOD_A, L, B, NULL, &X, NULL, &Y, &E, cm);
    double t0 = clock_now();
    cholmod_solve2(CHOLMOD_A, L, B, NULL, &X, NULL, &Y, &E, cm);
    double t = clock_now() - t0;
    if (lv >= 0) omp_set_max_active_levels(lv);
    cholmod_free_dense(&B, cm);
    cholmod_free_dense(&X, cm);
    cholmod_free_dense(&Y, cm);
    cholmod_free_dense(&E, cm);
    return t;
}

static cholmod_factor *analyze(cholmod_sparse *A, int *perm, cholmod_common *cm, double *t)
{
    cm->nmethods = 1;
    cm->method[0].ordering = CHOLMOD_GIVEN;
    cm->postorder = 1;
    double t0 = clock_now();
    int lv = omp_get_max_active_levels ? omp_get_max_active_levels() : -1;
    if (lv >= 0) omp_set_max_active_levels(0);
    cholmod_factor *L = cholmod_analyze_p(A, perm, NULL, 0, cm);
    if (lv >= 0) omp_set_max_active_levels(lv);
    *t = clock_now() - t0;
    return L;
}

int main(int argc, char **argv)
{
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir || !*dir) dir = SCAF_DATA_DIR;
    char path[2048];
    if (argc > 1) snprintf(path, sizeof path, "%s", argv[1]);
    else snprintf(path, sizeof path, "%s/disk/camelhead.off", dir);
    int K = argc > 2 ? atoi(argv[2]) : 5, R = argc > 3 ? atoi(argv[3]) : 5;
    int T = argc > 4 ? atoi(argv[4]) : 1; /* BLAS threads of the variants run */
    if (K < 1) K = 1;
    if (R < 1) R = 1;
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        return 1;
    }
    int *loop = malloc(sizeof(int) * (size_t)m.nv), st0[2];
    double *uv = malloc(sizeof(double) * 2 * (size_t)m.nv);
    int nb = loop && uv ? boundary_loop(&m, loop) : 0;
    if (!nb) {
        fprintf(stderr, "%s: not a single-boundary disk\n", path);
        return 1;
    }
    st0[0] = 0;
    st0[1] = nb;
    opt_chart_loops ol = {1, st0, loop, 0};
    if (opt_embed_chart(m.nv, m.V, m.nf, m.F, &ol, OPT_EMBED_HARMONIC, uv, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "embed: %s\n", err.message);
        return 1;
    }
    scaf_loop L;
    if (scaf_loop_init(&L, m.nv, m.V, m.nf, m.F, uv, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "loop: %s\n", err.message);
        return 1;
    }
    double *it = malloc(sizeof(double) * (size_t)K), fsum = 0;
    if (!it) return 1;
    for (int k = 0; k < K; k++) {
        scaf_iteration_info_t info;
        if (scaf_loop_step(&L, &info, &err) != SCAF_OK) {
            fprintf(stderr, "step: %s\n", err.message);
            return 1;
        }
        it[k] = info.seconds;
        if (k == K - 1) fsum = info.phase_seconds[SCAF_PHASE_FACTORIZATION];
    }
    double it_med = K > 1 ? bench_median(it + 1, K - 1) : it[0]; /* the first has METIS */

    /* The last system and the loop's permutation. */
    const opt_csc *A = scaf_loop_last_system(&L);
    cholmod_sparse S = opt_csc_cholmod_view(A);
    size_t nm = 2 * (size_t)L.nv;
    int *perm = malloc(sizeof(int) * (size_t)A->n);
    int *perm2 = malloc(sizeof(int) * (size_t)A->n), np2 = 0, nring = 0;
    char *ring = calloc((size_t)A->n / 2 + 1, 1);
    if (!perm || !perm2 || !ring) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    memcpy(perm, scaf_loop_mesh_ordering(&L), nm * sizeof(int));
    for (size_t k = nm; k < (size_t)A->n; k++) perm[k] = (int)k;

    /* Variant ordering: scaffold vertices not adjacent to the chart
     * ("outer") first, then the mesh order, then the ring next to the
     * chart (which the mesh elimination turns into a clique). */
    {
        int nvs = A->n / 2;
        for (int J = L.nv; J < nvs; J++) {
            int col = 2 * J + 1;
            for (int k = A->colptr[col]; k < A->colptr[col + 1]; k++)
                if (A->rowidx[k] / 2 < L.nv) {
                    ring[J] = 1;
                    break;
                }
        }
        for (int J = L.nv; J < nvs; J++)
            if (!ring[J]) {
                perm2[np2++] = 2 * J;
                perm2[np2++] = 2 * J + 1;
            }
        memcpy(perm2 + np2, scaf_loop_mesh_ordering(&L), nm * sizeof(int));
        np2 += (int)nm;
        for (int J = L.nv; J < nvs; J++)
            if (ring[J]) {
                perm2[np2++] = 2 * J;
                perm2[np2++] = 2 * J + 1;
                nring++;
            }
        free(ring);
    }
    printf("scaffold vertices next to the chart: %d of %zu\n", nring, ((size_t)A->n - nm) / 2);
    /* Mesh-mesh couplings that only the scaffold makes (a scaffold
     * triangle with two boundary vertices that share no mesh edge): they
     * change the elimination tree of the mesh block, which is why the
     * mesh block's symbolic factor cannot simply be kept while the
     * scaffold changes. */
    {
        size_t ne = 3 * (size_t)m.nf, extra = 0, mm = 0;
        long long *key = malloc(sizeof *key * ne);
        if (!key) return 1;
        for (int f = 0; f < m.nf; f++)
            for (int j = 0; j < 3; j++) {
                long long a = m.F[3 * f + j], b = m.F[3 * f + (j + 1) % 3];
                key[3 * (size_t)f + j] = a < b ? a * m.nv + b : b * m.nv + a;
            }
        qsort(key, ne, sizeof *key, cmp_ll);
        for (int J = 0; J < L.nv; J++)
            for (int k = A->colptr[2 * J + 1]; k < A->colptr[2 * J + 2]; k++) {
                int I = A->rowidx[k] / 2;
                if (I >= J || A->rowidx[k] % 2) continue;
                long long q = (long long)I * m.nv + J;
                mm++;
                if (!bsearch(&q, key, ne, sizeof *key, cmp_ll)) extra++;
            }
        free(key);
        printf("mesh-mesh vertex couplings: %zu, of which %zu from the scaffold only\n", mm, extra);
    }
    cholmod_common cm;
    cholmod_start(&cm);
    cm.print = 0;
    cm.supernodal = CHOLMOD_SUPERNODAL;
    cm.final_ll = 1;
    enum { NVAR_MAX = 16 };
    typedef struct variant {
        const char *name;
        int nrelax[3];
        double zrelax[3];
        int threads;
        int alt;
    } variant;
    variant var[] = {
        {"default relax, 1 thread", {4, 16, 48}, {0.8, 0.1, 0.05}, 1, 0},
        {"relax x2, 1 thread", {8, 32, 96}, {0.8, 0.1, 0.05}, 1, 0},
        {"relax x3, 1 thread", {12, 48, 144}, {0.8, 0.1, 0.05}, 1, 0},
        {"relax x2 looser, 1 thread", {8, 32, 96}, {0.8, 0.2, 0.1}, 1, 0},
        {"relax x4, 1 thread", {16, 64, 192}, {0.8, 0.1, 0.05}, 1, 0},
        {"relax x4 looser, 1 thread", {16, 64, 192}, {0.8, 0.2, 0.1}, 1, 0},
        {"relax x8, 1 thread", {32, 128, 384}, {0.8, 0.1, 0.05}, 1, 0},
        {"default relax, 2 threads", {4, 16, 48}, {0.8, 0.1, 0.05}, 2, 0},
        {"relax x4, outer scaffold first, 1 thread", {16, 64, 192}, {0.8, 0.1, 0.05}, 1, 1},
        {"relax x4, 2 threads", {16, 64, 192}, {0.8, 0.1, 0.05}, 2, 0},
        {"relax x2, 2 threads", {8, 32, 96}, {0.8, 0.1, 0.05}, 2, 0},
    };
    int nvar = (int)(sizeof var / sizeof var[0]);
    if (nvar > NVAR_MAX) nvar = NVAR_MAX;
    use_cpu_clock = T == 1;
    cholmod_factor *F[NVAR_MAX];
    double ta[NVAR_MAX][64], tf[NVAR_MAX][64], ts[NVAR_MAX][64], lnz[NVAR_MAX], fl[NVAR_MAX];
    long nsuper[NVAR_MAX];
    for (int r = 0; r < R && r < 64; r++)
        for (int v = 0; v < nvar; v++) {
            if (var[v].threads != T) continue;
            for (int q = 0; q < 3; q++) {
                cm.nrelax[q] = (size_t)var[v].nrelax[q];
                cm.zrelax[q] = var[v].zrelax[q];
            }
            if (openblas_set_num_threads) openblas_set_num_threads(var[v].threads);
            F[v] = analyze(&S, var[v].alt ? perm2 : perm, &cm, &ta[v][r]);
            if (!F[v]) {
                fprintf(stderr, "analysis failed\n");
                return 1;
            }
            tf[v][r] = time_factor(&S, F[v], &cm);
            ts[v][r] = time_solve(F[v], &cm);
            fl[v] = cm.fl;
            nsuper[v] = (long)F[v]->nsuper;
            lnz[v] = (double)F[v]->xsize; /* stored entries (relaxed supernodes hold zeros) */
            cholmod_free_factor(&F[v], &cm);
        }
    if (openblas_set_num_threads) openblas_set_num_threads(1);
    printf("%s: %d vertices, %d faces; system n = %d, nnz(A) = %d (upper), scaffold unknowns %zu; "
           "%d iterations, median iteration %.4f s (last: factorization %.4f s)\n",
           path, m.nv, m.nf, A->n, A->nnz, (size_t)A->n - nm, K, it_med, fsum);
    printf("variants timed in %s seconds, median of %d\n", use_cpu_clock ? "CPU" : "wall", R);
    printf("| variant | supernodes | stored L entries | flops (exact L) | analysis s | "
           "factorization s | solve s (1 rhs) | factorization + solve s | "
           "iteration / factorization |\n");
    printf("|---|---|---|---|---|---|---|---|---|\n");
    int Rn = R < 64 ? R : 64;
    for (int v = 0; v < nvar; v++) {
        if (var[v].threads != T) continue;
        double a = bench_median(ta[v], Rn), f = bench_median(tf[v], Rn),
               so = bench_median(ts[v], Rn);
        for (int r = 0; r < Rn; r++) ts[v][r] += tf[v][r];
        printf("| %s | %ld | %.0f | %.3g | %.4f | %.4f | %.4f | %.4f | %.2f |\n", var[v].name,
               nsuper[v], lnz[v], fl[v], a, f, so, bench_median(ts[v], Rn),
               f > 0 ? it_med / f : 0.0);
    }
    cholmod_finish(&cm);
    free(perm);
    free(perm2);
    free(it);
    scaf_loop_free(&L);
    free(loop);
    free(uv);
    mesh_free(&m);
    return 0;
}
