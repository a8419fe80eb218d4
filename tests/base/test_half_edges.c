/* Tests for base/half_edges (the one grouping of face sides) and
 * base/union_find. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "base/half_edges.h"
#include "base/union_find.h"

/* (lo, hi, h) strictly increasing along the order. */
static void assert_sorted(const int *F, const int *order, int n)
{
    for (int i = 1; i < n; i++) {
        int g = order[i - 1], h = order[i];
        int lg = half_edge_lo(F, g), lh = half_edge_lo(F, h), hg = half_edge_hi(F, g),
            hh = half_edge_hi(F, h);
        assert_true(lg < lh || (lg == lh && (hg < hh || (hg == hh && g < h))));
    }
}

static void sides_are_grouped_by_edge(void **state)
{
    (void)state;
    /* a fan of three triangles around 0 and one degenerate face */
    int F[] = {0, 1, 2, 0, 2, 3, 3, 0, 4, 5, 5, 1};
    int order[12], n = -1;
    assert_int_equal(half_edges_sort(6, 4, F, NULL, order, &n, NULL), SCAF_OK);
    assert_int_equal(n, 12);
    assert_sorted(F, order, n);
    /* edge {0, 2}: half-edges 2 (2 -> 0) and 3 (0 -> 2), adjacent */
    int at = -1;
    for (int i = 0; i < n; i++)
        if (half_edge_lo(F, order[i]) == 0 && half_edge_hi(F, order[i]) == 2) {
            at = i;
            break;
        }
    assert_true(at >= 0 && at + 1 < n);
    assert_int_equal(order[at], 2);
    assert_int_equal(order[at + 1], 3);
    assert_true(half_edges_same_edge(F, order[at], order[at + 1]));
    /* the side 5 -> 5 of the degenerate face is listed as a run lo == hi */
    int deg = 0;
    for (int i = 0; i < n; i++) deg += half_edge_lo(F, order[i]) == half_edge_hi(F, order[i]);
    assert_int_equal(deg, 1);
    assert_int_equal(half_edges_index_count(4, F), 6);
}

static void skipped_faces_are_not_read(void **state)
{
    (void)state;
    /* face 1 holds an index out of range: skipped, never read */
    int F[] = {0, 1, 2, 7, -5, 99, 2, 1, 3};
    unsigned char skip[3] = {0, 1, 0};
    int order[9], n = -1;
    assert_int_equal(half_edges_sort(4, 3, F, skip, order, &n, NULL), SCAF_OK);
    assert_int_equal(n, 6);
    assert_sorted(F, order, n);
    for (int i = 0; i < n; i++) assert_int_not_equal(order[i] / 3, 1);
}

static void larger_lists_stay_sorted(void **state)
{
    (void)state;
    /* a strip with a vertex of high valence (bucket sorted by qsort) */
    enum { NF = 200 };
    int *F = malloc(sizeof(int) * 3 * NF), *order = malloc(sizeof(int) * 3 * NF), n = 0;
    assert_non_null(F);
    assert_non_null(order);
    for (int f = 0; f < NF; f++) {
        F[3 * f] = 0;
        F[3 * f + 1] = 1 + (f * 7) % NF;
        F[3 * f + 2] = 1 + (f * 7 + 1) % NF;
    }
    assert_int_equal(half_edges_sort(NF + 1, NF, F, NULL, order, &n, NULL), SCAF_OK);
    assert_int_equal(n, 3 * NF);
    assert_sorted(F, order, n);
    free(F);
    free(order);
}

static void union_find_roots_are_smallest(void **state)
{
    (void)state;
    int p[6];
    uf_init(p, 6);
    assert_int_equal(uf_union(p, 4, 2), 1);
    assert_int_equal(uf_union(p, 5, 4), 1);
    assert_int_equal(uf_union(p, 2, 5), 0);
    assert_int_equal(uf_find(p, 5), 2);
    assert_int_equal(uf_find(p, 3), 3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sides_are_grouped_by_edge),
        cmocka_unit_test(skipped_faces_are_not_read),
        cmocka_unit_test(larger_lists_stay_sorted),
        cmocka_unit_test(union_find_roots_are_smallest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
