/* tests/support/cli_capture: running the `scaf` program and reading the
 * numbers of its one-line JSON reports. */
#ifndef SCAF_TESTS_CLI_CAPTURE_H
#define SCAF_TESTS_CLI_CAPTURE_H

#include <stddef.h>

/* Run a shell command built printf-style and capture its standard output
 * into out (at most size - 1 bytes, NUL-terminated). Returns the exit
 * status, or -1 when the command could not run or did not exit normally. */
int test_capture(char *out, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* The integer value of "key" in a JSON text (true/false read as 1/0);
 * fails the running cmocka test, naming the key, when it is missing. */
long long test_json_field(const char *json, const char *key);

#endif
