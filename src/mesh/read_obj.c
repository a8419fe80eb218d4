/* mesh/read_obj: Wavefront OBJ parser (positions, texture coordinates, faces).
 *
 * Line based. `v x y z [w | r g b]` (extra values ignored), `vt u [v [w]]`
 * (v defaults to 0), `vn` counted and ignored, `f` with corners `a`, `a/t`,
 * `a//n`, `a/t/n`, negative indices relative to the elements read so far;
 * polygons are fan-triangulated (a0 ai ai+1) and counted. Comments, blank
 * lines, CRLF, trailing blanks, a missing final newline and a UTF-8 BOM are
 * accepted; grouping/material/curve statements are ignored; any other
 * statement is an error. Positive indices may refer forward; the largest one
 * is checked against the final count (message names its line).
 *
 * UV policy: the mesh gets UVs when every face has texture indices. When
 * some faces have them and others do not, the UVs are dropped and the
 * number of faces without them is reported in info->faces_without_uv (a
 * warning for the caller to print). Within one face, corners must agree.
 *
 * Errors (SCAF_ERR_PARSE, "NAME:LINE: reason"): malformed number or index,
 * NaN/inf coordinate, index 0, index out of range or overflowing int,
 * relative index before the first element, face with fewer than 3 corners
 * or a repeated vertex, unknown statement, no faces at all.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"
#include "mesh/mesh_builder.h"
#include "mesh/mesh_readers.h"
#include "mesh/text_scan.h"

/* Statements that carry no geometry we use. */
static const char *const obj_ignored[] = {
    "o",        "g",        "s",    "mtllib", "usemtl", "l",          "p",         "vp",
    "cstype",   "deg",      "bmat", "step",   "curv",   "curv2",      "surf",      "parm",
    "trim",     "hole",     "scrv", "sp",     "end",    "con",        "mg",        "bevel",
    "c_interp", "d_interp", "lod",  "maplib", "usemap", "shadow_obj", "trace_obj", "ctech",
    "stech",    "call",     "csh",  NULL};

static int obj_is_ignored(const char *s, size_t n)
{
    for (const char *const *k = obj_ignored; *k; k++)
        if (strlen(*k) == n && memcmp(*k, s, n) == 0) return 1;
    return 0;
}

/* Parsing state kept across lines. */
typedef struct obj_parser {
    const char *name;
    scaf_error *err;
    mesh_builder b;
    int *cv, *ct; /* corners of the current face: vertex and vt indices */
    size_t ccap;
    long long max_v; /* largest 1-based positive vertex index seen */
    long max_v_line;
    long long max_t;
    long max_t_line;
    long long with_uv; /* faces with / without texture indices */
    long long without_uv;
    long long polygons;
    long long normals;
} obj_parser;

static scaf_status obj_number_error(obj_parser *P, long line, scan_result r, const char *s,
                                    const char *eol, const char *what)
{
    char tok[64];
    if (r == SCAN_NONE) return mesh_parse_fail(P->err, P->name, line, "%s: missing value", what);
    mesh_quote_token(s, eol, tok, sizeof tok);
    if (r == SCAN_NONFINITE)
        return mesh_parse_fail(P->err, P->name, line, "%s: '%s' is not a finite number", what, tok);
    return mesh_parse_fail(P->err, P->name, line, "%s: '%s' is not a number", what, tok);
}

static scaf_status obj_vertex(obj_parser *P, long line, const char *s, const char *eol)
{
    double x[3];
    for (int k = 0; k < 3; k++) {
        s = scan_skip_blank(s, eol);
        scan_result r = scan_double(&s, eol, &x[k]);
        if (r != SCAN_OK) return obj_number_error(P, line, r, s, eol, "vertex coordinate");
    }
    if (mesh_builder_add_v(&P->b, x[0], x[1], x[2]))
        return err_set(P->err, SCAF_ERR_NOMEM,
                       "%s:%ld: out of memory (or more than INT_MAX vertices)", P->name, line);
    return SCAF_OK;
}

