/* bench/bench_newton: SLIM vs SLIM-then-Newton on a fixed-boundary disk.
 *
 * Groundwork for issue 11 (projected Newton), opt layer only (no scaffold):
 * a disk mesh, its Tutte start (boundary on the circle, fixed), symmetric
 * Dirichlet. Strategies, each from the same start:
 *   slim        opt_slim_step only;
 *   switch@tau  SLIM until one iteration's relative energy decrease is
 *               below tau, then opt_newton_step;
 *   newton      opt_newton_step from the start.
 * Each runs until the line search takes no step (converged to rounding) or
 * the iteration cap. Prints per strategy the energy per iteration (mean
 * density E, 4 at an isometry) with cumulative time and, for Newton steps,
 * whether the exact Hessian was used (or tried and rejected as not
 * positive definite) and how many triangles had a negative eigenvalue; then a summary: iterations and seconds to come within 1e-4,
 * 1e-6, 1e-8, 1e-10 (relative) of the lowest energy any strategy reached.
 * Usage: bench_newton [--obj FILE] [max_iterations (300)] [--quiet]
 * Without --obj: a generated curved disk (tests/opt/polar_disk.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/opt/polar_disk.h"
#include "base/timer.h"
#include "disk_mesh.h"
#include "opt/embed.h"
#include "opt/slim.h"

enum { NSTRAT = 5 };

typedef struct trace {
    const char *name;
    int n;          /* iterations run */
    double *E, *t;  /* n+1 energies (mean) and cumulative seconds */
    int newton_from; /* first Newton iteration (n+1: none) */
} trace;

static int run(trace *tr, double tau, int newton_only, int max_it, const opt_term *term, int nv,
               const int *dof, int nfree, const double *X0, double wsum, int quiet)
{
    double *X = malloc(2 * (size_t)nv * sizeof *X);
    tr->E = malloc(((size_t)max_it + 1) * sizeof *tr->E);
    tr->t = malloc(((size_t)max_it + 1) * sizeof *tr->t);
    if (!X || !tr->E || !tr->t) return -1;
    memcpy(X, X0, 2 * (size_t)nv * sizeof *X);
    scaf_error err;
    opt_slim *sl = opt_slim_create(NULL, &err);
    if (!sl) return -1;
    tr->E[0] = opt_term_energy(term, X) / wsum;
    tr->t[0] = 0;
    tr->newton_from = newton_only ? 1 : max_it + 1;
    int newton = newton_only, k = 0;
    double t0 = timer_now();
    if (!quiet) printf("\n%s\n| iter | method | E | seconds | exact H | negative |\n|---|---|---|---|---|---|\n", tr->name);
    while (k < max_it) {
        opt_slim_stats st;
        scaf_status s = newton ? opt_newton_step(sl, term, 1, NULL, nv, dof, nfree, X, &st, &err)
                               : opt_slim_step(sl, term, 1, NULL, nv, dof, nfree, X, &st, &err);
        if (s != SCAF_OK) {
            fprintf(stderr, "%s iteration %d: %s\n", tr->name, k + 1, err.message);
            break;
        }
        if (st.ls.step == 0) break;
        k++;
        tr->E[k] = st.ls.energy_after / wsum;
        tr->t[k] = timer_now() - t0;
        if (!quiet)
            printf("| %d | %s | %.12f | %.3f | %s | %d |\n", k, newton ? "Newton" : "SLIM", tr->E[k],
                   tr->t[k], newton ? (st.exact ? "yes" : st.exact_rejected ? "rejected" : "no") : "", newton ? st.clamped : 0);
        if (!newton && tau > 0 && (tr->E[k - 1] - tr->E[k]) < tau * tr->E[k]) {
            newton = 1;
            tr->newton_from = k + 1;
        }
        if (tr->E[k] == tr->E[k - 1]) break;
    }
    tr->n = k;
    opt_slim_destroy(sl);
    free(X);
    return 0;
}

