/* mesh/read_off: Object File Format parser (OFF and its common variants).
 *
 * Header keyword `[ST][C][N][n]OFF` (texture, colour, normal flags only add
 * values at the end of vertex lines, which are ignored; `nOFF` is followed
 * by the dimension, which must be 3; 4D `4OFF` is rejected), then the
 * counts `#V #F [#E]` (on the keyword line or after it; #E is ignored),
 * then one vertex per line (`x y z ...`) and one face per line
 * (`k i0 .. ik-1 [colour]`, 0-based indices, polygons fan-triangulated).
 * `#` comments, blank lines, CRLF and a missing final newline are accepted.
 *
 * Counts are checked against the bytes that follow before anything is
 * allocated (a vertex line takes at least 6 bytes, a face line 2), so an
 * absurd header is a "truncated file" error, never a huge allocation.
 * Other errors: malformed or non-finite number, index out of range, face
 * with fewer than 3 corners or a repeated vertex, no faces. All are
 * SCAF_ERR_PARSE "NAME:LINE: reason".
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"
#include "mesh/mesh_builder.h"
#include "mesh/mesh_readers.h"
#include "mesh/text_scan.h"

typedef struct off_cursor {
    const char *p, *end;
    long line; /* line number of p */
} off_cursor;

/* Next token, skipping blanks, newlines and comments; NULL at end of data. */
static const char *off_next_token(off_cursor *c)
{
    while (c->p < c->end) {
        char ch = *c->p;
        if (ch == '\n') {
            c->line++;
            c->p++;
        } else if (scan_is_blank(ch)) {
            c->p++;
        } else if (ch == '#') {
            const char *nl = memchr(c->p, '\n', (size_t)(c->end - c->p));
            c->p = nl ? nl : c->end;
        } else {
            return c->p;
        }
    }
    return NULL;
}

/* Next line holding something other than blanks or a comment: [*s, *eol). */
static int off_next_line(off_cursor *c, const char **s, const char **eol)
{
    while (c->p < c->end) {
        const char *e = memchr(c->p, '\n', (size_t)(c->end - c->p));
        if (!e) e = c->end;
        const char *t = scan_skip_blank(c->p, e);
        c->line++;
        c->p = e + 1;
        if (t < e && *t != '#') {
            c->line--; /* report the line the content is on */
            *s = t;
            *eol = e;
            return 1;
        }
    }
    return 0;
}

static scaf_status off_header_int(off_cursor *c, const char *name, const char *what, long long *out,
                                  scaf_error *err)
{
    const char *t = off_next_token(c);
    if (!t) return mesh_parse_fail(err, name, c->line, "truncated header: missing %s", what);
    const char *s = t;
    scan_result r = scan_long(&s, c->end, 0, 0, INT_MAX - 1, out);
    if (r != SCAN_OK) {
        char tok[64];
        return mesh_parse_fail(err, name, c->line, "bad %s '%s'%s", what,
                               mesh_quote_token(t, c->end, tok, sizeof tok),
                               r == SCAN_RANGE ? " (negative or too large)" : "");
    }
    c->p = s;
    return SCAF_OK;
}

