/* End-to-end: every energy of the library's list (scaf_energy_count /
 * scaf_energy_info, read from opt/energy_table) is offered by `scaf param
 * --help`, accepted by `scaf param --energy NAME` (identifier with '-'
 * and with '_', and each alias), and gives a map that passes `scaf
 * check` (the exact bijectivity checker), with the report naming it; an
 * unknown name is exit 2 with no output file. A new row of the table is
 * tested here without an edit. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "scaf/scaf.h"
#include "support/support.h"

/* name with '-' for '_' into buf */
static const char *dashed(const char *name, char *buf, size_t size)
{
    size_t k = 0;
    for (; name[k] && k + 1 < size; k++) buf[k] = name[k] == '_' ? '-' : name[k];
    buf[k] = 0;
    return buf;
}

/* s with every run of spaces and newlines made one space, in place */
static char *squeeze(char *s)
{
    char *w = s;
    for (const char *r = s; *r; r++)
        if (*r != ' ' && *r != '\n') *w++ = *r;
        else if (w > s && w[-1] != ' ') *w++ = ' ';
    *w = 0;
    return s;
}

static void every_energy_is_offered_and_bijective(void **state)
{
    (void)state;
    char in[512], out[512], rep[512], help[512];
    test_tmp_path("e2e_energy_in.obj", in, sizeof in);
    test_tmp_path("e2e_energy_out.obj", out, sizeof out);
    test_tmp_path("e2e_energy.json", rep, sizeof rep);
    test_tmp_path("e2e_energy_help.txt", help, sizeof help);
    assert_int_equal(test_run("%s gen holes --size 4 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s param --help > %s", SCAF_BINARY, help), 0);
    char *usage = test_slurp(help);
    assert_non_null(usage);
    squeeze(usage); /* the help lines are wrapped */
    assert_true(scaf_energy_count() >= 3);
    for (int e = 0; e < scaf_energy_count(); e++) {
        scaf_energy_info_t info;
        assert_int_equal(scaf_energy_info(e, &info), SCAF_OK);
        char name[64];
        dashed(info.name, name, sizeof name);
        assert_non_null(strstr(usage, name));
        char line[512];
        snprintf(line, sizeof line, "%s", info.help);
        assert_non_null(strstr(usage, squeeze(line)));
        const char *spellings[2] = {name, info.name};
        for (int k = 0; k < 2; k++) {
            remove(out);
            assert_int_equal(test_run("%s param %s -o %s --energy %s --iterations 8 --quiet "
                                      "--report %s",
                                      SCAF_BINARY, in, out, spellings[k], rep),
                             0);
            assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
            char *json = test_slurp(rep);
            assert_non_null(json);
            char want[80];
            snprintf(want, sizeof want, "\"energy\": \"%s\"", name);
            if (!strstr(json, want)) {
                print_error("report of --energy %s lacks %s\n", spellings[k], want);
                fail();
            }
            free(json);
        }
        scaf_energy found = (scaf_energy)-1;
        assert_int_equal(scaf_energy_find(name, &found), SCAF_OK);
        assert_int_equal((int)found, e);
    }
    free(usage);
    scaf_energy_info_t info;
    assert_int_equal(scaf_energy_info(scaf_energy_count(), &info), SCAF_ERR_USAGE);
    assert_int_equal(scaf_energy_info(-1, &info), SCAF_ERR_USAGE);
    assert_int_equal(scaf_energy_info(0, NULL), SCAF_ERR_USAGE);
    scaf_energy found = SCAF_ENERGY_ARAP;
    assert_int_equal(scaf_energy_find("no-such-energy", &found), SCAF_ERR_USAGE);
    assert_int_equal(scaf_energy_find(NULL, &found), SCAF_ERR_USAGE);
    assert_int_equal((int)found, SCAF_ENERGY_ARAP);
    remove(out);
    assert_int_equal(test_run("%s param %s -o %s --energy no-such-energy --quiet 2> /dev/null",
                              SCAF_BINARY, in, out),
                     2);
    assert_false(test_exists(out));
}

/* The options check names the field: an energy past the list. */
static void param_refuses_an_energy_past_the_list(void **state)
{
    (void)state;
    scaf_options_t o = scaf_options_default();
    o.energy = (scaf_energy)scaf_energy_count();
    scaf_param_t *p = scaf_param_new(NULL);
    assert_non_null(p);
    assert_int_equal(scaf_param_set_options(p, &o), SCAF_ERR_USAGE);
    assert_non_null(strstr(scaf_param_error(p), "energy"));
    scaf_param_destroy(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_energy_is_offered_and_bijective),
        cmocka_unit_test(param_refuses_an_energy_past_the_list),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
