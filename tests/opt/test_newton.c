/* Tests for opt/newton_fill: the assembled (projected or exact) Newton
 * system against a dense assembly of the per-simplex pieces, in SLIM's
 * pattern. Newton steps through the SCAF loop (descent, convergence,
 * fallbacks) are tested in tests/scaffold/test_scaf_loop_newton.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "opt/cholmod_solver.h"
#include "opt/embed.h"
#include "opt/newton_fill.h"
#include "opt/isotropic_hessian.h"
#include "polar_disk.h"
#include "rng.h"
#include "tet_grid.h"

/* A problem: one term over nv vertices, dof numbering, start positions,
 * and the minimum energy when known (NAN otherwise). */
typedef struct problem {
    int d, nv, nfree;
    opt_simplices S;
    double *X;
    int *dof;
    double e_min;
} problem;

static void problem_free(problem *p)
{
    opt_simplices_free(&p->S);
    free(p->X);
    free(p->dof);
}

/* Flat disk: rest = the planar polar grid, boundary fixed at rest, interior
 * pushed by a smooth swirl and shear. The minimum is the rest shape, where
 * every triangle has density 4. */
static void flat_disk(problem *p, int rings, int seg, double amount)
{
    polar_disk m;
    assert_int_equal(polar_disk_make(&m, rings, seg, 0.0, 0), 0);
    p->d = 2;
    p->nv = m.nv;
    double *R = malloc(2 * (size_t)m.nv * sizeof *R);
    p->X = malloc(2 * (size_t)m.nv * sizeof *p->X);
    p->dof = malloc((size_t)m.nv * sizeof *p->dof);
    unsigned char *fixed = calloc((size_t)m.nv, 1);
    for (int k = 0; k < m.start[1]; k++) fixed[m.loops[k]] = 1;
    for (int v = 0; v < m.nv; v++) {
        double x = m.V[3 * v], y = m.V[3 * v + 1], b = 1 - (x * x + y * y), a = amount * b;
        R[2 * v] = x;
        R[2 * v + 1] = y;
        p->X[2 * v] = cos(a) * x - sin(a) * y + 0.5 * amount * b * y;
        p->X[2 * v + 1] = sin(a) * x + cos(a) * y;
    }
    assert_int_equal(opt_simplices_from_current(&p->S, 2, m.nv, R, m.nf, m.F, 0.0, NULL), SCAF_OK);
    p->nfree = opt_dof_numbering(m.nv, fixed, p->dof);
    double w = 0;
    for (int s = 0; s < p->S.n; s++) w += p->S.weight[s];
    p->e_min = 4 * w;
    free(fixed);
    free(R);
    polar_disk_free(&m);
}

/* Cube of tets: rest = the grid, boundary fixed, interior jittered. The
 * minimum is the rest shape (density 6). */
static void jittered_cube(problem *p, int cells, double amount, uint64_t seed)
{
    tet_grid g;
    assert_int_equal(tet_grid_make(&g, cells), 0);
    p->d = 3;
    p->nv = g.nv;
    assert_int_equal(opt_simplices_from_current(&p->S, 3, g.nv, g.X, g.nt, g.T, 0.0, NULL),
                     SCAF_OK);
    rng r = {seed};
    p->X = malloc(3 * (size_t)g.nv * sizeof *p->X);
    p->dof = malloc((size_t)g.nv * sizeof *p->dof);
    for (int v = 0; v < g.nv; v++)
        for (int a = 0; a < 3; a++)
            p->X[3 * v + a] =
                g.X[3 * v + a] + (g.boundary[v] ? 0 : rng_uniform(&r, -amount, amount));
    p->nfree = opt_dof_numbering(g.nv, g.boundary, p->dof);
    double w = 0;
    for (int s = 0; s < p->S.n; s++) w += p->S.weight[s];
    p->e_min = 6 * w;
    tet_grid_free(&g);
}

/* ---- assembly ---------------------------------------------------------- */

/* The block's upper CSC expanded to a dense symmetric n by n matrix. */
static double *dense_of(const opt_csc *A)
{
    int n = A->n;
    double *M = calloc((size_t)n * n, sizeof *M);
    for (int c = 0; c < n; c++)
        for (int k = A->colptr[c]; k < A->colptr[c + 1]; k++) {
            int r = A->rowidx[k];
            M[(size_t)r * n + c] = A->val[k];
            M[(size_t)c * n + r] = A->val[k];
        }
    return M;
}

