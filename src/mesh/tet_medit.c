/* mesh/tet_medit: Medit .mesh reading and writing (see the header). */
#include "mesh/tet_medit.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "geom/simplex_arrays.h"
#include "mesh/text_scan.h"

/* ---- writing ---- */

static int write_body(FILE *f, int nv, const double *V, int nt, const int *T, const int *label)
{
    char a[40], b[40], c[40];
    int digits = 15; /* what the last number needed (text_scan.h) */
    if (fprintf(f, "MeshVersionFormatted 1\nDimension 3\nVertices\n%d\n", nv) < 0) return -1;
    for (int i = 0; i < nv; i++) {
        const double *v = V + 3 * (size_t)i;
        scan_format_double_hint(a, sizeof a, v[0], &digits);
        scan_format_double_hint(b, sizeof b, v[1], &digits);
        scan_format_double_hint(c, sizeof c, v[2], &digits);
        if (fprintf(f, "%s %s %s 0\n", a, b, c) < 0) return -1;
    }
    if (fprintf(f, "Tetrahedra\n%d\n", nt) < 0) return -1;
    for (int t = 0; t < nt; t++) {
        const int *q = T + 4 * (size_t)t;
        if (fprintf(f, "%d %d %d %d %d\n", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1,
                    label ? label[t] : 0) < 0)
            return -1;
    }
    if (fprintf(f, "End\n") < 0) return -1;
    return ferror(f) ? -1 : 0;
}

scaf_status tet_medit_write(const char *path, int nv, const double *V, int nt, const int *T,
                            const int *label, scaf_error *err)
{
    scaf_status s = simplex_arrays_check(nv, V, nt, T, 4, "tet", err);
    if (s) return s;
    atomic_file a;
    s = atomic_open(&a, path, err);
    if (s) return s;
    if (write_body(a.f, nv, V, nt, T, label) != 0) {
        atomic_abort(&a);
        return err_set(err, SCAF_ERR_IO, "%s: write failed: %s", path, strerror(errno));
    }
    return atomic_commit(&a, err);
}

/* ---- reading ---- */

typedef struct reader {
    FILE *f;
    const char *path;
    int line;
    char tok[128];
} reader;

/* Next whitespace-separated token outside # comments; 0 at end of file. */
static int next_token(reader *r)
{
    int c;
    for (;;) {
        c = getc(r->f);
        if (c == EOF) return 0;
        if (c == '\n') r->line++;
        if (c == '#') {
            while ((c = getc(r->f)) != EOF && c != '\n') {}
            if (c == EOF) return 0;
            r->line++;
            continue;
        }
        if (!scan_is_space((char)c)) break;
    }
    size_t n = 0;
    while (c != EOF && !scan_is_space((char)c)) {
        if (n + 1 < sizeof r->tok) r->tok[n++] = (char)c;
        c = getc(r->f);
    }
    if (c == '\n') ungetc(c, r->f);
    r->tok[n] = '\0';
    return 1;
}

static scaf_status read_int(reader *r, long lo, long hi, const char *what, long *out,
                            scaf_error *err)
{
    if (!next_token(r))
        return err_set(err, SCAF_ERR_PARSE, "%s:%d: end of file where %s was expected", r->path,
                       r->line, what);
    char *end;
    errno = 0;
    long v = strtol(r->tok, &end, 10);
    if (errno || *end || end == r->tok || v < lo || v > hi)
        return err_set(err, SCAF_ERR_PARSE, "%s:%d: '%s' is not %s (an integer in %ld..%ld)",
                       r->path, r->line, r->tok, what, lo, hi);
    *out = v;
    return SCAF_OK;
}

static scaf_status read_double(reader *r, const char *what, double *out, scaf_error *err)
{
    if (!next_token(r))
        return err_set(err, SCAF_ERR_PARSE, "%s:%d: end of file where %s was expected", r->path,
                       r->line, what);
    char *end;
    double v = strtod(r->tok, &end);
    if (*end || end == r->tok || !isfinite(v))
        return err_set(err, SCAF_ERR_PARSE, "%s:%d: '%s' is not a finite number (%s)", r->path,
                       r->line, r->tok, what);
    *out = v;
    return SCAF_OK;
}

/* Skip a section of count entries of per tokens each. */
static scaf_status skip_section(reader *r, int per, scaf_error *err)
{
    long n;
    scaf_status s = read_int(r, 0, INT_MAX, "an entry count", &n, err);
    for (long i = 0; s == SCAF_OK && i < n * per; i++)
        if (!next_token(r))
            s = err_set(err, SCAF_ERR_PARSE, "%s:%d: the file ends inside a section", r->path,
                        r->line);
    return s;
}

