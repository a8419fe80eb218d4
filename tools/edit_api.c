/* tools/edit_api: the requests `scaf edit` answers (see edit_api.h). */
#define _POSIX_C_SOURCE 200809L /* open's O_CLOEXEC */
#include "edit_api.h"

#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/atomic_file.h"
#include "base/json_write.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "edit_json.h"
#include "exit_codes.h"

#define JSON_TYPE "application/json"
#define DRAG_STEPS_MAX 20
#define OPTIMIZE_STEPS_DEFAULT 100
#define COMPACT_STEPS_DEFAULT 30
#define STEPS_MAX 1000
#define OPTIMIZE_TOLERANCE 1e-4 /* relative decrease of E per iteration */
#define MAX_ANGLE 1000.0        /* radians of a chart drag */
#define REACH_FACTOR 1000.0     /* drag targets: within this times the layout's size */

void edit_response_free(edit_response *rs)
{
    if (!rs->body_static) free(rs->body);
    rs->body = NULL;
    rs->len = 0;
}

/* ---- responses -------------------------------------------------------------- */

static void reply_failure(edit_api *a, edit_response *rs, const char *what);

/* A JSON response written with stdio into memory. */
typedef struct json_out {
    FILE *f;
    char *buf;
    size_t len;
} json_out;

static void reply(edit_response *rs, int status, const char *type, char *body, size_t len)
{
    rs->status = status;
    rs->content_type = type;
    rs->body = body;
    rs->len = len;
    rs->body_static = 0;
}

