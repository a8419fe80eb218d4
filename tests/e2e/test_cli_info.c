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

static void expect(const char *json, const char *key, const char *value)
{
    char v[256];
    if (!json_value(json, key, v, sizeof v)) print_error("key %s missing in:\n%s\n", key, json);
    assert_non_null(json_value(json, key, v, sizeof v));
    if (strcmp(v, value)) print_error("%s: got %s, want %s\n", key, v, value);
    assert_string_equal(v, value);
}

static void info_json_on_generated_samples(void **state)
{
    (void)state;
    char path[1024], cmd[2048];
    static char json[1 << 16];

    test_tmp_path("cli_info_cubesphere.obj", path, sizeof path);
    snprintf(cmd, sizeof cmd, "'%s' gen cubesphere --size 5 -o '%s'", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 0);
    snprintf(cmd, sizeof cmd, "'%s' info --json '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, sizeof json), 0);
    /* 6 faces of a 5 x 5 cube grid on a sphere: V = 6*25+2, F = 12*25 */
    expect(json, "vertices", "152");
    expect(json, "faces", "300");
    expect(json, "components", "1");
    expect(json, "boundary_loops", "0");
    expect(json, "euler_characteristic", "2");
    expect(json, "genus", "0");
    expect(json, "manifold", "true");
    expect(json, "non_manifold_edges", "0");
    expect(json, "non_manifold_vertices", "0");
    expect(json, "misoriented_edges", "0");
    expect(json, "degenerate_faces", "0");
    expect(json, "unreferenced_vertices", "0");
    expect(json, "uv_charts", "6");
    expect(json, "seam_edges", "60");
    expect(json, "duplicate_faces", "0");
    assert_non_null(strstr(json, "\"chart_kinds\": {\"disk\": 6}"));
    assert_int_equal(json[strlen(json) - 2], '}');

    test_tmp_path("cli_info_holes.obj", path, sizeof path);
    snprintf(cmd, sizeof cmd, "'%s' gen holes -o '%s'", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 0);
    snprintf(cmd, sizeof cmd, "'%s' info --json '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, sizeof json), 0);
    expect(json, "boundary_loops", "7");
    expect(json, "euler_characteristic", "-5");
    expect(json, "genus", "0");
    expect(json, "uv_charts", "1");

    /* the text report works too */
    snprintf(cmd, sizeof cmd, "'%s' info '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, sizeof json), 0);
    assert_non_null(strstr(json, "boundary loops  7"));
}

static void info_json_on_non_manifold_file(void **state)
{
    (void)state;
    char path[1024], cmd[2048];
    static char json[1 << 16];
    /* two tetrahedra sharing vertex 1 (a pinch) plus one unreferenced vertex */
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                      "v 2 0 0\nv 1 1 0\nv 1 0 1\nv 9 9 9\n"
                      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                      "f 2 6 5\nf 2 5 7\nf 2 7 6\nf 5 6 7\n";
    test_tmp_path("cli_info_pinch.obj", path, sizeof path);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(obj, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' info --json '%s'", SCAF_BINARY, path);
    assert_int_equal(capture(cmd, json, sizeof json), 0);
    expect(json, "vertices", "7");
    expect(json, "faces", "8");
    expect(json, "components", "1");
    expect(json, "boundary_loops", "0");
    expect(json, "euler_characteristic", "3");
    expect(json, "genus", "null");
    expect(json, "manifold", "false");
    expect(json, "non_manifold_vertices", "1");
    expect(json, "non_manifold_edges", "0");
    expect(json, "unreferenced_vertices", "1");
}

static void exit_codes(void **state)
{
    (void)state;
    char path[1024], cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' info /nonexistent/dir/missing.obj 2>/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 3);
    snprintf(cmd, sizeof cmd, "'%s' info --frobnicate x.obj 2>/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 2);
    snprintf(cmd, sizeof cmd, "'%s' info 2>/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 2);
    snprintf(cmd, sizeof cmd, "'%s' info --help >/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 0);
    snprintf(cmd, sizeof cmd, "'%s' gen --help >/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 0);
    snprintf(cmd, sizeof cmd, "'%s' gen --list | grep -q cubesphere", SCAF_BINARY);
    assert_int_equal(run(cmd), 0);

    test_tmp_path("cli_gen_never.obj", path, sizeof path);
    remove(path);
    snprintf(cmd, sizeof cmd, "'%s' gen nosuchsample -o '%s' 2>/dev/null", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 2);
    snprintf(cmd, sizeof cmd, "'%s' gen hemisphere --size 0 -o '%s' 2>/dev/null", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 2);
    snprintf(cmd, sizeof cmd, "'%s' gen hemisphere --size 99999999 -o '%s' 2>/dev/null", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 2);
    snprintf(cmd, sizeof cmd, "'%s' gen hemisphere 2>/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 2);
    struct stat st;
    assert_int_not_equal(stat(path, &st), 0);  /* nothing written */
    snprintf(cmd, sizeof cmd, "'%s' gen hemisphere -o /nonexistent/dir/out.obj 2>/dev/null", SCAF_BINARY);
    assert_int_equal(run(cmd), 5);

    /* a malformed file: exit 3 with the reason on stderr */
    test_tmp_path("cli_info_bad.obj", path, sizeof path);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nf 1 2 7\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' info '%s' 2>/dev/null", SCAF_BINARY, path);
    assert_int_equal(run(cmd), 3);
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
