/* tools/deform_targets: the handle file of `scaf deform` (see deform_targets.h). */
#include "deform_targets.h"

#include <ctype.h>
#include <stdint.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/interrupt.h"

/* Path points read between two looks for a pending signal (SIGINT,
 * SIGTERM: a long file stops within a few microseconds). */
#define POINTS_PER_INTERRUPT_CHECK 4096

/* Paths are read per handle, then laid out frame-major at the end. */
typedef struct reader {
    const char *s, *path;
    int line;
    int cap;
    double *paths; /* cap by path_len by 2, handle-major */
    int path_len;  /* -1 until the first handle */
    int first_cap; /* points of the first handle's path r->paths has room for */
    deform_targets *t;
    scaf_error *err;
} reader;

static scaf_status fail(reader *r, const char *what)
{
    return err_set(r->err, SCAF_ERR_PARSE, "%s:%d: %s", r->path, r->line, what);
}

static void skip_ws(reader *r)
{
    for (; *r->s == ' ' || *r->s == '\t' || *r->s == '\r' || *r->s == '\n'; r->s++)
        if (*r->s == '\n') r->line++;
}

static int eat(reader *r, char c)
{
    skip_ws(r);
    if (*r->s != c) return 0;
    r->s++;
    return 1;
}

/* A key: only plain ASCII names are expected. */
static scaf_status key(reader *r, char *out, size_t size)
{
    if (!eat(r, '"')) return fail(r, "expected a key in double quotes");
    size_t n = 0;
    for (; *r->s && *r->s != '"'; r->s++) {
        if (*r->s == '\\' || *r->s == '\n' || n + 1 >= size) return fail(r, "unexpected key");
        out[n++] = *r->s;
    }
    out[n] = '\0';
    if (*r->s != '"') return fail(r, "unterminated key");
    r->s++;
    if (!eat(r, ':')) return fail(r, "expected ':' after a key");
    return SCAF_OK;
}

static scaf_status number(reader *r, double *v, const char *what)
{
    skip_ws(r);
    const char *p = r->s;
    if (*p == '-') p++;
    if (!isdigit((unsigned char)*p))
        return err_set(r->err, SCAF_ERR_PARSE, "%s:%d: %s: expected a number", r->path, r->line,
                       what);
    char *end;
    errno = 0;
    *v = strtod(r->s, &end);
    if (errno == ERANGE || !isfinite(*v)) /* well-formed, but not a usable double */
        return err_set(r->err, SCAF_ERR_MESH,
                       "%s:%d: %s: number out of range (%.*s is not a finite double)", r->path,
                       r->line, what, (int)(end - r->s < 40 ? end - r->s : 40), r->s);
    /* strtod also reads C's hexadecimal floats (0x1p3): not JSON */
    for (const char *q = r->s; q < end; q++)
        if (!isdigit((unsigned char)*q) && !strchr(".eE+-", *q))
            return err_set(r->err, SCAF_ERR_PARSE, "%s:%d: %s: not a JSON number", r->path, r->line,
                           what);
    r->s = end;
    return SCAF_OK;
}

/* "path": [[x, y], ...] of the handle being read (index t->n) into
 * r->paths; the first handle's path sets the length every other must have. */
