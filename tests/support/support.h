/* tests/support: helpers shared by the test programs. */
#ifndef SCAF_TESTS_SUPPORT_H
#define SCAF_TESTS_SUPPORT_H

#include <stddef.h>

/* Absolute path of a file under the shared test-mesh folder
 * (SCAF_DATA_DIR, overridable by the environment variable SCAF_DATA_DIR),
 * written into buf. Returns buf, or NULL when the file does not exist:
 * callers then skip() so the suite passes where ../shared/data is absent.
 * Under SCAF_REQUIRE_DATA (see test_missing) a missing file ends the test
 * program with a failure instead, so CI cannot pass with tests unrun. */
const char *test_data_path(const char *relative, char *buf, size_t size);

/* Whether the environment variable SCAF_REQUIRE_DATA is set to anything
 * but "" or "0" (.ci/run sets it): then test data or a tool that a test
 * needs must be there. */
int test_data_required(void);

/* Say that what (a data file, a program) is missing. Under
 * SCAF_REQUIRE_DATA it prints why and exits 1 (the test fails); otherwise
 * it prints why and returns, and the caller skips. */
void test_missing(const char *what);

/* Whether the program name is on PATH; a missing one goes through
 * test_missing (so under SCAF_REQUIRE_DATA the test fails). */
int test_have_program(const char *name);

/* A fresh path in the build's scratch folder for a test output file:
 * "<tmpdir>/<name>" (the folder is created by the build). */
const char *test_tmp_path(const char *name, char *buf, size_t size);

/* Run a shell command built printf-style; returns its exit status, or -1
 * when it did not exit normally. */
int test_run(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Whether a file (or folder) exists. */
int test_exists(const char *path);

/* The whole file as a NUL-terminated string (caller frees), NULL when it
 * cannot be read. */
char *test_slurp(const char *path);

#endif