int main(int argc, char **argv)
{
    polar_disk m;
    int max_it = 300, quiet = 0, argi = 1;
    const char *path = NULL;
    for (; argi < argc; argi++) {
        if (strcmp(argv[argi], "--obj") == 0 && argi + 1 < argc) path = argv[++argi];
        else if (strcmp(argv[argi], "--quiet") == 0) quiet = 1;
        else if (atoi(argv[argi]) > 0) max_it = atoi(argv[argi]);
        else {
            fprintf(stderr, "usage: bench_newton [--obj FILE] [max_iterations] [--quiet]\n");
            return 2;
        }
    }
    if (path) {
        if (disk_mesh_load(path, &m) != 0) { fprintf(stderr, "cannot load %s\n", path); return 1; }
    } else {
        if (polar_disk_make(&m, 60, 160, 1.2, 0) != 0) return 1;
        for (int v = 0; v < m.nv; v++)
            if (m.V[3 * v] > 0) m.V[3 * v + 2] *= 1 + 2 * m.V[3 * v];
    }
    scaf_error err;
    opt_simplices S;
    double wsum;
    if (disk_mesh_chart(&m, &S, &wsum) != 0) return 1;
    double *X0 = malloc(2 * (size_t)m.nv * sizeof *X0);
    int *dof = malloc((size_t)m.nv * sizeof *dof);
    unsigned char *fixed = calloc((size_t)m.nv, 1);
    if (!X0 || !dof || !fixed) return 1;
    opt_chart_loops L = {1, m.start, m.loops, 0};
    if (opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_TUTTE, X0, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    if (disk_mesh_fixed(&m, fixed) != 0) return 1;
    int nfree = opt_dof_numbering(m.nv, fixed, dof);
    opt_term term = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    printf("%s: %d vertices, %d triangles, boundary (%d vertices) fixed on the circle; Tutte start E = %.6f\n",
           path ? path : "generated curved disk", m.nv, m.nf, m.start[1],
           opt_term_energy(&term, X0) / wsum);

    trace tr[NSTRAT] = {{"slim", 0, NULL, NULL, 0}, {"switch@1e-2", 0, NULL, NULL, 0},
                        {"switch@1e-3", 0, NULL, NULL, 0}, {"switch@1e-4", 0, NULL, NULL, 0},
                        {"newton", 0, NULL, NULL, 0}};
    const double taus[NSTRAT] = {0, 1e-2, 1e-3, 1e-4, 0};
    for (int k = 0; k < NSTRAT; k++)
        if (run(&tr[k], taus[k], k == NSTRAT - 1, max_it, &term, m.nv, dof, nfree, X0, wsum, quiet) != 0)
            return 1;
    double best = INFINITY;
    for (int k = 0; k < NSTRAT; k++) best = fmin(best, tr[k].E[tr[k].n]);
    static const double tols[4] = {1e-4, 1e-6, 1e-8, 1e-10};
    printf("\nlowest E = %.12f\n\n| strategy | Newton from | iterations | final E | to 1e-4 | to 1e-6 | to 1e-8 | to 1e-10 |\n|---|---|---|---|---|---|---|---|\n",
           best);
    for (int k = 0; k < NSTRAT; k++) {
        char from[32] = "-";
        if (tr[k].newton_from <= tr[k].n) snprintf(from, sizeof from, "%d", tr[k].newton_from);
        printf("| %s | %s | %d | %.12f |", tr[k].name, from, tr[k].n, tr[k].E[tr[k].n]);
        for (int j = 0; j < 4; j++) {
            int it = -1;
            for (int i = 0; i <= tr[k].n; i++)
                if (tr[k].E[i] - best <= tols[j] * best) { it = i; break; }
            if (it < 0) printf(" not reached |");
            else printf(" %d it, %.2f s |", it, tr[k].t[it]);
        }
        printf("\n");
        free(tr[k].E);
        free(tr[k].t);
    }
    free(X0); free(dof); free(fixed);
    opt_simplices_free(&S);
    polar_disk_free(&m);
    return 0;
}
