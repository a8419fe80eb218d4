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
 * Set OPENBLAS_NUM_THREADS to study BLAS threading.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/opt/polar_disk.h"
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
    int rings = argc > 1 ? atoi(argv[1]) : 196, seg = argc > 2 ? atoi(argv[2]) : 256;
    int iters = argc > 3 ? atoi(argv[3]) : 6;
    if (rings < 2 || seg < 3 || iters < 2) {
        fprintf(stderr, "usage: bench_opt [rings>=2 segments>=3 iterations>=2]\n");
        return 2;
    }
    polar_disk m;
    if (polar_disk_make(&m, rings, seg, 1.0, 0) != 0) return 1;
    const char *thr = getenv("OPENBLAS_NUM_THREADS");
    printf("disk: %d vertices, %d triangles; OPENBLAS_NUM_THREADS=%s\n", m.nv, m.nf, thr ? thr : "(unset)");
    scaf_error err;
    opt_simplices S;
    if (opt_simplices_from_surface(&S, m.nv, m.V, m.nf, m.F, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    double wsum = 0;
    for (int s = 0; s < S.n; s++) wsum += S.weight[s];
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
    t0 = timer_now();
    opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_HARMONIC, X, NULL, &err);
    printf("harmonic embedding: %.3f s\n\n", timer_now() - t0);
    for (int k = 0; k < m.start[1]; k++) fixed[m.loops[k]] = 1;
    int nfree = opt_dof_numbering(m.nv, fixed, dof);
    opt_term t = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};

    const opt_ordering ords[3] = {OPT_ORDER_AMD, OPT_ORDER_METIS, OPT_ORDER_CHOLMOD_DEFAULT};
    const char *names[3] = {"AMD", "METIS", "default"};
    printf("| ordering | iter | pattern | assemble | analyze | factor | solve | line search | total | E after | nnz(L) | flops |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int o = 0; o < 3; o++) {
        memcpy(X, X0, 2 * (size_t)m.nv * sizeof *X);
        opt_slim_options so;
        opt_slim_options_default(&so);
        so.ordering = ords[o];
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

    /* Re-analysis cost with a reused permutation vs a fresh AMD analysis. */
    {
        opt_proxy_block b = {0};
        double *rhs = calloc(2 * (size_t)nfree, sizeof *rhs);
        opt_proxy_block_pattern(&b, &S, dof, nfree, &err);
        opt_proxy_block_fill(&b, &t, dof, X0, rhs);
        opt_chol *c = opt_chol_create(OPT_ORDER_AMD, &err);
        double a = timer_now();
        opt_chol_analyze_given(c, &b.A, NULL, &err);
        double t_amd = timer_now() - a;
        int *perm = malloc((size_t)b.A.n * sizeof *perm);
        memcpy(perm, opt_chol_permutation(c), (size_t)b.A.n * sizeof *perm);
        a = timer_now();
        opt_chol_analyze_given(c, &b.A, perm, &err);
        double t_given = timer_now() - a;
        a = timer_now();
        opt_chol_factor(c, &b.A, &err);
        double t_fac = timer_now() - a;
        printf("\n\nanalysis: AMD %.4f s, reusing the permutation (cholmod_analyze_p) %.4f s; one factorization %.4f s\n",
               t_amd, t_given, t_fac);
        double pa = timer_now();
        opt_proxy_block bb = {0};
        opt_proxy_block_pattern(&bb, &S, dof, nfree, &err);
        printf("pattern build (sort + map) %.4f s; factor flops %.3g (%.2f GFlop/s), nnz(L) %.0f\n",
               timer_now() - pa, opt_chol_get_stats(c).flops,
               1e-9 * opt_chol_get_stats(c).flops / t_fac, opt_chol_get_stats(c).nnz_L);
        opt_proxy_block_free(&bb);
        free(perm);
        free(rhs);
        opt_chol_destroy(c);
        opt_proxy_block_free(&b);
    }
    opt_simplices_free(&S);
    polar_disk_free(&m);
    free(X0); free(X); free(dof); free(fixed);
    return 0;
}
