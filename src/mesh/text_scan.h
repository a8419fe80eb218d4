/* mesh/text_scan: number and token scanning shared by the text mesh readers.
 *
 * Internal to src/mesh. All scanners work on a byte range [p, end) that is
 * NOT NUL-terminated and never read at or past `end`. Decimal numbers are
 * parsed on a fast path (at most 19 significant digits, a mantissa below
 * 2^53 and a power of ten below 10^22: one exact IEEE operation, so the
 * result is correctly rounded) and otherwise handed to strtod on a copy of
 * the token, so every value equals what strtod gives for the same text.
 * Scanners report a kind of failure; the readers turn it into a message
 * with file and line.
 */
#ifndef SCAF_MESH_TEXT_SCAN_H
#define SCAF_MESH_TEXT_SCAN_H

#include <stddef.h>
#include <stdint.h>

typedef enum scan_result {
    SCAN_OK = 0,
    SCAN_NONE,      /* no token before the end of the range */
    SCAN_BAD,       /* token is not a number of the wanted kind */
    SCAN_NONFINITE, /* NaN, inf, or a decimal that overflows a double */
    SCAN_RANGE      /* integer does not fit the wanted range */
} scan_result;

/* Space within a line: blank, tab, CR (CRLF files), vertical tab, form feed. */
static inline int scan_is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

static inline int scan_is_space(char c) { return scan_is_blank(c) || c == '\n'; }

static inline const char *scan_skip_blank(const char *p, const char *end)
{
    while (p < end && scan_is_blank(*p)) p++;
    return p;
}

/* End of the token starting at p (first blank/newline or end). */
static inline const char *scan_token_end(const char *p, const char *end)
{
    while (p < end && !scan_is_space(*p)) p++;
    return p;
}

/* Slow path: strtod on a NUL-terminated copy of [p, q). Defined in text_scan.c. */
scan_result scan_double_slow(const char *p, const char *q, double *out);

/* Parse the decimal number that starts at *pp (no leading blanks) and ends
 * at a blank, newline or `end`; on success store it and advance *pp past it. */
static inline scan_result scan_double(const char **pp, const char *end, double *out)
{
    static const double pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char *p = *pp, *s = p;
    if (s >= end) return SCAN_NONE;
    int neg = 0;
    if (*s == '+' || *s == '-') neg = (*s++ == '-');
    uint64_t m = 0;
    int nd = 0, any = 0, lost = 0;
    long e10 = 0;
    while (s < end && (unsigned)(*s - '0') < 10u) {
        unsigned d = (unsigned)(*s - '0');
        any = 1;
        if (nd < 19) {
            if (m || d) {
                m = m * 10 + d;
                nd++;
            }
        } else {
            e10++;
            lost |= d != 0;
        }
        s++;
    }
    if (s < end && *s == '.') {
        s++;
        while (s < end && (unsigned)(*s - '0') < 10u) {
            unsigned d = (unsigned)(*s - '0');
            any = 1;
            if (nd < 19) {
                if (m || d) {
                    m = m * 10 + d;
                    nd++;
                }
                e10--;
            } else {
                lost |= d != 0;
            }
            s++;
        }
    }
    if (!any) {
        /* inf / nan / hex or plain garbage: let strtod classify it. */
        const char *q = scan_token_end(p, end);
        double v;
        scan_result r = scan_double_slow(p, q, &v);
        if (r == SCAN_OK) r = SCAN_BAD; /* e.g. hex floats: not accepted */
        return r;
    }
    if (s < end && (*s == 'e' || *s == 'E')) {
        s++;
        int eneg = 0;
        if (s < end && (*s == '+' || *s == '-')) eneg = (*s++ == '-');
        if (s >= end || (unsigned)(*s - '0') >= 10u) return SCAN_BAD;
        long x = 0;
        while (s < end && (unsigned)(*s - '0') < 10u) {
            if (x < 100000) x = x * 10 + (*s - '0');
            s++;
        }
        e10 += eneg ? -x : x;
    }
    if (s < end && !scan_is_space(*s)) return SCAN_BAD;
    if (!lost && m <= (UINT64_C(1) << 53) && e10 >= -22 && e10 <= 22) {
        double v = (double)m;
        v = e10 < 0 ? v / pow10[-e10] : v * pow10[e10];
        *out = neg ? -v : v;
        *pp = s;
        return SCAN_OK;
    }
    if (m == 0 && !lost) {
        *out = neg ? -0.0 : 0.0;
        *pp = s;
        return SCAN_OK;
    }
    scan_result r = scan_double_slow(p, s, out);
    if (r == SCAN_OK) *pp = s;
    return r;
}

/* Parse an optionally signed decimal integer in [lo, hi] that ends at a
 * blank, newline, `end` or the character `stop` (0 for none). */
static inline scan_result scan_long(const char **pp, const char *end, char stop, long long lo,
                                    long long hi, long long *out)
{
    const char *s = *pp;
    if (s >= end) return SCAN_NONE;
    int neg = 0;
    if (*s == '+' || *s == '-') neg = (*s++ == '-');
    if (s >= end || (unsigned)(*s - '0') >= 10u) return SCAN_BAD;
    unsigned long long v = 0;
    int big = 0;
    while (s < end && (unsigned)(*s - '0') < 10u) {
        if (v < (1ULL << 62) / 10) v = v * 10 + (unsigned)(*s - '0');
        else big = 1;
        s++;
    }
    if (s < end && !scan_is_space(*s) && *s != stop) return SCAN_BAD;
    if (big) return SCAN_RANGE;
    long long x = neg ? -(long long)v : (long long)v;
    if (x < lo || x > hi) return SCAN_RANGE;
    *out = x;
    *pp = s;
    return SCAN_OK;
}

/* Print x with the fewest of 15, 16 or 17 significant digits that
 * scan_double reads back to the same double (so a write-read cycle is
 * bitwise exact and short values stay short). Returns snprintf's count. */
int scan_format_double(char *buf, size_t size, double x);

/* The same text, the search started where *digits (15..17: what the
 * stream's last number needed, 15 for the first) says, and *digits set to
 * what x needed: a stream of an optimizer's results (16-17 digits) prints
 * about 1.4x faster. */
int scan_format_double_hint(char *buf, size_t size, double x, int *digits);

#endif /* SCAF_MESH_TEXT_SCAN_H */