static scaf_status read_body(reader *r, tet_medit *m, scaf_error *err)
{
    scaf_status s = SCAF_OK;
    int seen_v = 0, seen_t = 0, ended = 0;
    while (s == SCAF_OK && !ended && next_token(r)) {
        long n, x;
        if (!strcmp(r->tok, "MeshVersionFormatted")) {
            s = read_int(r, 1, 2, "the format version (1 or 2)", &x, err);
        } else if (!strcmp(r->tok, "Dimension")) {
            s = read_int(r, 3, 3, "the dimension (3)", &x, err);
        } else if (!strcmp(r->tok, "Vertices")) {
            if (seen_v++)
                return err_set(err, SCAF_ERR_PARSE, "%s:%d: a second Vertices section", r->path,
                               r->line);
            s = read_int(r, 0, INT_MAX / 3, "the number of vertices", &n, err);
            if (s) break;
            m->nv = (int)n;
            m->V = malloc(sizeof(double) * 3 * (size_t)(n > 0 ? n : 1));
            if (!m->V) return err_nomem(err, "tet mesh vertices");
            for (long i = 0; s == SCAF_OK && i < n; i++) {
                for (int k = 0; s == SCAF_OK && k < 3; k++)
                    s = read_double(r, "a vertex coordinate", &m->V[3 * i + k], err);
                if (s == SCAF_OK)
                    s = read_int(r, LONG_MIN, LONG_MAX, "a vertex reference", &x, err);
            }
        } else if (!strcmp(r->tok, "Tetrahedra")) {
            if (seen_t++)
                return err_set(err, SCAF_ERR_PARSE, "%s:%d: a second Tetrahedra section", r->path,
                               r->line);
            if (!seen_v)
                return err_set(err, SCAF_ERR_PARSE, "%s:%d: Tetrahedra before Vertices", r->path,
                               r->line);
            s = read_int(r, 0, INT_MAX / 4, "the number of tetrahedra", &n, err);
            if (s) break;
            m->nt = (int)n;
            m->T = malloc(sizeof(int) * 4 * (size_t)(n > 0 ? n : 1));
            m->label = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
            if (!m->T || !m->label) return err_nomem(err, "tetrahedra");
            for (long t = 0; s == SCAF_OK && t < n; t++) {
                for (int k = 0; s == SCAF_OK && k < 4; k++) {
                    s = read_int(r, 1, m->nv, "a vertex index", &x, err);
                    m->T[4 * t + k] = (int)x - 1;
                }
                if (s == SCAF_OK) s = read_int(r, INT_MIN, INT_MAX, "a tet reference", &x, err);
                m->label[t] = (int)x;
            }
        } else if (!strcmp(r->tok, "Triangles")) {
            s = skip_section(r, 4, err);
        } else if (!strcmp(r->tok, "Quadrilaterals")) {
            s = skip_section(r, 5, err);
        } else if (!strcmp(r->tok, "Edges") || !strcmp(r->tok, "Ridges") ||
                   !strcmp(r->tok, "Corners") || !strcmp(r->tok, "RequiredVertices")) {
            s = skip_section(r, !strcmp(r->tok, "Edges") ? 3 : 1, err);
        } else if (!strcmp(r->tok, "End")) {
            ended = 1;
        } else {
            return err_set(err, SCAF_ERR_PARSE, "%s:%d: unsupported keyword '%s'", r->path, r->line,
                           r->tok);
        }
    }
    if (s == SCAF_OK && !seen_t)
        s = err_set(err, SCAF_ERR_PARSE, "%s: no Tetrahedra section: not a tetrahedral mesh",
                    r->path);
    return s;
}

scaf_status tet_medit_read(const char *path, tet_medit *m, scaf_error *err)
{
    memset(m, 0, sizeof *m);
    reader r = {fopen(path, "r"), path, 1, {0}};
    if (!r.f) return err_set(err, SCAF_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    scaf_status s = read_body(&r, m, err);
    if (s == SCAF_OK && ferror(r.f)) s = err_set(err, SCAF_ERR_IO, "%s: read error", path);
    fclose(r.f);
    if (s) tet_medit_free(m);
    return s;
}

void tet_medit_free(tet_medit *m)
{
    free(m->V);
    free(m->T);
    free(m->label);
    memset(m, 0, sizeof *m);
}