static scaf_status obj_texcoord(obj_parser *P, long line, const char *s, const char *eol)
{
    double t[2] = {0.0, 0.0};
    for (int k = 0; k < 2; k++) {
        s = scan_skip_blank(s, eol);
        if (k == 1 && (s == eol || *s == '#')) break; /* `vt u`: v defaults to 0 */
        scan_result r = scan_double(&s, eol, &t[k]);
        if (r != SCAN_OK) return obj_number_error(P, line, r, s, eol, "texture coordinate");
    }
    if (mesh_builder_add_uv(&P->b, t[0], t[1]))
        return err_set(P->err, SCAF_ERR_NOMEM, "%s:%ld: out of memory (or more than INT_MAX vt)",
                       P->name, line);
    return SCAF_OK;
}

/* Parse one index of a corner and resolve it to 0-based against `count`
 * elements read so far; track the largest forward reference. */
static scaf_status obj_index(obj_parser *P, long line, const char **ps, const char *eol, char stop,
                             size_t count, const char *what, long long *max_seen, long *max_line,
                             int *out)
{
    const char *s = *ps;
    long long v;
    scan_result r = scan_long(&s, eol, stop, -(long long)INT_MAX, INT_MAX, &v);
    if (r != SCAN_OK) {
        char tok[64];
        mesh_quote_token(*ps, eol, tok, sizeof tok);
        if (r == SCAN_RANGE)
            return mesh_parse_fail(P->err, P->name, line, "%s index in '%s' overflows an int", what,
                                   tok);
        return mesh_parse_fail(P->err, P->name, line, "bad face corner '%s'", tok);
    }
    if (v == 0)
        return mesh_parse_fail(P->err, P->name, line, "%s index 0 (OBJ indices start at 1)", what);
    if (v < 0) {
        long long a = (long long)count + v;
        if (a < 0)
            return mesh_parse_fail(P->err, P->name, line,
                                   "relative %s index %lld reaches before the first one (%zu so "
                                   "far)",
                                   what, v, count);
        *out = (int)a;
    } else {
        if (v > *max_seen) {
            *max_seen = v;
            *max_line = line;
        }
        *out = (int)(v - 1);
    }
    *ps = s;
    return SCAF_OK;
}

static scaf_status obj_face(obj_parser *P, long line, const char *s, const char *eol)
{
    size_t n = 0;
    int has_t = -1;
    scaf_status st;
    for (;;) {
        s = scan_skip_blank(s, eol);
        if (s == eol || *s == '#') break;
        const char *corner = s;
        int vi = 0, ti = -1, this_t = 0;
        st = obj_index(P, line, &s, eol, '/', P->b.nv, "vertex", &P->max_v, &P->max_v_line, &vi);
        if (st) return st;
        if (s < eol && *s == '/') {
            s++;
            if (s < eol && *s == '/') {
                s++; /* a//n */
            } else if (s < eol && !scan_is_space(*s)) {
                st = obj_index(P, line, &s, eol, '/', P->b.nuv, "texture", &P->max_t,
                               &P->max_t_line, &ti);
                if (st) return st;
                this_t = 1;
                if (s < eol && *s == '/') s++;
            }
            if (s < eol && !scan_is_space(*s)) { /* normal index: syntax checked, value unused */
                long long nidx;
                scan_result r = scan_long(&s, eol, 0, -(long long)INT_MAX, INT_MAX, &nidx);
                if (r != SCAN_OK) {
                    char tok[64];
                    return mesh_parse_fail(P->err, P->name, line, "bad face corner '%s'",
                                           mesh_quote_token(corner, eol, tok, sizeof tok));
                }
            }
        }
        if (has_t < 0) has_t = this_t;
        else if (has_t != this_t)
            return mesh_parse_fail(P->err, P->name, line,
                                   "face mixes corners with and without texture index");
        if (n == P->ccap) {
            size_t cap = P->ccap ? 2 * P->ccap : 16;
            int *a = realloc(P->cv, cap * sizeof *a);
            if (!a) return err_nomem(P->err, "face corners");
            P->cv = a;
            int *t = realloc(P->ct, cap * sizeof *t);
            if (!t) return err_nomem(P->err, "face corners");
            P->ct = t;
            P->ccap = cap;
        }
        P->cv[n] = vi;
        P->ct[n] = ti;
        n++;
    }
    if (n < 3)
        return mesh_parse_fail(P->err, P->name, line, "face has %zu corner%s (needs at least 3)", n,
                               n == 1 ? "" : "s");
    int dup;
    int rep = mesh_corners_repeat(P->cv, n, &dup);
    if (rep < 0) return err_nomem(P->err, "face corners");
    if (rep)
        return mesh_parse_fail(P->err, P->name, line,
                               "face uses vertex %d more than once (degenerate face)", dup + 1);
    for (size_t i = 1; i + 1 < n; i++)
        if (mesh_builder_add_f(&P->b, P->cv[0], P->cv[i], P->cv[i + 1], P->ct[0], P->ct[i],
                               P->ct[i + 1]))
            return err_set(P->err, SCAF_ERR_NOMEM,
                           "%s:%ld: out of memory (or more than INT_MAX faces)", P->name, line);
    if (n > 3) P->polygons++;
    if (has_t) P->with_uv++;
    else P->without_uv++;
    return SCAF_OK;
}

