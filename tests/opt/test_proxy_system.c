/* Tests for opt/proxy_block and opt/proxy_system: the assembled matrix and
 * right side are those of the SLIM proxy quadratic (checked against the
 * quadratic evaluated directly), the proxy's gradient at the current point
 * is the true energy gradient (SLIM's property, at system level), and
 * summing blocks equals assembling everything in one block, including
 * after one block's pattern is rebuilt; the sum's values are those of
 * adding every block's entries in block order from 0 (== to the bit),
 * whether a column is copied from its only block or merged. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "opt/proxy_system.h"
#include "opt/proxy_block.h"
#include "polar_disk.h"
#include "rng.h"
#include "tet_grid.h"

typedef struct problem {
    int d, nv, nfree;
    double *X;
    int *dof;
    opt_simplices S;
} problem;

/* 2D: a polar disk, rest = 3D triangles, X = its xy projection (CCW),
 * outer ring fixed. 3D: a tet grid, rest = grid, X = grid with interior
 * vertices jittered, surface fixed. */
static void make_problem(problem *p, int d)
{
    rng r = {41};
    p->d = d;
    if (d == 2) {
        polar_disk m;
        assert_int_equal(polar_disk_make(&m, 4, 9, 0.7, 0), 0);
        p->nv = m.nv;
        p->X = malloc(2 * m.nv * sizeof *p->X);
        for (int v = 0; v < m.nv; v++) {
            p->X[2 * v] = m.V[3 * v] * 1.3;
            p->X[2 * v + 1] = m.V[3 * v + 1];
        }
        assert_int_equal(opt_simplices_from_surface(&p->S, m.nv, m.V, m.nf, m.F, NULL), SCAF_OK);
        unsigned char *fixed = calloc(m.nv, 1);
        for (int k = 0; k < m.start[1]; k++) fixed[m.loops[k]] = 1;
        p->dof = malloc(m.nv * sizeof *p->dof);
        p->nfree = opt_dof_numbering(m.nv, fixed, p->dof);
        free(fixed);
        polar_disk_free(&m);
    } else {
        tet_grid g;
        assert_int_equal(tet_grid_make(&g, 3), 0);
        p->nv = g.nv;
        assert_int_equal(opt_simplices_from_current(&p->S, 3, g.nv, g.X, g.nt, g.T, 0.0, NULL),
                         SCAF_OK);
        p->X = malloc(3 * g.nv * sizeof *p->X);
        for (int v = 0; v < g.nv; v++)
            for (int a = 0; a < 3; a++)
                p->X[3 * v + a] =
                    g.X[3 * v + a] + (g.boundary[v] ? 0 : rng_uniform(&r, -0.08, 0.08));
        p->dof = malloc(g.nv * sizeof *p->dof);
        p->nfree = opt_dof_numbering(g.nv, g.boundary, p->dof);
        tet_grid_free(&g);
    }
    for (int s = 0; s < p->S.n; s++) p->S.weight[s] *= rng_uniform(&r, 0.5, 1.5);
}

static void free_problem(problem *p)
{
    free(p->X);
    free(p->dof);
    opt_simplices_free(&p->S);
}

/* The proxy quadratic with W, T frozen at X0, at positions Y. */
static double proxy_value(const problem *p, opt_energy e, const double *X0, const double *Y)
{
    int d = p->d;
    double q = 0;
    for (int s = 0; s < p->S.n; s++) {
        double J0[9], J[9], W[9], T[9];
        opt_jacobian(&p->S, s, X0, J0);
        opt_slim_proxy(e, d, J0, W, T);
        opt_jacobian(&p->S, s, Y, J);
        for (int a = 0; a < d; a++)
            for (int b = 0; b < d; b++) {
                double acc = 0;
                for (int k = 0; k < d; k++) acc += W[a * d + k] * (J[k * d + b] - T[k * d + b]);
                q += p->S.weight[s] * acc * acc;
            }
    }
    return q;
}