static void check_fill_against_dense_energy(problem *p, int project, opt_energy energy)
{
    int d = p->d, nd = (d + 1) * d, n = p->nfree * d;
    opt_proxy_block b = {0};
    assert_int_equal(opt_proxy_block_pattern(&b, &p->S, p->dof, p->nfree, NULL), SCAF_OK);
    assert_int_equal(b.A.n, n);
    opt_term t = {&p->S, energy};
    double *rhs = calloc((size_t)n, sizeof *rhs);
    opt_newton_fill_stats st;
    assert_int_equal(opt_newton_block_fill(&b, &t, p->dof, p->X, project, rhs, &st, NULL), SCAF_OK);
    assert_true(fabs(st.energy - opt_term_energy(&t, p->X)) <= 1e-12 * st.energy);
    assert_true(st.clamped > 0); /* some simplices have negative eigenvalues */
    /* Reference: the per-simplex pieces scattered densely over free unknowns. */
    double *Href = calloc((size_t)n * n, sizeof *Href), *gref = calloc((size_t)n, sizeof *gref);
    for (int s = 0; s < p->S.n; s++) {
        double e, g[12], H[144];
        assert_true(opt_isotropic_simplex_hessian(energy, &p->S, s, p->X, project, &e, g, H) >= 0);
        const int *ix = p->S.idx + (size_t)s * (d + 1);
        for (int m = 0; m < nd; m++) {
            int dm = p->dof[ix[m / d]];
            if (dm < 0) continue;
            int gm = dm * d + m % d;
            gref[gm] -= g[m];
            for (int k = 0; k < nd; k++) {
                int dk = p->dof[ix[k / d]];
                if (dk >= 0) Href[(size_t)gm * n + dk * d + k % d] += H[m * nd + k];
            }
        }
    }
    double *M = dense_of(&b.A), hs = 0, gs = 0;
    for (size_t k = 0; k < (size_t)n * n; k++) hs = fmax(hs, fabs(Href[k]));
    for (int k = 0; k < n; k++) gs = fmax(gs, fabs(gref[k]));
    for (size_t k = 0; k < (size_t)n * n; k++)
        if (fabs(M[k] - Href[k]) > 1e-12 * hs) {
            print_error("%s d=%d entry (%zu, %zu): block %.17g dense %.17g\n",
                        opt_energy_name(energy), d, k / n, k % n, M[k], Href[k]);
            fail();
        }
    for (int k = 0; k < n; k++) assert_true(fabs(rhs[k] - gref[k]) <= 1e-12 * gs);
    /* Same pattern as SLIM's proxy: a SLIM fill touches exactly these entries. */
    int nnz = b.A.nnz;
    opt_proxy_block_fill(&b, &t, p->dof, p->X, rhs);
    assert_int_equal(b.A.nnz, nnz);
    free(M);
    free(Href);
    free(gref);
    free(rhs);
    opt_proxy_block_free(&b);
}

/* Every energy's block (each has a Hessian: opt/isotropic_hessian). */
static void check_fill_against_dense(problem *p, int project)
{
    const opt_energy all[3] = {OPT_ENERGY_SYMMETRIC_DIRICHLET, OPT_ENERGY_ARAP,
                               OPT_ENERGY_CONFORMAL};
    for (int k = 0; k < 3; k++) check_fill_against_dense_energy(p, project, all[k]);
}

static void newton_fill_matches_dense_assembly(void **state)
{
    (void)state;
    problem p;
    flat_disk(&p, 3, 10, 1.2);
    check_fill_against_dense(&p, 1);
    check_fill_against_dense(&p, 0);
    /* Also with an interior vertex fixed (couplings to it dropped). */
    p.dof[0] = -1;
    for (int v = 1; v < p.nv; v++)
        if (p.dof[v] >= 0) p.dof[v]--;
    p.nfree--;
    check_fill_against_dense(&p, 1);
    problem_free(&p);
    jittered_cube(&p, 2, 0.12, 3);
    check_fill_against_dense(&p, 1);
    check_fill_against_dense(&p, 0);
    problem_free(&p);
}

/* add_local folds a simplex whose vertex repeats (i != j, same vertex)
 * into the vertex's diagonal block from both orders. */
static void add_local_folds_repeated_vertices(void **state)
{
    (void)state;
    opt_simplices S;
    assert_int_equal(opt_simplices_alloc(&S, 2, 1, NULL), SCAF_OK);
    int idx[3] = {1, 0, 1}, dof[2] = {0, 1};
    memcpy(S.idx, idx, sizeof idx);
    for (int k = 0; k < 6; k++) S.grad[k] = 1.0;
    S.vol[0] = S.weight[0] = 1.0;
    opt_proxy_block b = {0};
    assert_int_equal(opt_proxy_block_pattern(&b, &S, dof, 2, NULL), SCAF_OK);
    rng r = {21};
    double K[36], ref[16] = {0};
    for (int m = 0; m < 6; m++)
        for (int k = m; k < 6; k++) K[m * 6 + k] = K[k * 6 + m] = rng_uniform(&r, -1, 1);
    for (int m = 0; m < 6; m++)
        for (int k = 0; k < 6; k++)
            ref[(dof[idx[m / 2]] * 2 + m % 2) * 4 + dof[idx[k / 2]] * 2 + k % 2] += K[m * 6 + k];
    memset(b.A.val, 0, (size_t)b.A.nnz * sizeof *b.A.val);
    opt_proxy_block_add_local(&b, &S, 0, dof, K);
    double *M = dense_of(&b.A);
    for (int k = 0; k < 16; k++) assert_true(fabs(M[k] - ref[k]) < 1e-15);
    free(M);
    opt_proxy_block_free(&b);
    opt_simplices_free(&S);
}

static void newton_fill_refuses_bad_input(void **state)
{
    (void)state;
    problem p;
    flat_disk(&p, 2, 8, 0.5);
    opt_proxy_block b = {0};
    assert_int_equal(opt_proxy_block_pattern(&b, &p.S, p.dof, p.nfree, NULL), SCAF_OK);
    double *rhs = calloc((size_t)p.nfree * 2, sizeof *rhs);
    scaf_error e;
    /* Collapse the center onto a boundary vertex: inverted simplices named. */
    p.X[0] = 2 * p.X[2 * p.nv - 2];
    p.X[1] = 2 * p.X[2 * p.nv - 1];
    opt_term t = {&p.S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    assert_int_equal(opt_newton_block_fill(&b, &t, p.dof, p.X, 1, rhs, NULL, &e), SCAF_ERR_NUMERIC);
    assert_non_null(strstr(e.message, "simplex"));
    free(rhs);
    opt_proxy_block_free(&b);
    problem_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(newton_fill_matches_dense_assembly),
        cmocka_unit_test(add_local_folds_repeated_vertices),
        cmocka_unit_test(newton_fill_refuses_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
