/* mesh/obj_rewrite: the input OBJ with new texture coordinates (see obj_rewrite.h). */
#include "mesh/obj_rewrite.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "mesh/mesh_io.h"
#include "mesh/text_scan.h"
#include "scaf/scaf.h"

/* One corner of an `f` line: its vertex and normal tokens as written. */
typedef struct corner {
    const char *v, *n; /* token starts (n NULL: no normal) */
    int vlen, nlen;
    int vertex; /* resolved 0-based vertex index */
} corner;

typedef struct rewriter {
    const char *name;
    const mesh *m;
    FILE *f;
    const char *eol; /* "\n" or "\r\n" */
    corner *c;
    size_t ccap;
    char *line; /* an output line being built */
    size_t linecap;
    long long nv_seen; /* `v` lines so far (relative indices) */
    int face;          /* next face of m */
    int vt_written;
    const int *group; /* nf face groups written as `g chart_N`, or NULL */
} rewriter;

/* Parse the vertex index of token [s, e) (up to the first '/'). */
static int corner_vertex(const char *s, const char *e, long long nv_seen, int *out)
{
    long long v;
    const char *p = s;
    if (scan_long(&p, e, '/', -(long long)INT_MAX, INT_MAX, &v) != SCAN_OK || v == 0) return 0;
    long long a = v < 0 ? nv_seen + v : v - 1;
    if (a < 0 || a > INT_MAX) return 0;
    *out = (int)a;
    return 1;
}

static int write_vt_block(rewriter *R)
{
    char line[96];
    size_t le = strlen(R->eol);
    int digits = 15; /* what the last number needed (text_scan.h) */
    for (int i = 0; i < R->m->nuv; i++) {
        memcpy(line, "vt ", 3);
        size_t n = 3;
        n += (size_t)scan_format_double_hint(line + n, 40, R->m->UV[2 * (size_t)i], &digits);
        line[n++] = ' ';
        n += (size_t)scan_format_double_hint(line + n, 40, R->m->UV[2 * (size_t)i + 1], &digits);
        memcpy(line + n, R->eol, le);
        if (fwrite(line, 1, n + le, R->f) != n + le) return -1;
    }
    R->vt_written = 1;
    return 0;
}

