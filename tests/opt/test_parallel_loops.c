/* Tests for the threaded loops over simplices (base/parallel): with 2 and 3
 * threads the SLIM proxy fill and the Newton fill write exactly the serial
 * values (matrix and right side, byte for byte), the flip-free bound and
 * the exact validity check are the serial ones, the sum of two blocks
 * into one system is the serial sum, and the energy sums agree
 * with the serial sums to round-off and are the same run after run. The
 * meshes are big enough for several chunks (PAR_MIN_CHUNK), their vertex
 * ids shuffled so that many simplices straddle two threads' columns, and
 * have fixed vertices (couplings moved to the right side); the fills are
 * also checked in the chart's layout (breadth-first ids, simplices by
 * their last vertex). No timing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "base/parallel.h"
#include "mesh/vertex_order.h"
#include "opt/flip_free_step.h"
#include "opt/newton_fill.h"
#include "opt/objective.h"
#include "opt/proxy_block.h"
#include "opt/proxy_system.h"
#include "polar_disk.h"
#include "rng.h"
#include "tet_grid.h"

typedef struct problem {
    int d, nv, nfree;
    double *X, *D;
    int *dof;
    opt_simplices S;
} problem;

/* Shuffle vertex ids (Fisher-Yates): perm[old] = new. */
static int *shuffled(int nv, rng *r)
{
    int *perm = malloc((size_t)nv * sizeof *perm);
    for (int v = 0; v < nv; v++) perm[v] = v;
    for (int v = nv - 1; v > 0; v--) {
        int k = (int)rng_uniform(r, 0, v + 1);
        int t = perm[v];
        perm[v] = perm[k];
        perm[k] = t;
    }
    return perm;
}

/* 2D: a polar disk of 13,900 triangles, X = its xy projection stretched,
 * outer ring fixed. 3D: a tet grid of 13,182 tets, interior jittered,
 * surface fixed. Ids shuffled; D a random direction. */
static void make_problem(problem *p, int d)
{
    rng r = {7};
    p->d = d;
    unsigned char *fixed;
    int *F, n;
    double *V = NULL;
    if (d == 2) {
        polar_disk m;
        assert_int_equal(polar_disk_make(&m, 70, 100, 0.7, 0), 0);
        p->nv = m.nv;
        n = m.nf;
        int *perm = shuffled(m.nv, &r);
        V = malloc(3 * (size_t)m.nv * sizeof *V);
        p->X = malloc(2 * (size_t)m.nv * sizeof *p->X);
        fixed = calloc((size_t)m.nv, 1);
        for (int v = 0; v < m.nv; v++) {
            memcpy(V + 3 * perm[v], m.V + 3 * v, 3 * sizeof *V);
            p->X[2 * perm[v]] = m.V[3 * v] * 1.3;
            p->X[2 * perm[v] + 1] = m.V[3 * v + 1];
        }
        for (int k = 0; k < m.start[1]; k++) fixed[perm[m.loops[k]]] = 1;
        F = malloc(3 * (size_t)n * sizeof *F);
        for (int k = 0; k < 3 * n; k++) F[k] = perm[m.F[k]];
        assert_int_equal(opt_simplices_from_surface(&p->S, m.nv, V, n, F, NULL), SCAF_OK);
        free(perm);
        polar_disk_free(&m);
    } else {
        tet_grid g;
        assert_int_equal(tet_grid_make(&g, 13), 0);
        p->nv = g.nv;
        n = g.nt;
        int *perm = shuffled(g.nv, &r);
        V = malloc(3 * (size_t)g.nv * sizeof *V);
        p->X = malloc(3 * (size_t)g.nv * sizeof *p->X);
        fixed = calloc((size_t)g.nv, 1);
        for (int v = 0; v < g.nv; v++) {
            memcpy(V + 3 * perm[v], g.X + 3 * v, 3 * sizeof *V);
            for (int a = 0; a < 3; a++)
                p->X[3 * perm[v] + a] =
                    g.X[3 * v + a] + (g.boundary[v] ? 0 : rng_uniform(&r, -0.01, 0.01));
            fixed[perm[v]] = g.boundary[v];
        }
        F = malloc(4 * (size_t)n * sizeof *F);
        for (int k = 0; k < 4 * n; k++) F[k] = perm[g.T[k]];
        assert_int_equal(opt_simplices_from_current(&p->S, 3, g.nv, V, n, F, 0.0, NULL), SCAF_OK);
        free(perm);
        tet_grid_free(&g);
    }
    assert_true(n >= 3 * PAR_MIN_CHUNK); /* 3 chunks at 3 threads */
    p->dof = malloc((size_t)p->nv * sizeof *p->dof);
    p->nfree = opt_dof_numbering(p->nv, fixed, p->dof);
    p->D = malloc((size_t)d * p->nv * sizeof *p->D);
    for (int k = 0; k < d * p->nv; k++) p->D[k] = rng_uniform(&r, -1, 1);
    for (int s = 0; s < p->S.n; s++) p->S.weight[s] *= rng_uniform(&r, 0.5, 1.5);
    free(fixed);
    free(F);
    free(V);
}

