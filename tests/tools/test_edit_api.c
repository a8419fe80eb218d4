/* tools/edit_api: the request handler of `scaf edit`, without sockets.
 * Every bad request (wrong token, Host or Origin, oversized body,
 * malformed JSON, unknown chart or vertex, values out of range, unknown
 * path, wrong method, nothing to undo) gets its 4xx and leaves the layout,
 * its handles, its undo stack and the output file exactly as they were;
 * good requests do what they say (drag moves the chart and iterates,
 * undo restores bit for bit, save writes a file scaf check accepts). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "edit_api.h"
#include "mesh/samples.h"
#include "support/support.h"

#define PORT 8123
#define TOKEN "0123456789abcdef0123456789abcdef"

typedef struct fixture {
    mesh m;
    mesh_read_info rinfo;
    scaf_drag_t *d;
    edit_api api;
    char out[512];
} fixture;

static int setup(void **state)
{
    fixture *x = calloc(1, sizeof *x);
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 3, &x->m, &err), SCAF_OK);
    scaf_drag_options_t opt = scaf_drag_options_default();
    opt.start = SCAF_DRAG_START_INPUT;
    x->d = scaf_drag_new(&opt);
    assert_int_equal(
        scaf_drag_set_mesh(x->d, x->m.V, x->m.nv, x->m.F, x->m.nf, x->m.UV, x->m.nuv, x->m.FT),
        SCAF_OK);
    test_tmp_path("edit_api_out.obj", x->out, sizeof x->out);
    remove(x->out);
    assert_int_equal(
        edit_api_init(&x->api, x->d, &x->m, "cubesphere.obj", &x->rinfo, x->out, opt.padding, &err),
        SCAF_OK);
    strcpy(x->api.token, TOKEN);
    x->api.port = PORT;
    x->api.page = "<html></html>";
    x->api.page_len = 13;
    *state = x;
    return 0;
}

static int teardown(void **state)
{
    fixture *x = *state;
    edit_api_free(&x->api);
    scaf_drag_destroy(x->d);
    mesh_free(&x->m);
    free(x);
    return 0;
}

/* What a request could change: the layout, its numbers, handles, undo. */
typedef struct snapshot {
    double *uv;
    int n, iterations, handles, undo;
    double energy;
} snapshot;

static snapshot snap(fixture *x)
{
    snapshot s;
    s.n = scaf_drag_uv_count(x->d);
    s.uv = malloc(sizeof(double) * 2 * (size_t)s.n);
    assert_int_equal(scaf_drag_get_uv(x->d, s.uv, NULL, NULL), SCAF_OK);
    s.iterations = scaf_drag_iterations(x->d);
    s.handles = scaf_drag_handle_count(x->d);
    s.undo = scaf_drag_undo_count(x->d);
    s.energy = scaf_drag_energy(x->d);
    return s;
}

static int same(const snapshot *a, const snapshot *b)
{
    return a->n == b->n && !memcmp(a->uv, b->uv, sizeof(double) * 2 * (size_t)a->n) &&
        a->iterations == b->iterations && a->handles == b->handles && a->undo == b->undo &&
        !memcmp(&a->energy, &b->energy, sizeof a->energy);
}

/* A request as the page sends it, then the fields a case changes. */
static edit_request good(const char *method, const char *path, const char *body)
{
    edit_request rq = {method,
                       path,
                       TOKEN,
                       "http://127.0.0.1:8123",
                       "127.0.0.1:8123",
                       body,
                       body ? strlen(body) : 0,
                       0};
    return rq;
}

/* Send rq; returns the status, the body (NUL-terminated copy) in *text. */
static int send(fixture *x, const edit_request *rq, char **text)
{
    edit_response rs;
    edit_api_handle(&x->api, rq, &rs);
    if (text) {
        *text = malloc(rs.len + 1);
        memcpy(*text, rs.body, rs.len);
        (*text)[rs.len] = '\0';
    }
    int status = rs.status;
    edit_response_free(&rs);
    return status;
}