static scaf_status read_path(reader *r, int *len)
{
    if (!eat(r, '[')) return fail(r, "\"path\" must be an array of [x, y]");
    if (eat(r, ']')) return SCAF_OK;
    do {
        if (r->path_len >= 0 && *len >= r->path_len)
            return err_set(r->err, SCAF_ERR_PARSE,
                           "%s:%d: handle %d has a longer path than the first handle (%d points)",
                           r->path, r->line, r->t->n + 1, r->path_len);
        if (r->path_len < 0 && *len == r->first_cap) {
            if (r->first_cap >= INT32_MAX / 2) return fail(r, "\"path\" too long");
            /* the first handle: grow geometrically (one point at a time
             * was quadratic: 12 minutes for 200,000 points under ASan) */
            int cap = r->first_cap < 64 ? 64 : r->first_cap;
            cap *= 2;
            double *pp = realloc(r->paths, sizeof(double) * 2 * (size_t)cap);
            if (!pp) return err_nomem(r->err, "handle paths");
            r->paths = pp;
            r->first_cap = cap;
        }
        if (*len % POINTS_PER_INTERRUPT_CHECK == 0 && interrupt_pending())
            return err_set(r->err, SCAF_ERR_CANCELLED, "%s:%d: interrupted by %s while reading",
                           r->path, r->line, interrupt_signal_name(interrupt_pending()));
        size_t stride = r->path_len >= 0 ? (size_t)r->path_len : (size_t)*len + 1;
        double *q = r->paths + 2 * (stride * (size_t)r->t->n + (size_t)*len);
        scaf_status st;
        if (!eat(r, '[')) return fail(r, "a \"path\" point must be [x, y]");
        char what[64];
        snprintf(what, sizeof what, "handle %d: \"path\" point %d x", r->t->n + 1, *len + 1);
        if ((st = number(r, &q[0], what))) return st;
        if (!eat(r, ',')) return fail(r, "a \"path\" point must have two numbers");
        what[strlen(what) - 1] = 'y';
        if ((st = number(r, &q[1], what))) return st;
        if (!eat(r, ']')) return fail(r, "a \"path\" point must have exactly two numbers");
        (*len)++;
    } while (eat(r, ','));
    if (!eat(r, ']')) return fail(r, "expected ',' or ']' in \"path\"");
    return SCAF_OK;
}

/* A JSON true or false. */
static scaf_status boolean(reader *r, unsigned char *v, const char *what)
{
    skip_ws(r);
    if (!strncmp(r->s, "true", 4)) *v = 1, r->s += 4;
    else if (!strncmp(r->s, "false", 5)) *v = 0, r->s += 5;
    else
        return err_set(r->err, SCAF_ERR_PARSE, "%s:%d: %s must be true or false", r->path, r->line,
                       what);
    return SCAF_OK;
}

/* "pins": [i, ...] */
static scaf_status read_pins(reader *r)
{
    deform_targets *t = r->t;
    if (!eat(r, '[')) return fail(r, "\"pins\" must be an array of vertex indices");
    if (eat(r, ']')) return SCAF_OK;
    int cap = 0;
    do {
        if (t->npins == cap) {
            if (cap >= INT32_MAX / 4) return fail(r, "\"pins\" too long");
            cap = cap ? 2 * cap : 16;
            int *p = realloc(t->pins, sizeof(int) * (size_t)cap);
            if (!p) return err_nomem(r->err, "pins");
            t->pins = p;
        }
        if (t->npins % POINTS_PER_INTERRUPT_CHECK == 0 && interrupt_pending())
            return err_set(r->err, SCAF_ERR_CANCELLED, "%s:%d: interrupted by %s while reading",
                           r->path, r->line, interrupt_signal_name(interrupt_pending()));
        double v;
        char what[48];
        snprintf(what, sizeof what, "pin %d", t->npins + 1);
        scaf_status st = number(r, &v, what);
        if (st) return st;
        if (v != floor(v) || v < 0 || v > 2147483647.0)
            return fail(r, "a pin must be a vertex index, an integer >= 0");
        t->pins[t->npins++] = (int)v;
    } while (eat(r, ','));
    if (!eat(r, ']')) return fail(r, "expected ',' or ']' in \"pins\"");
    return SCAF_OK;
}

