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

int scan_format_double(char *buf, size_t size, double x)
{
    int n = 0;
    for (int prec = 15; prec <= 17; prec++) {
        n = snprintf(buf, size, "%.*g", prec, x);
        const char *p = buf;
        double y;
        if (scan_double(&p, buf + n, &y) == SCAN_OK && memcmp(&x, &y, sizeof x) == 0) break;
    }
    return n;
}
