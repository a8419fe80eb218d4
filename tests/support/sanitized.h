/* tests/support/sanitized: whether the tests run under AddressSanitizer.
 *
 * Sanitized runs are ~3-10x slower, so heavy tests shorten themselves
 * (fewer random cases, fewer iterations) when this says so. Cannot fail. */
#ifndef SCAF_TESTS_SANITIZED_H
#define SCAF_TESTS_SANITIZED_H

/* 1 when this build uses AddressSanitizer (the whole build shares the
 * flags, so this holds for the calling test program too), else 0. */
int test_is_sanitized(void);

#endif
