/* tests/mesh/mesh_test_util: small helpers shared by the mesh I/O tests.
 *
 * Header-only (static functions) so each test program stays one file:
 * write a string or bytes into the test scratch folder, read a mesh from a
 * string with a given file name, and check that a parse fails with a code
 * and a message naming the expected "NAME:LINE:".
 */
#ifndef SCAF_TESTS_MESH_TEST_UTIL_H
#define SCAF_TESTS_MESH_TEST_UTIL_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/mesh_io.h"
#include "support/support.h"

/* Write bytes to the scratch file `name`; returns its path in buf. */
static inline const char *write_tmp(const char *name, const void *bytes, size_t n, char *buf,
                                    size_t size)
{
    test_tmp_path(name, buf, size);
    FILE *f = fopen(buf, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
    return buf;
}

/* Parse text (format given) expecting success; fills m and info. */
static inline void parse_ok(const char *text, mesh_format fmt, mesh *m, mesh_read_info *info)
{
    scaf_error e;
    err_clear(&e);
    scaf_status s = mesh_parse(text, strlen(text), fmt, "t", m, info, &e);
    if (s != SCAF_OK) print_error("unexpected failure: %s\n", e.message);
    assert_int_equal(s, SCAF_OK);
}

/* Parse bytes expecting failure with `code`, no mesh left behind, and the
 * message starting with "t:LINE:" and containing `needle` (may be NULL).
 * Returns 0 when all of that holds, else 1 with the first difference
 * written into why. */
static inline int parse_failure_differs(const char *bytes, size_t n, mesh_format fmt,
                                        scaf_status code, long line, const char *needle, char *why,
                                        size_t size)
{
    scaf_error e;
    err_clear(&e);
    mesh m;
    scaf_status s = mesh_parse(bytes, n, fmt, "t", &m, NULL, &e);
    char want[64];
    snprintf(want, sizeof want, "t:%ld: ", line);
    if (s != code)
        snprintf(why, size, "expected failure %d, got status %d: %s", (int)code, (int)s, e.message);
    else if (m.nv != 0 || m.V != NULL)
        snprintf(why, size, "the failed parse left a mesh (nv %d)", m.nv);
    else if (strncmp(e.message, want, strlen(want)) != 0)
        snprintf(why, size, "message: %s (wanted %s)", e.message, want);
    else if (needle && !strstr(e.message, needle))
        snprintf(why, size, "message: %s (wanted '%s')", e.message, needle);
    else return 0;
    return 1;
}

/* Asserts parse_failure_differs finds no difference. */
static inline void parse_fails_n(const char *bytes, size_t n, mesh_format fmt, scaf_status code,
                                 long line, const char *needle)
{
    char why[2048];
    if (parse_failure_differs(bytes, n, fmt, code, line, needle, why, sizeof why))
        fail_msg("%s", why);
}

/* One malformed text of a table: the line its error names and a phrase the
 * message must contain (may be NULL). */
typedef struct parse_case {
    const char *text;
    long line;
    const char *needle;
} parse_case;

/* Every row of cases (n rows, format fmt) fails with SCAF_ERR_PARSE as
 * parse_fails_n expects; a failure names the table and the row. */
static inline void parse_cases_fail(const char *table, mesh_format fmt, const parse_case *cases,
                                    int n)
{
    for (int i = 0; i < n; i++) {
        char why[2048];
        if (parse_failure_differs(cases[i].text, strlen(cases[i].text), fmt, SCAF_ERR_PARSE,
                                  cases[i].line, cases[i].needle, why, sizeof why))
            fail_msg("%s, row %d (needle '%s'): %s", table, i,
                     cases[i].needle ? cases[i].needle : "", why);
    }
}

#define PARSE_CASES_FAIL(fmt, cases)                                                               \
    parse_cases_fail(#cases, fmt, cases, (int)(sizeof cases / sizeof cases[0]))

static inline void parse_fails(const char *text, mesh_format fmt, long line, const char *needle)
{
    parse_fails_n(text, strlen(text), fmt, SCAF_ERR_PARSE, line, needle);
}

/* Whether two meshes hold bitwise identical arrays. */
static inline void assert_same_mesh(const mesh *a, const mesh *b)
{
    assert_int_equal(a->nv, b->nv);
    assert_int_equal(a->nf, b->nf);
    assert_int_equal(a->nuv, b->nuv);
    assert_memory_equal(a->V, b->V, sizeof(double) * 3 * (size_t)a->nv);
    assert_memory_equal(a->F, b->F, sizeof(int) * 3 * (size_t)a->nf);
    if (a->nuv) {
        assert_memory_equal(a->UV, b->UV, sizeof(double) * 2 * (size_t)a->nuv);
        assert_memory_equal(a->FT, b->FT, sizeof(int) * 3 * (size_t)a->nf);
    }
}

#endif
