/* End-to-end tests of `scaf gen` and `scaf info`: run the built program
 * (SCAF_BINARY) on generated samples, read the JSON report, check values
 * known from the sample's construction and the exit codes of failures. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <cmocka.h>

#include "support/support.h"

#ifndef SCAF_BINARY
#define SCAF_BINARY "scaf"
#endif

/* Run a shell command; returns its exit status (-1 if it did not exit). */
static int run(const char *cmd)
{
    int s = system(cmd);
    return s != -1 && WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

/* Run a command and capture its stdout into buf. Returns the exit status. */
static int capture(const char *cmd, char *buf, size_t size)
{
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t n = fread(buf, 1, size - 1, p);
    buf[n] = '\0';
    int s = pclose(p);
    return s != -1 && WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

/* The raw text of top-level key's value ("12", "true", "null", ...). */
static const char *json_value(const char *json, const char *key, char *out, size_t size)
{
    char pat[128];
    snprintf(pat, sizeof pat, "\n  \"%s\": ", key);
    const char *p = strstr(json, pat);
    if (!p) return NULL;
    p += strlen(pat);
    size_t n = strcspn(p, ",\n");
    if (n >= size) n = size - 1;
    memcpy(out, p, n);
    out[n] = '\0';
    return out;
}

/* One expected top-level value of the JSON report. */
typedef struct json_field {
    const char *key, *value;
} json_field;

/* Every field of the list has its value in json; a failure names the case
 * (what) and the key. */
static void expect_fields(const char *what, const char *json, const json_field *f, int n)
{
    for (int i = 0; i < n; i++) {
        char v[256];
        if (!json_value(json, f[i].key, v, sizeof v))
            fail_msg("%s: key %s missing in:\n%s", what, f[i].key, json);
        if (strcmp(v, f[i].value))
            fail_msg("%s: %s: got %s, want %s", what, f[i].key, v, f[i].value);
    }
}

#define EXPECT_FIELDS(what, json, fields)                                                          \
    expect_fields(what, json, fields, (int)(sizeof fields / sizeof fields[0]))

/* Write text to path (the test's input file). */
static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* `scaf info --json path` into json (exit 0 required). */
static void info_json(const char *path, char *json, size_t size)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' info --json '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, size), 0);
}

/* `scaf gen <gen_args> -o <scratch file>` (exit 0 required), then its JSON
 * report into json; the file's path into path. */
static void gen_then_info_json(const char *gen_args, const char *file, char *path, size_t path_size,
                               char *json, size_t size)
{
    char cmd[2048];
    test_tmp_path(file, path, path_size);
    snprintf(cmd, sizeof cmd, "'%s' gen %s -o '%s'", SCAF_BINARY, gen_args, path);
    assert_int_equal(run(cmd), 0);
    info_json(path, json, size);
}

/* 6 faces of a 5 x 5 cube grid on a sphere: V = 6*25+2, F = 12*25 */
static const json_field cubesphere5_fields[] = {
    {"vertices", "152"},
    {"faces", "300"},
    {"components", "1"},
    {"boundary_loops", "0"},
    {"euler_characteristic", "2"},
    {"genus", "0"},
    {"manifold", "true"},
    {"non_manifold_edges", "0"},
    {"non_manifold_vertices", "0"},
    {"misoriented_edges", "0"},
    {"degenerate_faces", "0"},
    {"unreferenced_vertices", "0"},
    {"uv_charts", "6"},
    {"seam_edges", "60"},
    {"duplicate_faces", "0"},
};

static const json_field holes_fields[] = {
    {"boundary_loops", "7"},
    {"euler_characteristic", "-5"},
    {"genus", "0"},
    {"uv_charts", "1"},
};