static void bad_requests_change_nothing(void **state)
{
    fixture *x = *state;
    /* a held chart and one undo point, so that a wrong request could
     * drop, move or pop something */
    edit_request g = good("POST", "/api/grab", "{\"chart\": 1}");
    assert_int_equal(send(x, &g, NULL), 200);
    edit_request d =
        good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.01, \"dy\": 0, \"angle\": 0}");
    assert_int_equal(send(x, &d, NULL), 200);
    snapshot before = snap(x);
    assert_int_equal(before.handles, 1);
    assert_int_equal(before.undo, 1);

    static char big[EDIT_MAX_BODY + 2];
    memset(big, ' ', sizeof big - 1);
    struct {
        edit_request rq;
        int status;
        const char *says;
    } cases[] = {
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "token"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "token"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "token"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "origin"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "origin"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "Host"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}"), 403, "Host"},
        {good("POST", "/api/drag", big), 413, "over"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5"), 400, "malformed JSON"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 0.5}x"), 400, "malformed JSON"},
        {good("POST", "/api/drag", "{\"chart\": 6, \"dx\": 0.5}"), 400, "unknown chart 6"},
        {good("POST", "/api/drag", "{\"chart\": 99999999, \"dx\": 1}"), 400, "unknown chart"},
        {good("POST", "/api/drag", "{\"vertex\": 999999, \"x\": 0, \"y\": 0}"), 400,
         "unknown vertex"},
        {good("POST", "/api/drag", "{\"vertex\": 0, \"x\": 0}"), 400, "x and y"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"x\": 0}"), 400, "not x and y"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"vertex\": 0}"), 400, "either"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"dx\": 1e300}"), 400, "out of range"},
        {good("POST", "/api/drag", "{\"vertex\": 0, \"x\": 0, \"y\": -1e9}"), 400, "out of range"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"angle\": 1e4}"), 400, "radians"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"steps\": 0}"), 400, "out of range"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"steps\": 21}"), 400, "out of range"},
        {good("POST", "/api/drag", "{\"chart\": 1, \"evil\": 1}"), 400, "unknown key"},
        {good("POST", "/api/grab", "{\"chart\": 6}"), 400, "unknown chart"},
        {good("POST", "/api/grab", "{}"), 400, "either"},
        {good("POST", "/api/release", "{\"all\": 1}"), 400, "unknown key"},
        {good("POST", "/api/optimize", "{\"steps\": 1001}"), 400, "out of range"},
        {good("POST", "/api/compact", "{\"steps\": -1}"), 400, "integer"},
        {good("POST", "/api/undo", "null"), 400, "malformed JSON"},
        {good("POST", "/api/save", ""), 400, "malformed JSON"},
        {good("GET", "/api/drag", NULL), 405, "not allowed"},
        {good("DELETE", "/api/state", NULL), 405, "not allowed"},
        {good("GET", "/api/nothing", NULL), 404, "no such path"},
        {good("GET", "/../etc/passwd", NULL), 404, "no such path"},
    };
    cases[0].rq.token = NULL;
    cases[1].rq.token = "0123456789abcdef0123456789abcdeF";
    cases[2].rq.token = TOKEN "0";
    cases[3].rq.origin = "http://evil.example";
    cases[4].rq.origin = "http://127.0.0.1:8124";
    cases[5].rq.host = "evil.example:8123";
    cases[6].rq.host = NULL;
    cases[7].rq.body_too_large = 1;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *text;
        int status = send(x, &cases[i].rq, &text);
        if (status != cases[i].status || !strstr(text, cases[i].says) ||
            strncmp(text, "{\"error\": ", 10))
            fail_msg("case %zu (%s %s): status %d, %s (want %d, \"%s\")", i, cases[i].rq.method,
                     cases[i].rq.path, status, text, cases[i].status, cases[i].says);
        free(text);
        snapshot now = snap(x);
        if (!same(&before, &now)) fail_msg("case %zu (%s) changed the state", i, cases[i].says);
        free(now.uv);
    }
    assert_false(test_exists(x->out));
    free(before.uv);
}

