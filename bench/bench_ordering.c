/* bench/bench_ordering: fill-reducing orderings for chart + scaffold systems.
 *
 * SCAF re-analyses its system every iteration because the scaffold changes.
 * This compares, on a generated disk chart (tests/opt/polar_disk.h, Tutte
 * start) surrounded by a ring "scaffold" of extra rings out to a fixed
 * outer ring: AMD and METIS on the whole system every iteration, against
 * an ordering of the chart computed once and extended to the scaffold
 * (opt/ordering_reuse) then analysed with cholmod_analyze_p. Reported per
 * strategy: per-iteration ordering+analysis seconds, factorization seconds,
 * nnz(L) and flops (flops and nnz are exact; seconds depend on load).
 * Usage: bench_ordering [chart_rings segments scaffold_rings] (196 256 12)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/opt/polar_disk.h"
#include "base/timer.h"
#include "opt/embed.h"
#include "opt/ordering_reuse.h"
#include "opt/proxy_system.h"
#include "opt/slim.h"

int main(int argc, char **argv)
{
    int rc = argc > 1 ? atoi(argv[1]) : 196, seg = argc > 2 ? atoi(argv[2]) : 256;
    int rs = argc > 3 ? atoi(argv[3]) : 12;
    if (rc < 2 || seg < 3 || rs < 1) { fprintf(stderr, "usage: bench_ordering [chart_rings segments scaffold_rings]\n"); return 2; }
    scaf_error err;
    polar_disk chart, all;
    if (polar_disk_make(&chart, rc, seg, 1.0, 0) || polar_disk_make(&all, rc + rs, seg, 0.0, 0)) return 1;
    /* Vertex numbering of `all` extends `chart` (center, rings 1..rc first). */
    int nvc = chart.nv, nv = all.nv;
    double *X = malloc(2 * (size_t)nv * sizeof *X);
    opt_chart_loops L = {1, chart.start, chart.loops, 0};
    if (opt_embed_chart(chart.nv, chart.V, chart.nf, chart.F, &L, OPT_EMBED_TUTTE, X, NULL, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
    for (int k = 1; k <= rs; k++)
        for (int j = 0; j < seg; j++) {
            int b = chart.loops[j], v = nvc + (k - 1) * seg + j;
            double s = 1.0 + 0.08 * k;
            X[2 * v] = s * X[2 * b];
            X[2 * v + 1] = s * X[2 * b + 1];
        }
    opt_simplices Sc, Ss;
    if (opt_simplices_from_surface(&Sc, chart.nv, chart.V, chart.nf, chart.F, &err)) return 1;
    int nfs = all.nf - chart.nf; /* faces beyond the chart's come last in `all` */
    if (opt_simplices_from_current(&Ss, 2, nv, X, nfs, all.F + 3 * (size_t)chart.nf, 0.0, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
    for (int s = 0; s < Ss.n; s++) Ss.weight[s] = 1e-3;
    unsigned char *fixed = calloc((size_t)nv, 1);
    for (int j = 0; j < seg; j++) fixed[nvc + (rs - 1) * seg + j] = 1;
    int *dof = malloc((size_t)nv * sizeof *dof);
    int nfree = opt_dof_numbering(nv, fixed, dof);
    opt_term tc = {&Sc, OPT_ENERGY_SYMMETRIC_DIRICHLET}, ts = {&Ss, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_proxy_block bc = {0}, bs = {0};
    double *rhs = calloc(2 * (size_t)nfree, sizeof *rhs);
    if (opt_proxy_block_pattern(&bc, &Sc, dof, nfree, &err) || opt_proxy_block_pattern(&bs, &Ss, dof, nfree, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
    opt_proxy_block_fill(&bc, &tc, dof, X, rhs);
    opt_proxy_block_fill(&bs, &ts, dof, X, rhs);
    opt_proxy_system sys = {0};
    const opt_proxy_block *bl[2] = {&bc, &bs};
    if (opt_proxy_system_sum(&sys, bl, 2, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
    printf("chart %d triangles, scaffold %d triangles, %d unknowns; OPENBLAS_NUM_THREADS=%s\n\n", chart.nf, nfs,
           sys.A.n, getenv("OPENBLAS_NUM_THREADS") ? getenv("OPENBLAS_NUM_THREADS") : "(unset)");
    printf("| strategy | once (chart ordering) | per iteration: order + analyze | factor | nnz(L) | flops |\n|---|---|---|---|---|---|\n");
    int *perm = malloc((size_t)sys.A.n * sizeof *perm), *lead = malloc((size_t)bc.A.n * sizeof *lead);
    for (int strat = 0; strat < 4; strat++) {
        opt_ordering ord = (strat % 2) ? OPT_ORDER_METIS : OPT_ORDER_AMD;
        opt_chol *c = opt_chol_create(ord, &err);
        opt_chol_set_block(c, 2);
        double once = 0, t_an, a;
        if (strat < 2) {
            a = timer_now();
            if (opt_chol_analyze_given(c, &sys.A, NULL, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
            t_an = timer_now() - a;
        } else {
            a = timer_now();
            if (opt_chol_compute_ordering(c, &bc.A, lead, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
            once = timer_now() - a;
            a = timer_now();
            opt_ordering_extend(&sys.A, 2, bc.nfree, lead, perm, &err);
            if (opt_chol_analyze_given(c, &sys.A, perm, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
            t_an = timer_now() - a;
        }
        a = timer_now();
        if (opt_chol_factor(c, &sys.A, &err)) { fprintf(stderr, "%s\n", err.message); return 1; }
        double t_f = timer_now() - a;
        opt_chol_stats st = opt_chol_get_stats(c);
        const char *names[4] = {"AMD every iteration", "METIS every iteration", "chart AMD once + extend", "chart METIS once + extend"};
        printf("| %s | %.4f | %.4f | %.4f | %.0f | %.3g |\n", names[strat], once, t_an, t_f, st.nnz_L, st.flops);
        opt_chol_destroy(c);
    }
    free(perm); free(lead); free(rhs); free(dof); free(fixed); free(X);
    opt_proxy_system_free(&sys);
    opt_proxy_block_free(&bc); opt_proxy_block_free(&bs);
    opt_simplices_free(&Sc); opt_simplices_free(&Ss);
    polar_disk_free(&chart); polar_disk_free(&all);
    return 0;
}
