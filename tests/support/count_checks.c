/* tests/support/count_checks: see count_checks.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "support/count_checks.h"

void test_expect_counts(const char *label, const count_check *checks, int n)
{
    for (int i = 0; i < n; i++)
        if (checks[i].got != checks[i].want)
            fail_msg("%s: %s = %lld, expected %lld", label, checks[i].what, checks[i].got,
                     checks[i].want);
}