static void undo_with_nothing_to_undo_is_409(void **state)
{
    fixture *x = *state;
    snapshot before = snap(x);
    edit_request u = good("POST", "/api/undo", "{}");
    char *text;
    assert_int_equal(send(x, &u, &text), 409);
    assert_non_null(strstr(text, "nothing to undo"));
    free(text);
    snapshot now = snap(x);
    assert_true(same(&before, &now));
    free(before.uv);
    free(now.uv);
}

static double chart_x(fixture *x, int c)
{
    scaf_drag_chart_info_t info;
    assert_int_equal(scaf_drag_chart_info(x->d, c, &info), SCAF_OK);
    return info.centroid[0];
}

static void drag_undo_save(void **state)
{
    fixture *x = *state;
    char *text;
    edit_request page = good("GET", "/", NULL);
    page.origin = NULL; /* a navigation sends none */
    assert_int_equal(send(x, &page, &text), 200);
    assert_string_equal(text, "<html></html>");
    free(text);
    edit_request m = good("GET", "/api/mesh", NULL);
    assert_int_equal(send(x, &m, &text), 200);
    assert_non_null(strstr(text, "\"ncharts\": 6"));
    free(text);
    edit_request dist = good("GET", "/api/distortion", NULL);
    assert_int_equal(send(x, &dist, &text), 200);
    assert_non_null(strstr(text, "\"face_energy\": ["));
    free(text);

    snapshot start = snap(x);
    double x0 = chart_x(x, 2);
    edit_request g = good("POST", "/api/grab", "{\"chart\": 2}");
    assert_int_equal(send(x, &g, NULL), 200);
    edit_request d = good("POST", "/api/drag",
                          "{\"chart\": 2, \"dx\": 0.05, \"dy\": 0, \"angle\": 0, \"steps\": 4}");
    assert_int_equal(send(x, &d, &text), 200);
    assert_non_null(strstr(text, "\"handles\": 1"));
    {
        /* energy is the area-matched E of the layout drawn (docs/energy.md),
         * the drag's own figure is the objective */
        const char *e = strstr(text, "\"energy\": ");
        assert_non_null(e);
        assert_non_null(strstr(text, "\"objective\": "));
        int nuv = scaf_drag_uv_count(x->d), nf = scaf_drag_face_count(x->d);
        double *uv = malloc(sizeof(double) * 2 * (size_t)nuv), expect = 0.0;
        int *ft = malloc(sizeof(int) * 3 * (size_t)nf);
        assert_int_equal(scaf_drag_get_uv(x->d, uv, ft, NULL), SCAF_OK);
        assert_int_equal(scaf_area_matched_energy(x->api.m->V, x->api.m->nv, x->api.m->F, nf, uv,
                                                  nuv, ft, &expect),
                         SCAF_OK);
        assert_true(expect >= 4.0 && fabs(strtod(e + 10, NULL) - expect) <= 1e-8 * expect);
        free(uv);
        free(ft);
    }
    free(text);
    assert_int_equal(scaf_drag_iterations(x->d), start.iterations + 4);
    assert_true(chart_x(x, 2) > x0 + 0.01); /* it follows the pull */
    edit_request r = good("POST", "/api/release", "{}");
    assert_int_equal(send(x, &r, NULL), 200);
    assert_int_equal(scaf_drag_handle_count(x->d), 0);
    /* a rotation (about the chart's centroid): a vertex of it moves */
    double before_rot[2];
    int v0 = 0;
    {
        snapshot s0 = snap(x);
        int *ch = malloc(sizeof(int) * (size_t)s0.n);
        assert_int_equal(scaf_drag_uv_charts(x->d, ch), SCAF_OK);
        while (ch[v0] != 3) v0++;
        before_rot[0] = s0.uv[2 * v0];
        before_rot[1] = s0.uv[2 * v0 + 1];
        free(ch);
        free(s0.uv);
    }
    edit_request g3 = good("POST", "/api/grab", "{\"chart\": 3}");
    assert_int_equal(send(x, &g3, NULL), 200);
    edit_request rot = good("POST", "/api/drag", "{\"chart\": 3, \"angle\": 0.5, \"steps\": 4}");
    assert_int_equal(send(x, &rot, NULL), 200);
    {
        snapshot s1 = snap(x);
        double dxy = hypot(s1.uv[2 * v0] - before_rot[0], s1.uv[2 * v0 + 1] - before_rot[1]);
        assert_true(dxy > 0.01);
        free(s1.uv);
    }
    assert_int_equal(send(x, &r, NULL), 200);
    /* a vertex drag */
    edit_request gv = good("POST", "/api/grab", "{\"vertex\": 0}");
    assert_int_equal(send(x, &gv, NULL), 200);
    edit_request dv = good("POST", "/api/drag", "{\"vertex\": 0, \"x\": 0, \"y\": 0}");
    assert_int_equal(send(x, &dv, NULL), 200);
    assert_int_equal(send(x, &r, NULL), 200);
    /* three undos: back to the start, bit for bit; three redos: the
     * vertex drag's layout again, bit for bit; then nothing to redo */
    snapshot dragged = snap(x);
    edit_request u = good("POST", "/api/undo", "{}");
    edit_request re = good("POST", "/api/redo", "{}");
    assert_int_equal(send(x, &re, &text), 409);
    assert_non_null(strstr(text, "nothing to redo"));
    free(text);
    assert_int_equal(send(x, &u, NULL), 200);
    assert_int_equal(send(x, &u, NULL), 200);
    assert_int_equal(send(x, &u, &text), 200);
    assert_non_null(strstr(text, "\"redo\": 3"));
    free(text);
    snapshot back = snap(x);
    assert_int_equal(back.n, start.n);
    assert_memory_equal(back.uv, start.uv, sizeof(double) * 2 * (size_t)start.n);
    free(back.uv);
    for (int k = 0; k < 3; k++) assert_int_equal(send(x, &re, NULL), 200);
    snapshot again = snap(x);
    assert_memory_equal(again.uv, dragged.uv, sizeof(double) * 2 * (size_t)start.n);
    assert_int_equal(again.iterations, dragged.iterations);
    assert_int_equal(send(x, &re, NULL), 409);
    for (int k = 0; k < 3; k++) assert_int_equal(send(x, &u, NULL), 200);
    free(again.uv);
    free(dragged.uv);
    free(start.uv);

    edit_request o = good("POST", "/api/optimize", "{\"steps\": 3}");
    assert_int_equal(send(x, &o, &text), 200);
    assert_non_null(strstr(text, "\"iterations_run\": "));
    free(text);
    edit_request c = good("POST", "/api/compact", "{\"steps\": 2}");
    assert_int_equal(send(x, &c, NULL), 200);
    edit_request s = good("POST", "/api/save", "{}");
    assert_int_equal(send(x, &s, &text), 200);
    assert_non_null(strstr(text, "\"bijective\": true"));
    free(text);
    assert_true(test_exists(x->out));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, x->out), 0);
    remove(x->out);
}

