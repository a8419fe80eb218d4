/* Tests of base/json_write: numbers that JSON cannot hold (NaN, +-inf)
 * are written as null, never as a bare "nan"/"inf" token a strict parser
 * refuses; finite numbers read back to the same double; strings are
 * escaped. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "base/json_write.h"

/* What json_write_number writes for x (static buffer). */
static const char *number_text(double x)
{
    static char buf[64];
    FILE *f = tmpfile();
    assert_non_null(f);
    json_write_number(f, x);
    rewind(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static void non_finite_numbers_are_null(void **state)
{
    (void)state;
    assert_string_equal(number_text(NAN), "null");
    assert_string_equal(number_text(-NAN), "null");
    assert_string_equal(number_text(INFINITY), "null");
    assert_string_equal(number_text(-INFINITY), "null");
}

static void finite_numbers_round_trip(void **state)
{
    (void)state;
    const double x[] = {0.0,   -0.0,     1.0, 0.1, -2.5e-310, 4.9e-324, 1.7976931348623157e308,
                        1e155, 1.0 / 3.0};
    for (size_t i = 0; i < sizeof x / sizeof *x; i++) {
        const char *t = number_text(x[i]);
        char *end;
        double y = strtod(t, &end);
        assert_true(*end == '\0');
        assert_memory_equal(&y, &x[i], sizeof y);
        /* only JSON number characters */
        assert_true(strspn(t, "0123456789+-.e") == strlen(t));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(non_finite_numbers_are_null),
        cmocka_unit_test(finite_numbers_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