static void matrix_is_the_proxy_quadratic(void **state)
{
    (void)state;
    rng r = {43};
    for (int d = 2; d <= 3; d++)
        for (int e = 0; e < 3; e++) {
            problem p;
            make_problem(&p, d);
            opt_term t = {&p.S, (opt_energy)e};
            opt_proxy_block b = {0};
            assert_int_equal(opt_proxy_block_pattern(&b, &p.S, p.dof, p.nfree, NULL), SCAF_OK);
            int n = p.nfree * d;
            double *rhs = calloc(n, sizeof *rhs), *y = malloc(n * sizeof *y),
                   *Ay = malloc(n * sizeof *Ay);
            double *Y = malloc(p.nv * d * sizeof *Y);
            /* the fill writes every value, whatever the block held */
            for (int k = 0; k < b.A.nnz; k++) b.A.val[k] = NAN;
            opt_proxy_block_fill(&b, &t, p.dof, p.X, rhs);
            /* Structure: upper, sorted. */
            for (int c = 0; c < n; c++)
                for (int k = b.A.colptr[c]; k < b.A.colptr[c + 1]; k++) {
                    assert_true(b.A.rowidx[k] <= c);
                    if (k > b.A.colptr[c]) assert_true(b.A.rowidx[k] > b.A.rowidx[k - 1]);
                }
            /* Q(y) = y'Ay - 2 b'y + Q(0) for random free positions y. */
            memcpy(Y, p.X, p.nv * d * sizeof *Y);
            for (int v = 0; v < p.nv; v++)
                if (p.dof[v] >= 0)
                    for (int a = 0; a < d; a++) Y[v * d + a] = 0;
            double q0 = proxy_value(&p, t.energy, p.X, Y);
            for (int trial = 0; trial < 5; trial++) {
                for (int i = 0; i < n; i++) y[i] = rng_uniform(&r, -1, 1);
                for (int v = 0; v < p.nv; v++)
                    if (p.dof[v] >= 0)
                        for (int a = 0; a < d; a++) Y[v * d + a] = y[p.dof[v] * d + a];
                opt_csc_symv(&b.A, y, Ay);
                double form = q0;
                for (int i = 0; i < n; i++) form += y[i] * Ay[i] - 2 * rhs[i] * y[i];
                double direct = proxy_value(&p, t.energy, p.X, Y);
                assert_true(fabs(form - direct) < 1e-9 * (1 + fabs(direct)));
            }
            /* SLIM: 2 (A x - b) = grad E at the current X (free part). */
            for (int v = 0; v < p.nv; v++)
                if (p.dof[v] >= 0)
                    for (int a = 0; a < d; a++) y[p.dof[v] * d + a] = p.X[v * d + a];
            opt_csc_symv(&b.A, y, Ay);
            double *g = calloc(p.nv * d, sizeof *g);
            opt_term_gradient(&t, p.X, g);
            double gmax = 0;
            for (int k = 0; k < p.nv * d; k++) gmax = fmax(gmax, fabs(g[k]));
            if (!(d == 3 && e == OPT_ENERGY_CONFORMAL))
                for (int v = 0; v < p.nv; v++)
                    if (p.dof[v] >= 0)
                        for (int a = 0; a < d; a++) {
                            int i = p.dof[v] * d + a;
                            assert_true(fabs(2 * (Ay[i] - rhs[i]) - g[v * d + a]) <
                                        1e-8 * (1 + gmax));
                        }
            free(g);
            free(rhs);
            free(y);
            free(Ay);
            free(Y);
            opt_proxy_block_free(&b);
            free_problem(&p);
        }
}

/* sys->A's values against the plain sum: each block's entries added, block
 * after block, into zeros at their union positions; both kinds of column
 * (copied from one block, merged from several) must occur. */
