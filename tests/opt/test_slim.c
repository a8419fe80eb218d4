/* End-to-end tests for opt/slim: fixed-boundary SLIM on a distorted disk
 * (Tutte start) and on a jittered tetrahedral cube lowers the energy at
 * every iteration and never inverts a simplex (exact check each time);
 * a second term whose pattern is rebuilt every iteration (like the
 * scaffold) does not force a new analysis when its pattern is unchanged. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"
#include "opt/embed.h"
#include "opt/slim.h"
#include "polar_disk.h"
#include "rng.h"
#include "tet_grid.h"

typedef struct disk_case {
    polar_disk m;
    opt_simplices S;
    double *X;
    int *dof, nfree;
    double wsum;
} disk_case;

static void disk_setup(disk_case *c)
{
    assert_int_equal(polar_disk_make(&c->m, 10, 32, 1.2, 0), 0);
    /* Squeeze one side to make the surface less symmetric. */
    for (int v = 0; v < c->m.nv; v++)
        if (c->m.V[3 * v] > 0) c->m.V[3 * v + 2] *= 1 + 2 * c->m.V[3 * v];
    assert_int_equal(opt_simplices_from_surface(&c->S, c->m.nv, c->m.V, c->m.nf, c->m.F, NULL), SCAF_OK);
    c->X = malloc(2 * c->m.nv * sizeof *c->X);
    opt_chart_loops L = {1, c->m.start, c->m.loops, 0};
    assert_int_equal(opt_embed_chart(c->m.nv, c->m.V, c->m.nf, c->m.F, &L, OPT_EMBED_TUTTE, c->X, NULL, NULL), SCAF_OK);
    unsigned char *fixed = calloc(c->m.nv, 1);
    for (int k = 0; k < c->m.start[1]; k++) fixed[c->m.loops[k]] = 1;
    c->dof = malloc(c->m.nv * sizeof *c->dof);
    c->nfree = opt_dof_numbering(c->m.nv, fixed, c->dof);
    free(fixed);
    c->wsum = 0;
    for (int s = 0; s < c->S.n; s++) c->wsum += c->S.weight[s];
}

static void disk_teardown(disk_case *c)
{
    polar_disk_free(&c->m);
    opt_simplices_free(&c->S);
    free(c->X);
    free(c->dof);
}

static void run_disk(opt_energy energy, int iters)
{
    disk_case c;
    disk_setup(&c);
    opt_term t = {&c.S, energy};
    opt_slim *sl = opt_slim_create(NULL, NULL);
    assert_non_null(sl);
    double e_first = opt_term_energy(&t, c.X) / c.wsum, e_prev = e_first;
    int moved = 0;
    for (int it = 0; it < iters; it++) {
        opt_slim_stats st;
        scaf_error e;
        scaf_status s = opt_slim_step(sl, &t, 1, NULL, c.m.nv, c.dof, c.nfree, c.X, &st, &e);
        if (s != SCAF_OK) print_error("%s\n", e.message);
        assert_int_equal(s, SCAF_OK);
        assert_true(st.ls.energy_after <= st.ls.energy_before);
        assert_true(opt_terms_oriented(&t, 1, c.X, NULL, NULL));
        double en = opt_term_energy(&t, c.X) / c.wsum;
        assert_true(en <= e_prev);
        moved += st.ls.step > 0;
        e_prev = en;
        if (it > 0) assert_int_equal(st.analyzed, 0);
    }
    assert_true(moved > 0);
    assert_true(e_prev < e_first);
    if (energy == OPT_ENERGY_SYMMETRIC_DIRICHLET) {
        assert_true(e_prev >= 4.0);
        assert_true(e_prev < 0.5 * (e_first + 4.0)); /* real progress, not a crawl */
    }
    opt_slim_destroy(sl);
    disk_teardown(&c);
}

static void slim_disk_symmetric_dirichlet(void **state) { (void)state; run_disk(OPT_ENERGY_SYMMETRIC_DIRICHLET, 12); }
static void slim_disk_arap(void **state) { (void)state; run_disk(OPT_ENERGY_ARAP, 5); }
static void slim_disk_conformal(void **state) { (void)state; run_disk(OPT_ENERGY_CONFORMAL, 5); }