/* The chart's layout (app/param, scaffold/scaf_loop): vertices renumbered
 * breadth first (mesh/vertex_order), simplices ordered by their last vertex. A
 * batch of a parallel fill then writes a narrow band of columns, which
 * opt/fill_split cuts inside. */
static void localize(problem *p)
{
    int d = p->d, nv = p->nv, n = p->S.n;
    int *rank = malloc((size_t)nv * sizeof *rank), *order = malloc((size_t)n * sizeof *order);
    double *X = malloc((size_t)d * nv * sizeof *X), *D = malloc((size_t)d * nv * sizeof *D);
    unsigned char *fixed = calloc((size_t)nv, 1);
    assert_true(rank && order && X && D && fixed);
    assert_int_equal(mesh_vertex_order_breadth_first(d + 1, n, p->S.idx, nv, rank, NULL), SCAF_OK);
    for (int v = 0; v < nv; v++) {
        memcpy(X + (size_t)d * rank[v], p->X + (size_t)d * v, (size_t)d * sizeof *X);
        memcpy(D + (size_t)d * rank[v], p->D + (size_t)d * v, (size_t)d * sizeof *D);
        fixed[rank[v]] = p->dof[v] < 0;
    }
    for (size_t k = 0; k < (size_t)n * (d + 1); k++) p->S.idx[k] = rank[p->S.idx[k]];
    assert_int_equal(opt_simplices_order_by_last_vertex(&p->S, nv, order, NULL), SCAF_OK);
    assert_int_equal(opt_simplices_permute(&p->S, order, NULL), SCAF_OK);
    p->nfree = opt_dof_numbering(nv, fixed, p->dof);
    free(p->X);
    free(p->D);
    p->X = X;
    p->D = D;
    free(fixed);
    free(order);
    free(rank);
}

static void free_problem(problem *p)
{
    free(p->X);
    free(p->D);
    free(p->dof);
    opt_simplices_free(&p->S);
}

/* The block's values and the right side after a SLIM (newton = 0) or
 * projected Newton fill with `threads` threads. */
static void fill(const problem *p, opt_energy e, int newton, int threads, double **val,
                 double **rhs, double *energy)
{
    par_set_threads(threads);
    opt_term t = {&p->S, e};
    opt_proxy_block b = {0};
    assert_int_equal(opt_proxy_block_pattern(&b, &p->S, p->dof, p->nfree, NULL), SCAF_OK);
    size_t n = (size_t)p->nfree * p->d;
    *rhs = calloc(n, sizeof **rhs);
    *energy = 0;
    /* a fill must write every value: what a block held before is not zero
     * (a SLIM fill stores at each entry's first writer instead of zeroing) */
    for (int k = 0; k < b.A.nnz; k++) b.A.val[k] = NAN;
    if (newton) {
        opt_newton_fill_stats st;
        assert_int_equal(opt_newton_block_fill(&b, &t, p->dof, p->X, 1, *rhs, &st, NULL), SCAF_OK);
        *energy = st.energy;
    } else {
        *energy = opt_proxy_block_fill_capped(&b, &t, p->dof, p->X, *rhs, INFINITY);
    }
    *val = malloc((size_t)b.A.nnz * sizeof **val);
    memcpy(*val, b.A.val, (size_t)b.A.nnz * sizeof **val);
    assert_true(b.A.nnz > 0);
    opt_proxy_block_free(&b);
    par_set_threads(1);
}