static void assert_sum_is_plain(const opt_proxy_system *sys, const opt_proxy_block *const *bl,
                                int nb)
{
    int d = sys->d, copied = 0, merged = 0;
    double *ref = calloc((size_t)sys->A.nnz + 1, sizeof *ref);
    assert_non_null(ref);
    for (int k = 0; k < nb; k++) {
        const opt_proxy_block *b = bl[k];
        for (int c = 0; c < b->nfree; c++)
            for (int e = b->vcolptr[c]; e < b->vcolptr[c + 1]; e++) {
                int kb = e - b->vcolptr[c], ku = sys->emap[k][e] - sys->vcolptr[c];
                for (int a2 = 0; a2 < d; a2++) {
                    int m = b->vrowidx[e] == c ? a2 + 1 : d;
                    for (int a = 0; a < m; a++)
                        ref[sys->A.colptr[c * d + a2] + ku * d + a] +=
                            b->A.val[b->A.colptr[c * d + a2] + kb * d + a];
                }
            }
    }
    for (int i = 0; i < sys->A.nnz; i++) assert_true(sys->A.val[i] == ref[i]);
    for (int c = 0; c < sys->nfree; c++) {
        copied += sys->only[c] >= 0;
        merged += sys->only[c] < 0 && sys->vcolptr[c + 1] > sys->vcolptr[c];
    }
    assert_true(copied > 0);
    assert_true(merged > 0);
    free(ref);
}