/* Two terms: the chart split in two, the second rebuilt every iteration. */
static void slim_two_terms_rebuilt(void **state)
{
    (void)state;
    disk_case c;
    disk_setup(&c);
    int k = c.S.n / 2;
    opt_simplices A = c.S, B = c.S;
    A.n = k;
    B.n = c.S.n - k;
    B.idx += (size_t)3 * k;
    B.grad += (size_t)6 * k;
    B.vol += k;
    B.weight += k;
    opt_term t[2] = {{&A, OPT_ENERGY_SYMMETRIC_DIRICHLET}, {&B, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
    opt_term whole = {&c.S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_slim_options o;
    opt_slim_options_default(&o);
    o.ordering = OPT_ORDER_METIS;
    opt_slim *sl = opt_slim_create(&o, NULL);
    int changed[2] = {0, 1};
    double e_prev = opt_term_energy(&whole, c.X);
    for (int it = 0; it < 6; it++) {
        opt_slim_stats st;
        assert_int_equal(opt_slim_step(sl, t, 2, changed, c.m.nv, c.dof, c.nfree, c.X, &st, NULL), SCAF_OK);
        assert_true(opt_terms_oriented(t, 2, c.X, NULL, NULL));
        double en = opt_term_energy(&whole, c.X);
        assert_true(en <= e_prev);
        e_prev = en;
        assert_int_equal(st.analyzed, it == 0);
        assert_int_equal(st.blocks_rebuilt, it == 0 ? 2 : 1); /* the chart's block is kept */
    }
    assert_int_equal(opt_chol_get_stats(opt_slim_solver(sl)).analyses, 1);
    /* An empty second term (no scaffold simplex) is harmless. */
    opt_simplices none = c.S;
    none.n = 0;
    opt_term t2[2] = {{&c.S, OPT_ENERGY_SYMMETRIC_DIRICHLET}, {&none, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
    assert_int_equal(opt_slim_step(sl, t2, 2, changed, c.m.nv, c.dof, c.nfree, c.X, NULL, NULL), SCAF_OK);
    assert_true(opt_terms_oriented(t2, 2, c.X, NULL, NULL));
    opt_slim_destroy(sl);
    disk_teardown(&c);
}

/* A SCAF-like loop: the chart's boundary is free, a ring "scaffold" of
 * extra rings surrounds it with its outer ring fixed, and every iteration
 * the scaffold is re-triangulated (quads split along alternating
 * diagonals where valid), its rest shape reset to the current one and its
 * weight set to lambda = E_M / (100 |S|). Every simplex stays positive
 * (exact), each step lowers its iteration's total energy, the chart's
 * block is never rebuilt and its energy goes down. */
static void changing_scaffold(int iters, int newton_from)
{
    int rc = 6, seg = 24, rs = 4;
    polar_disk chart;
    assert_int_equal(polar_disk_make(&chart, rc, seg, 1.5, 0), 0);
    int nvc = chart.nv, nv = nvc + rs * seg;
    double *X = malloc(2 * nv * sizeof *X);
    opt_chart_loops L = {1, chart.start, chart.loops, 0};
    assert_int_equal(opt_embed_chart(chart.nv, chart.V, chart.nf, chart.F, &L, OPT_EMBED_TUTTE, X, NULL, NULL), SCAF_OK);
    for (int k = 1; k <= rs; k++)
        for (int j = 0; j < seg; j++) {
            int b = chart.loops[j], v = nvc + (k - 1) * seg + j;
            X[2 * v] = (1 + 0.25 * k) * X[2 * b];
            X[2 * v + 1] = (1 + 0.25 * k) * X[2 * b + 1];
        }
    /* Ring k = 0 is the chart boundary, 1..rs the scaffold rings. */
#define RV(k, j) ((k) == 0 ? chart.loops[(j) % seg] : nvc + ((k) - 1) * seg + ((j) % seg))
    unsigned char *fixed = calloc(nv, 1);
    for (int j = 0; j < seg; j++) fixed[RV(rs, j)] = 1;
    int *dof = malloc(nv * sizeof *dof);
    int nfree = opt_dof_numbering(nv, fixed, dof);
    opt_simplices C;
    assert_int_equal(opt_simplices_from_surface(&C, chart.nv, chart.V, chart.nf, chart.F, NULL), SCAF_OK);
    int nsf = 2 * seg * rs;
    int *SF = malloc(3 * nsf * sizeof *SF);
    opt_slim *sl = opt_slim_create(NULL, NULL);
    opt_term tc = {&C, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    double e_first = opt_term_mean_energy(&tc, X), e_prev = e_first;
    for (int it = 0; it < iters; it++) {
        int f = 0;
        for (int k = 0; k < rs; k++)
            for (int j = 0; j < seg; j++) {
                int a = RV(k, j), b = RV(k, j + 1), c = RV(k + 1, j), d = RV(k + 1, j + 1);
                int alt = (it + j) % 2;
                int t1[3] = {a, c, b}, t2[3] = {b, c, d}, u1[3] = {a, c, d}, u2[3] = {a, d, b};
                int ok_alt = orient2d(X + 2 * a, X + 2 * c, X + 2 * b) > 0 && orient2d(X + 2 * b, X + 2 * c, X + 2 * d) > 0;
                const int *p1 = alt && ok_alt ? t1 : u1, *p2 = alt && ok_alt ? t2 : u2;
                if (!alt || !ok_alt) /* the other split must then be valid */
                    assert_true(orient2d(X + 2 * a, X + 2 * c, X + 2 * d) > 0 && orient2d(X + 2 * a, X + 2 * d, X + 2 * b) > 0);
                memcpy(SF + 3 * f++, p1, sizeof t1);
                memcpy(SF + 3 * f++, p2, sizeof t1);
            }
        opt_simplices Sc;
        assert_int_equal(opt_simplices_from_current(&Sc, 2, nv, X, nsf, SF, 1e-12, NULL), SCAF_OK);
        double lambda = opt_term_energy(&tc, X) / (100.0 * nsf);
        for (int q = 0; q < nsf; q++) Sc.weight[q] = lambda;
        opt_term terms[2] = {tc, {&Sc, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
        int changed[2] = {0, 1};
        opt_slim_stats st;
        scaf_error e;
        scaf_status s = it >= newton_from
                            ? opt_newton_step(sl, terms, 2, changed, nv, dof, nfree, X, &st, &e)
                            : opt_slim_step(sl, terms, 2, changed, nv, dof, nfree, X, &st, &e);
        if (s != SCAF_OK) print_error("%s\n", e.message);
        assert_int_equal(s, SCAF_OK);
        assert_true(st.ls.energy_after <= st.ls.energy_before);
        assert_true(opt_terms_oriented(terms, 2, X, NULL, NULL));
        assert_int_equal(st.blocks_rebuilt, it == 0 ? 2 : 1);
        e_prev = opt_term_mean_energy(&tc, X);
        opt_simplices_free(&Sc);
    }
#undef RV
    print_message("changing scaffold: chart E %.4f -> %.4f after %d iterations (Newton from %d)\n",
                  e_first, e_prev, iters, newton_from);
    assert_true(e_prev < e_first);
    opt_slim_destroy(sl);
    opt_simplices_free(&C);
    free(SF); free(dof); free(fixed); free(X);
    polar_disk_free(&chart);
}

static void slim_with_changing_scaffold(void **state)
{
    (void)state;
    changing_scaffold(8, 8);
}

/* The same loop switching to Newton steps (true scaffold Hessian, exact or
 * projected) after 3 SLIM steps: the same guarantees. */
static void newton_with_changing_scaffold(void **state)
{
    (void)state;
    changing_scaffold(12, 3);
}

static void slim_tets(void **state)
{
    (void)state;
    tet_grid g;
    assert_int_equal(tet_grid_make(&g, 4), 0);
    opt_simplices S;
    assert_int_equal(opt_simplices_from_current(&S, 3, g.nv, g.X, g.nt, g.T, 0.0, NULL), SCAF_OK);
    rng r = {53};
    double *X = malloc(3 * g.nv * sizeof *X);
    for (int v = 0; v < g.nv; v++)
        for (int a = 0; a < 3; a++) X[3 * v + a] = g.X[3 * v + a] + (g.boundary[v] ? 0 : rng_uniform(&r, -0.06, 0.06));
    opt_term t = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    assert_true(opt_terms_oriented(&t, 1, X, NULL, NULL));
    int *dof = malloc(g.nv * sizeof *dof);
    int nfree = opt_dof_numbering(g.nv, g.boundary, dof);
    opt_slim *sl = opt_slim_create(NULL, NULL);
    double wsum = 0;
    for (int s = 0; s < S.n; s++) wsum += S.weight[s];
    double e0 = opt_term_energy(&t, X) / wsum, e_prev = e0;
    for (int it = 0; it < 8; it++) {
        opt_slim_stats st;
        assert_int_equal(opt_slim_step(sl, &t, 1, NULL, g.nv, dof, nfree, X, &st, NULL), SCAF_OK);
        assert_true(opt_terms_oriented(&t, 1, X, NULL, NULL));
        double en = opt_term_energy(&t, X) / wsum;
        assert_true(en <= e_prev);
        e_prev = en;
    }
    assert_true(e0 > 6.0);
    assert_true(e_prev - 6.0 < 0.1 * (e0 - 6.0)); /* the identity is the minimum */
    /* No free vertex: a usage error, X untouched. */
    unsigned char *all = malloc(g.nv);
    memset(all, 1, g.nv);
    int n0 = opt_dof_numbering(g.nv, all, dof);
    scaf_error e;
    assert_int_equal(opt_slim_step(sl, &t, 1, NULL, g.nv, dof, n0, X, NULL, &e), SCAF_ERR_USAGE);
    free(all);
    opt_slim_destroy(sl);
    free(dof);
    free(X);
    opt_simplices_free(&S);
    tet_grid_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(slim_disk_symmetric_dirichlet),
        cmocka_unit_test(slim_disk_arap),
        cmocka_unit_test(slim_disk_conformal),
        cmocka_unit_test(slim_two_terms_rebuilt),
        cmocka_unit_test(slim_with_changing_scaffold),
        cmocka_unit_test(newton_with_changing_scaffold),
        cmocka_unit_test(slim_tets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