static scaf_status handle(reader *r)
{
    deform_targets *t = r->t;
    if (t->n == r->cap) {
        int cap = r->cap ? 2 * r->cap : 16;
        int *v = realloc(t->vertex, sizeof(int) * (size_t)cap);
        if (v) t->vertex = v;
        double *x = realloc(t->target, sizeof(double) * 2 * (size_t)cap);
        if (x) t->target = x;
        unsigned char *hd = realloc(t->hard, (size_t)cap);
        if (hd) t->hard = hd;
        double *pp = r->path_len > 0
            ? realloc(r->paths, sizeof(double) * 2 * (size_t)r->path_len * (size_t)cap)
            : r->paths;
        if (pp) r->paths = pp;
        if (!v || !x || !hd || (r->path_len > 0 && !pp)) return err_nomem(r->err, "handles");
        r->cap = cap;
    }
    if (!eat(r, '{'))
        return fail(r, "a handle must be an object {\"vertex\": i, \"target\": [x, y]}");
    int seen_v = 0, seen_t = 0, seen_hard = 0, len = 0;
    t->hard[t->n] = 0;
    char k[32];
    do {
        scaf_status st = key(r, k, sizeof k);
        if (st) return st;
        if (!strcmp(k, "vertex") && !seen_v) {
            double v;
            if ((st = number(r, &v, "\"vertex\""))) return st;
            if (v != floor(v) || v < 0 || v > 2147483647.0)
                return fail(r, "\"vertex\" must be an integer >= 0");
            t->vertex[t->n] = (int)v;
            seen_v = 1;
        } else if (!strcmp(k, "target") && !seen_t) {
            if (!eat(r, '[')) return fail(r, "\"target\" must be an array [x, y]");
            char what[48];
            snprintf(what, sizeof what, "handle %d: \"target\" x", t->n + 1);
            if ((st = number(r, &t->target[2 * t->n], what))) return st;
            if (!eat(r, ',')) return fail(r, "\"target\" must have two numbers");
            what[strlen(what) - 1] = 'y';
            if ((st = number(r, &t->target[2 * t->n + 1], what))) return st;
            if (!eat(r, ']')) return fail(r, "\"target\" must have exactly two numbers");
            seen_t = 1;
        } else if (!strcmp(k, "path") && len == 0) {
            if ((st = read_path(r, &len))) return st;
        } else if (!strcmp(k, "hard") && !seen_hard) {
            if ((st = boolean(r, &t->hard[t->n], "\"hard\""))) return st;
            seen_hard = 1;
        } else {
            return err_set(r->err, SCAF_ERR_PARSE,
                           "%s:%d: unknown or repeated key \"%s\" in a handle", r->path, r->line,
                           k);
        }
    } while (eat(r, ','));
    if (!eat(r, '}')) return fail(r, "expected ',' or '}' in a handle");
    if (!seen_v || !seen_t) return fail(r, "a handle needs both \"vertex\" and \"target\"");
    if (r->path_len < 0) { /* the first handle: room for the others' paths */
        r->path_len = len;
        if (len > 0) {
            double *pp = realloc(r->paths, sizeof(double) * 2 * (size_t)len * (size_t)r->cap);
            if (!pp) return err_nomem(r->err, "handle paths");
            r->paths = pp;
        }
    }
    if (len != r->path_len)
        return err_set(r->err, SCAF_ERR_PARSE,
                       "%s:%d: handle %d has a path of %d points, the first handle one of %d "
                       "(every handle's path must have the same length)",
                       r->path, r->line, t->n + 1, len, r->path_len);
    t->n++;
    return SCAF_OK;
}

static scaf_status document(reader *r)
{
    if (!eat(r, '{')) return fail(r, "expected '{' (the file is one JSON object)");
    if (eat(r, '}'))
        return err_set(r->err, SCAF_ERR_PARSE,
                       "%s:%d: no \"handles\" array (the object is empty; expected "
                       "{\"handles\": [{\"vertex\": i, \"target\": [x, y]}, ...]})",
                       r->path, r->line);
    int seen_h = 0, seen_p = 0;
    char k[32];
    do {
        scaf_status st = key(r, k, sizeof k);
        if (st) return st;
        if (!strcmp(k, "handles") && !seen_h) {
            if (!eat(r, '[')) return fail(r, "\"handles\" must be an array");
            if (!eat(r, ']')) {
                do {
                    if (interrupt_pending())
                        return err_set(r->err, SCAF_ERR_CANCELLED,
                                       "%s:%d: interrupted by %s while reading", r->path, r->line,
                                       interrupt_signal_name(interrupt_pending()));
                    if ((st = handle(r))) return st;
                } while (eat(r, ','));
                if (!eat(r, ']')) return fail(r, "expected ',' or ']' in \"handles\"");
            }
            seen_h = 1;
        } else if (!strcmp(k, "weight") && !r->t->has_weight) {
            if ((st = number(r, &r->t->weight, "\"weight\""))) return st;
            if (r->t->weight < 0) return fail(r, "\"weight\" must be >= 0");
            r->t->has_weight = 1;
        } else if (!strcmp(k, "pins") && !seen_p) {
            if ((st = read_pins(r))) return st;
            seen_p = 1;
        } else {
            return err_set(r->err, SCAF_ERR_PARSE, "%s:%d: unknown or repeated key \"%s\"", r->path,
                           r->line, k);
        }
    } while (eat(r, ','));
    if (!eat(r, '}')) return fail(r, "expected ',' or '}'");
    skip_ws(r);
    if (*r->s) return fail(r, "unexpected text after the object");
    if (!seen_h) return err_set(r->err, SCAF_ERR_PARSE, "%s: no \"handles\" array", r->path);
    return SCAF_OK;
}