/* Decimal digits of v >= 0 at p; returns the count. */
static size_t put_uint(char *p, unsigned v)
{
    char t[12];
    size_t n = 0;
    do {
        t[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    for (size_t i = 0; i < n; i++) p[i] = t[n - 1 - i];
    return n;
}

/* Rewrite one `f` line (s: after the keyword, e: end of line content). */
static scaf_status rewrite_face(rewriter *R, long line, const char *s, const char *e,
                                scaf_error *err)
{
    size_t n = 0;
    for (;;) {
        s = scan_skip_blank(s, e);
        if (s == e || *s == '#') break;
        const char *t = scan_token_end(s, e);
        if (n == R->ccap) {
            size_t cap = R->ccap ? 2 * R->ccap : 16;
            corner *c = realloc(R->c, cap * sizeof *c);
            if (!c) return err_nomem(err, "face corners");
            R->c = c;
            R->ccap = cap;
        }
        corner *c = &R->c[n++];
        memset(c, 0, sizeof *c);
        c->v = s;
        const char *slash = memchr(s, '/', (size_t)(t - s));
        c->vlen = (int)((slash ? slash : t) - s);
        if (!corner_vertex(s, slash ? slash : t, R->nv_seen, &c->vertex))
            return err_set(err, SCAF_ERR_MESH,
                           "%s:%ld: bad face corner (the file changed since it was read?)", R->name,
                           line);
        if (slash) {
            const char *slash2 = memchr(slash + 1, '/', (size_t)(t - slash - 1));
            if (slash2 && slash2 + 1 < t) {
                c->n = slash2 + 1;
                c->nlen = (int)(t - c->n);
            }
        }
        s = t;
    }
    if (n < 3)
        return err_set(err, SCAF_ERR_MESH,
                       "%s:%ld: face with %zu corners (the file changed since it was read?)",
                       R->name, line, n);
    for (size_t i = 1; i + 1 < n; i++) {
        const corner *tri[3] = {&R->c[0], &R->c[i], &R->c[i + 1]};
        int fi = R->face;
        if (fi >= R->m->nf)
            return err_set(err, SCAF_ERR_MESH, "%s:%ld: more faces than the mesh read from it (%d)",
                           R->name, line, R->m->nf);
        for (int j = 0; j < 3; j++)
            if (tri[j]->vertex != R->m->F[3 * (size_t)fi + j])
                return err_set(err, SCAF_ERR_MESH,
                               "%s:%ld: face %d does not match the mesh read from it (the file "
                               "changed?)",
                               R->name, line, fi + 1);
        /* the line built by hand and written at once: fprintf's "%.*s"
         * per corner was most of the 3.2 s that 1.77M faces took */
        size_t need = 1 + 2;
        for (int j = 0; j < 3; j++) need += 15 + (size_t)tri[j]->vlen + (size_t)tri[j]->nlen;
        if (need > R->linecap) {
            char *l = realloc(R->line, need);
            if (!l) return err_nomem(err, "face line");
            R->line = l;
            R->linecap = need;
        }
        const int *g = R->group;
        if (g && (fi == 0 || g[fi] != g[fi - 1]) &&
            fprintf(R->f, "g chart_%d%s", g[fi], R->eol) < 0)
            return err_set(err, SCAF_ERR_IO, "write failed");
        char *o = R->line;
        *o++ = 'f';
        for (int j = 0; j < 3; j++) {
            *o++ = ' ';
            memcpy(o, tri[j]->v, (size_t)tri[j]->vlen);
            o += tri[j]->vlen;
            *o++ = '/';
            o += put_uint(o, (unsigned)R->m->FT[3 * (size_t)fi + j] + 1u);
            if (tri[j]->n) {
                *o++ = '/';
                memcpy(o, tri[j]->n, (size_t)tri[j]->nlen);
                o += tri[j]->nlen;
            }
        }
        for (const char *q = R->eol; *q; q++) *o++ = *q;
        size_t len = (size_t)(o - R->line);
        if (fwrite(R->line, 1, len, R->f) != len) return err_set(err, SCAF_ERR_IO, "write failed");
        R->face++;
    }
    return SCAF_OK;
}

static scaf_status rewrite(rewriter *R, const char *data, size_t size, scaf_error *err)
{
    const char *p = data, *end = data + size;
    const char *nl = memchr(p, '\n', size);
    R->eol = nl && nl > p && nl[-1] == '\r' ? "\r\n" : "\n";
    if (size >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0) {
        if (fwrite(p, 1, 3, R->f) != 3) return err_set(err, SCAF_ERR_IO, "write failed");
        p += 3;
    }
    if (fprintf(R->f, "# texture coordinates by scaf %s; everything else as in the input%s",
                scaf_version(), R->eol) < 0)
        return err_set(err, SCAF_ERR_IO, "write failed");
    long line = 0;
    while (p < end) {
        line++;
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        const char *next = eol ? eol + 1 : end;
        const char *content_end = eol ? eol : end;
        if (content_end > p && content_end[-1] == '\r') content_end--;
        const char *k = scan_skip_blank(p, content_end);
        const char *ke = scan_token_end(k, content_end);
        size_t kn = (size_t)(ke - k);
        if (kn == 2 && k[0] == 'v' && k[1] == 't') {
            /* old texture coordinate: dropped */
        } else if (kn == 1 && k[0] == 'g' && R->group) {
            /* the input's groups give way to the charts' */
        } else if (kn == 1 && k[0] == 'f') {
            if (!R->vt_written && write_vt_block(R) != 0)
                return err_set(err, SCAF_ERR_IO, "write failed");
            scaf_status st = rewrite_face(R, line, ke, content_end, err);
            if (st != SCAF_OK) return st;
        } else {
            if (kn == 1 && k[0] == 'v') R->nv_seen++;
            if (fwrite(p, 1, (size_t)(next - p), R->f) != (size_t)(next - p))
                return err_set(err, SCAF_ERR_IO, "write failed");
        }
        p = next;
    }
    if (R->face != R->m->nf)
        return err_set(err, SCAF_ERR_MESH,
                       "%s: %d faces, the mesh read from it has %d (the file changed?)", R->name,
                       R->face, R->m->nf);
    return SCAF_OK;
}

/* Both entry points: checks, then the text rewritten into out_path. */
static scaf_status rewrite_text(const char *name, const char *data, size_t size,
                                const char *out_path, const mesh *m, const int *group,
                                scaf_error *err)
{
    atomic_file af;
    scaf_status st = atomic_open(&af, out_path, err);
    if (st != SCAF_OK) return st;
    static const size_t bufsize = 1 << 20;
    char *buf = malloc(bufsize);
    if (buf) setvbuf(af.f, buf, _IOFBF, bufsize);
    rewriter R = {.name = name, .m = m, .f = af.f, .group = group};
    st = rewrite(&R, data, size, err);
    if (st == SCAF_ERR_IO) err_set(err, SCAF_ERR_IO, "%s: cannot write (disk full?)", out_path);
    if (st == SCAF_OK) st = atomic_commit(&af, err);
    else atomic_abort(&af);
    free(buf);
    free(R.c);
    free(R.line);
    return st;
}

static scaf_status check_args(const char *out_path, const mesh *m, scaf_error *err)
{
    if (!out_path || !m || !m->F || !mesh_has_uv(m) || !m->UV)
        return err_set(err, SCAF_ERR_USAGE, "obj_rewrite_uv: missing path, faces or UVs");
    for (size_t k = 0; k < 3 * (size_t)m->nf; k++)
        if (m->FT[k] < 0 || m->FT[k] >= m->nuv)
            return err_set(err, SCAF_ERR_MESH, "obj_rewrite_uv: face %zu uses UV %d of %d", k / 3,
                           m->FT[k], m->nuv);
    return SCAF_OK;
}

scaf_status obj_rewrite_uv(const char *in_path, const char *out_path, const mesh *m,
                           scaf_error *err)
{
    return obj_rewrite_uv_grouped(in_path, out_path, m, NULL, err);
}

scaf_status obj_rewrite_uv_grouped(const char *in_path, const char *out_path, const mesh *m,
                                   const int *face_group, scaf_error *err)
{
    if (!in_path) return err_set(err, SCAF_ERR_USAGE, "obj_rewrite_uv: missing path, faces or UVs");
    scaf_status st = check_args(out_path, m, err);
    if (st != SCAF_OK) return st;
    char *data = NULL;
    size_t size = 0;
    st = mesh_load_file(in_path, &data, &size, err);
    if (st != SCAF_OK) return st;
    st = rewrite_text(in_path, data, size, out_path, m, face_group, err);
    free(data);
    return st;
}

scaf_status obj_rewrite_uv_text(const char *name, const char *data, size_t size,
                                const char *out_path, const mesh *m, scaf_error *err)
{
    if (!name || (!data && size))
        return err_set(err, SCAF_ERR_USAGE, "obj_rewrite_uv_text: no text");
    scaf_status st = check_args(out_path, m, err);
    if (st != SCAF_OK) return st;
    return obj_rewrite_uv_text_grouped(name, data, size, out_path, m, NULL, err);
}

scaf_status obj_rewrite_uv_text_grouped(const char *name, const char *data, size_t size,
                                        const char *out_path, const mesh *m, const int *face_group,
                                        scaf_error *err)
{
    if (!name || (!data && size))
        return err_set(err, SCAF_ERR_USAGE, "obj_rewrite_uv_text: no text");
    scaf_status st = check_args(out_path, m, err);
    if (st != SCAF_OK) return st;
    return rewrite_text(name, data ? data : "", size, out_path, m, face_group, err);
}
