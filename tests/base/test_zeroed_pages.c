/* Tests for base/zeroed_pages: small and large blocks (past the huge-page
 * hint's threshold) come back zero in every byte sampled and writable;
 * a count whose byte size overflows is refused (NULL), zero counts give a
 * block free() accepts. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <stdlib.h>

#include "base/zeroed_pages.h"

static void zero_and_writable(void **state)
{
    (void)state;
    const size_t counts[4] = {1, 1000, (size_t)3 << 20, (size_t)5 << 20}; /* doubles */
    for (int k = 0; k < 4; k++) {
        size_t n = counts[k];
        double *p = zeroed_pages(n, sizeof *p);
        assert_non_null(p);
        for (size_t i = 0; i < n; i += 511) assert_true(p[i] == 0.0);
        assert_true(p[n - 1] == 0.0);
        for (size_t i = 0; i < n; i += 4096) p[i] = (double)i;
        p[n - 1] = 1.0;
        assert_true(p[n - 1] == 1.0);
        free(p);
    }
}

static void overflow_refused(void **state)
{
    (void)state;
    assert_null(zeroed_pages(SIZE_MAX / 4, 8));
    void *p = zeroed_pages(0, 8), *q = zeroed_pages(8, 0);
    assert_non_null(p);
    assert_non_null(q);
    free(p);
    free(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zero_and_writable),
        cmocka_unit_test(overflow_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