scaf_status deform_targets_read(const char *path, deform_targets *t, scaf_error *err)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "rb");
    if (!f) return err_set(err, SCAF_ERR_IO, "cannot open '%s': %s", path, strerror(errno));
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n - 1, f);
        if (n < cap - 1) break;
        char *b = cap < ((size_t)1 << 30) ? realloc(buf, 2 * cap) : NULL;
        if (!b) free(buf);
        buf = b;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf) return err_nomem(err, "reading the targets");
    if (bad) {
        free(buf);
        return err_set(err, SCAF_ERR_IO, "cannot read '%s'", path);
    }
    buf[n] = '\0';
    scaf_status st = deform_targets_parse(buf, n, path, t, err);
    free(buf);
    return st;
}

scaf_status deform_targets_parse(const char *text, size_t size, const char *name, deform_targets *t,
                                 scaf_error *err)
{
    memset(t, 0, sizeof *t);
    if (memchr(text, '\0', size) || text[size] != '\0')
        return err_set(err, SCAF_ERR_PARSE, "%s: contains a NUL byte (not a JSON text)", name);
    interrupt_test_point("targets");
    reader r = {text, name, 1, 0, NULL, -1, 0, t, err};
    scaf_status st = document(&r);
    if (st == SCAF_OK && r.path_len > 0) { /* handle-major -> frame-major */
        t->frames = malloc(sizeof(double) * 2 * (size_t)r.path_len * (size_t)t->n);
        if (!t->frames) st = err_nomem(err, "handle paths");
        for (int i = 0; st == SCAF_OK && i < t->n; i++)
            for (int k = 0; k < r.path_len; k++)
                for (int a = 0; a < 2; a++)
                    t->frames[2 * ((size_t)k * t->n + i) + a] =
                        r.paths[2 * ((size_t)i * r.path_len + k) + a];
        t->nframes = r.path_len;
    }
    free(r.paths);
    if (st != SCAF_OK) deform_targets_free(t);
    return st;
}

scaf_status deform_targets_write(const char *path, int n, const double *T, int nframes,
                                 const double *frames, scaf_error *err)
{
    FILE *f = fopen(path, "wb");
    if (!f) return err_set(err, SCAF_ERR_IO, "cannot write '%s': %s", path, strerror(errno));
    fputs("{\"handles\": [\n", f);
    for (int i = 0; i < n; i++) {
        fprintf(f, "  {\"vertex\": %d, \"target\": [%.17g, %.17g]", i, T[2 * i], T[2 * i + 1]);
        if (nframes > 0) {
            fputs(", \"path\": [", f);
            for (int k = 0; k < nframes; k++) {
                const double *q = frames + 2 * ((size_t)k * n + i);
                fprintf(f, "%s[%.17g, %.17g]", k ? ", " : "", q[0], q[1]);
            }
            fputc(']', f);
        }
        fprintf(f, "}%s\n", i + 1 < n ? "," : "");
    }
    fputs("]}\n", f);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) return err_set(err, SCAF_ERR_IO, "cannot write '%s'", path);
    return SCAF_OK;
}

/* Whether (x, y) lies within DEFORM_TARGET_RANGE mesh sizes of the
 * mesh's box [lo, hi]. */