static void reply_error(edit_response *rs, int status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int json_open(json_out *j)
{
    j->buf = NULL;
    j->len = 0;
    j->f = open_memstream(&j->buf, &j->len);
    return j->f != NULL;
}

static void reply_error(edit_response *rs, int status, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    json_out j;
    if (!json_open(&j)) {
        reply(rs, 500, "text/plain", NULL, 0);
        return;
    }
    fputs("{\"error\": ", j.f);
    json_write_string(j.f, msg);
    fputs("}\n", j.f);
    fclose(j.f);
    reply(rs, status, JSON_TYPE, j.buf, j.len);
}

/* 1, or 0 after answering 500 (no memory for the stream). */
static int json_begin(json_out *j, edit_response *rs)
{
    if (json_open(j)) return 1;
    reply_error(rs, 500, "out of memory");
    return 0;
}

/* , "key": x */
static void json_key_number(FILE *f, const char *key, double x)
{
    fprintf(f, ", \"%s\": ", key);
    json_write_number(f, x);
}

static void json_end(json_out *j, edit_response *rs)
{
    if (fclose(j->f) != 0) {
        free(j->buf);
        reply_error(rs, 500, "out of memory");
        return;
    }
    reply(rs, 200, JSON_TYPE, j->buf, j->len);
}

static void write_ints(FILE *f, const char *key, const int *x, size_t n)
{
    fprintf(f, "\"%s\": [", key);
    for (size_t i = 0; i < n; i++) fprintf(f, i ? ",%d" : "%d", x[i]);
    fputs("]", f);
}

/* Numbers for drawing: 9 significant digits are far below a pixel; null
 * for what JSON cannot hold. */
static void write_doubles(FILE *f, const char *key, const double *x, size_t n)
{
    fprintf(f, "\"%s\": [", key);
    for (size_t i = 0; i < n; i++) {
        if (i) fputc(',', f);
        if (isfinite(x[i])) fprintf(f, "%.9g", x[i]);
        else fputs("null", f);
    }
    fputs("]", f);
}

static void reply_state_reached(edit_api *a, edit_response *rs, const char *extra_key, int extra,
                                double reached);

/* The layout and its numbers; extra (may be NULL) adds fields first. */
static void reply_state(edit_api *a, edit_response *rs, const char *extra_key, int extra)
{
    reply_state_reached(a, rs, extra_key, extra, NAN);
}

/* reply_state with "reached" (a rigid motion's kept fraction) unless NAN. */
static void reply_state_reached(edit_api *a, edit_response *rs, const char *extra_key, int extra,
                                double reached)
{
    if (scaf_drag_get_uv(a->drag, a->uv, NULL, NULL) != SCAF_OK) {
        reply_error(rs, 500, "%s", scaf_drag_error(a->drag));
        return;
    }
    json_out j;
    if (!json_begin(&j, rs)) return;
    fputc('{', j.f);
    if (extra_key) fprintf(j.f, "\"%s\": %d, ", extra_key, extra);
    if (!isnan(reached)) {
        fputs("\"reached\": ", j.f);
        json_write_number(j.f, reached);
        fputs(", ", j.f);
    }
    fprintf(j.f, "\"iteration\": %d", scaf_drag_iterations(a->drag));
    /* energy: the figure scaf atlas and scaf check give for the same layout
     * (docs/energy.md); objective: the drag's own, at its layout's scale */
    double e = NAN;
    if (a->m->nf == a->nf)
        scaf_area_matched_energy(a->m->V, a->m->nv, a->m->F, a->nf, a->uv, a->nuv, a->FT, &e);
    json_key_number(j.f, "energy", e);
    json_key_number(j.f, "objective", scaf_drag_energy(a->drag));
    json_key_number(j.f, "efficiency", scaf_drag_packing_efficiency(a->drag));
    fprintf(j.f, ", \"handles\": %d, \"pinned\": %d, \"undo\": %d, \"redo\": %d, \"unsaved\": %s",
            scaf_drag_handle_count(a->drag), scaf_drag_pinned_count(a->drag),
            scaf_drag_undo_count(a->drag), scaf_drag_redo_count(a->drag),
            edit_api_unsaved(a) ? "true" : "false");
    json_key_number(j.f, "max_handle_error", scaf_drag_max_handle_error(a->drag));
    json_key_number(j.f, "padding", a->padding);
    fputs(", \"pinned_vertices\": [", j.f);
    for (int i = 0, n = 0; i < a->nuv; i++)
        if (scaf_drag_is_pinned(a->drag, i)) fprintf(j.f, n++ ? ",%d" : "%d", i);
    fputs("], ", j.f);
    write_doubles(j.f, "uv", a->uv, 2 * (size_t)a->nuv);
    fputs("}\n", j.f);
    json_end(&j, rs);
}

/* Per-face distortion ||J||^2 + ||J^-1||^2 (4 at an isometry), for the
 * page's shading. */
static void reply_distortion(edit_api *a, edit_response *rs)
{
    double *E = malloc(sizeof(double) * (size_t)(a->nf ? a->nf : 1));
    if (!E) {
        reply_error(rs, 500, "out of memory");
        return;
    }
    json_out j;
    if (scaf_drag_face_energy(a->drag, E) != SCAF_OK) {
        reply_failure(a, rs, "distortion");
    } else if (json_begin(&j, rs)) {
        fprintf(j.f, "{\"iteration\": %d, ", scaf_drag_iterations(a->drag));
        write_doubles(j.f, "face_energy", E, (size_t)a->nf);
        fputs("}\n", j.f);
        json_end(&j, rs);
    }
    free(E);
}

static void reply_mesh(edit_api *a, edit_response *rs)
{
    json_out j;
    if (!json_begin(&j, rs)) return;
    fputs("{\"name\": ", j.f);
    json_write_string(j.f, a->name);
    fputs(", \"output\": ", j.f);
    json_write_string(j.f, a->out);
    fprintf(j.f, ", \"ncharts\": %d, \"nuv\": %d", a->ncharts, a->nuv);
    json_key_number(j.f, "padding", a->padding);
    json_key_number(j.f, "diagonal", a->diagonal);
    fputs(", \"texture\": ", j.f);
    if (a->texture) {
        json_write_string(j.f, a->texture_name ? a->texture_name : "");
        fprintf(j.f, ", \"texture_size\": [%d, %d]", a->texture_width, a->texture_height);
    } else {
        fputs("null", j.f);
    }
    fprintf(j.f, ", \"three\": %s, ", a->three_js_len ? "true" : "false");
    write_ints(j.f, "faces", a->FT, 3 * (size_t)a->nf);
    fputs(", ", j.f);
    write_ints(j.f, "face_chart", a->chart, (size_t)a->nf);
    fputs(", ", j.f);
    write_ints(j.f, "faces3d", a->m->F, 3 * (size_t)a->nf);
    fputs(", ", j.f);
    write_doubles(j.f, "xyz", a->m->V, 3 * (size_t)a->m->nv);
    fputs("}\n", j.f);
    json_end(&j, rs);
}

/* ---- checks ----------------------------------------------------------------- */

/* Equal strings, in a time that does not tell where they differ. */
static int same_secret(const char *given, const char *secret)
{
    size_t n = strlen(secret);
    if (!given || strlen(given) != n) return 0;
    unsigned char d = 0;
    for (size_t i = 0; i < n; i++) d |= (unsigned char)(given[i] ^ secret[i]);
    return d == 0;
}

/* "127.0.0.1:PORT" or "localhost:PORT" (after prefix, e.g. "http://"). */
static int is_our_address(const char *s, const char *prefix, int port)
{
    if (!s) return 0;
    size_t p = strlen(prefix);
    if (strncmp(s, prefix, p)) return 0;
    s += p;
    char want[64];
    snprintf(want, sizeof want, "127.0.0.1:%d", port);
    if (!strcmp(s, want)) return 1;
    snprintf(want, sizeof want, "localhost:%d", port);
    return !strcmp(s, want);
}

/* ---- actions ---------------------------------------------------------------- */

static int parse(const edit_request *rq, edit_response *rs, edit_json_field *f, int n)
{
    char msg[256];
    if (edit_json_parse(rq->body, rq->body_len, f, n, msg, sizeof msg)) return 1;
    reply_error(rs, 400, "%s %s: %s", rq->method, rq->path, msg);
    return 0;
}

static int check_chart(edit_api *a, edit_response *rs, double c)
{
    if (c < a->ncharts) return 1;
    reply_error(rs, 400, "unknown chart %.0f: the atlas has charts 0..%d", c, a->ncharts - 1);
    return 0;
}

static int check_vertex(edit_api *a, edit_response *rs, double v)
{
    if (v < a->nuv) return 1;
    reply_error(rs, 400, "unknown vertex %.0f: the layout has vertices 0..%d", v, a->nuv - 1);
    return 0;
}

static int check_steps(edit_response *rs, const edit_json_field *f, int max)
{
    if (!f->seen || (f->value >= 1 && f->value <= max)) return 1;
    reply_error(rs, 400, "\"steps\" %.0f is out of range: it must be in 1..%d", f->value, max);
    return 0;
}

/* A library failure: 500 with its message (the layout of the last
 * finished iteration stays). */
static void reply_failure(edit_api *a, edit_response *rs, const char *what)
{
    reply_error(rs, 500, "%s: %s", what, scaf_drag_error(a->drag));
}

/* SIGINT / SIGTERM stop long runs at the next iteration. */
static int stop_on_signal(const scaf_iteration_info_t *info, void *user)
{
    (void)info, (void)user;
    return cli_signal_caught() != 0;
}

/* A "mode" word: 1 rigid, 0 deform (the default: absent), -1 after
 * answering 400. */
static int mode_of(edit_response *rs, const edit_json_extra *x)
{
    if (!x->seen || !strcmp(x->word, "deform")) return 0;
    if (!strcmp(x->word, "rigid")) return 1;
    reply_error(rs, 400, "\"mode\" \"%s\" is unknown: \"rigid\" or \"deform\"", x->word);
    return -1;
}

/* The chart ids of an INTEGERS extra into ids (1, or 0 after 400). */
static int chart_list(edit_api *a, edit_response *rs, const edit_json_extra *x, int *ids)
{
    if (x->len < 1) {
        reply_error(rs, 400, "\"%s\" is empty: give at least one chart id", x->key);
        return 0;
    }
    for (int i = 0; i < x->len; i++) {
        if (!check_chart(a, rs, x->list[i])) return 0;
        ids[i] = (int)x->list[i];
    }
    return 1;
}

static void grab(edit_api *a, const edit_request *rq, edit_response *rs)
{
    edit_json_field f[] = {{"chart", EDIT_JSON_INTEGER, 0, 0, 0},
                           {"vertex", EDIT_JSON_INTEGER, 0, 0, 0}};
    int cap = a->ncharts > 0 ? a->ncharts : 1, *ids = NULL;
    double *list = malloc(sizeof(double) * (size_t)cap);
    if (!list) {
        reply_error(rs, 500, "out of memory");
        return;
    }
    edit_json_extra x[] = {{"mode", EDIT_JSON_WORD, 0, NULL, 0, 0, "", 0, 0},
                           {"charts", EDIT_JSON_INTEGERS, 0, list, cap, 0, "", 0, 0}};
    char msg[256];
    int mode;
    if (!edit_json_parse_extra(rq->body, rq->body_len, f, 2, x, 2, msg, sizeof msg)) {
        reply_error(rs, 400, "%s %s: %s", rq->method, rq->path, msg);
        goto done;
    }
    if (f[0].seen == f[1].seen) {
        reply_error(rs, 400, "give either \"chart\" or \"vertex\"");
        goto done;
    }
    if (f[0].seen ? !check_chart(a, rs, f[0].value) : !check_vertex(a, rs, f[1].value)) goto done;
    if ((mode = mode_of(rs, &x[0])) < 0) goto done;
    if ((mode == 0 || f[1].seen) && x[1].seen) {
        reply_error(rs, 400, "\"charts\" goes with a chart and \"mode\": \"rigid\"");
        goto done;
    }
    int n = x[1].seen ? x[1].len : 1;
    ids = malloc(sizeof(int) * (size_t)n);
    if (!ids) {
        reply_error(rs, 500, "out of memory");
        goto done;
    }
    if (x[1].seen ? !chart_list(a, rs, &x[1], ids) : (ids[0] = (int)f[0].value, 0)) goto done;
    if (scaf_drag_clear_handles(a->drag) != SCAF_OK || scaf_drag_rigid_end(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "grab");
        goto done;
    }
    a->rigid_grab = 0;
    if (mode == 1 && f[0].seen) {
        if (scaf_drag_rigid_begin(a->drag, ids, n) != SCAF_OK) { /* a pinned chart */
            reply_error(rs, 409, "grab: %s", scaf_drag_error(a->drag));
            goto done;
        }
        a->rigid_grab = 1;
    }
    if (scaf_drag_checkpoint(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "grab");
        goto done;
    }
    reply_state(a, rs, NULL, 0);
done:
    free(ids);
    free(list);
}

/* A rigid chart drag: the total motion since the grab (scaf_drag_rigid_move). */
static void drag_rigid(edit_api *a, edit_response *rs, int chart, double dx, double dy,
                       double angle)
{
    if (!a->rigid_grab) { /* grabbed in deform mode: this chart alone */
        if (scaf_drag_rigid_begin(a->drag, &chart, 1) != SCAF_OK) {
            reply_error(rs, 409, "drag: %s", scaf_drag_error(a->drag));
            return;
        }
        a->rigid_grab = 1;
    }
    scaf_drag_motion_t m = scaf_drag_motion_identity();
    m.dx = dx, m.dy = dy, m.angle = angle;
    double reached = 0.0;
    a->changes++;
    if (scaf_drag_rigid_move(a->drag, &m, &reached) != SCAF_OK) {
        reply_failure(a, rs, "drag");
        return;
    }
    reply_state_reached(a, rs, NULL, 0, reached);
}

static void drag_to(edit_api *a, const edit_request *rq, edit_response *rs)
{
    edit_json_field f[] = {
        {"chart", EDIT_JSON_INTEGER, 0, 0, 0},  {"dx", EDIT_JSON_NUMBER, 0, 0, 0},
        {"dy", EDIT_JSON_NUMBER, 0, 0, 0},      {"angle", EDIT_JSON_NUMBER, 0, 0, 0},
        {"vertex", EDIT_JSON_INTEGER, 0, 0, 0}, {"x", EDIT_JSON_NUMBER, 0, 0, 0},
        {"y", EDIT_JSON_NUMBER, 0, 0, 0},       {"steps", EDIT_JSON_INTEGER, 0, 0, 0}};
    edit_json_extra x[] = {{"mode", EDIT_JSON_WORD, 0, NULL, 0, 0, "", 0, 0}};
    char msg[256];
    if (!edit_json_parse_extra(rq->body, rq->body_len, f, 8, x, 1, msg, sizeof msg)) {
        reply_error(rs, 400, "%s %s: %s", rq->method, rq->path, msg);
        return;
    }
    int mode = mode_of(rs, &x[0]);
    if (mode < 0) return;
    int chart = f[0].seen, vertex = f[4].seen;
    if (chart == vertex) {
        reply_error(rs, 400,
                    "give either \"chart\" (with dx, dy, angle) or \"vertex\" (with x, y)");
        return;
    }
    if (chart && (f[5].seen || f[6].seen)) {
        reply_error(rs, 400, "a chart drag takes dx, dy and angle, not x and y");
        return;
    }
    if (vertex && (f[1].seen || f[2].seen || f[3].seen || !f[5].seen || !f[6].seen)) {
        reply_error(rs, 400, "a vertex drag takes x and y (both), not dx, dy or angle");
        return;
    }
    if (chart ? !check_chart(a, rs, f[0].value) : !check_vertex(a, rs, f[4].value)) return;
    if (!check_steps(rs, &f[7], DRAG_STEPS_MAX)) return;
    if (mode == 1 && (!chart || f[7].seen)) {
        reply_error(rs, 400, "\"mode\": \"rigid\" moves a chart (dx, dy, angle), without steps");
        return;
    }
    /* a pointer stays on the screen: bounded motions keep the handle
     * energy finite */
    for (int k = 1; k < 7; k++) {
        double limit = k == 3 ? MAX_ANGLE : a->reach;
        if (k != 4 && f[k].seen && !(fabs(f[k].value) <= limit)) {
            reply_error(rs, 400, "\"%s\" %g is out of range: at most %g in magnitude%s", f[k].key,
                        f[k].value, limit,
                        k == 3 ? " (radians)" : " (1000 times the layout's size)");
            return;
        }
    }
    if (mode == 1) {
        drag_rigid(a, rs, (int)f[0].value, f[1].value, f[2].value, f[3].value);
        return;
    }
    scaf_status st = chart
        ? scaf_drag_move_chart(a->drag, (int)f[0].value, f[1].value, f[2].value, f[3].value)
        : scaf_drag_move_vertex(a->drag, (int)f[4].value, f[5].value, f[6].value);
    if (st != SCAF_OK) { /* nothing changed (a motion out of range) */
        reply_error(rs, 400, "%s", scaf_drag_error(a->drag));
        return;
    }
    int steps = f[7].seen ? (int)f[7].value : 1;
    st = scaf_drag_step(a->drag, steps, stop_on_signal, NULL);
    a->changes++; /* a failed step keeps its last finished iteration */
    if (st != SCAF_OK && st != SCAF_ERR_CANCELLED) {
        reply_failure(a, rs, "step");
        return;
    }
    reply_state(a, rs, NULL, 0);
}

/* Pin or unpin one vertex (the layout does not change). */
static void pin(edit_api *a, const edit_request *rq, edit_response *rs)
{
    edit_json_field f[] = {{"vertex", EDIT_JSON_INTEGER, 0, 0, 0},
                           {"pinned", EDIT_JSON_INTEGER, 0, 0, 0}};
    if (!parse(rq, rs, f, 2)) return;
    if (!f[0].seen || !f[1].seen || f[1].value > 1) {
        reply_error(rs, 400, "give \"vertex\" and \"pinned\" (1: pin, 0: unpin)");
        return;
    }
    if (!check_vertex(a, rs, f[0].value)) return;
    if (scaf_drag_pin_vertex(a->drag, (int)f[0].value, (int)f[1].value) != SCAF_OK) {
        reply_failure(a, rs, "pin");
        return;
    }
    reply_state(a, rs, NULL, 0);
}

static void release(edit_api *a, const edit_request *rq, edit_response *rs)
{
    if (!parse(rq, rs, NULL, 0)) return;
    if (scaf_drag_clear_handles(a->drag) != SCAF_OK || scaf_drag_rigid_end(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "release");
        return;
    }
    a->rigid_grab = 0;
    reply_state(a, rs, NULL, 0);
}

/* Optimize (compact = 0) or compact: a checkpoint, no handles, then
 * iterations; the state with "iterations_run". */
static void run(edit_api *a, const edit_request *rq, edit_response *rs, int compact)
{
    edit_json_field f[] = {{"steps", EDIT_JSON_INTEGER, 0, 0, 0},
                           {"padding", EDIT_JSON_NUMBER, 0, 0, 0}};
    /* optimize takes no padding: its key is unknown there */
    if (!parse(rq, rs, f, compact ? 2 : 1) || !check_steps(rs, &f[0], STEPS_MAX)) return;
    if (f[1].seen && f[1].value != a->padding) {
        if (!(f[1].value >= 0x1p-200 && f[1].value < 0.5)) {
            reply_error(rs, 400, "\"padding\" %g is out of range: it must be in [2^-200, 0.5)",
                        f[1].value);
            return;
        }
        /* refused (nothing changed) when the layout is closer than that now */
        if (scaf_drag_set_padding(a->drag, f[1].value) != SCAF_OK) {
            reply_error(rs, 409, "%s", scaf_drag_error(a->drag));
            return;
        }
        a->padding = f[1].value;
        a->changes++; /* the next save certifies the new padding */
    }
    int cap =
        f[0].seen ? (int)f[0].value : (compact ? COMPACT_STEPS_DEFAULT : OPTIMIZE_STEPS_DEFAULT);
    if (scaf_drag_clear_handles(a->drag) != SCAF_OK || scaf_drag_checkpoint(a->drag) != SCAF_OK) {
        reply_failure(a, rs, compact ? "compact" : "optimize");
        return;
    }
    int before = scaf_drag_iterations(a->drag);
    a->changes++;
    scaf_drag_rigid_end(a->drag);
    a->rigid_grab = 0;
    scaf_status st = SCAF_OK;
    if (compact) {
        st = scaf_drag_compact(a->drag, cap, stop_on_signal, NULL);
    } else {
        /* one iteration at a time: stop once E barely moves */
        for (int i = 0; i < cap && st == SCAF_OK && !cli_signal_caught(); i++) {
            double e0 = scaf_drag_energy(a->drag);
            int n0 = scaf_drag_iterations(a->drag);
            st = scaf_drag_step(a->drag, 1, stop_on_signal, NULL);
            if (scaf_drag_iterations(a->drag) == n0) break; /* a minimum */
            if (e0 - scaf_drag_energy(a->drag) < OPTIMIZE_TOLERANCE * e0) break;
        }
    }
    if (st != SCAF_OK && st != SCAF_ERR_CANCELLED) {
        reply_failure(a, rs, compact ? "compact" : "optimize");
        return;
    }
    reply_state(a, rs, "iterations_run", scaf_drag_iterations(a->drag) - before);
}

/* One rigid operation on a selection (scaf_drag_transform) after a
 * checkpoint. */
static void transform(edit_api *a, const edit_request *rq, edit_response *rs)
{
    edit_json_field f[] = {{"dx", EDIT_JSON_NUMBER, 0, 0, 0},
                           {"dy", EDIT_JSON_NUMBER, 0, 0, 0},
                           {"angle", EDIT_JSON_NUMBER, 0, 0, 0},
                           {"factor", EDIT_JSON_NUMBER, 0, 0, 0}};
    int cap = a->ncharts > 0 ? a->ncharts : 1, *ids = NULL;
    double *list = malloc(sizeof(double) * (size_t)cap), pivot[2] = {0, 0};
    if (!list) {
        reply_error(rs, 500, "out of memory");
        return;
    }
    edit_json_extra x[] = {{"charts", EDIT_JSON_INTEGERS, 1, list, cap, 0, "", 0, 0},
                           {"op", EDIT_JSON_WORD, 1, NULL, 0, 0, "", 0, 0},
                           {"axis", EDIT_JSON_WORD, 0, NULL, 0, 0, "", 0, 0},
                           {"pivot", EDIT_JSON_NUMBERS, 0, pivot, 2, 0, "", 0, 0},
                           {"remirror", EDIT_JSON_BOOL, 0, NULL, 0, 0, "", 0, 0}};
    char msg[256];
    if (!edit_json_parse_extra(rq->body, rq->body_len, f, 4, x, 5, msg, sizeof msg)) {
        reply_error(rs, 400, "%s %s: %s", rq->method, rq->path, msg);
        goto done;
    }
    ids = malloc(sizeof(int) * (size_t)(x[0].len > 0 ? x[0].len : 1));
    if (!ids) {
        reply_error(rs, 500, "out of memory");
        goto done;
    }
    if (!chart_list(a, rs, &x[0], ids)) goto done;
    const char *op = x[1].word;
    /* which numbers each operation takes */
    static const struct {
        const char *op;
        int takes[4]; /* dx dy angle factor */
        const char *needs;
    } ops[] = {{"translate", {1, 1, 0, 0}, "\"dx\" and \"dy\""},
               {"rotate", {0, 0, 1, 0}, "\"angle\" (radians)"},
               {"scale", {0, 0, 0, 1}, "\"factor\""},
               {"flip", {0, 0, 0, 0}, "\"axis\": \"u\" or \"v\""}};
    int k = 0;
    while (k < 4 && strcmp(ops[k].op, op)) k++;
    if (k == 4) {
        reply_error(rs, 400,
                    "\"op\" \"%s\" is unknown: \"translate\", \"rotate\", \"scale\" or "
                    "\"flip\"",
                    op);
        goto done;
    }
    int ok = 1;
    for (int i = 0; i < 4; i++)
        if (f[i].seen != ops[k].takes[i]) ok = 0;
    if (k == 3) ok = ok && x[2].seen && (!strcmp(x[2].word, "u") || !strcmp(x[2].word, "v"));
    else ok = ok && !x[2].seen;
    if (!ok || (x[3].seen && x[3].len != 2)) {
        reply_error(rs, 400, "\"op\": \"%s\" takes %s%s", op, ops[k].needs,
                    x[3].seen && x[3].len != 2 ? "; \"pivot\" is [u, v]" : " and nothing else");
        goto done;
    }
    for (int i = 0; i < 3; i++) {
        double limit = i == 2 ? MAX_ANGLE : a->reach;
        if (f[i].seen && !(fabs(f[i].value) <= limit)) {
            reply_error(rs, 400, "\"%s\" %g is out of range: at most %g in magnitude", f[i].key,
                        f[i].value, limit);
            goto done;
        }
    }
    if (x[3].seen && !(fabs(pivot[0]) <= a->reach && fabs(pivot[1]) <= a->reach)) {
        reply_error(rs, 400, "\"pivot\" is out of range: at most %g in magnitude", a->reach);
        goto done;
    }
    scaf_drag_motion_t m = scaf_drag_motion_identity();
    if (f[0].seen) m.dx = f[0].value, m.dy = f[1].value;
    if (f[2].seen) m.angle = f[2].value;
    if (f[3].seen) m.factor = f[3].value;
    if (k == 3) m.flip = x[2].word[0] == 'u' ? SCAF_DRAG_FLIP_U : SCAF_DRAG_FLIP_V;
    m.remirror = x[4].seen && x[4].flag;
    if (x[3].seen) m.has_pivot = 1, m.pivot[0] = pivot[0], m.pivot[1] = pivot[1];
    if (k == 3 && !m.remirror) {
        reply_error(rs, 409,
                    "flip refused: a mirror turns the charts' triangles clockwise, so the layout "
                    "would not be bijective and could never be saved; send \"remirror\": true "
                    "to apply it as a half turn");
        goto done;
    }
    if (f[3].seen && !(f[3].value >= 1.0 / 1024 && f[3].value <= 1024)) {
        reply_error(rs, 400, "\"factor\" %g is out of range: in [1/1024, 1024]", f[3].value);
        goto done;
    }
    if (scaf_drag_clear_handles(a->drag) != SCAF_OK || scaf_drag_rigid_end(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "transform");
        goto done;
    }
    a->rigid_grab = 0;
    /* the grab first: a pinned chart is refused before anything changes */
    if (scaf_drag_rigid_begin(a->drag, ids, x[0].len) != SCAF_OK) {
        reply_error(rs, 409, "transform: %s", scaf_drag_error(a->drag));
        goto done;
    }
    if (scaf_drag_checkpoint(a->drag) != SCAF_OK) {
        scaf_drag_rigid_end(a->drag);
        reply_failure(a, rs, "transform");
        goto done;
    }
    a->changes++;
    double reached = 0.0;
    scaf_status st = scaf_drag_rigid_move(a->drag, &m, &reached);
    scaf_drag_rigid_end(a->drag);
    if (st != SCAF_OK) {
        reply_failure(a, rs, "transform");
        goto done;
    }
    reply_state_reached(a, rs, NULL, 0, reached);
done:
    free(ids);
    free(list);
}

static void undo(edit_api *a, const edit_request *rq, edit_response *rs)
{
    if (!parse(rq, rs, NULL, 0)) return;
    if (scaf_drag_undo_count(a->drag) == 0) {
        reply_error(rs, 409, "nothing to undo");
        return;
    }
    a->changes++;
    scaf_drag_rigid_end(a->drag); /* a rigid grab ends with its layout */
    a->rigid_grab = 0;
    if (scaf_drag_undo(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "undo");
        return;
    }
    reply_state(a, rs, NULL, 0);
}

/* Redo: the layout the last undo left, bit for bit (the drag API keeps it
 * until the next change). */
static void redo(edit_api *a, const edit_request *rq, edit_response *rs)
{
    if (!parse(rq, rs, NULL, 0)) return;
    if (scaf_drag_redo_count(a->drag) == 0) {
        reply_error(rs, 409, "nothing to redo");
        return;
    }
    a->changes++;
    scaf_drag_rigid_end(a->drag); /* a rigid grab ends with its layout */
    a->rigid_grab = 0;
    if (scaf_drag_redo(a->drag) != SCAF_OK) {
        reply_failure(a, rs, "redo");
        return;
    }
    reply_state(a, rs, NULL, 0);
}

/* The output checked again before each save: it may have become a link
 * to the input (or the input a hard link of it) since the start. The
 * rules of cli_outputs_check (input, autosave and output as they are
 * named now), and the input as it was at the start, through the
 * descriptor kept open (the name may have moved away). 1, or 0 after
 * answering 409 (the output names another file of the session) or 500. */
static int check_output(edit_api *a, edit_response *rs, cli_outputs *outs)
{
    cli_outputs_init(outs, "edit", a->in);
    cli_outputs_add_input(outs, "the autosave", a->autosave);
    cli_outputs_add(outs, "-o", a->out, CLI_OUTPUT_MESH);
    int rc = cli_outputs_check(outs);
    if (rc != EXIT_OK) {
        reply_error(rs, rc == EXIT_USAGE ? 409 : 500, "save: %s; nothing written", outs->message);
        return 0;
    }
    struct stat in, out;
    char target[4096];
    scaf_error err;
    err_clear(&err);
    if (a->in_fd >= 0 && fstat(a->in_fd, &in) == 0 &&
        atomic_resolve(a->out, target, sizeof target, NULL, &err) == SCAF_OK &&
        stat(target, &out) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino) {
        fprintf(stderr, "scaf edit: -o %s names the input file (%s as it was at the start)\n",
                a->out, a->in);
        reply_error(rs, 409,
                    "save: -o %s now names the input file (%s as it was at the start): it would "
                    "be overwritten; nothing written",
                    a->out, a->in);
        return 0;
    }
    return 1;
}

/* Where save reads the input's text: the descriptor kept open. */
static const char *input_source(const edit_api *a, char *buf, size_t size)
{
    if (a->in_fd < 0) return a->in;
    snprintf(buf, size, "/proc/self/fd/%d", a->in_fd);
    return access(buf, R_OK) == 0 ? buf : a->in;
}

/* Normalize, certify exactly (scaf_drag_get_output), write atomically
 * through tools/cli_outputs like `scaf atlas`. */
static void save(edit_api *a, const edit_request *rq, edit_response *rs)
{
    if (!parse(rq, rs, NULL, 0)) return;
    cli_outputs outs;
    if (!check_output(a, rs, &outs)) return;
    const int k = 0; /* the only output */
    double *UV = malloc(sizeof(double) * 2 * (size_t)(a->nuv ? a->nuv : 1));
    int *FT = malloc(sizeof(int) * 3 * (size_t)(a->nf ? a->nf : 1));
    if (!UV || !FT) {
        free(UV);
        free(FT);
        reply_error(rs, 500, "save: out of memory");
        return;
    }
    double eff = NAN, gap = NAN;
    if (scaf_drag_get_output(a->drag, UV, FT, NULL, &eff, &gap) != SCAF_OK) {
        reply_error(rs, 500, "save: %s; nothing written", scaf_drag_error(a->drag));
        free(UV);
        free(FT);
        return;
    }
    scaf_error err;
    err_clear(&err);
    mesh o = {a->m->nv, a->m->V, a->m->nf, a->m->F, a->nuv, UV, FT};
    char note[1024] = "", source[64];
    const char *path = cli_outputs_begin(&outs, k, &err);
    int rc = cli_outputs_end(&outs, k,
                             path ? cli_write_uv_from(a->in, input_source(a, source, sizeof source),
                                                      a->rinfo, path, &o, note, sizeof note, &err)
                                  : SCAF_ERR_IO,
                             &err);
    if (rc == 0) rc = cli_outputs_commit(&outs);
    cli_outputs_abort(&outs);
    free(UV);
    free(FT);
    if (rc != 0) {
        reply_error(rs, 500, "save: %s; nothing written",
                    err.message[0] ? err.message : "interrupted");
        return;
    }
    if (note[0]) fprintf(stderr, "scaf edit: warning: %s: %s\n", a->out, note);
    a->saves++;
    a->saved_changes = a->changes;
    /* the saved file is newer than the autosave: a resume from it would
     * go back in time */
    if (a->autosave && remove(a->autosave) == 0) a->autosaved_changes = a->changes;
    json_out j;
    if (!json_begin(&j, rs)) return;
    fputs("{\"path\": ", j.f);
    json_write_string(j.f, a->out);
    fputs(", \"bijective\": true", j.f);
    json_key_number(j.f, "padding", a->padding);
    json_key_number(j.f, "gap", gap);
    json_key_number(j.f, "efficiency", eff);
    fprintf(j.f, ", \"saves\": %d, \"unsaved\": false", a->saves);
    if (note[0]) {
        fputs(", \"note\": ", j.f);
        json_write_string(j.f, note);
    }
    fputs("}\n", j.f);
    json_end(&j, rs);
}

int edit_api_unsaved(const edit_api *a) { return a->changes != a->saved_changes; }

scaf_status edit_api_autosave(edit_api *a, int *written, scaf_error *err)
{
    if (written) *written = 0;
    if (!a->autosave || !edit_api_unsaved(a) || a->autosaved_changes == a->changes) return SCAF_OK;
    double *UV = malloc(sizeof(double) * 2 * (size_t)(a->nuv ? a->nuv : 1));
    int *FT = malloc(sizeof(int) * 3 * (size_t)(a->nf ? a->nf : 1));
    scaf_status st = SCAF_OK;
    if (!UV || !FT) {
        st = err_nomem(err, "the autosave");
    } else if (scaf_drag_get_output(a->drag, UV, FT, NULL, NULL, NULL) != SCAF_OK) {
        st = err_set(err, SCAF_ERR_INTERNAL, "%s", scaf_drag_error(a->drag));
    } else {
        mesh o = {a->m->nv, a->m->V, a->m->nf, a->m->F, a->nuv, UV, FT};
        st = mesh_write_obj(a->autosave, &o, err);
    }
    free(UV);
    free(FT);
    if (st == SCAF_OK) {
        a->autosaved_changes = a->changes;
        if (written) *written = 1;
    }
    return st;
}

/* ---- routing ---------------------------------------------------------------- */

/* A file compiled in or read at start-up (static: not copied); 404 with
 * why_none when there is none. */
static void reply_asset(edit_response *rs, const char *type, const char *body, size_t len,
                        const char *why_none)
{
    if (!body || !len) {
        reply_error(rs, 404, "%s", why_none);
        return;
    }
    rs->status = 200;
    rs->content_type = type;
    rs->body = (char *)body;
    rs->len = len;
    rs->body_static = 1;
}

typedef struct route {
    const char *path;
    const char *method;
    int kind;
} route;

enum {
    R_PAGE,
    R_TOOLS_JS,
    R_THREE_JS,
    R_TEXTURE,
    R_MESH,
    R_STATE,
    R_DISTORTION,
    R_GRAB,
    R_DRAG,
    R_RELEASE,
    R_PIN,
    R_OPTIMIZE,
    R_COMPACT,
    R_UNDO,
    R_REDO,
    R_SAVE,
    R_TRANSFORM
};

static const route routes[] = {
    {"/", "GET", R_PAGE},
    {"/index.html", "GET", R_PAGE},
    {"/edit_page_tools.js", "GET", R_TOOLS_JS},
    {"/three.min.js", "GET", R_THREE_JS},
    {"/texture.png", "GET", R_TEXTURE},
    {"/api/mesh", "GET", R_MESH},
    {"/api/state", "GET", R_STATE},
    {"/api/distortion", "GET", R_DISTORTION},
    {"/api/grab", "POST", R_GRAB},
    {"/api/drag", "POST", R_DRAG},
    {"/api/release", "POST", R_RELEASE},
    {"/api/pin", "POST", R_PIN},
    {"/api/optimize", "POST", R_OPTIMIZE},
    {"/api/compact", "POST", R_COMPACT},
    {"/api/undo", "POST", R_UNDO},
    {"/api/redo", "POST", R_REDO},
    {"/api/save", "POST", R_SAVE},
    {"/api/transform", "POST", R_TRANSFORM},
};

void edit_api_handle(void *user, const edit_request *rq, edit_response *rs)
{
    edit_api *a = user;
    memset(rs, 0, sizeof *rs);
    if (!is_our_address(rq->host, "", a->port)) {
        reply_error(rs, 403, "Host must be 127.0.0.1:%d or localhost:%d", a->port, a->port);
        return;
    }
    if (rq->origin && !is_our_address(rq->origin, "http://", a->port)) {
        reply_error(rs, 403, "requests from another origin are refused");
        return;
    }
    if (!same_secret(rq->token, a->token)) {
        reply_error(rs, 403, "wrong or missing token: open the URL `scaf edit` printed");
        return;
    }
    if (rq->body_too_large) {
        reply_error(rs, 413, "request body over %d bytes", EDIT_MAX_BODY);
        return;
    }
    const route *r = NULL;
    int path_known = 0;
    for (size_t i = 0; i < sizeof routes / sizeof routes[0]; i++)
        if (!strcmp(rq->path, routes[i].path)) {
            path_known = 1;
            if (!strcmp(rq->method, routes[i].method)) r = &routes[i];
        }
    if (!r) {
        if (path_known) reply_error(rs, 405, "%s is not allowed on %s", rq->method, rq->path);
        else reply_error(rs, 404, "no such path: %s", rq->path);
        return;
    }
    switch (r->kind) {
    case R_PAGE:
        rs->status = 200;
        rs->content_type = "text/html; charset=utf-8";
        rs->body = (char *)a->page;
        rs->len = a->page_len;
        rs->body_static = 1;
        return;
    case R_TOOLS_JS:
        reply_asset(rs, "text/javascript; charset=utf-8", a->tools_js, a->tools_js_len,
                    "the page's script is not built in");
        return;
    case R_THREE_JS:
        reply_asset(rs, "text/javascript; charset=utf-8", a->three_js, a->three_js_len,
                    "scaf was built without three.js (libjs-three was not installed at build "
                    "time): no 3D view");
        return;
    case R_TEXTURE:
        reply_asset(rs, "image/png", (const char *)a->texture, a->texture ? a->texture_len : 0,
                    "no --texture was given");
        return;
    case R_MESH: reply_mesh(a, rs); return;
    case R_STATE: reply_state(a, rs, NULL, 0); return;
    case R_DISTORTION: reply_distortion(a, rs); return;
    case R_GRAB: grab(a, rq, rs); return;
    case R_DRAG: drag_to(a, rq, rs); return;
    case R_RELEASE: release(a, rq, rs); return;
    case R_PIN: pin(a, rq, rs); return;
    case R_OPTIMIZE: run(a, rq, rs, 0); return;
    case R_COMPACT: run(a, rq, rs, 1); return;
    case R_UNDO: undo(a, rq, rs); return;
    case R_REDO: redo(a, rq, rs); return;
    case R_SAVE: save(a, rq, rs); return;
    case R_TRANSFORM: transform(a, rq, rs); return;
    }
    reply_error(rs, 500, "internal error: route %d", r->kind);
}

/* ---- set-up ----------------------------------------------------------------- */

scaf_status edit_api_init(edit_api *a, scaf_drag_t *d, const mesh *m, const char *in,
                          const mesh_read_info *rinfo, const char *out, double padding,
                          scaf_error *err)
{
    memset(a, 0, sizeof *a);
    a->in_fd = open(in, O_RDONLY | O_CLOEXEC);
    a->drag = d;
    a->m = m;
    a->in = in;
    a->rinfo = rinfo;
    a->out = out;
    a->name = in;
    a->padding = padding;
    a->nuv = scaf_drag_uv_count(d);
    a->nf = scaf_drag_face_count(d);
    a->ncharts = scaf_drag_chart_count(d);
    a->FT = malloc(sizeof(int) * 3 * (size_t)(a->nf ? a->nf : 1));
    a->chart = malloc(sizeof(int) * (size_t)(a->nf ? a->nf : 1));
    a->uv = malloc(sizeof(double) * 2 * (size_t)(a->nuv ? a->nuv : 1));
    if (!a->FT || !a->chart || !a->uv) {
        edit_api_free(a);
        return err_nomem(err, "the editor's arrays");
    }
    if (scaf_drag_get_uv(d, a->uv, a->FT, a->chart) != SCAF_OK) {
        scaf_status st = err_set(err, SCAF_ERR_INTERNAL, "%s", scaf_drag_error(d));
        edit_api_free(a);
        return st;
    }
    double ulo[2] = {INFINITY, INFINITY}, uhi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < a->nuv; i++)
        for (int c = 0; c < 2; c++) {
            ulo[c] = fmin(ulo[c], a->uv[2 * i + c]);
            uhi[c] = fmax(uhi[c], a->uv[2 * i + c]);
        }
    double size = fmax(fmax(uhi[0] - ulo[0], uhi[1] - ulo[1]),
                       fmax(fmax(fabs(ulo[0]), fabs(uhi[0])), fmax(fabs(ulo[1]), fabs(uhi[1]))));
    a->reach = REACH_FACTOR * (size > 0 ? size : 1.0);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < m->nv; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m->V[3 * i + c]);
            hi[c] = fmax(hi[c], m->V[3 * i + c]);
        }
    a->diagonal = m->nv
        ? sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
               (hi[2] - lo[2]) * (hi[2] - lo[2]))
        : 1.0;
    return SCAF_OK;
}

void edit_api_free(edit_api *a)
{
    if (a->in_fd >= 0) close(a->in_fd);
    a->in_fd = -1;
    free(a->FT);
    free(a->chart);
    free(a->uv);
    a->FT = a->chart = NULL;
    a->uv = NULL;
}