static void info_json_on_generated_samples(void **state)
{
    (void)state;
    char path[1024], cmd[2048];
    static char json[1 << 16];

    gen_then_info_json("cubesphere --size 5", "cli_info_cubesphere.obj", path, sizeof path, json,
                       sizeof json);
    EXPECT_FIELDS("cubesphere --size 5", json, cubesphere5_fields);
    assert_non_null(strstr(json, "\"chart_kinds\": {\"disk\": 6}"));
    assert_true(strlen(json) >= 2);
    assert_int_equal(json[strlen(json) - 2], '}');

    gen_then_info_json("holes", "cli_info_holes.obj", path, sizeof path, json, sizeof json);
    EXPECT_FIELDS("holes", json, holes_fields);

    /* the text report works too */
    snprintf(cmd, sizeof cmd, "'%s' info '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, sizeof json), 0);
    assert_non_null(strstr(json, "boundary loops  7"));
}

static const json_field pinch_fields[] = {
    {"vertices", "7"},
    {"faces", "8"},
    {"components", "1"},
    {"boundary_loops", "0"},
    {"euler_characteristic", "3"},
    {"genus", "null"},
    {"manifold", "false"},
    {"non_manifold_vertices", "1"},
    {"non_manifold_edges", "0"},
    {"unreferenced_vertices", "1"},
};

static void info_json_on_non_manifold_file(void **state)
{
    (void)state;
    char path[1024];
    static char json[1 << 16];
    /* two tetrahedra sharing vertex 1 (a pinch) plus one unreferenced vertex */
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                      "v 2 0 0\nv 1 1 0\nv 1 0 1\nv 9 9 9\n"
                      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                      "f 2 6 5\nf 2 5 7\nf 2 7 6\nf 5 6 7\n";
    test_tmp_path("cli_info_pinch.obj", path, sizeof path);
    write_text(path, obj);
    info_json(path, json, sizeof json);
    EXPECT_FIELDS("two tetrahedra pinched at a vertex", json, pinch_fields);
}

/* One command line: `scaf <args>[ '<path>'] <tail>` and its exit code. */
typedef struct cli_case {
    const char *args;
    int with_path;
    const char *tail;
    int want;
} cli_case;

/* Runs each row (path: the file given to rows with_path); a failure names
 * the table, the row and the command. */
static void expect_exits(const char *table, const cli_case *c, int n, const char *path)
{
    for (int i = 0; i < n; i++) {
        char cmd[2048];
        snprintf(cmd, sizeof cmd, "'%s' %s%s%s%s %s", SCAF_BINARY, c[i].args,
                 c[i].with_path ? " '" : "", c[i].with_path ? path : "", c[i].with_path ? "'" : "",
                 c[i].tail);
        int got = run(cmd);
        if (got != c[i].want)
            fail_msg("%s, row %d: %s exits %d, expected %d", table, i, cmd, got, c[i].want);
    }
}

#define EXPECT_EXITS(cases, path)                                                                  \
    expect_exits(#cases, cases, (int)(sizeof cases / sizeof cases[0]), path)

static const cli_case usage_cases[] = {
    {"info /nonexistent/dir/missing.obj", 0, "2>/dev/null", 3},
    {"info --frobnicate x.obj", 0, "2>/dev/null", 2},
    {"info", 0, "2>/dev/null", 2},
    {"info --help", 0, ">/dev/null", 0},
    {"gen --help", 0, ">/dev/null", 0},
    {"gen --list", 0, "| grep -q cubesphere", 0},
};

/* refused before anything is written to the path */
static const cli_case refused_gen_cases[] = {
    {"gen nosuchsample -o", 1, "2>/dev/null", 2},
    {"gen hemisphere --size 0 -o", 1, "2>/dev/null", 2},
    {"gen hemisphere --size 99999999 -o", 1, "2>/dev/null", 2},
    {"gen hemisphere", 0, "2>/dev/null", 2},
};

static const cli_case unwritable_gen_cases[] = {
    {"gen hemisphere -o /nonexistent/dir/out.obj", 0, "2>/dev/null", 5},
};

/* a malformed file: exit 3 with the reason on stderr */
static const cli_case malformed_info_cases[] = {
    {"info", 1, "2>/dev/null", 3},
};

static void exit_codes(void **state)
{
    (void)state;
    char path[1024];
    EXPECT_EXITS(usage_cases, NULL);

    test_tmp_path("cli_gen_never.obj", path, sizeof path);
    remove(path);
    EXPECT_EXITS(refused_gen_cases, path);
    struct stat st;
    assert_int_not_equal(stat(path, &st), 0); /* nothing written */
    EXPECT_EXITS(unwritable_gen_cases, NULL);

    test_tmp_path("cli_info_bad.obj", path, sizeof path);
    write_text(path, "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    EXPECT_EXITS(malformed_info_cases, path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(info_json_on_generated_samples),
        cmocka_unit_test(info_json_on_non_manifold_file),
        cmocka_unit_test(exit_codes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