/* A pinned vertex keeps its bits while its chart is dragged, optimized
 * and compacted; bad pin requests are 400 and change nothing. */
static void pinned_vertex_stays(void **state)
{
    fixture *x = *state;
    char *text;
    int *ch = malloc(sizeof(int) * (size_t)scaf_drag_uv_count(x->d));
    assert_non_null(ch);
    assert_int_equal(scaf_drag_uv_charts(x->d, ch), SCAF_OK);
    int v = 0;
    while (ch[v] != 2) v++;
    free(ch);
    edit_request bad1 = good("POST", "/api/pin", "{\"vertex\": 100000, \"pinned\": 1}");
    assert_int_equal(send(x, &bad1, NULL), 400);
    edit_request bad2 = good("POST", "/api/pin", "{\"vertex\": 0, \"pinned\": 2}");
    assert_int_equal(send(x, &bad2, NULL), 400);
    edit_request bad3 = good("POST", "/api/pin", "{\"vertex\": 0}");
    assert_int_equal(send(x, &bad3, NULL), 400);
    assert_int_equal(scaf_drag_pinned_count(x->d), 0);
    char body[96];
    snprintf(body, sizeof body, "{\"vertex\": %d, \"pinned\": 1}", v);
    edit_request p = good("POST", "/api/pin", body);
    assert_int_equal(send(x, &p, &text), 200);
    assert_non_null(strstr(text, "\"pinned\": 1"));
    char ids[64]; /* the ids too: the page draws them, also after a reload */
    snprintf(ids, sizeof ids, "\"pinned_vertices\": [%d]", v);
    assert_non_null(strstr(text, ids));
    free(text);
    snapshot before = snap(x);
    double x0 = chart_x(x, 2);
    edit_request g = good("POST", "/api/grab", "{\"chart\": 2}");
    assert_int_equal(send(x, &g, NULL), 200);
    edit_request d = good("POST", "/api/drag",
                          "{\"chart\": 2, \"dx\": 0.05, \"dy\": 0, \"angle\": 0, \"steps\": 4}");
    assert_int_equal(send(x, &d, NULL), 200);
    edit_request r = good("POST", "/api/release", "{}");
    assert_int_equal(send(x, &r, NULL), 200);
    assert_true(chart_x(x, 2) > x0 + 0.005); /* the rest of the chart follows */
    edit_request o = good("POST", "/api/optimize", "{\"steps\": 3}");
    assert_int_equal(send(x, &o, NULL), 200);
    edit_request c = good("POST", "/api/compact", "{\"steps\": 2}");
    assert_int_equal(send(x, &c, NULL), 200);
    snapshot after = snap(x);
    assert_memory_equal(after.uv + 2 * v, before.uv + 2 * v, 2 * sizeof(double));
    free(after.uv);
    free(before.uv);
    snprintf(body, sizeof body, "{\"vertex\": %d, \"pinned\": 0}", v);
    edit_request up = good("POST", "/api/pin", body);
    assert_int_equal(send(x, &up, NULL), 200);
    assert_int_equal(scaf_drag_pinned_count(x->d), 0);
}

