/* Tests for base/timer: the clock is monotonic and advances. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "base/timer.h"

static void clock_is_monotonic(void **state)
{
    (void)state;
    double prev = timer_now();
    volatile double sink = 0;
    for (int k = 0; k < 100000; k++) {
        double t = timer_now();
        assert_true(t >= prev);
        prev = t;
        sink += t;
    }
    assert_true(prev > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(clock_is_monotonic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
