/* tools/edit_json: the strict reader of `scaf edit`'s request bodies
 * takes exactly a flat object of known numeric keys, and on every refusal
 * names what is wrong and leaves the caller's fields as they were. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "edit_json.h"

/* {"chart": integer, required; "dx": number} */
static int parse(const char *body, edit_json_field f[2], char *msg, size_t size)
{
    f[0] = (edit_json_field){"chart", EDIT_JSON_INTEGER, 1, -7, -7};
    f[1] = (edit_json_field){"dx", EDIT_JSON_NUMBER, 0, -7, -7};
    return edit_json_parse(body, strlen(body), f, 2, msg, size);
}

static void accepts_flat_objects(void **state)
{
    (void)state;
    edit_json_field f[2];
    char msg[256];
    assert_true(parse("{\"chart\": 3, \"dx\": -0.25e1}", f, msg, sizeof msg));
    assert_int_equal(f[0].seen, 1);
    assert_true(f[0].value == 3.0);
    assert_int_equal(f[1].seen, 1);
    assert_true(f[1].value == -2.5);
    assert_true(parse(" \r\n\t{\"chart\":0}\n ", f, msg, sizeof msg));
    assert_int_equal(f[1].seen, 0);
    assert_true(f[1].value == -7); /* not given: untouched */
    assert_true(parse("{\"dx\": 0, \"chart\": 2147483647}", f, msg, sizeof msg));
    assert_true(f[0].value == 2147483647.0);
    /* no field at all: {} only */
    assert_true(edit_json_parse("{}", 2, NULL, 0, msg, sizeof msg));
    assert_false(edit_json_parse("{\"a\": 1}", 8, NULL, 0, msg, sizeof msg));
    assert_non_null(strstr(msg, "unknown key \"a\""));
}

static void refuses_everything_else(void **state)
{
    (void)state;
    static const struct {
        const char *body, *says;
    } bad[] = {
        {"", "expected an object"},
        {"[1]", "expected an object"},
        {"{\"chart\": 1", "expected ',' or '}'"},
        {"{\"chart\": 1,}", "expected a key"},
        {"{\"chart\": 1} x", "unexpected data after the object"},
        {"{\"chart\": 1}{}", "unexpected data after the object"},
        {"{chart: 1}", "expected a key"},
        {"{\"chart\" 1}", "expected ':'"},
        {"{\"chart\": 1, \"chart\": 2}", "given twice"},
        {"{\"chart\": 1, \"dy\": 2}", "unknown key \"dy\""},
        {"{\"dx\": 1}", "missing key \"chart\""},
        {"{\"chart\": \"1\"}", "expected a number"},
        {"{\"chart\": true}", "expected a number"},
        {"{\"chart\": null}", "expected a number"},
        {"{\"chart\": 1.5}", "must be an integer >= 0"},
        {"{\"chart\": -1}", "must be an integer >= 0"},
        {"{\"chart\": 2147483648}", "must be an integer >= 0"},
        {"{\"chart\": 01}", "expected ',' or '}'"},
        {"{\"chart\": +1}", "expected a number"},
        {"{\"chart\": 1, \"dx\": .5}", "expected a number"},
        {"{\"chart\": 1, \"dx\": 1.}", "expected a digit after '.'"},
        {"{\"chart\": 1, \"dx\": 1e}", "expected a digit in the exponent"},
        {"{\"chart\": 1, \"dx\": 1e999}", "number out of range"},
        {"{\"chart\": 1, \"dx\": NaN}", "expected a number"},
        {"{\"chart\": 1, \"dx\": Infinity}", "expected a number"},
        {"{\"chart\": 1, \"dx\": 0x10}", "expected ',' or '}'"},
        {"{\"ch\\u0061rt\": 1}", "unexpected key"},
        {"{\"chart\": 1, \"dx\": {\"a\": 1}}", "expected a number"},
        {"{\"chart\": 1, \"dx\": [1]}", "expected a number"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        edit_json_field f[2];
        char msg[256] = "";
        if (parse(bad[i].body, f, msg, sizeof msg) || !strstr(msg, bad[i].says))
            fail_msg("body %s: accepted or wrong message \"%s\" (want \"%s\")", bad[i].body, msg,
                     bad[i].says);
        /* nothing written into the fields */
        assert_true(f[0].value == -7 && f[0].seen == -7);
        assert_true(f[1].value == -7 && f[1].seen == -7);
    }
}

/* The body is a length, not a C string: a NUL inside is a byte like any
 * other (refused), and nothing past the length is read. */
static void reads_only_len_bytes(void **state)
{
    (void)state;
    edit_json_field f[1] = {{"chart", EDIT_JSON_INTEGER, 1, 0, 0}};
    char msg[256];
    const char body[] = "{\"chart\": 1}\0garbage";
    assert_false(edit_json_parse(body, sizeof body - 1, f, 1, msg, sizeof msg));
    assert_non_null(strstr(msg, "byte 12"));
    assert_true(edit_json_parse(body, 12, f, 1, msg, sizeof msg));
    assert_false(edit_json_parse(body, 11, f, 1, msg, sizeof msg)); /* cut before '}' */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(accepts_flat_objects),
        cmocka_unit_test(refuses_everything_else),
        cmocka_unit_test(reads_only_len_bytes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