static int clamp_int(long long x) { return x > INT_MAX ? INT_MAX : (int)x; }

scaf_status mesh_parse_obj(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err)
{
    obj_parser P;
    memset(&P, 0, sizeof P);
    P.name = name;
    P.err = err;
    mesh_builder_init(&P.b, 1);
    /* A guess from typical line lengths; growth handles the rest. */
    mesh_builder_reserve(&P.b, size / 64 + 16, size / 48 + 16);

    const char *p = data, *end = data + size;
    if (size >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    long line = 0;
    scaf_status st = SCAF_OK;
    while (p < end && st == SCAF_OK) {
        line++;
        if ((line & 0xffff) == 0 && interrupt_pending()) { /* SIGINT / SIGTERM */
            st = interrupt_check(NULL, "reading the mesh", err);
            break;
        }
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        const char *s = scan_skip_blank(p, eol);
        p = eol + 1;
        if (s == eol || *s == '#') continue;
        const char *k = s;
        const char *ke = scan_token_end(k, eol);
        size_t kn = (size_t)(ke - k);
        if (kn == 1 && k[0] == 'v') st = obj_vertex(&P, line, ke, eol);
        else if (kn == 1 && k[0] == 'f') st = obj_face(&P, line, ke, eol);
        else if (kn == 2 && k[0] == 'v' && k[1] == 't') st = obj_texcoord(&P, line, ke, eol);
        else if (kn == 2 && k[0] == 'v' && k[1] == 'n') P.normals++;
        else if (!obj_is_ignored(k, kn)) {
            char tok[64];
            st = mesh_parse_fail(err, name, line, "unknown statement '%s'",
                                 mesh_quote_token(k, eol, tok, sizeof tok));
        }
    }
    if (st == SCAF_OK && P.b.nf == 0)
        st = mesh_parse_fail(err, name, line > 0 ? line : 1, "no faces (empty mesh)");
    if (st == SCAF_OK && P.max_v > (long long)P.b.nv)
        st = mesh_parse_fail(err, name, P.max_v_line,
                             "vertex index %lld out of range (the file has %zu vertices)", P.max_v,
                             P.b.nv);
    if (st == SCAF_OK && P.max_t > (long long)P.b.nuv)
        st = mesh_parse_fail(err, name, P.max_t_line,
                             "texture index %lld out of range (the file has %zu vt)", P.max_t,
                             P.b.nuv);
    free(P.cv);
    free(P.ct);
    if (st != SCAF_OK) {
        mesh_builder_free(&P.b);
        return st;
    }
    info->format = MESH_FORMAT_OBJ;
    info->polygons_triangulated = clamp_int(P.polygons);
    info->normals_ignored = clamp_int(P.normals);
    int keep_uv = P.with_uv > 0 && P.without_uv == 0;
    info->faces_without_uv = P.with_uv > 0 ? clamp_int(P.without_uv) : 0;
    if (keep_uv) info->uv_source = "OBJ vt";
    return mesh_builder_finish(&P.b, keep_uv, m, err);
}