scaf_status mesh_parse_off(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err)
{
    off_cursor c = {data, data + size, 1};
    if (size >= 3 && memcmp(c.p, "\xEF\xBB\xBF", 3) == 0) c.p += 3;
    const char *k = off_next_token(&c);
    if (!k) return mesh_parse_fail(err, name, c.line, "empty file (no OFF header)");
    const char *ke = scan_token_end(k, c.end);
    size_t kn = (size_t)(ke - k);
    char tok[64];
    if (kn < 3 || memcmp(ke - 3, "OFF", 3) != 0 || kn > 8)
        return mesh_parse_fail(err, name, c.line, "not an OFF file: header is '%s'",
                               mesh_quote_token(k, c.end, tok, sizeof tok));
    int ndim = 0;
    for (const char *q = k; q < ke - 3; q++) {
        if (*q == 'n') ndim = 1;
        else if (*q == '4')
            return mesh_parse_fail(err, name, c.line, "4D OFF ('%s') is not supported",
                                   mesh_quote_token(k, c.end, tok, sizeof tok));
        else if (!strchr("STCN", *q))
            return mesh_parse_fail(err, name, c.line, "unknown OFF variant '%s'",
                                   mesh_quote_token(k, c.end, tok, sizeof tok));
    }
    c.p = ke;
    long long dim = 3, nv, nf;
    scaf_status st;
    if (ndim) {
        if ((st = off_header_int(&c, name, "dimension", &dim, err))) return st;
        if (dim != 3)
            return mesh_parse_fail(err, name, c.line, "dimension %lld is not supported (only 3)",
                                   dim);
    }
    if ((st = off_header_int(&c, name, "vertex count", &nv, err))) return st;
    if ((st = off_header_int(&c, name, "face count", &nf, err))) return st;
    /* The edge count, if any, is the rest of this line: skip it. */
    const char *nl = memchr(c.p, '\n', (size_t)(c.end - c.p));
    long header_line = c.line;
    if (nl) {
        c.p = nl + 1;
        c.line++;
    } else {
        c.p = c.end;
    }
    size_t rest = (size_t)(c.end - c.p);
    /* a face line takes at least 2 bytes ("3\n", a malformed one): bounding
     * by the 8 of a valid one called a short file with a 2-corner face
     * "truncated"; the faces' own lines say what is wrong with them */
    if ((unsigned long long)nv * 6 + (unsigned long long)nf * 2 > (unsigned long long)rest + 1)
        return mesh_parse_fail(err, name, header_line,
                               "header says %lld vertices and %lld faces but only %zu bytes follow "
                               "(truncated file?)",
                               nv, nf, rest);
    if (nf == 0) return mesh_parse_fail(err, name, header_line, "no faces (empty mesh)");

    mesh_builder b;
    mesh_builder_init(&b, 0);
    int *corners = NULL;
    size_t ccap = 0;
    long long polygons = 0;
    if (mesh_builder_reserve(&b, (size_t)nv, (size_t)nf)) {
        st = err_nomem(err, "mesh arrays");
        goto done;
    }
    const char *s, *eol;
    for (long long i = 0; i < nv; i++) {
        if ((i & 0xffff) == 0xffff && interrupt_pending()) { /* SIGINT / SIGTERM */
            st = interrupt_check(NULL, "reading the mesh", err);
            goto done;
        }
        if (!off_next_line(&c, &s, &eol)) {
            st = mesh_parse_fail(err, name, c.line, "truncated file: %lld of %lld vertices read", i,
                                 nv);
            goto done;
        }
        double x[3];
        for (int d = 0; d < 3; d++) {
            s = scan_skip_blank(s, eol);
            scan_result r = scan_double(&s, eol, &x[d]);
            if (r != SCAN_OK) {
                if (r == SCAN_NONE)
                    st = mesh_parse_fail(err, name, c.line,
                                         "vertex %lld has %d coordinate%s (needs 3)", i, d,
                                         d == 1 ? "" : "s");
                else
                    st = mesh_parse_fail(err, name, c.line,
                                         "vertex coordinate '%s' is not a %snumber",
                                         mesh_quote_token(s, eol, tok, sizeof tok),
                                         r == SCAN_NONFINITE ? "finite " : "");
                goto done;
            }
        }
        mesh_builder_add_v(&b, x[0], x[1], x[2]); /* reserved: cannot fail */
        c.line++;
    }
    for (long long i = 0; i < nf; i++) {
        if ((i & 0xffff) == 0xffff && interrupt_pending()) { /* SIGINT / SIGTERM */
            st = interrupt_check(NULL, "reading the mesh", err);
            goto done;
        }
        if (!off_next_line(&c, &s, &eol)) {
            st = mesh_parse_fail(err, name, c.line, "truncated file: %lld of %lld faces read", i,
                                 nf);
            goto done;
        }
        long long n;
        const char *t = s;
        scan_result r = scan_long(&s, eol, 0, 0, INT_MAX, &n);
        if (r != SCAN_OK) {
            st = mesh_parse_fail(err, name, c.line, "bad corner count '%s'",
                                 mesh_quote_token(t, eol, tok, sizeof tok));
            goto done;
        }
        if (n < 3) {
            st = mesh_parse_fail(err, name, c.line, "face has %lld corner%s (needs at least 3)", n,
                                 n == 1 ? "" : "s");
            goto done;
        }
        if ((size_t)n > (size_t)(eol - s) / 2 + 1) {
            st = mesh_parse_fail(err, name, c.line,
                                 "face says %lld corners but the line is shorter", n);
            goto done;
        }
        if ((size_t)n > ccap) {
            size_t cap = (size_t)n < 16 ? 16 : (size_t)n;
            int *a = realloc(corners, cap * sizeof *a);
            if (!a) {
                st = err_nomem(err, "face corners");
                goto done;
            }
            corners = a;
            ccap = cap;
        }
        for (long long j = 0; j < n; j++) {
            s = scan_skip_blank(s, eol);
            long long v;
            t = s;
            r = scan_long(&s, eol, 0, LLONG_MIN / 2, LLONG_MAX / 2, &v);
            if (r == SCAN_NONE) {
                st = mesh_parse_fail(err, name, c.line, "face has %lld of its %lld indices", j, n);
                goto done;
            }
            if (r != SCAN_OK || v < 0 || v >= nv) {
                mesh_quote_token(t, eol, tok, sizeof tok);
                if (r == SCAN_BAD)
                    st = mesh_parse_fail(err, name, c.line, "bad vertex index '%s'", tok);
                else
                    st = mesh_parse_fail(err, name, c.line,
                                         "vertex index %s out of range (the file has %lld "
                                         "vertices)",
                                         tok, nv);
                goto done;
            }
            corners[j] = (int)v;
        }
        int dup;
        int rep = mesh_corners_repeat(corners, (size_t)n, &dup);
        if (rep) {
            st = rep < 0
                ? err_nomem(err, "face corners")
                : mesh_parse_fail(err, name, c.line,
                                  "face uses vertex %d more than once (degenerate face)", dup);
            goto done;
        }
        for (long long j = 1; j + 1 < n; j++)
            if (mesh_builder_add_f(&b, corners[0], corners[j], corners[j + 1], 0, 0, 0)) {
                st = err_set(err, SCAF_ERR_NOMEM,
                             "%s:%ld: out of memory (or more than INT_MAX faces)", name, c.line);
                goto done;
            }
        if (n > 3) polygons++;
        c.line++;
    }
    st = SCAF_OK;
done:
    free(corners);
    if (st != SCAF_OK) {
        mesh_builder_free(&b);
        return st;
    }
    info->format = MESH_FORMAT_OFF;
    info->polygons_triangulated = polygons > INT_MAX ? INT_MAX : (int)polygons;
    return mesh_builder_finish(&b, 0, m, err);
}
