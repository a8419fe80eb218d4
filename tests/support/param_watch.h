/* tests/support/param_watch: run the SCAF parametrizer on a shared mesh and
 * prove, after EVERY iteration, that the map is bijective (the kernel's
 * exact checker: zero flipped, zero degenerate, zero crossings) and that
 * each accepted step lowered that iteration's total energy. */
#ifndef SCAF_TESTS_PARAM_WATCH_H
#define SCAF_TESTS_PARAM_WATCH_H

#include <stddef.h>

#include "scaf/scaf.h"
#include "support/sanitized.h" /* test_is_sanitized, used with param_watch */

/* Runs `iterations` iterations on ../shared/data/<rel> with the given start
 * (tolerance 0: no early stop) and asserts the properties above and a final
 * E below the initial E. Returns the final E, or NAN when the file is
 * absent (the caller skips) or, when `rejected` is given, when its charts
 * are refused (then `rejected` holds the message). */
double param_run_watched(const char *rel, int iterations, scaf_init init, char *rejected,
                         size_t size);

#endif
