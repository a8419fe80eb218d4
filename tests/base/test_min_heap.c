/* tests/base/test_min_heap: pairs come out by key, ties by the smaller id,
 * whatever the order they went in; the heap is reusable after a free. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "base/min_heap.h"

static void pops_in_key_then_id_order(void **state)
{
    (void)state;
    min_heap h = {0};
    enum { N = 1000 };
    unsigned s = 12345u;
    for (int i = 0; i < N; i++) {
        s = s * 1103515245u + 12345u;
        int id = (int)((s >> 8) % N);
        double key = (double)((s >> 16) % 17); /* many ties */
        assert_true(min_heap_push(&h, key, id));
    }
    assert_int_equal(h.n, N);
    min_heap_item prev = min_heap_pop(&h);
    while (h.n > 0) {
        min_heap_item x = min_heap_pop(&h);
        assert_true(prev.key < x.key || (prev.key == x.key && prev.id <= x.id));
        prev = x;
    }
    min_heap_free(&h);
    assert_null(h.a);
    assert_int_equal(h.cap, 0);
    /* reusable after the free, and a single element comes back whole */
    assert_true(min_heap_push(&h, -2.5, 7));
    min_heap_item one = min_heap_pop(&h);
    assert_true(one.key == -2.5);
    assert_int_equal(one.id, 7);
    assert_int_equal(h.n, 0);
    min_heap_free(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(pops_in_key_then_id_order)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
