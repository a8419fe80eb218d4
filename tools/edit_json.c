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

/* A word in double quotes: printable ASCII without escapes. */
static int word(reader *r, char *out, size_t size)
{
    skip_ws(r);
    if (peek(r) != '"') return fail(r, "expected a string in double quotes");
    r->at++;
    size_t n = 0;
    for (; peek(r) != '"'; r->at++) {
        int c = peek(r);
        if (c < 0x20 || c > 0x7e || c == '\\' || n + 1 >= size)
            return fail(r, "unexpected string (printable ASCII, no escapes, at most 31)");
        out[n++] = (char)c;
    }
    out[n] = '\0';
    r->at++;
    return 1;
}

static int literal(reader *r, const char *w)
{
    skip_ws(r);
    size_t n = strlen(w);
    if (r->len - r->at < n || memcmp(r->s + r->at, w, n)) return 0;
    r->at += n;
    return 1;
}

/* One extra value into x (scratch: list of x->cap, word). */
static int extra_value(reader *r, edit_json_extra *x, double *list, int *len, char *w, int *flag,
                       const char *k)
{
    switch (x->kind) {
    case EDIT_JSON_WORD: return word(r, w, 32);
    case EDIT_JSON_BOOL:
        if (literal(r, "true")) *flag = 1;
        else if (literal(r, "false")) *flag = 0;
        else return fail(r, "expected true or false");
        return 1;
    case EDIT_JSON_INTEGERS:
    case EDIT_JSON_NUMBERS:
        if (!eat(r, '[')) return fail(r, "expected an array '['");
        *len = 0;
        if (eat(r, ']')) return 1;
        do {
            double v;
            if (!number(r, &v)) return 0;
            if (x->kind == EDIT_JSON_INTEGERS && (v != floor(v) || v < 0 || v > 2147483647.0)) {
                snprintf(r->msg, r->size, "\"%s\" must hold integers >= 0", k);
                return 0;
            }
            if (*len == x->cap) {
                snprintf(r->msg, r->size, "\"%s\" holds more than %d values", k, x->cap);
                return 0;
            }
            list[(*len)++] = v;
        } while (eat(r, ','));
        if (!eat(r, ']')) return fail(r, "expected ',' or ']'");
        return 1;
    }
    return fail(r, "internal error: extra kind");
}

#define MAX_EXTRA 8

int edit_json_parse_extra(const char *body, size_t len, edit_json_field *fields, int n,
                          edit_json_extra *extra, int nextra, char *msg, size_t size)
{
    reader r = {body, len, 0, msg, size};
    double value[MAX_FIELDS];
    int seen[MAX_FIELDS] = {0}, xseen[MAX_EXTRA] = {0}, xlen[MAX_EXTRA] = {0},
        xflag[MAX_EXTRA] = {0};
    char xword[MAX_EXTRA][32];
    double *xlist[MAX_EXTRA] = {NULL};
    int ok = 0;
    if (n > MAX_FIELDS || nextra > MAX_EXTRA) {
        snprintf(msg, size, "internal error: too many fields");
        return 0;
    }
    for (int x = 0; x < nextra; x++)
        if ((extra[x].kind == EDIT_JSON_INTEGERS || extra[x].kind == EDIT_JSON_NUMBERS) &&
            !(xlist[x] = malloc(sizeof(double) * (size_t)(extra[x].cap > 0 ? extra[x].cap : 1)))) {
            snprintf(msg, size, "out of memory");
            goto done;
        }
    if (!eat(&r, '{')) {
        fail(&r, "expected an object '{'");
        goto done;
    }
    if (!eat(&r, '}')) {
        do {
            char k[40];
            if (!key(&r, k, sizeof k)) goto done;
            int f = 0, x = 0;
            while (f < n && strcmp(fields[f].key, k)) f++;
            while (f == n && x < nextra && strcmp(extra[x].key, k)) x++;
            if (f == n && x == nextra) {
                snprintf(msg, size, "unknown key \"%s\"", k);
                goto done;
            }
            if (f < n ? seen[f] : xseen[x]) {
                snprintf(msg, size, "key \"%s\" given twice", k);
                goto done;
            }
            if (f == n) {
                if (!extra_value(&r, &extra[x], xlist[x], &xlen[x], xword[x], &xflag[x], k))
                    goto done;
                xseen[x] = 1;
                continue;
            }
            if (!number(&r, &value[f])) goto done;
            if (fields[f].kind == EDIT_JSON_INTEGER &&
                (value[f] != floor(value[f]) || value[f] < 0 || value[f] > 2147483647.0)) {
                snprintf(msg, size, "\"%s\" must be an integer >= 0", k);
                goto done;
            }
            seen[f] = 1;
        } while (eat(&r, ','));
        if (!eat(&r, '}')) {
            fail(&r, "expected ',' or '}'");
            goto done;
        }
    }
    skip_ws(&r);
    if (r.at != len) {
        fail(&r, "unexpected data after the object");
        goto done;
    }
    for (int f = 0; f < n; f++)
        if (fields[f].required && !seen[f]) {
            snprintf(msg, size, "missing key \"%s\"", fields[f].key);
            goto done;
        }
    for (int x = 0; x < nextra; x++)
        if (extra[x].required && !xseen[x]) {
            snprintf(msg, size, "missing key \"%s\"", extra[x].key);
            goto done;
        }
    for (int f = 0; f < n; f++) {
        fields[f].seen = seen[f];
        if (seen[f]) fields[f].value = value[f];
    }
    for (int x = 0; x < nextra; x++) {
        extra[x].seen = xseen[x];
        if (!xseen[x]) continue;
        extra[x].len = xlen[x];
        extra[x].flag = xflag[x];
        memcpy(extra[x].word, xword[x], sizeof xword[x]);
        if (xlist[x]) memcpy(extra[x].list, xlist[x], sizeof(double) * (size_t)xlen[x]);
    }
    ok = 1;
done:
    for (int x = 0; x < nextra; x++) free(xlist[x]);
    return ok;
}

int edit_json_parse(const char *body, size_t len, edit_json_field *fields, int n, char *msg,
                    size_t size)
{
    return edit_json_parse_extra(body, len, fields, n, NULL, 0, msg, size);
}
