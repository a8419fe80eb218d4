/* mesh/reader_common: helpers shared by the OBJ, OFF and PLY readers.
 *
 * Error messages in the "NAME:LINE: reason" form, quoting of offending
 * tokens (bounded, non-printable bytes escaped), and detection of a polygon
 * that uses one vertex twice (a "degenerate index" face, rejected by the
 * readers): small polygons are checked pairwise, large ones by sorting a
 * copy, so a hostile file with a million-corner face cannot make the check
 * quadratic.
 */
#include "mesh/mesh_readers.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

scaf_status mesh_parse_fail(scaf_error *err, const char *name, long line, const char *fmt, ...)
{
    char reason[SCAF_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(reason, sizeof reason, fmt, ap);
    va_end(ap);
    return err_set(err, SCAF_ERR_PARSE, "%s:%ld: %s", name, line, reason);
}

const char *mesh_quote_token(const char *p, const char *end, char *buf, size_t size)
{
    size_t o = 0;
    while (p < end && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n' && o + 5 < size) {
        unsigned char c = (unsigned char)*p++;
        if (c >= 32 && c < 127) {
            buf[o++] = (char)c;
        } else {
            snprintf(buf + o, size - o, "\\x%02x", c);
            o += 4;
        }
        if (o >= 40 && p < end && *p != ' ') {
            if (o + 4 < size) {
                memcpy(buf + o, "...", 3);
                o += 3;
            }
            break;
        }
    }
    buf[o] = '\0';
    return buf;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

int mesh_corners_repeat(const int *idx, size_t n, int *dup)
{
    if (n <= 32) {
        for (size_t i = 1; i < n; i++)
            for (size_t j = 0; j < i; j++)
                if (idx[i] == idx[j]) {
                    *dup = idx[i];
                    return 1;
                }
        return 0;
    }
    int *c = malloc(n * sizeof *c);
    if (!c) return -1;
    memcpy(c, idx, n * sizeof *c);
    qsort(c, n, sizeof *c, cmp_int);
    int found = 0;
    for (size_t i = 1; i < n && !found; i++)
        if (c[i] == c[i - 1]) {
            *dup = c[i];
            found = 1;
        }
    free(c);
    return found;
}