/* GET path: the status; the content type and a copy of the body. */
static int get(fixture *x, const char *path, const char *token, const char **type, char **body,
               size_t *len)
{
    edit_request rq = good("GET", path, NULL);
    rq.token = token;
    rq.origin = NULL; /* a script or image the page loads sends none */
    edit_response rs;
    edit_api_handle(&x->api, &rq, &rs);
    *type = rs.content_type;
    *len = rs.len;
    *body = malloc(rs.len + 1);
    memcpy(*body, rs.body, rs.len);
    (*body)[rs.len] = '\0';
    int status = rs.status;
    edit_response_free(&rs);
    return status;
}

/* The compiled-in scripts and the --texture image: sent with the token
 * only, 404 saying why when the build or the command line has none; GET
 * only; /api/mesh says which there are. */
static void scripts_and_texture(void **state)
{
    fixture *x = *state;
    const char *type;
    char *body;
    size_t len;
    const char *paths[] = {"/edit_page_tools.js", "/three.min.js", "/texture.png"};
    for (int k = 0; k < 3; k++) {
        assert_int_equal(get(x, paths[k], TOKEN, &type, &body, &len), 404);
        free(body);
        assert_int_equal(get(x, paths[k], NULL, &type, &body, &len), 403);
        free(body);
    }
    assert_int_equal(get(x, "/three.min.js", TOKEN, &type, &body, &len), 404);
    assert_non_null(strstr(body, "without three.js"));
    free(body);
    assert_int_equal(get(x, "/api/mesh", TOKEN, &type, &body, &len), 200);
    assert_non_null(strstr(body, "\"texture\": null"));
    assert_non_null(strstr(body, "\"three\": false"));
    free(body);
    static const unsigned char png[] = {0x89, 'P', 'N', 'G', 1, 2, 3};
    x->api.tools_js = "\"use strict\";";
    x->api.tools_js_len = 13;
    x->api.three_js = "var THREE;";
    x->api.three_js_len = 10;
    x->api.texture = png;
    x->api.texture_len = sizeof png;
    x->api.texture_name = "t.png";
    x->api.texture_width = 2;
    x->api.texture_height = 3;
    assert_int_equal(get(x, "/edit_page_tools.js", TOKEN, &type, &body, &len), 200);
    assert_string_equal(type, "text/javascript; charset=utf-8");
    assert_string_equal(body, "\"use strict\";");
    free(body);
    assert_int_equal(get(x, "/three.min.js", TOKEN, &type, &body, &len), 200);
    assert_string_equal(body, "var THREE;");
    free(body);
    assert_int_equal(get(x, "/texture.png", TOKEN, &type, &body, &len), 200);
    assert_string_equal(type, "image/png");
    assert_int_equal(len, sizeof png);
    assert_memory_equal(body, png, sizeof png);
    free(body);
    assert_int_equal(get(x, "/texture.png", "0123456789abcdef0123456789abcdeX", &type, &body, &len),
                     403);
    free(body);
    assert_int_equal(get(x, "/api/mesh", TOKEN, &type, &body, &len), 200);
    assert_non_null(strstr(body, "\"texture\": \"t.png\", \"texture_size\": [2, 3]"));
    assert_non_null(strstr(body, "\"three\": true"));
    free(body);
    edit_request post = good("POST", "/texture.png", "{}");
    assert_int_equal(send(x, &post, NULL), 405);
    /* nothing else is a file */
    assert_int_equal(get(x, "/texture.png/../cmd_edit.c", TOKEN, &type, &body, &len), 404);
    free(body);
}