static int within_range(const double *q, const double lo[2], const double hi[2], double size)
{
    for (int a = 0; a < 2; a++) {
        double reach = DEFORM_TARGET_RANGE * size;
        if (!isfinite(q[a]) || q[a] < lo[a] - reach || q[a] > hi[a] + reach) return 0;
    }
    return 1;
}

scaf_status deform_targets_check(const deform_targets *t, int nv, const double *P, const char *name,
                                 scaf_error *err)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < nv; v++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], P[2 * v + a]);
            hi[a] = fmax(hi[a], P[2 * v + a]);
        }
    /* the larger side (a mesh of one point: 1) */
    double size = nv > 0 ? fmax(hi[0] - lo[0], hi[1] - lo[1]) : 1.0;
    if (!(size > 0.0) || !isfinite(size)) size = nv > 0 ? fmax(fabs(lo[0]), fabs(lo[1])) : 1.0;
    if (!(size > 0.0) || !isfinite(size)) size = 1.0;
    int *owner = malloc(sizeof(int) * (size_t)(nv > 0 ? nv : 1));
    if (!owner) return err_nomem(err, "checking the handles");
    for (int v = 0; v < nv; v++) owner[v] = -1;
    scaf_status st = SCAF_OK;
    for (int i = 0; i < t->n && st == SCAF_OK; i++) {
        int v = t->vertex[i];
        if (v < 0 || v >= nv) {
            st = err_set(err, SCAF_ERR_MESH,
                         "%s: handle %d: vertex %d is not one of the mesh's %d (0-based)", name,
                         i + 1, v, nv);
        } else if (owner[v] >= 0) {
            st = err_set(err, SCAF_ERR_MESH,
                         "%s: handle %d: vertex %d already has a handle (handle %d); give each "
                         "vertex one handle",
                         name, i + 1, v, owner[v] + 1);
        } else if (!within_range(&t->target[2 * i], lo, hi, size)) {
            st = err_set(err, SCAF_ERR_MESH,
                         "%s: handle %d (vertex %d): target [%g, %g] is out of range: a target "
                         "must lie within %g mesh sizes (%g) of the mesh's box [%g, %g] x [%g, %g]",
                         name, i + 1, v, t->target[2 * i], t->target[2 * i + 1],
                         DEFORM_TARGET_RANGE, size, lo[0], hi[0], lo[1], hi[1]);
        }
        owner[v < 0 || v >= nv ? 0 : v] = i;
        for (int k = 0; k < t->nframes && st == SCAF_OK; k++) {
            const double *q = t->frames + 2 * ((size_t)k * t->n + i);
            if (!within_range(q, lo, hi, size))
                st = err_set(err, SCAF_ERR_MESH,
                             "%s: handle %d (vertex %d): path point %d [%g, %g] is out of range: "
                             "a waypoint must lie within %g mesh sizes (%g) of the mesh's box "
                             "[%g, %g] x [%g, %g]",
                             name, i + 1, v, k + 1, q[0], q[1], DEFORM_TARGET_RANGE, size, lo[0],
                             hi[0], lo[1], hi[1]);
        }
    }
    for (int i = 0; i < t->npins && st == SCAF_OK; i++) {
        int v = t->pins[i];
        if (v < 0 || v >= nv)
            st = err_set(err, SCAF_ERR_MESH,
                         "%s: pin %d: vertex %d is not one of the mesh's %d (0-based)", name, i + 1,
                         v, nv);
        else if (owner[v] >= 0)
            st = err_set(err, SCAF_ERR_MESH,
                         "%s: pin %d: vertex %d has a handle (handle %d): a pinned vertex stays "
                         "where it is, give it a hard handle instead",
                         name, i + 1, v, owner[v] + 1);
        else if (owner[v] < -1)
            st = err_set(err, SCAF_ERR_MESH, "%s: pin %d: vertex %d is pinned twice (pin %d)", name,
                         i + 1, v, -owner[v] - 1);
        else owner[v] = -(i + 2);
    }
    free(owner);
    return st;
}

void deform_targets_free(deform_targets *t)
{
    free(t->vertex);
    free(t->target);
    free(t->frames);
    free(t->hard);
    free(t->pins);
    memset(t, 0, sizeof *t);
}