static void blocks_sum_like_one(void **state)
{
    (void)state;
    rng r = {47};
    for (int d = 2; d <= 3; d++) {
        problem p;
        make_problem(&p, d);
        int n = p.nfree * d, ns = p.S.n;
        /* Split the simplices: first k in part A, the rest in part B. */
        opt_simplices A = p.S, B = p.S;
        int k = ns / 3;
        A.n = k;
        B.n = ns - k;
        B.idx += (size_t)k * (d + 1);
        B.grad += (size_t)k * (d + 1) * d;
        B.vol += k;
        B.weight += k;
        opt_term tall = {&p.S, OPT_ENERGY_SYMMETRIC_DIRICHLET}, ta = {&A, tall.energy},
                 tb = {&B, tall.energy};
        opt_proxy_block ball = {0}, ba = {0}, bb = {0};
        assert_int_equal(opt_proxy_block_pattern(&ball, &p.S, p.dof, p.nfree, NULL), SCAF_OK);
        assert_int_equal(opt_proxy_block_pattern(&ba, &A, p.dof, p.nfree, NULL), SCAF_OK);
        assert_int_equal(opt_proxy_block_pattern(&bb, &B, p.dof, p.nfree, NULL), SCAF_OK);
        double *r1 = calloc(n, sizeof *r1), *r2 = calloc(n, sizeof *r2);
        double *y = malloc(n * sizeof *y), *y1 = malloc(n * sizeof *y1),
               *y2 = malloc(n * sizeof *y2);
        opt_proxy_block_fill(&ball, &tall, p.dof, p.X, r1);
        opt_proxy_block_fill(&ba, &ta, p.dof, p.X, r2);
        opt_proxy_block_fill(&bb, &tb, p.dof, p.X, r2);
        for (int i = 0; i < n; i++) assert_true(fabs(r1[i] - r2[i]) < 1e-12 * (1 + fabs(r1[i])));
        opt_proxy_system sys = {0};
        const opt_proxy_block *bl[2] = {&ba, &bb};
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
        unsigned v1 = sys.version;
        const double *val1 = sys.A.val;
        assert_sum_is_plain(&sys, bl, 2);
        assert_int_equal(sys.A.nnz, ball.A.nnz);
        assert_memory_equal(sys.A.rowidx, ball.A.rowidx, ball.A.nnz * sizeof(int));
        for (int trial = 0; trial < 3; trial++) {
            for (int i = 0; i < n; i++) y[i] = rng_uniform(&r, -1, 1);
            opt_csc_symv(&ball.A, y, y1);
            opt_csc_symv(&sys.A, y, y2);
            for (int i = 0; i < n; i++)
                assert_true(fabs(y1[i] - y2[i]) < 1e-10 * (1 + fabs(y1[i])));
        }
        /* Same patterns again: no union rebuild. */
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
        assert_int_equal(sys.version, v1);
        /* Rebuild block B as a different subset (like a new scaffold): the
         * union follows, block A's pattern is untouched. */
        unsigned va = ba.version;
        B.n = (ns - k) / 2;
        assert_int_equal(opt_proxy_block_pattern(&bb, &B, p.dof, p.nfree, NULL), SCAF_OK);
        memset(r2, 0, n * sizeof *r2);
        opt_proxy_block_fill(&ba, &ta, p.dof, p.X, r2);
        opt_proxy_block_fill(&bb, &tb, p.dof, p.X, r2);
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
        assert_true(sys.version != v1);
        assert_int_equal(ba.version, va);
        assert_sum_is_plain(&sys, bl, 2);
        assert_ptr_equal(sys.A.val, val1); /* a smaller union refills its storage */
        opt_simplices C = p.S;
        C.n = k + B.n;
        opt_term tc = {&C, tall.energy};
        opt_proxy_block bc = {0};
        assert_int_equal(opt_proxy_block_pattern(&bc, &C, p.dof, p.nfree, NULL), SCAF_OK);
        memset(r1, 0, n * sizeof *r1);
        opt_proxy_block_fill(&bc, &tc, p.dof, p.X, r1);
        for (int i = 0; i < n; i++) y[i] = rng_uniform(&r, -1, 1);
        opt_csc_symv(&bc.A, y, y1);
        opt_csc_symv(&sys.A, y, y2);
        for (int i = 0; i < n; i++) assert_true(fabs(y1[i] - y2[i]) < 1e-10 * (1 + fabs(y1[i])));
        /* One block (A aliases it), then two again with B whole: the kept
         * storage serves the union once more and the sum is right. */
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 1, NULL), SCAF_OK);
        assert_ptr_equal(sys.A.val, ba.A.val);
        assert_int_equal(sys.owns, 0);
        B.n = ns - k;
        assert_int_equal(opt_proxy_block_pattern(&bb, &B, p.dof, p.nfree, NULL), SCAF_OK);
        memset(r2, 0, n * sizeof *r2);
        opt_proxy_block_fill(&ba, &ta, p.dof, p.X, r2);
        opt_proxy_block_fill(&bb, &tb, p.dof, p.X, r2);
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
        assert_ptr_equal(sys.A.val, val1);
        assert_sum_is_plain(&sys, bl, 2);
        assert_int_equal(sys.A.nnz, ball.A.nnz);
        assert_memory_equal(sys.A.rowidx, ball.A.rowidx, ball.A.nnz * sizeof(int));
        opt_proxy_block_free(&bc);
        opt_proxy_system_free(&sys);
        opt_proxy_block_free(&ball);
        opt_proxy_block_free(&ba);
        opt_proxy_block_free(&bb);
        free(r1);
        free(r2);
        free(y);
        free(y1);
        free(y2);
        free_problem(&p);
    }
}

/* Chart block on the low dofs, a "scaffold" block on the rest whose
 * numbering and size change (one of its vertices becomes fixed, the others
 * renumbered): the chart block is reused untouched and the sum equals one
 * block built from scratch with the new numbering. */
