/* mesh/read_ply: PLY parser (ascii, binary little and big endian).
 *
 * The header declares elements and their properties. We take x, y, z of
 * the `vertex` element (any numeric type; other vertex properties, lists
 * included, are skipped) and the `vertex_indices` (or `vertex_index`) list
 * of the `face` element (any integer count and index type; polygons are
 * fan-triangulated; other face properties skipped). Every other element is
 * skipped item by item with its declared layout, so binary files stay in
 * step. Header lines may end in CRLF; `comment` and `obj_info` are ignored.
 *
 * Before reading the body, every element count is checked against the
 * bytes that follow (each binary item has a known minimum size, each ascii
 * value needs at least two bytes), so an absurd count is a "truncated file"
 * error instead of a huge allocation. Errors (SCAF_ERR_PARSE, "NAME:LINE:
 * reason"; in binary bodies LINE is the end_header line and the reason
 * names the element, item and byte offset): unknown format or type, missing
 * x/y/z or face list, truncated data, non-finite coordinate, index out of
 * range, face with fewer than 3 corners or a repeated vertex, no faces.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"
#include "mesh/mesh_builder.h"
#include "mesh/mesh_readers.h"
#include "mesh/text_scan.h"
#include "mesh/uv_weld.h"

typedef enum ply_type {
    PT_NONE,
    PT_I8,
    PT_U8,
    PT_I16,
    PT_U16,
    PT_I32,
    PT_U32,
    PT_F32,
    PT_F64
} ply_type;

static const struct {
    const char *a, *b;
    ply_type t;
    int size;
} ply_types[] = {{"char", "int8", PT_I8, 1},      {"uchar", "uint8", PT_U8, 1},
                 {"short", "int16", PT_I16, 2},   {"ushort", "uint16", PT_U16, 2},
                 {"int", "int32", PT_I32, 4},     {"uint", "uint32", PT_U32, 4},
                 {"float", "float32", PT_F32, 4}, {"double", "float64", PT_F64, 8}};

static int type_size(ply_type t) { return t == PT_NONE ? 0 : ply_types[t - 1].size; }
static int type_is_int(ply_type t) { return t >= PT_I8 && t <= PT_U32; }

typedef enum ply_role {
    ROLE_SKIP,
    ROLE_X,
    ROLE_Y,
    ROLE_Z,
    ROLE_INDICES,
    ROLE_U,       /* vertex s / u / texture_u / texture_s */
    ROLE_V,       /* vertex t / v / texture_v / texture_t */
    ROLE_TEXCOORD /* face list texcoord: u v per corner */
} ply_role;

