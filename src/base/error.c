/* base/error: status + message plumbing (see error.h). */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void err_clear(scaf_error *err)
{
    if (!err) return;
    err->code = SCAF_OK;
    err->message[0] = '\0';
}

scaf_status err_set(scaf_error *err, scaf_status code, const char *fmt, ...)
{
    if (!err) return code;
    err->code = code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return code;
}

void err_prefix(scaf_error *err, const char *fmt, ...)
{
    if (!err) return;
    char head[SCAF_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    char old[SCAF_ERROR_MESSAGE_MAX];
    memcpy(old, err->message, sizeof old);
    /* Truncation is intended: the message buffer has a fixed size. */
    size_t n = strlen(head);
    if (n > sizeof err->message - 3) n = sizeof err->message - 3;
    memcpy(err->message, head, n);
    err->message[n] = ':';
    err->message[n + 1] = ' ';
    size_t room = sizeof err->message - (n + 2) - 1;
    size_t m = strlen(old);
    if (m > room) m = room;
    memcpy(err->message + n + 2, old, m);
    err->message[n + 2 + m] = '\0';
}

scaf_status err_nomem(scaf_error *err, const char *what)
{
    return err_set(err, SCAF_ERR_NOMEM, "out of memory while allocating %s", what);
}

const char *scaf_status_name(scaf_status status)
{
    switch (status) {
    case SCAF_OK: return "ok";
    case SCAF_ERR_USAGE: return "usage error";
    case SCAF_ERR_IO: return "i/o error";
    case SCAF_ERR_PARSE: return "parse error";
    case SCAF_ERR_MESH: return "invalid mesh";
    case SCAF_ERR_NUMERIC: return "numerical failure";
    case SCAF_ERR_NOMEM: return "out of memory";
    case SCAF_ERR_CANCELLED: return "cancelled";
    case SCAF_ERR_INTERNAL: return "internal error";
    }
    return "unknown status";
}

const char *scaf_version(void) { return SCAF_VERSION_STRING; }
