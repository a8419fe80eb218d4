/* tools/edit_json: the strict reader of `scaf edit`'s request bodies (see edit_json.h). */
#include "edit_json.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FIELDS 16

typedef struct reader {
    const char *s;
    size_t len, at;
    char *msg;
    size_t size;
} reader;

static int fail(reader *r, const char *what)
{
    snprintf(r->msg, r->size, "malformed JSON at byte %zu: %s", r->at, what);
    return 0;
}

static void skip_ws(reader *r)
{
    while (
        r->at < r->len &&
        (r->s[r->at] == ' ' || r->s[r->at] == '\t' || r->s[r->at] == '\r' || r->s[r->at] == '\n'))
        r->at++;
}

static int peek(reader *r) { return r->at < r->len ? (unsigned char)r->s[r->at] : -1; }

static int eat(reader *r, char c)
{
    skip_ws(r);
    if (peek(r) != (unsigned char)c) return 0;
    r->at++;
    return 1;
}

static int is_digit(int c) { return c >= '0' && c <= '9'; }

/* A key: printable ASCII without escapes (no key the editor knows needs one). */
static int key(reader *r, char *out, size_t size)
{
    if (!eat(r, '"')) return fail(r, "expected a key in double quotes");
    size_t n = 0;
    for (; peek(r) != '"'; r->at++) {
        int c = peek(r);
        if (c < 0x20 || c > 0x7e || c == '\\' || n + 1 >= size) return fail(r, "unexpected key");
        out[n++] = (char)c;
    }
    out[n] = '\0';
    r->at++; /* the closing quote */
    if (!eat(r, ':')) return fail(r, "expected ':' after a key");
    return 1;
}

/* An RFC 8259 number: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)? */
static int number(reader *r, double *v)
{
    skip_ws(r);
    size_t start = r->at;
    if (peek(r) == '-') r->at++;
    if (peek(r) == '0') r->at++;
    else if (is_digit(peek(r)))
        while (is_digit(peek(r))) r->at++;
    else return fail(r, "expected a number");
    if (peek(r) == '.') {
        r->at++;
        if (!is_digit(peek(r))) return fail(r, "expected a digit after '.'");
        while (is_digit(peek(r))) r->at++;
    }
    if (peek(r) == 'e' || peek(r) == 'E') {
        r->at++;
        if (peek(r) == '+' || peek(r) == '-') r->at++;
        if (!is_digit(peek(r))) return fail(r, "expected a digit in the exponent");
        while (is_digit(peek(r))) r->at++;
    }
    char text[64];
    size_t n = r->at - start;
    if (n >= sizeof text) return fail(r, "number too long");
    memcpy(text, r->s + start, n);
    text[n] = '\0';
    errno = 0;
    *v = strtod(text, NULL);
    if (errno == ERANGE || !isfinite(*v)) return fail(r, "number out of range");
    return 1;
}

int edit_json_parse(const char *body, size_t len, edit_json_field *fields, int n, char *msg,
                    size_t size)
{
    reader r = {body, len, 0, msg, size};
    double value[MAX_FIELDS];
    int seen[MAX_FIELDS] = {0};
    if (n > MAX_FIELDS) {
        snprintf(msg, size, "internal error: too many fields");
        return 0;
    }
    if (!eat(&r, '{')) return fail(&r, "expected an object '{'");
    if (!eat(&r, '}')) {
        do {
            char k[40];
            if (!key(&r, k, sizeof k)) return 0;
            int f = 0;
            while (f < n && strcmp(fields[f].key, k)) f++;
            if (f == n) {
                snprintf(msg, size, "unknown key \"%s\"", k);
                return 0;
            }
            if (seen[f]) {
                snprintf(msg, size, "key \"%s\" given twice", k);
                return 0;
            }
            if (!number(&r, &value[f])) return 0;
            if (fields[f].kind == EDIT_JSON_INTEGER &&
                (value[f] != floor(value[f]) || value[f] < 0 || value[f] > 2147483647.0)) {
                snprintf(msg, size, "\"%s\" must be an integer >= 0", k);
                return 0;
            }
            seen[f] = 1;
        } while (eat(&r, ','));
        if (!eat(&r, '}')) return fail(&r, "expected ',' or '}'");
    }
    skip_ws(&r);
    if (r.at != len) return fail(&r, "unexpected data after the object");
    for (int f = 0; f < n; f++)
        if (fields[f].required && !seen[f]) {
            snprintf(msg, size, "missing key \"%s\"", fields[f].key);
            return 0;
        }
    for (int f = 0; f < n; f++) {
        fields[f].seen = seen[f];
        if (seen[f]) fields[f].value = value[f];
    }
    return 1;
}