static void fills_equal_serial(void **state)
{
    (void)state;
    for (int layout = 0; layout < 4; layout++) {
        int d = 2 + layout / 2;
        problem p;
        make_problem(&p, d);
        if (layout % 2) localize(&p);
        opt_proxy_block b = {0};
        assert_int_equal(opt_proxy_block_pattern(&b, &p.S, p.dof, p.nfree, NULL), SCAF_OK);
        size_t nnz = (size_t)b.A.nnz, n = (size_t)p.nfree * d;
        opt_proxy_block_free(&b);
        for (int newton = 0; newton <= 1; newton++)
            for (int e = 0; e < 3; e++) {
                double *v1, *r1, e1;
                fill(&p, (opt_energy)e, newton, 1, &v1, &r1, &e1);
                for (int threads = 2; threads <= 3; threads++) {
                    double *v, *r, en;
                    fill(&p, (opt_energy)e, newton, threads, &v, &r, &en);
                    assert_memory_equal(v, v1, nnz * sizeof *v);
                    assert_memory_equal(r, r1, n * sizeof *r);
                    assert_memory_equal(&en, &e1, sizeof en); /* w2 max / energy in order */
                    free(v);
                    free(r);
                }
                free(v1);
                free(r1);
            }
        free_problem(&p);
    }
}

/* Two blocks (the first and the second half of the simplices) summed into
 * one system: the same values with 1, 2 and 3 threads. */
static void system_sum_equal_serial(void **state)
{
    (void)state;
    problem p;
    make_problem(&p, 2);
    int d = p.d, half = p.S.n / 2;
    opt_simplices part[2] = {p.S, p.S};
    part[0].n = half;
    part[1].n = p.S.n - half;
    part[1].idx += (size_t)half * (d + 1);
    part[1].grad += (size_t)half * (d + 1) * d;
    part[1].vol += half;
    part[1].weight += half;
    opt_proxy_block blk[2] = {{0}, {0}};
    size_t n = (size_t)p.nfree * d;
    double *rhs = calloc(n, sizeof *rhs), *v1 = NULL;
    size_t nnz = 0;
    for (int threads = 1; threads <= 3; threads++) {
        par_set_threads(threads);
        const opt_proxy_block *bl[2];
        for (int k = 0; k < 2; k++) {
            assert_int_equal(opt_proxy_block_pattern(&blk[k], &part[k], p.dof, p.nfree, NULL),
                             SCAF_OK);
            opt_term t = {&part[k], OPT_ENERGY_SYMMETRIC_DIRICHLET};
            opt_proxy_block_fill(&blk[k], &t, p.dof, p.X, rhs);
            bl[k] = &blk[k];
        }
        opt_proxy_system sys = {0};
        assert_int_equal(opt_proxy_system_sum(&sys, bl, 2, NULL), SCAF_OK);
        assert_true(sys.A.nnz > 2 * PAR_MIN_CHUNK);
        if (threads == 1) {
            nnz = (size_t)sys.A.nnz;
            v1 = malloc(nnz * sizeof *v1);
            memcpy(v1, sys.A.val, nnz * sizeof *v1);
        } else {
            assert_int_equal(sys.A.nnz, nnz);
            assert_memory_equal(sys.A.val, v1, nnz * sizeof *v1);
        }
        opt_proxy_system_free(&sys);
    }
    par_set_threads(1);
    for (int k = 0; k < 2; k++) opt_proxy_block_free(&blk[k]);
    free(v1);
    free(rhs);
    free_problem(&p);
}

