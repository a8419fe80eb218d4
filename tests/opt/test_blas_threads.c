/* Tests for opt/blas_threads: the core count is at least 1; a serial
 * section sets the BLAS to one thread and its end restores the count it
 * found (also when it found one, and nested); scaf_set_threads sets the
 * BLAS count; scaf_set_deterministic is what opt_deterministic reports.
 * A one-threaded BLAS (count 1) or one without a count to query (0) keeps
 * its count through it all. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "opt/blas_threads.h"
#include "scaf/scaf.h"

static void serial_sections_restore(void **state)
{
    (void)state;
    assert_true(opt_blas_cores() >= 1);
    scaf_set_threads(2);
    int before = opt_blas_threads(); /* 2, or 1 for a one-threaded BLAS, 0: none to ask */
    assert_true(before >= 0 && before <= 2);
    int s = opt_blas_serial_begin();
    assert_int_equal(s, before);
    assert_true(opt_blas_threads() == (before ? 1 : 0));
    int inner = opt_blas_serial_begin(); /* nested: finds one, keeps one */
    assert_true(opt_blas_threads() == (before ? 1 : 0));
    opt_blas_serial_end(inner);
    assert_true(opt_blas_threads() == (before ? 1 : 0));
    opt_blas_serial_end(s);
    assert_int_equal(opt_blas_threads(), before);
    scaf_set_threads(1);
    assert_true(opt_blas_threads() == (before ? 1 : 0));
    s = opt_blas_serial_begin();
    opt_blas_serial_end(s);
    assert_true(opt_blas_threads() == (before ? 1 : 0));
}

static void deterministic_flag(void **state)
{
    (void)state;
    scaf_set_deterministic(1);
    assert_true(opt_deterministic());
    scaf_set_deterministic(0);
    assert_false(opt_deterministic());
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(serial_sections_restore),
        cmocka_unit_test(deterministic_flag),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
