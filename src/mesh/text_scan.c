/* mesh/text_scan: the strtod slow path of the number scanner, and the
 * shortest round-trip printer (see text_scan.h).
 *
 * Tokens the fast path cannot round correctly (more than 19 significant
 * digits, large exponents) and non-decimal tokens (inf, nan, hex) are copied
 * into a NUL-terminated buffer and given to strtod; the whole token must be
 * consumed. Fails with SCAN_NONFINITE for NaN/inf/overflow, SCAN_BAD else.
 */
#include "mesh/text_scan.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

scan_result scan_double_slow(const char *p, const char *q, double *out)
{
    char local[128];
    size_t n = (size_t)(q - p);
    if (n == 0) return SCAN_NONE;
    char *buf = n < sizeof local ? local : malloc(n + 1);
    if (!buf) return SCAN_BAD; /* a token this long is garbage anyway */
    memcpy(buf, p, n);
    buf[n] = '\0';
    char *stop = NULL;
    errno = 0;
    double v = strtod(buf, &stop);
    int whole = stop == buf + n;
    int overflow = errno == ERANGE && fabs(v) > 1.0;
    if (buf != local) free(buf);
    if (!whole) return SCAN_BAD;
    if (!isfinite(v) || overflow) return SCAN_NONFINITE;
    *out = v;
    return SCAN_OK;
}

/* Whether the %.*g text of x at prec digits (in buf, *n characters)
 * reads back as x. */
static int prints_back(char *buf, size_t size, double x, int prec, int *n)
{
    *n = snprintf(buf, size, "%.*g", prec, x);
    if (*n < 0 || (size_t)*n >= size) return 0;
    const char *p = buf;
    double y;
    return scan_double(&p, buf + *n, &y) == SCAN_OK && memcmp(&x, &y, sizeof x) == 0;
}

/* A text that reads back at p digits also does at p + 1 (the nearest
 * decimal of p + 1 digits is at least as near to x), so the search may
 * start in the middle: from 16, a failure means 17 with no check and a
 * success leaves only 15 to try. Numbers read from short decimals need 15
 * (start there), an optimizer's results 16 or 17 (start at 16: one
 * conversion and one parse fewer each); *digits carries what the last
 * number of a stream needed. */
int scan_format_double_hint(char *buf, size_t size, double x, int *digits)
{
    int n;
    if (*digits <= 15) {
        for (int prec = 15; prec <= 16; prec++)
            if (prints_back(buf, size, x, prec, &n)) return *digits = prec, n;
        return *digits = 17, snprintf(buf, size, "%.17g", x);
    }
    if (!prints_back(buf, size, x, 16, &n)) return *digits = 17, snprintf(buf, size, "%.17g", x);
    char b15[32];
    int n15;
    if (prints_back(b15, sizeof b15, x, 15, &n15) && (size_t)n15 < size) {
        memcpy(buf, b15, (size_t)n15 + 1);
        return *digits = 15, n15;
    }
    return *digits = 16, n;
}

int scan_format_double(char *buf, size_t size, double x)
{
    int digits = 15;
    return scan_format_double_hint(buf, size, x, &digits);
}