/* The names of a per-vertex UV pair, in the order they are looked for. */
static const char *const uv_names[][2] = {
    {"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};

typedef struct ply_prop {
    ply_type type;       /* scalar type, or list item type */
    ply_type count_type; /* PT_NONE for a scalar */
    ply_role role;
} ply_prop;

typedef struct ply_elem {
    char name[32];
    long long count;
    ply_prop *props;
    int nprops, cap;
    int is_vertex, is_face;
} ply_elem;

typedef enum ply_format { PLY_ASCII, PLY_LE, PLY_BE } ply_format;

/* Body reader state. */
typedef struct ply_reader {
    const char *p, *end, *body;
    ply_format fmt;
    long line; /* ascii: current line; binary: the end_header line */
    const char *name;
    scaf_error *err;
} ply_reader;

static int host_is_le(void)
{
    const uint16_t one = 1;
    unsigned char c;
    memcpy(&c, &one, 1);
    return c == 1;
}

/* Binary scalar at R->p as double (exact for every PLY type). */
static void bin_decode(const ply_reader *R, ply_type t, int swap, double *d, long long *i)
{
    unsigned char b[8];
    int n = type_size(t);
    memcpy(b, R->p, (size_t)n);
    if (swap)
        for (int k = 0; k < n / 2; k++) {
            unsigned char x = b[k];
            b[k] = b[n - 1 - k];
            b[n - 1 - k] = x;
        }
    long long iv = 0;
    double dv = 0;
    switch (t) {
    case PT_I8: {
        int8_t v;
        memcpy(&v, b, 1);
        iv = v;
        dv = v;
        break;
    }
    case PT_U8: {
        uint8_t v;
        memcpy(&v, b, 1);
        iv = v;
        dv = v;
        break;
    }
    case PT_I16: {
        int16_t v;
        memcpy(&v, b, 2);
        iv = v;
        dv = v;
        break;
    }
    case PT_U16: {
        uint16_t v;
        memcpy(&v, b, 2);
        iv = v;
        dv = v;
        break;
    }
    case PT_I32: {
        int32_t v;
        memcpy(&v, b, 4);
        iv = v;
        dv = v;
        break;
    }
    case PT_U32: {
        uint32_t v;
        memcpy(&v, b, 4);
        iv = v;
        dv = v;
        break;
    }
    case PT_F32: {
        float v;
        memcpy(&v, b, 4);
        dv = v;
        iv = 0;
        break;
    }
    case PT_F64: {
        double v;
        memcpy(&v, b, 8);
        dv = v;
        iv = 0;
        break;
    }
    default: break;
    }
    if (d) *d = dv;
    if (i) *i = iv;
}

/* Skip blanks and newlines in an ascii body (counting lines). */
static void ascii_skip(ply_reader *R)
{
    while (R->p < R->end && scan_is_space(*R->p)) {
        if (*R->p == '\n') R->line++;
        R->p++;
    }
}

static scaf_status ply_truncated(ply_reader *R, const char *what, long long item)
{
    if (R->fmt == PLY_ASCII)
        return mesh_parse_fail(R->err, R->name, R->line, "truncated file: %s %lld is incomplete",
                               what, item);
    return mesh_parse_fail(R->err, R->name, R->line,
                           "truncated binary data: %s %lld is incomplete (byte %zu)", what, item,
                           (size_t)(R->p - R->body));
}

/* Read one value of type t. want_int: must be an integer (list counts and
 * indices); d receives it as a double otherwise. */
static scaf_status ply_value(ply_reader *R, ply_type t, int want_int, double *d, long long *i,
                             const char *what, long long item)
{
    if (R->fmt != PLY_ASCII) {
        int n = type_size(t);
        if (R->end - R->p < n) return ply_truncated(R, what, item);
        bin_decode(R, t, (R->fmt == PLY_LE) != host_is_le(), d, i);
        R->p += n;
        return SCAF_OK;
    }
    ascii_skip(R);
    if (R->p >= R->end) return ply_truncated(R, what, item);
    const char *t0 = R->p;
    scan_result r;
    if (want_int) {
        r = scan_long(&R->p, R->end, 0, -(1LL << 62), 1LL << 62, i);
    } else if (d) {
        r = scan_double(&R->p, R->end, d);
    } else {
        R->p = scan_token_end(R->p, R->end);
        r = SCAN_OK;
    }
    if (r != SCAN_OK) {
        char tok[64];
        mesh_quote_token(t0, R->end, tok, sizeof tok);
        return mesh_parse_fail(R->err, R->name, R->line, "%s %lld: '%s' is not %s", what, item, tok,
                               want_int                  ? "an integer in range"
                                   : r == SCAN_NONFINITE ? "a finite number"
                                                         : "a number");
    }
    return SCAF_OK;
}

/* Skip a property (scalar or list) of one item. */
static scaf_status ply_skip_prop(ply_reader *R, const ply_prop *pr, const char *what,
                                 long long item)
{
    scaf_status st;
    if (pr->count_type == PT_NONE) return ply_value(R, pr->type, 0, NULL, NULL, what, item);
    long long n;
    if ((st = ply_value(R, pr->count_type, 1, NULL, &n, what, item))) return st;
    if (n < 0)
        return mesh_parse_fail(R->err, R->name, R->line, "%s %lld: negative list length %lld", what,
                               item, n);
    if (R->fmt != PLY_ASCII) {
        long long bytes = n * type_size(pr->type);
        if (R->end - R->p < bytes) return ply_truncated(R, what, item);
        R->p += bytes;
        return SCAF_OK;
    }
    for (long long k = 0; k < n; k++)
        if ((st = ply_value(R, pr->type, 0, NULL, NULL, what, item))) return st;
    return SCAF_OK;
}

/* One header line [s, e) (CR stripped) split at blanks into up to 5 words. */
static int split_words(const char *s, const char *e, const char *w[5], size_t wl[5])
{
    int n = 0;
    for (;;) {
        s = scan_skip_blank(s, e);
        if (s >= e) break;
        const char *t = s;
        while (t < e && !scan_is_blank(*t)) t++;
        if (n == 5) return 6;
        w[n] = s;
        wl[n] = (size_t)(t - s);
        n++;
        s = t;
    }
    return n;
}

static int word_is(const char *w, size_t n, const char *lit)
{
    return strlen(lit) == n && memcmp(w, lit, n) == 0;
}

static ply_type parse_type(const char *w, size_t n)
{
    for (size_t k = 0; k < sizeof ply_types / sizeof *ply_types; k++)
        if (word_is(w, n, ply_types[k].a) || word_is(w, n, ply_types[k].b)) return ply_types[k].t;
    return PT_NONE;
}

typedef struct ply_header {
    ply_elem *elems;
    int nelems, cap;
    ply_format fmt;
    long end_line; /* line of end_header */
    const char *body;
} ply_header;

static void header_free(ply_header *h)
{
    for (int k = 0; k < h->nelems; k++) free(h->elems[k].props);
    free(h->elems);
}

static scaf_status parse_header(const char *data, size_t size, const char *name, ply_header *h,
                                scaf_error *err)
{
    const char *p = data, *end = data + size;
    long line = 0;
    int have_format = 0;
    char tok[64];
    while (p < end) {
        line++;
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        const char *e = eol;
        if (e > p && e[-1] == '\r') e--;
        const char *next = eol < end ? eol + 1 : end;
        const char *w[5];
        size_t wl[5];
        int nw = split_words(p, e, w, wl);
        if (line == 1) {
            if (nw != 1 || !word_is(w[0], wl[0], "ply"))
                return mesh_parse_fail(err, name, line,
                                       "not a PLY file (first line must be 'ply')");
        } else if (nw == 0) {
            /* tolerate blank header lines */
        } else if (word_is(w[0], wl[0], "comment") || word_is(w[0], wl[0], "obj_info")) {
            /* ignored */
        } else if (word_is(w[0], wl[0], "format")) {
            if (nw != 3)
                return mesh_parse_fail(err, name, line, "format line needs a format and a version");
            if (word_is(w[1], wl[1], "ascii")) h->fmt = PLY_ASCII;
            else if (word_is(w[1], wl[1], "binary_little_endian")) h->fmt = PLY_LE;
            else if (word_is(w[1], wl[1], "binary_big_endian")) h->fmt = PLY_BE;
            else
                return mesh_parse_fail(err, name, line, "unknown PLY format '%s'",
                                       mesh_quote_token(w[1], e, tok, sizeof tok));
            have_format = 1;
        } else if (word_is(w[0], wl[0], "element")) {
            if (nw != 3)
                return mesh_parse_fail(err, name, line, "element line needs a name and a count");
            const char *c = w[2];
            long long count;
            if (scan_long(&c, w[2] + wl[2], 0, 0, 1LL << 62, &count) != SCAN_OK)
                return mesh_parse_fail(err, name, line, "bad element count '%s'",
                                       mesh_quote_token(w[2], e, tok, sizeof tok));
            if (h->nelems == h->cap) {
                int cap = h->cap ? 2 * h->cap : 4;
                ply_elem *a = realloc(h->elems, (size_t)cap * sizeof *a);
                if (!a) return err_nomem(err, "PLY header");
                h->elems = a;
                h->cap = cap;
            }
            ply_elem *el = &h->elems[h->nelems++];
            memset(el, 0, sizeof *el);
            snprintf(el->name, sizeof el->name, "%.*s", (int)(wl[1] < 31 ? wl[1] : 31), w[1]);
            el->count = count;
            el->is_vertex = word_is(w[1], wl[1], "vertex");
            el->is_face = word_is(w[1], wl[1], "face");
        } else if (word_is(w[0], wl[0], "property")) {
            if (h->nelems == 0)
                return mesh_parse_fail(err, name, line, "property before any element");
            ply_elem *el = &h->elems[h->nelems - 1];
            ply_prop pr = {PT_NONE, PT_NONE, ROLE_SKIP};
            const char *pname;
            size_t pnl;
            if (nw == 5 && word_is(w[1], wl[1], "list")) {
                pr.count_type = parse_type(w[2], wl[2]);
                pr.type = parse_type(w[3], wl[3]);
                if (pr.count_type == PT_NONE || pr.type == PT_NONE)
                    return mesh_parse_fail(err, name, line, "unknown PLY type '%s'",
                                           mesh_quote_token(pr.count_type == PT_NONE ? w[2] : w[3],
                                                            e, tok, sizeof tok));
                if (!type_is_int(pr.count_type))
                    return mesh_parse_fail(err, name, line,
                                           "list count type must be an integer type");
                pname = w[4];
                pnl = wl[4];
            } else if (nw == 3) {
                pr.type = parse_type(w[1], wl[1]);
                if (pr.type == PT_NONE)
                    return mesh_parse_fail(err, name, line, "unknown PLY type '%s'",
                                           mesh_quote_token(w[1], e, tok, sizeof tok));
                pname = w[2];
                pnl = wl[2];
            } else {
                return mesh_parse_fail(err, name, line, "malformed property line");
            }
            if (el->is_vertex && pr.count_type == PT_NONE) {
                if (word_is(pname, pnl, "x")) pr.role = ROLE_X;
                else if (word_is(pname, pnl, "y")) pr.role = ROLE_Y;
                else if (word_is(pname, pnl, "z")) pr.role = ROLE_Z;
                for (size_t q = 0; q < sizeof uv_names / sizeof uv_names[0]; q++) {
                    if (word_is(pname, pnl, uv_names[q][0])) pr.role = ROLE_U;
                    if (word_is(pname, pnl, uv_names[q][1])) pr.role = ROLE_V;
                }
                /* a second UV pair (u,v besides s,t) is skipped: the first one counts */
                for (int k = 0; (pr.role == ROLE_U || pr.role == ROLE_V) && k < el->nprops; k++)
                    if (el->props[k].role == pr.role) pr.role = ROLE_SKIP;
            }
            if (el->is_face && pr.count_type != PT_NONE && word_is(pname, pnl, "texcoord"))
                pr.role = ROLE_TEXCOORD;
            if (el->is_face && pr.count_type != PT_NONE &&
                (word_is(pname, pnl, "vertex_indices") || word_is(pname, pnl, "vertex_index"))) {
                if (!type_is_int(pr.type))
                    return mesh_parse_fail(err, name, line,
                                           "face indices must have an integer type");
                pr.role = ROLE_INDICES;
            }
            for (int k = 0; pr.role != ROLE_SKIP && k < el->nprops; k++)
                if (el->props[k].role == pr.role)
                    return mesh_parse_fail(err, name, line, "property declared twice");
            if (el->nprops == el->cap) {
                int cap = el->cap ? 2 * el->cap : 8;
                ply_prop *a = realloc(el->props, (size_t)cap * sizeof *a);
                if (!a) return err_nomem(err, "PLY header");
                el->props = a;
                el->cap = cap;
            }
            el->props[el->nprops++] = pr;
        } else if (word_is(w[0], wl[0], "end_header")) {
            if (!have_format)
                return mesh_parse_fail(err, name, line, "no format line before end_header");
            h->end_line = line;
            h->body = next;
            return SCAF_OK;
        } else {
            return mesh_parse_fail(err, name, line, "unknown header line '%s'",
                                   mesh_quote_token(w[0], e, tok, sizeof tok));
        }
        p = next;
    }
    return mesh_parse_fail(err, name, line > 0 ? line : 1, "truncated header (no end_header)");
}

/* Smallest number of bytes one item of el can take. */
static long long min_item_bytes(const ply_elem *el, ply_format fmt)
{
    long long s = 0;
    for (int k = 0; k < el->nprops; k++) {
        if (fmt == PLY_ASCII) s += 2;
        else
            s += type_size(el->props[k].count_type != PT_NONE ? el->props[k].count_type
                                                              : el->props[k].type);
    }
    return s;
}

/* The triangles of one face (corners[0..n), fanned), with its texcoord
 * list tc (2 per corner, ntc values) when not NULL, or per-vertex UV
 * indices (the builder's UVs are the vertices') when the builder has FT. */
static scaf_status emit_face(mesh_builder *b, const int *corners, long long n, const double *tc,
                             long long ntc, const char *name, long line, long long it,
                             scaf_error *err)
{
    if (n < 0) return mesh_parse_fail(err, name, line, "face %lld has no vertex_indices list", it);
    int base = (int)b->nuv;
    if (tc) {
        if (ntc != 2 * n)
            return mesh_parse_fail(err, name, line,
                                   "face %lld: texcoord list has %lld values for %lld corners "
                                   "(needs 2 per corner: u v)",
                                   it, ntc < 0 ? 0 : ntc, n);
        for (long long j = 0; j < n; j++)
            if (mesh_builder_add_uv(b, tc[2 * j], tc[2 * j + 1]))
                return err_nomem(err, "texture coordinates");
    }
    for (long long j = 1; j + 1 < n; j++) {
        int ta = corners[0], tb = corners[j], tcn = corners[j + 1];
        if (tc) {
            ta = base;
            tb = base + (int)j;
            tcn = base + (int)j + 1;
        }
        if (mesh_builder_add_f(b, corners[0], corners[j], corners[j + 1], ta, tb, tcn))
            return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory (or more than INT_MAX faces)",
                           name);
    }
    return SCAF_OK;
}

scaf_status mesh_parse_ply(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err)
{
    ply_header h;
    memset(&h, 0, sizeof h);
    mesh_builder b;
    mesh_builder_init(&b, 0);
    int *corners = NULL;
    size_t ccap = 0;
    double *tc = NULL; /* one face's texcoord list */
    size_t tcap = 0;
    int face_tc = 0, vertex_uv = 0; /* where the UVs come from */
    long long polygons = 0;
    scaf_status st = parse_header(data, size, name, &h, err);
    if (st) goto done;

    /* Find the vertex and face elements and check the counts fit the data. */
    ply_elem *ev = NULL, *ef = NULL;
    size_t rest = (size_t)(data + size - h.body);
    unsigned long long need = 0;
    for (int k = 0; k < h.nelems; k++) {
        ply_elem *el = &h.elems[k];
        if (el->is_vertex && !ev) ev = el;
        if (el->is_face && !ef) ef = el;
        long long mb = min_item_bytes(el, h.fmt);
        if (mb > 0 &&
            (unsigned long long)el->count >
                ((unsigned long long)rest + 1) / (unsigned long long)mb) {
            st = mesh_parse_fail(err, name, h.end_line,
                                 "header says %lld '%s' items but only %zu bytes follow (truncated "
                                 "file?)",
                                 el->count, el->name, rest);
            goto done;
        }
        need += (unsigned long long)el->count * (unsigned long long)mb;
        if (need > (unsigned long long)rest + 1) {
            st = mesh_parse_fail(err, name, h.end_line,
                                 "header element counts need more than the %zu bytes that follow "
                                 "(truncated file?)",
                                 rest);
            goto done;
        }
    }
    if (!ev) {
        st = mesh_parse_fail(err, name, h.end_line, "no 'vertex' element");
        goto done;
    }
    int roles = 0;
    for (int k = 0; k < ev->nprops; k++) roles |= 1 << ev->props[k].role;
    if ((roles & 14) != 14) {
        st = mesh_parse_fail(err, name, h.end_line, "vertex element lacks x, y or z");
        goto done;
    }
    if (ev->count > INT_MAX - 1) {
        st = mesh_parse_fail(err, name, h.end_line, "too many vertices (%lld)", ev->count);
        goto done;
    }
    int has_list = 0;
    if (ef)
        for (int k = 0; k < ef->nprops; k++) has_list |= ef->props[k].role == ROLE_INDICES;
    if (!ef || ef->count == 0) {
        st = mesh_parse_fail(err, name, h.end_line, "no faces (empty mesh)");
        goto done;
    }
    if (!has_list) {
        st = mesh_parse_fail(err, name, h.end_line, "face element lacks a 'vertex_indices' list");
        goto done;
    }
    /* UVs: a face texcoord list (per corner) wins over per-vertex u, v */
    vertex_uv = (roles & (1 << ROLE_U)) && (roles & (1 << ROLE_V));
    for (int k = 0; k < ef->nprops; k++) face_tc |= ef->props[k].role == ROLE_TEXCOORD;
    if (face_tc) vertex_uv = 0;
    b.with_ft = face_tc || vertex_uv;
    if (mesh_builder_reserve(&b, (size_t)ev->count, (size_t)ef->count)) {
        st = err_nomem(err, "mesh arrays");
        goto done;
    }

    ply_reader R = {h.body, data + size, h.body, h.fmt, h.end_line, name, err};
    if (h.fmt == PLY_ASCII) R.line = h.end_line + 1;
    const long long nv = ev->count;
    for (int k = 0; k < h.nelems && !st; k++) {
        ply_elem *el = &h.elems[k];
        const char *what = el == ev ? "vertex" : el == ef ? "face" : el->name;
        if (el->nprops == 0) continue; /* no data at all: never loop over its count */
        for (long long it = 0; it < el->count && !st; it++) {
            if ((it & 0xffff) == 0xffff && interrupt_pending()) { /* SIGINT / SIGTERM */
                st = interrupt_check(NULL, "reading the mesh", err);
                break;
            }
            double x[3] = {0, 0, 0}, t[2] = {0, 0};
            long long n = -1, ntc = -1; /* corners and texcoord values of this face */
            for (int q = 0; q < el->nprops && !st; q++) {
                const ply_prop *pr = &el->props[q];
                if (el == ev && pr->role >= ROLE_X && pr->role <= ROLE_Z) {
                    double *d = &x[pr->role - ROLE_X];
                    if ((st = ply_value(&R, pr->type, 0, d, NULL, what, it))) break;
                    if (!isfinite(*d))
                        st = mesh_parse_fail(err, name, R.line,
                                             "vertex %lld: coordinate is not finite", it);
                } else if (el == ev && vertex_uv && (pr->role == ROLE_U || pr->role == ROLE_V) &&
                           pr->count_type == PT_NONE) {
                    double *d = &t[pr->role - ROLE_U];
                    if ((st = ply_value(&R, pr->type, 0, d, NULL, what, it))) break;
                    if (!isfinite(*d))
                        st = mesh_parse_fail(err, name, R.line,
                                             "vertex %lld: texture coordinate is not finite", it);
                } else if (el == ef && pr->role == ROLE_TEXCOORD) {
                    if ((st = ply_value(&R, pr->count_type, 1, NULL, &ntc, what, it))) break;
                    size_t minb = h.fmt == PLY_ASCII ? 2 : (size_t)type_size(pr->type);
                    if (ntc < 0 || (unsigned long long)ntc > (size_t)(R.end - R.p) / minb + 1) {
                        st = ntc < 0 ? mesh_parse_fail(err, name, R.line,
                                                       "face %lld: negative texcoord count", it)
                                     : ply_truncated(&R, what, it);
                        break;
                    }
                    if ((size_t)ntc > tcap) {
                        size_t cap = (size_t)ntc < 16 ? 16 : (size_t)ntc;
                        double *a = realloc(tc, cap * sizeof *a);
                        if (!a) {
                            st = err_nomem(err, "face texture coordinates");
                            break;
                        }
                        tc = a;
                        tcap = cap;
                    }
                    for (long long j = 0; j < ntc && !st; j++) {
                        if ((st = ply_value(&R, pr->type, 0, &tc[j], NULL, what, it))) break;
                        if (!isfinite(tc[j]))
                            st = mesh_parse_fail(err, name, R.line,
                                                 "face %lld: texture coordinate is not finite", it);
                    }
                } else if (el == ef && pr->role == ROLE_INDICES) {
                    if ((st = ply_value(&R, pr->count_type, 1, NULL, &n, what, it))) break;
                    if (n < 3) {
                        st =
                            mesh_parse_fail(err, name, R.line,
                                            "face %lld has %lld corners (needs at least 3)", it, n);
                        break;
                    }
                    size_t minb = h.fmt == PLY_ASCII ? 2 : (size_t)type_size(pr->type);
                    if ((unsigned long long)n > (size_t)(R.end - R.p) / minb + 1) {
                        st = ply_truncated(&R, what, it);
                        break;
                    }
                    if ((size_t)n > ccap) {
                        size_t cap = (size_t)n < 16 ? 16 : (size_t)n;
                        int *a = realloc(corners, cap * sizeof *a);
                        if (!a) {
                            st = err_nomem(err, "face corners");
                            break;
                        }
                        corners = a;
                        ccap = cap;
                    }
                    for (long long j = 0; j < n && !st; j++) {
                        long long v;
                        if ((st = ply_value(&R, pr->type, 1, NULL, &v, what, it))) break;
                        if (v < 0 || v >= nv)
                            st = mesh_parse_fail(err, name, R.line,
                                                 "face %lld: vertex index %lld out of range (the "
                                                 "file has %lld vertices)",
                                                 it, v, nv);
                        else corners[j] = (int)v;
                    }
                    if (st) break;
                    int dup;
                    int rep = mesh_corners_repeat(corners, (size_t)n, &dup);
                    if (rep) {
                        st = rep < 0 ? err_nomem(err, "face corners")
                                     : mesh_parse_fail(err, name, R.line,
                                                       "face %lld uses vertex %d more than once "
                                                       "(degenerate face)",
                                                       it, dup);
                        break;
                    }
                } else {
                    st = ply_skip_prop(&R, pr, what, it);
                }
            }
            if (!st && el == ev) {
                mesh_builder_add_v(&b, x[0], x[1], x[2]); /* reserved */
                if (vertex_uv && mesh_builder_add_uv(&b, t[0], t[1]))
                    st = err_nomem(err, "texture coordinates");
            }
            if (!st && el == ef)
                st = emit_face(&b, corners, n, face_tc ? tc : NULL, ntc, name, R.line, it, err);
            if (!st && el == ef && n > 3) polygons++;
        }
    }
done:
    free(corners);
    free(tc);
    header_free(&h);
    if (st != SCAF_OK) {
        mesh_builder_free(&b);
        return st;
    }
    info->format = MESH_FORMAT_PLY;
    info->polygons_triangulated = polygons > INT_MAX ? INT_MAX : (int)polygons;
    info->uv_source = face_tc ? "PLY face texcoord" : vertex_uv ? "PLY vertex u, v" : NULL;
    st = mesh_builder_finish(&b, b.with_ft, m, err);
    if (st == SCAF_OK && face_tc) st = uv_weld_corners(m, err); /* corners of a vertex joined */
    if (st != SCAF_OK) mesh_free(m);
    return st;
}
