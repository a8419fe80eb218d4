/* bench/bench_opt: phase timings of one SLIM iteration on a generated disk.
 *
 * A polar-grid disk of ~100k triangles (tests/opt/polar_disk.h) lifted to a
 * curved surface, Tutte start, boundary fixed on the circle (no scaffold).
 * Prints, per ordering (AMD, METIS, CHOLMOD default): the first iteration
 * (with analysis) and the median of the following ones split into pattern,
 * assembly, analysis, factorization, solve and line search; then the cost
 * of re-analysing with the previous permutation (cholmod_analyze_p), and a
 * checksum of the final positions (determinism across runs / threads).
 * Usage: bench_opt [rings segments iterations]   (default 196 256 6)
 *        bench_opt --obj FILE [iterations]   a real disk mesh (OBJ/OFF/PLY,
 *        .gz ok; its single boundary loop fixed on the circle)
 *        [amd|metis|slim] after the iteration count runs one strategy.
 * Set OPENBLAS_NUM_THREADS to study BLAS threading.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/opt/polar_disk.h"
#include "disk_mesh.h"
#include "base/timer.h"
#include "opt/embed.h"
#include "opt/slim.h"

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static uint64_t checksum(const double *x, size_t n)
{
    uint64_t h = 1469598103934665603ULL;
    const unsigned char *p = (const unsigned char *)x;
    for (size_t k = 0; k < n * sizeof *x; k++) h = (h ^ p[k]) * 1099511628211ULL;
    return h;
}

int main(int argc, char **argv)
{
    polar_disk m;
    int iters, only = -1;
    int from_file = argc > 2 && strcmp(argv[1], "--obj") == 0;
    iters = argc > 3 ? atoi(argv[3]) : 6;
    if (argc > 4) only = strcmp(argv[4], "amd") == 0 ? 0 : strcmp(argv[4], "metis") == 0 ? 1 : 2;
    if (from_file) {
        if (disk_mesh_load(argv[2], &m) != 0) { fprintf(stderr, "cannot load %s\n", argv[2]); return 1; }
    } else {
        int rings = argc > 1 ? atoi(argv[1]) : 196, seg = argc > 2 ? atoi(argv[2]) : 256;
        if (rings < 2 || seg < 3) {
            fprintf(stderr, "usage: bench_opt [rings>=2 segments>=3 [iterations [amd|metis|slim]]] | --obj FILE [iterations [amd|metis|slim]]\n");
            return 2;
        }
        if (polar_disk_make(&m, rings, seg, 1.0, 0) != 0) return 1;
    }
    if (iters < 2) iters = 2;
    const char *thr = getenv("OPENBLAS_NUM_THREADS");
    printf("disk: %d vertices, %d triangles; OPENBLAS_NUM_THREADS=%s\n", m.nv, m.nf, thr ? thr : "(unset)");
    scaf_error err;
    opt_simplices S;
    double wsum;
    if (disk_mesh_chart(&m, &S, &wsum) != 0) return 1;
    double *X0 = malloc(2 * (size_t)m.nv * sizeof *X0), *X = malloc(2 * (size_t)m.nv * sizeof *X);
    int *dof = malloc((size_t)m.nv * sizeof *dof);
    unsigned char *fixed = calloc((size_t)m.nv, 1);
    if (!X0 || !X || !dof || !fixed) return 1;
    opt_chart_loops L = {1, m.start, m.loops, 0};
    double t0 = timer_now();
    if (opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_TUTTE, X0, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    printf("tutte embedding: %.3f s\n", timer_now() - t0);
    opt_term tstart = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    printf("Tutte start: E = %.5f\n", opt_term_mean_energy(&tstart, X0));
    t0 = timer_now();
    int fb = 0;
    if (opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_HARMONIC, X0, &fb, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    printf("harmonic embedding: %.3f s%s; start: E = %.5f (the iterations below start here)\n\n",
           timer_now() - t0, fb ? " (fell back to Tutte)" : "", opt_term_mean_energy(&tstart, X0));
    if (disk_mesh_fixed(&m, fixed) != 0) return 1;
    int nfree = opt_dof_numbering(m.nv, fixed, dof);
    opt_term t = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};

    /* AMD / METIS: the solver orders the system itself; "SLIM default":
     * opt_slim's defaults (chart ordered once with METIS, then reused). */
    const opt_ordering ords[3] = {OPT_ORDER_AMD, OPT_ORDER_METIS, OPT_ORDER_AMD};
    const char *names[3] = {"AMD", "METIS", "SLIM default"};
    printf("| ordering | iter | pattern | assemble | analyze | factor | solve | line search | total | E after | nnz(L) | flops |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int o = 0; o < 3; o++) {
        if (only >= 0 && o != only) continue;
        memcpy(X, X0, 2 * (size_t)m.nv * sizeof *X);
        opt_slim_options so;
        opt_slim_options_default(&so);
        so.ordering = ords[o];
        so.reuse_chart_ordering = o == 2;
        opt_slim *sl = opt_slim_create(&so, &err);
        if (!sl) { fprintf(stderr, "%s\n", err.message); return 1; }
        int nrest = iters - 1;
        double *tp = calloc((size_t)nrest, sizeof *tp), *ta = calloc((size_t)nrest, sizeof *ta);
        double *tf = calloc((size_t)nrest, sizeof *tf), *ts = calloc((size_t)nrest, sizeof *ts);
        double *tl = calloc((size_t)nrest, sizeof *tl), *tt = calloc((size_t)nrest, sizeof *tt);
        double e = 0;
        for (int it = 0; it < iters; it++) {
            opt_slim_stats st;
            double a = timer_now();
            if (opt_slim_step(sl, &t, 1, NULL, m.nv, dof, nfree, X, &st, &err) != SCAF_OK) {
                fprintf(stderr, "%s\n", err.message);
                return 1;
            }
            double tot = timer_now() - a;
            e = st.ls.energy_after / wsum;
            if (it == 0) {
                printf("| %s | first | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.5f | %.0f | %.3g |\n", names[o],
                       st.t_pattern, st.t_assemble, st.t_analyze, st.t_factor, st.t_solve,
                       st.t_line_search, tot, e, opt_chol_get_stats(opt_slim_solver(sl)).nnz_L,
                       opt_chol_get_stats(opt_slim_solver(sl)).flops);
            } else {
                tp[it - 1] = st.t_pattern; ta[it - 1] = st.t_assemble; tf[it - 1] = st.t_factor;
                ts[it - 1] = st.t_solve; tl[it - 1] = st.t_line_search; tt[it - 1] = tot;
            }
        }
        printf("| %s | median of %d | %.4f | %.4f | 0 | %.4f | %.4f | %.4f | %.4f | %.5f | | |\n", names[o], nrest,
               median(tp, nrest), median(ta, nrest), median(tf, nrest), median(ts, nrest),
               median(tl, nrest), median(tt, nrest), e);
        fprintf(stderr, "%s: final checksum %016llx\n", names[o], (unsigned long long)checksum(X, 2 * (size_t)m.nv));
        free(tp); free(ta); free(tf); free(ts); free(tl); free(tt);
        opt_slim_destroy(sl);
    }

    /* Fresh analyses: scalar vs vertex-graph (block) ordering, AMD vs METIS,
     * and re-analysis with the previous permutation (cholmod_analyze_p). */
    {
        opt_proxy_block b = {0};
        double *rhs = calloc(2 * (size_t)nfree, sizeof *rhs);
        double a = timer_now();
        opt_proxy_block_pattern(&b, &S, dof, nfree, &err);
        double t_pat = timer_now() - a;
        a = timer_now();
        opt_proxy_block_fill(&b, &t, dof, X0, rhs);
        double t_fill = timer_now() - a;
        printf("\n\npattern build (sort + map) %.4f s, value fill (SVD + weights + scatter) %.4f s\n\n", t_pat, t_fill);
        printf("| ordering | graph | analyze | analyze_p (reused perm) | factor | nnz(L) | flops |\n|---|---|---|---|---|---|---|\n");
        for (int cfg = 0; cfg < 4; cfg++) {
            if (only >= 0 && (cfg / 2) != (only == 1)) continue;
            opt_chol *c = opt_chol_create(cfg / 2 ? OPT_ORDER_METIS : OPT_ORDER_AMD, &err);
            opt_chol_set_block(c, cfg % 2 ? 2 : 1);
            a = timer_now();
            opt_chol_analyze_given(c, &b.A, NULL, &err);
            double t_an = timer_now() - a;
            int *perm = malloc((size_t)b.A.n * sizeof *perm);
            memcpy(perm, opt_chol_permutation(c), (size_t)b.A.n * sizeof *perm);
            a = timer_now();
            opt_chol_analyze_given(c, &b.A, perm, &err);
            double t_given = timer_now() - a;
            a = timer_now();
            if (opt_chol_factor(c, &b.A, &err) != SCAF_OK) fprintf(stderr, "%s\n", err.message);
            double t_fac = timer_now() - a;
            opt_chol_stats cs = opt_chol_get_stats(c);
            printf("| %s | %s | %.4f | %.4f | %.4f | %.0f | %.3g |\n", cfg / 2 ? "METIS" : "AMD",
                   cfg % 2 ? "vertex (block 2)" : "scalar", t_an, t_given, t_fac, cs.nnz_L, cs.flops);
            free(perm);
            opt_chol_destroy(c);
        }
        free(rhs);
        opt_proxy_block_free(&b);
    }
    opt_simplices_free(&S);
    polar_disk_free(&m);
    free(X0); free(X); free(dof); free(fixed);
    return 0;
}