static void chart_block_survives_scaffold_renumbering(void **state)
{
    (void)state;
    rng r = {59};
    problem p;
    make_problem(&p, 2);
    int d = 2, m = p.nfree / 2, ns = p.S.n;
    /* Sort simplices: chart = all free corners have dof < m. */
    int *ia = malloc(ns * sizeof *ia), na = 0, nb = 0;
    int *ib = malloc(ns * sizeof *ib);
    for (int s = 0; s < ns; s++) {
        int chart = 1;
        for (int i = 0; i < 3; i++) chart &= p.dof[p.S.idx[3 * s + i]] < m;
        if (chart) ia[na++] = s;
        else ib[nb++] = s;
    }
    assert_true(na > 0 && nb > 0);
    opt_simplices A, B;
    assert_int_equal(opt_simplices_alloc(&A, 2, na, NULL), SCAF_OK);
    assert_int_equal(opt_simplices_alloc(&B, 2, nb, NULL), SCAF_OK);
    for (int k = 0; k < na; k++) {
        memcpy(A.idx + 3 * k, p.S.idx + 3 * ia[k], 3 * sizeof(int));
        memcpy(A.grad + 6 * k, p.S.grad + 6 * ia[k], 6 * sizeof(double));
        A.vol[k] = p.S.vol[ia[k]];
        A.weight[k] = p.S.weight[ia[k]];
    }
    for (int k = 0; k < nb; k++) {
        memcpy(B.idx + 3 * k, p.S.idx + 3 * ib[k], 3 * sizeof(int));
        memcpy(B.grad + 6 * k, p.S.grad + 6 * ib[k], 6 * sizeof(double));
        B.vol[k] = p.S.vol[ib[k]];
        B.weight[k] = p.S.weight[ib[k]];
    }
    opt_term ta = {&A, OPT_ENERGY_SYMMETRIC_DIRICHLET}, tb = {&B, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_term tall = {&p.S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    opt_proxy_block ba = {0}, bb = {0}, ball = {0};
    assert_int_equal(opt_proxy_block_pattern(&ba, &A, p.dof, p.nfree, NULL), SCAF_OK);
    assert_true(ba.nfree <= m);
    /* New numbering: the highest-dof free vertex becomes fixed, the others
     * at or above m are numbered in reverse. */
    int *dof2 = malloc(p.nv * sizeof *dof2), top = -1, vtop = -1;
    for (int v = 0; v < p.nv; v++)
        if (p.dof[v] > top) {
            top = p.dof[v];
            vtop = v;
        }
    int n2 = p.nfree - 1;
    for (int v = 0; v < p.nv; v++) {
        int k = p.dof[v];
        dof2[v] = v == vtop ? -1 : k < m ? k : (k >= 0 ? m + (top - 1 - k) : -1);
    }
    assert_int_equal(opt_proxy_block_pattern(&bb, &B, dof2, n2, NULL), SCAF_OK);
    assert_int_equal(opt_proxy_block_pattern(&ball, &p.S, dof2, n2, NULL), SCAF_OK);
    unsigned va = ba.version;
    int n = n2 * d;
    double *r1 = calloc(n, sizeof *r1), *r2 = calloc(n, sizeof *r2);
    double *y = malloc(n * sizeof *y), *y1 = malloc(n * sizeof *y1), *y2 = malloc(n * sizeof *y2);
    opt_proxy_block_fill(&ba, &ta, dof2, p.X, r1);
    opt_proxy_block_fill(&bb, &tb, dof2, p.X, r1);
    opt_proxy_block_fill(&ball, &tall, dof2, p.X, r2);
    opt_proxy_system sys = {0};
    const opt_proxy_block *bl[2] = {&ba, &bb};
    assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
    assert_int_equal(sys.A.n, n);
    assert_int_equal(ba.version, va);
    for (int i = 0; i < n; i++) y[i] = rng_uniform(&r, -1, 1);
    opt_csc_symv(&sys.A, y, y1);
    opt_csc_symv(&ball.A, y, y2);
    for (int i = 0; i < n; i++) {
        assert_true(fabs(y1[i] - y2[i]) < 1e-10 * (1 + fabs(y2[i])));
        assert_true(fabs(r1[i] - r2[i]) < 1e-10 * (1 + fabs(r2[i])));
    }
    free(r1);
    free(r2);
    free(y);
    free(y1);
    free(y2);
    free(dof2);
    free(ia);
    free(ib);
    opt_proxy_system_free(&sys);
    opt_proxy_block_free(&ba);
    opt_proxy_block_free(&bb);
    opt_proxy_block_free(&ball);
    opt_simplices_free(&A);
    opt_simplices_free(&B);
    free_problem(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matrix_is_the_proxy_quadratic),
        cmocka_unit_test(blocks_sum_like_one),
        cmocka_unit_test(chart_block_survives_scaffold_renumbering),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
