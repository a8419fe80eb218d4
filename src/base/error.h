/* base/error: carrying a status and a message a person can act on.
 *
 * Every function that can fail takes a `scaf_error *err` (may be NULL when
 * the caller does not care about the text), fills it with err_set() and
 * returns the status. The first error set wins only if the caller resets
 * it; err_set always overwrites, so set at the innermost place that knows
 * the reason and let outer layers add context with err_prefix().
 */
#ifndef SCAF_BASE_ERROR_H
#define SCAF_BASE_ERROR_H

#include "scaf/scaf.h"

#define SCAF_ERROR_MESSAGE_MAX 1024

typedef struct scaf_error {
    scaf_status code;
    char message[SCAF_ERROR_MESSAGE_MAX];
} scaf_error;

/* Reset to SCAF_OK with an empty message. */
void err_clear(scaf_error *err);

/* Set code and printf-style message; returns code so callers can
 * `return err_set(err, SCAF_ERR_PARSE, "...")`. err may be NULL. */
scaf_status err_set(scaf_error *err, scaf_status code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Put "context: " in front of the current message (e.g. the file name). */
void err_prefix(scaf_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Convenience for allocation failure: sets SCAF_ERR_NOMEM naming what. */
scaf_status err_nomem(scaf_error *err, const char *what);

#endif /* SCAF_BASE_ERROR_H */
