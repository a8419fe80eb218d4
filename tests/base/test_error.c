/* Tests for base/error: messages are formatted, prefixed and truncated safely. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "base/error.h"

static void set_formats_and_returns_code(void **state)
{
    (void)state;
    scaf_error e;
    err_clear(&e);
    assert_int_equal(e.code, SCAF_OK);
    scaf_status s = err_set(&e, SCAF_ERR_PARSE, "line %d: bad token '%s'", 12, "x");
    assert_int_equal(s, SCAF_ERR_PARSE);
    assert_int_equal(e.code, SCAF_ERR_PARSE);
    assert_string_equal(e.message, "line 12: bad token 'x'");
    err_prefix(&e, "%s", "in.obj");
    assert_string_equal(e.message, "in.obj: line 12: bad token 'x'");
}

static void null_error_is_allowed(void **state)
{
    (void)state;
    assert_int_equal(err_set(NULL, SCAF_ERR_IO, "x"), SCAF_ERR_IO);
    err_prefix(NULL, "y");
    err_clear(NULL);
}

static void long_message_is_truncated(void **state)
{
    (void)state;
    char big[4000];
    memset(big, 'a', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    scaf_error e;
    err_set(&e, SCAF_ERR_MESH, "%s", big);
    assert_int_equal(strlen(e.message), SCAF_ERROR_MESSAGE_MAX - 1);
    err_prefix(&e, "ctx");
    assert_int_equal(strlen(e.message), SCAF_ERROR_MESSAGE_MAX - 1);
}

static void every_status_has_a_name(void **state)
{
    (void)state;
    for (int s = SCAF_OK; s <= SCAF_ERR_INTERNAL; s++)
        assert_string_not_equal(scaf_status_name((scaf_status)s), "unknown status");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(set_formats_and_returns_code),
        cmocka_unit_test(null_error_is_allowed),
        cmocka_unit_test(long_message_is_truncated),
        cmocka_unit_test(every_status_has_a_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
