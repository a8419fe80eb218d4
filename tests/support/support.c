/* tests/support: see support.h. */
#include "support/support.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#ifndef SCAF_DATA_DIR
#define SCAF_DATA_DIR "../shared/data"
#endif
#ifndef SCAF_TEST_TMPDIR
#define SCAF_TEST_TMPDIR "/tmp"
#endif

const char *test_data_path(const char *relative, char *buf, size_t size)
{
    const char *dir = getenv("SCAF_DATA_DIR");
    if (!dir || !*dir) dir = SCAF_DATA_DIR;
    snprintf(buf, size, "%s/%s", dir, relative);
    struct stat st;
    if (stat(buf, &st) != 0) {
        test_missing(buf);
        return NULL;
    }
    return buf;
}

int test_data_required(void)
{
    const char *v = getenv("SCAF_REQUIRE_DATA");
    return v && *v && strcmp(v, "0") != 0;
}

void test_missing(const char *what)
{
    if (test_data_required()) {
        fprintf(stderr,
                "FAIL: %s is missing and SCAF_REQUIRE_DATA is set (CI must run every test)\n",
                what);
        exit(1);
    }
    fprintf(stderr, "%s is missing: skipped\n", what);
}

int test_have_program(const char *name)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "command -v '%s' > /dev/null 2>&1", name);
    if (test_run("%s", cmd) == 0) return 1;
    char what[600];
    snprintf(what, sizeof what, "the program %s", name);
    test_missing(what);
    return 0;
}

const char *test_tmp_path(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", SCAF_TEST_TMPDIR, name);
    return buf;
}

int test_run(const char *fmt, ...)
{
    char cmd[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(cmd, sizeof cmd, fmt, ap);
    va_end(ap);
    int s = system(cmd);
    return s != -1 && WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

int test_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

char *test_slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) != 0) {
        fclose(f);
        return NULL;
    }
    long n = ftell(f);
    if (n < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    char *s = malloc((size_t)n + 1);
    if (!s) {
        fclose(f);
        return NULL;
    }
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    return s;
}
