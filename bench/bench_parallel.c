/* bench/bench_parallel: scaf's own threaded loops (base/parallel) on one
 * chart, at 1 and 2 threads, without the factorization around them.
 *
 * Harmonic start, one SCAF iteration (one thread), then on the chart's
 * triangles at that map, with D = the step that iteration took: the
 * energy, the line search's energy-and-slope, flip-free bound and exact
 * orientation check, the SLIM proxy fill and the projected Newton fill
 * (into the chart's own block). Each operation is timed R times per thread
 * count, the counts interleaved (1, 2, 1, 2, ...) so that a change of
 * load hits both alike; prints per operation the median wall seconds at
 * 1 and 2 threads and their ratio, and the process CPU seconds of all
 * repetitions per count (CPU at 2 / CPU at 1 = the threads' overhead).
 * The vertices are first renumbered breadth first, as `scaf param`'s
 * working mesh is (mesh/vertex_order), so the loops see the layout users
 * get. OpenBLAS is not involved. A missing or non-disk mesh prints the
 * reason and exits with status 1.
 *
 *   build/bench/bench_parallel [MESH.obj|.off] [R]   (default aphrodite, 21)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/parallel.h"
#include "base/timer.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "mesh/vertex_order.h"
#include "opt/embed.h"
#include "opt/newton_fill.h"
#include "opt/objective.h"
#include "scaffold/scaf_loop.h"

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif

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

enum { OP_ENERGY, OP_SLOPE, OP_MAX_STEP, OP_VALID, OP_SLIM_FILL, OP_NEWTON_FILL, NOPS };
static const char *const op_name[NOPS] = {"energy",       "energy + slope", "flip-free bound",
                                          "orientations", "SLIM fill",      "Newton fill"};

typedef struct bench {
    opt_obj_term t;
    const opt_simplices *S;
    const double *X, *D;
    int *dof;
    opt_proxy_block blk;
    double *rhs;
} bench;

/* m's vertices renumbered breadth first (app/param's working numbering). */
static scaf_status renumber(mesh *m, scaf_error *err)
{
    int *rank = malloc(sizeof(int) * (size_t)m->nv);
    double *V = malloc(sizeof(double) * 3 * (size_t)m->nv);
    if (!rank || !V) {
        free(rank);
        free(V);
        return err_nomem(err, "renumbering");
    }
    scaf_status st = mesh_vertex_order_breadth_first(3, m->nf, m->F, m->nv, rank, err);
    if (st == SCAF_OK) {
        for (int v = 0; v < m->nv; v++)
            memcpy(V + 3 * (size_t)rank[v], m->V + 3 * (size_t)v, 3 * sizeof *V);
        memcpy(m->V, V, sizeof(double) * 3 * (size_t)m->nv);
        for (size_t k = 0; k < 3 * (size_t)m->nf; k++) m->F[k] = rank[m->F[k]];
    }
    free(rank);
    free(V);
    return st;
}

static double sink;

static void run_op(bench *b, int op)
{
    double e = 0, s = 0;
    opt_term term = {b->S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    switch (op) {
    case OP_ENERGY: sink += b->t.ops->energy(&b->t, b->X); break;
    case OP_SLOPE:
        b->t.ops->energy_slope(&b->t, b->X, b->D, &e, &s);
        sink += e + s;
        break;
    case OP_MAX_STEP: sink += b->t.ops->max_step(&b->t, b->X, b->D); break;
    case OP_VALID: sink += b->t.ops->valid(&b->t, b->X); break;
    case OP_SLIM_FILL:
        memset(b->rhs, 0, sizeof *b->rhs * 2 * (size_t)b->blk.nfree);
        opt_proxy_block_fill(&b->blk, &term, b->dof, b->X, b->rhs);
        break;
    default:
        memset(b->rhs, 0, sizeof *b->rhs * 2 * (size_t)b->blk.nfree);
        opt_newton_block_fill(&b->blk, &term, b->dof, b->X, 1, b->rhs, NULL, NULL);
    }
}

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : SCAF_DATA_DIR "/disk/aphrodite.obj";
    int R = argc > 2 ? atoi(argv[2]) : 21;
    if (R < 1) R = 1;
    mesh m;
    scaf_error err;
    if (mesh_read(path, &m, NULL, &err) != SCAF_OK || renumber(&m, &err) != SCAF_OK) {
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
    scaf_loop L;
    if (opt_embed_chart(m.nv, m.V, m.nf, m.F, &ol, OPT_EMBED_HARMONIC, uv, NULL, &err) != SCAF_OK ||
        scaf_loop_init(&L, m.nv, m.V, m.nf, m.F, uv, NULL, &err) != SCAF_OK ||
        scaf_loop_step(&L, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "setup: %s\n", err.message);
        return 1;
    }
    bench b;
    memset(&b, 0, sizeof b);
    opt_simplex_term st = {&L.chart, OPT_ENERGY_SYMMETRIC_DIRICHLET, NULL, 0};
    b.t = opt_simplex_term_make(&st);
    b.S = &L.chart;
    b.X = L.uv;
    double *D = malloc(sizeof(double) * 2 * (size_t)m.nv);
    b.dof = malloc(sizeof(int) * (size_t)m.nv);
    b.rhs = malloc(sizeof(double) * 2 * (size_t)m.nv);
    if (!D || !b.dof || !b.rhs) return 1;
    for (size_t k = 0; k < 2 * (size_t)m.nv; k++) D[k] = L.uv[k] - uv[k];
    b.D = D;
    opt_dof_numbering(m.nv, NULL, b.dof);
    if (opt_proxy_block_pattern(&b.blk, b.S, b.dof, m.nv, &err) != SCAF_OK) return 1;
    printf("%s: %d triangles, %d runs per count, interleaved\n\n", path, m.nf, R);
    printf("| operation | 1 thread, s | 2 threads, s | 1 / 2 | CPU s at 1 | CPU s at 2 |\n");
    printf("|---|---|---|---|---|---|\n");
    double *w = malloc(sizeof(double) * 2 * (size_t)R);
    for (int op = 0; op < NOPS; op++) {
        double cpu[2] = {0, 0};
        for (int r = 0; r < R; r++)
            for (int t = 0; t < 2; t++) {
                par_set_threads(t + 1);
                clock_t c0 = clock();
                double t0 = timer_now();
                run_op(&b, op);
                w[t * R + r] = timer_now() - t0;
                cpu[t] += (double)(clock() - c0) / CLOCKS_PER_SEC;
            }
        qsort(w, (size_t)R, sizeof *w, cmp_double);
        qsort(w + R, (size_t)R, sizeof *w, cmp_double);
        double m1 = w[R / 2], m2 = w[R + R / 2];
        printf("| %s | %.5f | %.5f | %.2fx | %.3f | %.3f |\n", op_name[op], m1, m2, m1 / m2, cpu[0],
               cpu[1]);
    }
    par_set_threads(1);
    free(w);
    free(D);
    free(b.dof);
    free(b.rhs);
    opt_proxy_block_free(&b.blk);
    scaf_loop_free(&L);
    free(loop);
    free(uv);
    mesh_free(&m);
    return sink == 12345.678 ? 2 : 0;
}