static void line_search_loops(void **state)
{
    (void)state;
    for (int d = 2; d <= 3; d++) {
        problem p;
        make_problem(&p, d);
        opt_simplex_term st = {&p.S, OPT_ENERGY_SYMMETRIC_DIRICHLET, NULL, 0};
        opt_obj_term t = opt_simplex_term_make(&st);
        double e1 = t.ops->energy(&t, p.X), es1 = 0.5, s1 = -1.0;
        t.ops->energy_slope(&t, p.X, p.D, &es1, &s1);
        double m1 = t.ops->max_step(&t, p.X, p.D);
        assert_true(m1 > 0 && m1 < INFINITY);
        double *Y = malloc((size_t)d * p.nv * sizeof *Y);
        for (int k = 0; k < d * p.nv; k++) Y[k] = p.X[k] + 1.5 * m1 * p.D[k];
        assert_true(t.ops->valid(&t, p.X));
        assert_false(t.ops->valid(&t, Y)); /* past the first inversion */
        for (int threads = 2; threads <= 3; threads++) {
            par_set_threads(threads);
            double e = t.ops->energy(&t, p.X), es = 0.5, s = -1.0;
            t.ops->energy_slope(&t, p.X, p.D, &es, &s);
            assert_true(fabs(e - e1) <= 1e-12 * fabs(e1));
            assert_true(fabs(es - es1) <= 1e-12 * fabs(es1));
            assert_true(fabs(s - s1) <= 1e-12 * fabs(s1) + 1e-12);
            /* the same numbers again with the same count */
            double e_again = t.ops->energy(&t, p.X), es_again = 0.5, s_again = -1.0;
            t.ops->energy_slope(&t, p.X, p.D, &es_again, &s_again);
            assert_memory_equal(&e, &e_again, sizeof e);
            assert_memory_equal(&es, &es_again, sizeof es);
            assert_memory_equal(&s, &s_again, sizeof s);
            double m = t.ops->max_step(&t, p.X, p.D);
            assert_memory_equal(&m, &m1, sizeof m); /* a minimum: exact */
            assert_true(t.ops->valid(&t, p.X));
            assert_false(t.ops->valid(&t, Y));
        }
        par_set_threads(1);
        free(Y);
        free_problem(&p);
    }
}

static void chunks(void **state)
{
    (void)state;
    par_set_threads(4);
    assert_int_equal(par_threads(), 4);
    assert_int_equal(par_chunks(0), 1);
    assert_int_equal(par_chunks(2 * PAR_MIN_CHUNK - 1), 1);
    assert_int_equal(par_chunks(2 * PAR_MIN_CHUNK), 2);
    assert_int_equal(par_chunks(100 * PAR_MIN_CHUNK), 4);
    par_set_threads(1000);
    assert_int_equal(par_chunks((size_t)1000 * PAR_MIN_CHUNK), PAR_MAX_CHUNKS);
    par_set_threads(0);
    assert_int_equal(par_threads(), 1);
    size_t n = 10007;
    for (int nc = 1; nc <= 5; nc++) {
        assert_int_equal(par_chunk_begin(n, nc, 0), 0);
        assert_int_equal(par_chunk_begin(n, nc, nc), n);
        for (int k = 0; k < nc; k++)
            assert_true(par_chunk_begin(n, nc, k) <= par_chunk_begin(n, nc, k + 1));
    }
}

/* An inverted simplex stops the Newton fill with the same error at any
 * thread count: the first inverted simplex in order, named. */
static void newton_failure_named_as_serial(void **state)
{
    (void)state;
    for (int layout = 0; layout < 2; layout++) {
        problem p;
        make_problem(&p, 2);
        if (layout) localize(&p);
        /* a free vertex of a simplex past the middle, thrown far out */
        int s = p.S.n / 2 + 1000, v = -1;
        for (int i = 0; i < 3 && v < 0; i++)
            if (p.dof[p.S.idx[3 * s + i]] >= 0) v = p.S.idx[3 * s + i];
        assert_true(v >= 0);
        p.X[2 * v] += 50.0;
        p.X[2 * v + 1] -= 30.0;
        char first[sizeof(((scaf_error *)0)->message)] = "";
        for (int threads = 1; threads <= 3; threads++) {
            par_set_threads(threads);
            opt_term t = {&p.S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
            opt_proxy_block b = {0};
            assert_int_equal(opt_proxy_block_pattern(&b, &p.S, p.dof, p.nfree, NULL), SCAF_OK);
            double *rhs = calloc((size_t)p.nfree * 2, sizeof *rhs);
            scaf_error e;
            assert_int_equal(opt_newton_block_fill(&b, &t, p.dof, p.X, 1, rhs, NULL, &e),
                             SCAF_ERR_NUMERIC);
            assert_non_null(strstr(e.message, "simplex"));
            if (threads == 1) strcpy(first, e.message);
            else assert_string_equal(e.message, first);
            free(rhs);
            opt_proxy_block_free(&b);
        }
        par_set_threads(1);
        free_problem(&p);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(chunks),
        cmocka_unit_test(fills_equal_serial),
        cmocka_unit_test(newton_failure_named_as_serial),
        cmocka_unit_test(system_sum_equal_serial),
        cmocka_unit_test(line_search_loops),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
