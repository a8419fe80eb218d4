/* tools/deform_targets: the handle file of `scaf deform --targets`.
 *
 * What is asserted, per observed bug:
 *   - a path of 200,000 points is read with a number of reallocations that
 *     grows with its logarithm (counted through -Wl,--wrap=realloc): it
 *     grew one point at a time, 12+ minutes under ASan;
 *   - a pending SIGINT / SIGTERM (base/interrupt) stops the reader in the
 *     middle of a long path: SCAF_ERR_CANCELLED naming the signal;
 *   - "{}" says the "handles" array is missing (it said "expected a key in
 *     double quotes"); a path-length mismatch is a whole sentence;
 *   - a number beyond a double is refused as out of range naming the
 *     handle (SCAF_ERR_MESH: exit 4);
 *   - against the mesh (deform_targets_check, exit 4 naming the handle): a
 *     target far outside the mesh ([1e308, -1e308] ended "max handle error
 *     inf", exit 0), a waypoint likewise, two handles on one vertex, a
 *     vertex beyond the mesh; targets within range pass.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <signal.h>

#include "base/interrupt.h"
#include "deform_targets.h"

void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static long reallocs;
void *__wrap_realloc(void *p, size_t n)
{
    reallocs++;
    return __real_realloc(p, n);
}

/* {"handles": [{"vertex": 0, "target": [1, 2], "path": [[0, 0], ... n]}]} */
static char *long_path(int n, size_t *size)
{
    const char *head = "{\"handles\": [{\"vertex\": 0, \"target\": [1, 2], \"path\": [";
    size_t cap = strlen(head) + 16 * (size_t)n + 16;
    char *s = malloc(cap);
    assert_non_null(s);
    size_t k = (size_t)snprintf(s, cap, "%s", head);
    for (int i = 0; i < n; i++)
        k += (size_t)snprintf(s + k, cap - k, "%s[%d, 0.5]", i ? ", " : "", i % 1000);
    k += (size_t)snprintf(s + k, cap - k, "]}]}");
    *size = k;
    return s;
}

static void long_path_grows_geometrically(void **state)
{
    (void)state;
    size_t size;
    char *s = long_path(200000, &size);
    deform_targets t;
    scaf_error err;
    err_clear(&err);
    reallocs = 0;
    assert_int_equal(deform_targets_parse(s, size, "long.json", &t, &err), SCAF_OK);
    long n = reallocs;
    assert_int_equal(t.n, 1);
    assert_int_equal(t.nframes, 200000);
    assert_true(t.frames[2 * 199999] == 999.0 && t.frames[2 * 199999 + 1] == 0.5);
    deform_targets_free(&t);
    free(s);
    /* log2(200000 / 64) = 12 doublings, plus the handle arrays */
    print_message("reallocations for 200,000 points: %ld\n", n);
    assert_true(n < 40);
}

static void pending_signal_stops_the_reader(void **state)
{
    (void)state;
    size_t size;
    char *s = long_path(20000, &size);
    deform_targets t;
    scaf_error err;
    err_clear(&err);
    interrupt_clear();
    interrupt_request(SIGTERM);
    assert_int_equal(deform_targets_parse(s, size, "long.json", &t, &err), SCAF_ERR_CANCELLED);
    assert_non_null(strstr(err.message, "interrupted by SIGTERM"));
    assert_int_equal(t.n, 0); /* nothing kept */
    interrupt_clear();
    assert_int_equal(deform_targets_parse(s, size, "long.json", &t, &err), SCAF_OK);
    deform_targets_free(&t);
    free(s);
}

static void parse_fails(const char *text, scaf_status want, const char *what)
{
    deform_targets t;
    scaf_error err;
    err_clear(&err);
    scaf_status st = deform_targets_parse(text, strlen(text), "t.json", &t, &err);
    if (st != want || !strstr(err.message, what))
        print_error("%s -> %d '%s' (want %d, '%s')\n", text, st, err.message, want, what);
    assert_int_equal(st, want);
    assert_non_null(strstr(err.message, what));
}

static void messages_name_the_cause(void **state)
{
    (void)state;
    parse_fails("{}", SCAF_ERR_PARSE, "t.json:1: no \"handles\" array");
    parse_fails(" {\n } ", SCAF_ERR_PARSE, "no \"handles\" array");
    parse_fails("{\"handles\": [{\"vertex\": 0, \"target\": [1, 2], \"path\": [[0, 0]]},\n"
                "{\"vertex\": 1, \"target\": [1, 2]}]}",
                SCAF_ERR_PARSE,
                "handle 2 has a path of 0 points, the first handle one of 1 (every handle's path "
                "must have the same length)");
    parse_fails("{\"handles\": [{\"vertex\": 0, \"target\": [1, 2]}, {\"vertex\": 1, \"target\": "
                "[1e999, 2]}]}",
                SCAF_ERR_MESH, "handle 2: \"target\" x: number out of range (1e999");
    parse_fails("{\"handles\": [{\"vertex\": 0, \"target\": [1, 2], \"path\": [[0, 0], [3, "
                "-1e400]]}]}",
                SCAF_ERR_MESH, "handle 1: \"path\" point 2 y: number out of range");
}

static scaf_status check(const char *text, scaf_error *err)
{
    /* the mesh: the unit square's corners */
    static const double P[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    deform_targets t;
    err_clear(err);
    assert_int_equal(deform_targets_parse(text, strlen(text), "t.json", &t, err), SCAF_OK);
    scaf_status st = deform_targets_check(&t, 4, P, "t.json", err);
    deform_targets_free(&t);
    return st;
}

static void checked_against_the_mesh(void **state)
{
    (void)state;
    scaf_error err;
    assert_int_equal(check("{\"handles\": [{\"vertex\": 0, \"target\": [-5, 7], \"path\": [[0, "
                           "1]]}, {\"vertex\": 3, "
                           "\"target\": [1e5, -1e5], \"path\": [[2, 2]]}]}",
                           &err),
                     SCAF_OK);
    assert_int_equal(check("{\"handles\": [{\"vertex\": 0, \"target\": [0, 0]}, {\"vertex\": 1, "
                           "\"target\": [1e308, -1e308]}]}",
                           &err),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(err.message,
                           "t.json: handle 2 (vertex 1): target [1e+308, -1e+308] is "
                           "out of range"));
    assert_int_equal(check("{\"handles\": [{\"vertex\": 0, \"target\": [0, 0], \"path\": [[0, "
                           "0], [3e6, 0]]}]}",
                           &err),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "handle 1 (vertex 0): path point 2 [3e+06, 0]"));
    assert_int_equal(check("{\"handles\": [{\"vertex\": 2, \"target\": [0, 0]}, {\"vertex\": 1, "
                           "\"target\": [0, 0]}, {\"vertex\": 2, \"target\": [1, 1]}]}",
                           &err),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "handle 3: vertex 2 already has a handle (handle 1)"));
    assert_int_equal(check("{\"handles\": [{\"vertex\": 4, \"target\": [0, 0]}]}", &err),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(err.message, "handle 1: vertex 4 is not one of the mesh's 4"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(long_path_grows_geometrically),
        cmocka_unit_test(pending_signal_stops_the_reader),
        cmocka_unit_test(messages_name_the_cause),
        cmocka_unit_test(checked_against_the_mesh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