/* compact's "padding": out of range 400, more than the layout keeps 409,
 * both changing nothing; optimize takes none; a smaller one is kept by
 * the context, the state and the save. */
static void compact_takes_the_padding(void **state)
{
    fixture *x = *state;
    char *text;
    snapshot before = snap(x);
    double pad0 = scaf_drag_padding(x->d);
    const char *bad[][2] = {{"/api/compact", "{\"padding\": 0.5}"},
                            {"/api/compact", "{\"padding\": 0}"},
                            {"/api/compact", "{\"padding\": -0.01}"},
                            {"/api/optimize", "{\"padding\": 0.001}"}};
    for (int k = 0; k < 4; k++) {
        edit_request rq = good("POST", bad[k][0], bad[k][1]);
        assert_int_equal(send(x, &rq, NULL), 400);
    }
    edit_request wide = good("POST", "/api/compact", "{\"padding\": 0.4}");
    assert_int_equal(send(x, &wide, &text), 409);
    assert_non_null(strstr(text, "smallest chart gap"));
    free(text);
    snapshot after = snap(x);
    assert_true(same(&before, &after));
    free(after.uv);
    assert_true(scaf_drag_padding(x->d) == pad0);
    edit_request small = good("POST", "/api/compact", "{\"padding\": 0.001953125, \"steps\": 3}");
    assert_int_equal(send(x, &small, &text), 200);
    assert_non_null(strstr(text, "\"padding\": 0.001953125"));
    free(text);
    assert_true(scaf_drag_padding(x->d) == 0.001953125);
    assert_true(x->api.padding == 0.001953125);
    edit_request save = good("POST", "/api/save", "{}");
    assert_int_equal(send(x, &save, &text), 200);
    assert_non_null(strstr(text, "\"padding\": 0.001953125"));
    free(text);
    free(before.uv);
    remove(x->out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(bad_requests_change_nothing, setup, teardown),
        cmocka_unit_test_setup_teardown(undo_with_nothing_to_undo_is_409, setup, teardown),
        cmocka_unit_test_setup_teardown(drag_undo_save, setup, teardown),
        cmocka_unit_test_setup_teardown(pinned_vertex_stays, setup, teardown),
        cmocka_unit_test_setup_teardown(scripts_and_texture, setup, teardown),
        cmocka_unit_test_setup_teardown(compact_takes_the_padding, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
