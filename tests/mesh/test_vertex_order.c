/* Tests for mesh/vertex_order: the breadth-first numbering is a permutation,
 * brings a scrambled grid's triangles back to a narrow band, numbers each
 * connected part in one run and unused vertices in their place, and is the
 * same call after call. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <stdlib.h>

#include "mesh/vertex_order.h"

/* A w by h grid of squares, two triangles each, on vertices (w+1)(h+1)
 * numbered by perm (NULL: row by row) and shifted by `base`. */
static int *grid_faces(int w, int h, const int *perm, int base, int *nf)
{
    *nf = 2 * w * h;
    int *F = malloc(3 * (size_t)*nf * sizeof *F), k = 0;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            int a = j * (w + 1) + i, b = a + 1, c = a + w + 1, e = c + 1;
            int t[6] = {a, b, e, a, e, c};
            for (int q = 0; q < 6; q++) F[k++] = base + (perm ? perm[t[q]] : t[q]);
        }
    return F;
}

/* Largest spread of a triangle's numbers under rank (NULL: the ids). */
static int spread(const int *F, int nf, const int *rank)
{
    int worst = 0;
    for (int f = 0; f < nf; f++) {
        int lo = 1 << 30, hi = -1;
        for (int i = 0; i < 3; i++) {
            int r = rank ? rank[F[3 * f + i]] : F[3 * f + i];
            if (r < lo) lo = r;
            if (r > hi) hi = r;
        }
        if (hi - lo > worst) worst = hi - lo;
    }
    return worst;
}

static void assert_permutation(const int *rank, int n)
{
    char *seen = calloc((size_t)n, 1);
    for (int v = 0; v < n; v++) {
        assert_true(rank[v] >= 0 && rank[v] < n && !seen[rank[v]]);
        seen[rank[v]] = 1;
    }
    free(seen);
}

static void scrambled_grid_gets_a_narrow_band(void **state)
{
    (void)state;
    int w = 60, h = 40, nv = (w + 1) * (h + 1), nf;
    int *perm = malloc((size_t)nv * sizeof *perm);
    for (int v = 0; v < nv; v++) perm[v] = (int)((v * 1237L) % nv); /* 1237 prime to nv */
    int *F = grid_faces(w, h, perm, 0, &nf);
    int *rank = malloc((size_t)nv * sizeof *rank), *again = malloc((size_t)nv * sizeof *again);
    assert_int_equal(mesh_vertex_order_breadth_first(3, nf, F, nv, rank, NULL), SCAF_OK);
    assert_permutation(rank, nv);
    /* Breadth-first levels of this grid hold at most min(w, h) + 1
     * vertices and a triangle spans two levels. */
    int band = 2 * (h + 1) + 1;
    assert_true(spread(F, nf, NULL) > 10 * band);
    assert_true(spread(F, nf, rank) <= band);
    assert_int_equal(mesh_vertex_order_breadth_first(3, nf, F, nv, again, NULL), SCAF_OK);
    assert_memory_equal(rank, again, (size_t)nv * sizeof *rank);
    free(again);
    free(rank);
    free(F);
    free(perm);
}

/* Two grids after an unused vertex, another unused one between them: the
 * first unused vertex is number 0, each grid's numbers are one run, the
 * second unused vertex comes after the first grid. */
static void parts_and_unused_vertices(void **state)
{
    (void)state;
    int w = 5, h = 4, ng = (w + 1) * (h + 1), nf1, nf2;
    int nv = 2 * ng + 2;
    int *F1 = grid_faces(w, h, NULL, 1, &nf1), *F2 = grid_faces(w, h, NULL, ng + 2, &nf2);
    int *F = malloc(3 * (size_t)(nf1 + nf2) * sizeof *F);
    memcpy(F, F1, 3 * (size_t)nf1 * sizeof *F);
    memcpy(F + 3 * nf1, F2, 3 * (size_t)nf2 * sizeof *F);
    int *rank = malloc((size_t)nv * sizeof *rank);
    assert_int_equal(mesh_vertex_order_breadth_first(3, nf1 + nf2, F, nv, rank, NULL), SCAF_OK);
    assert_permutation(rank, nv);
    assert_int_equal(rank[0], 0);
    assert_int_equal(rank[ng + 1], ng + 1);
    for (int v = 1; v <= ng; v++) assert_true(rank[v] >= 1 && rank[v] <= ng);
    for (int v = ng + 2; v < nv; v++) assert_true(rank[v] >= ng + 2);
    free(rank);
    free(F);
    free(F1);
    free(F2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scrambled_grid_gets_a_narrow_band),
        cmocka_unit_test(parts_and_unused_vertices),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
