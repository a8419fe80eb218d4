/* tools/edit_api: rigid motions through the server (issue 34), on spot's
 * finished atlas (../shared/data/seams/spot.obj, started like `scaf edit`
 * starts from a mesh whose UVs are not an atlas: the atlas `scaf atlas`
 * makes; skipped when absent). A chart dragged across the atlas with
 * "mode": "rigid" in 24 requests: every other chart's UVs are their UVs
 * before translated (1e-12 of the layout's size), no iteration runs, the
 * layout certifies (bijective, padding: scaf_drag_get_output). POST
 * /api/transform rotates and scales a two-chart selection (undo and redo
 * restore bytes), refuses a flip without "remirror" (409, nothing
 * changes) and takes it with, and every malformed transform is a 400 that
 * changes nothing. The saved file passes `scaf check`. */
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
#include "mesh/mesh_io.h"
#include "support/support.h"

#define PORT 8124
#define TOKEN "0123456789abcdef0123456789abcdef"

typedef struct fixture {
    mesh m;
    mesh_read_info rinfo;
    scaf_drag_t *d;
    edit_api api;
    char out[512], in[4096];
} fixture;

static fixture *open_spot(void)
{
    fixture *x = calloc(1, sizeof *x);
    assert_non_null(x);
    if (!test_data_path("seams/spot.obj", x->in, sizeof x->in)) {
        free(x);
        return NULL;
    }
    scaf_error err;
    err_clear(&err);
    assert_int_equal(mesh_read(x->in, &x->m, &x->rinfo, &err), SCAF_OK);
    scaf_drag_options_t opt = scaf_drag_options_default();
    opt.start = SCAF_DRAG_START_ATLAS;
    x->d = scaf_drag_new(&opt);
    assert_int_equal(
        scaf_drag_set_mesh(x->d, x->m.V, x->m.nv, x->m.F, x->m.nf, x->m.UV, x->m.nuv, x->m.FT),
        SCAF_OK);
    test_tmp_path("edit_rigid_out.obj", x->out, sizeof x->out);
    remove(x->out);
    assert_int_equal(
        edit_api_init(&x->api, x->d, &x->m, x->in, &x->rinfo, x->out, opt.padding, &err), SCAF_OK);
    strcpy(x->api.token, TOKEN);
    x->api.port = PORT;
    x->api.page = "<html></html>";
    x->api.page_len = 13;
    return x;
}

static void close_spot(fixture *x)
{
    edit_api_free(&x->api);
    scaf_drag_destroy(x->d);
    mesh_free(&x->m);
    free(x);
}

static int post(fixture *x, const char *path, const char *body, char **text)
{
    edit_request rq = {"POST",           path, TOKEN,        "http://127.0.0.1:8124",
                       "127.0.0.1:8124", body, strlen(body), 0};
    edit_response rs;
    edit_api_handle(&x->api, &rq, &rs);
    if (text) {
        *text = malloc(rs.len + 1);
        memcpy(*text, rs.body, rs.len);
        (*text)[rs.len] = '\0';
    }
    int status = rs.status;
    edit_response_free(&rs);
    return status;
}

static double *uv_now(fixture *x)
{
    double *uv = malloc(sizeof(double) * 2 * (size_t)scaf_drag_uv_count(x->d));
    assert_non_null(uv);
    assert_int_equal(scaf_drag_get_uv(x->d, uv, NULL, NULL), SCAF_OK);
    return uv;
}

/* Largest deviation of chart c from a translation of it (a -> b). */
static double translation_error(fixture *x, const int *vc, const double *a, const double *b, int c)
{
    int n = scaf_drag_uv_count(x->d), v0 = -1;
    double e = 0.0;
    for (int v = 0; v < n; v++) {
        if (vc[v] != c) continue;
        if (v0 < 0) v0 = v;
        for (int k = 0; k < 2; k++)
            e = fmax(e, fabs((b[2 * v + k] - a[2 * v + k]) - (b[2 * v0 + k] - a[2 * v0 + k])));
    }
    return e;
}

static double extent(fixture *x, const double *uv)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < scaf_drag_uv_count(x->d); v++)
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], uv[2 * v + k]), hi[k] = fmax(hi[k], uv[2 * v + k]);
    return fmax(hi[0] - lo[0], hi[1] - lo[1]);
}

static void certified(fixture *x)
{
    double *UVn = malloc(sizeof(double) * 2 * (size_t)scaf_drag_uv_count(x->d)), gap = 0;
    assert_non_null(UVn);
    assert_int_equal(scaf_drag_get_output(x->d, UVn, NULL, NULL, NULL, &gap), SCAF_OK);
    assert_true(gap >= x->api.padding);
    free(UVn);
}

static void rigid_drag_through_the_server(void **state)
{
    (void)state;
    fixture *x = open_spot();
    if (!x) skip();
    int nc = scaf_drag_chart_count(x->d), n = scaf_drag_uv_count(x->d);
    int *vc = malloc(sizeof(int) * (size_t)n);
    assert_int_equal(scaf_drag_uv_charts(x->d, vc), SCAF_OK);
    int c = 0;
    double amin = INFINITY;
    scaf_drag_chart_info_t ci;
    for (int k = 0; k < nc; k++) {
        assert_int_equal(scaf_drag_chart_info(x->d, k, &ci), SCAF_OK);
        if (ci.uv_area < amin) amin = ci.uv_area, c = k;
    }
    assert_int_equal(scaf_drag_chart_info(x->d, c, &ci), SCAF_OK);
    double *uv0 = uv_now(x), side = extent(x, uv0);
    int it0 = scaf_drag_iterations(x->d);
    /* across the atlas: through the layout's middle to the other side */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < n; v++)
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], uv0[2 * v + k]), hi[k] = fmax(hi[k], uv0[2 * v + k]);
    double mx = lo[0] + hi[0] - 2 * ci.centroid[0], my = lo[1] + hi[1] - 2 * ci.centroid[1];
    char body[256], *text;
    snprintf(body, sizeof body, "{\"chart\": %d, \"mode\": \"rigid\"}", c);
    assert_int_equal(post(x, "/api/grab", body, NULL), 200);
    for (int f = 1; f <= 24; f++) {
        snprintf(body, sizeof body,
                 "{\"chart\": %d, \"dx\": %.17g, \"dy\": %.17g, \"angle\": 0, \"mode\": \"rigid\"}",
                 c, mx * f / 24, my * f / 24);
        assert_int_equal(post(x, "/api/drag", body, &text), 200);
        assert_non_null(strstr(text, "\"reached\": "));
        free(text);
        double *uv = uv_now(x);
        for (int k = 0; k < nc; k++)
            assert_true(translation_error(x, vc, uv0, uv, k) <= 1e-12 * side);
        free(uv);
        certified(x);
    }
    assert_int_equal(post(x, "/api/release", "{}", NULL), 200);
    assert_int_equal(scaf_drag_iterations(x->d), it0);
    /* a deform drag's keys do not mix with rigid */
    snprintf(body, sizeof body,
             "{\"chart\": %d, \"dx\": 0, \"dy\": 0, \"angle\": 0, \"steps\": 2, \"mode\": "
             "\"rigid\"}",
             c);
    assert_int_equal(post(x, "/api/drag", body, NULL), 400);
    assert_int_equal(
        post(x, "/api/drag", "{\"chart\": 0, \"dx\": 0, \"dy\": 0, \"mode\": \"stiff\"}", NULL),
        400);
    free(uv0);
    free(vc);
    close_spot(x);
}

static void transforms_undo_redo_and_refusals(void **state)
{
    (void)state;
    fixture *x = open_spot();
    if (!x) skip();
    int n = scaf_drag_uv_count(x->d);
    size_t bytes = sizeof(double) * 2 * (size_t)n;
    char *text;
    /* malformed: 400, nothing changes */
    const char *bad[] = {
        "{\"charts\": [0, 1], \"op\": \"twist\", \"angle\": 1}",
        "{\"charts\": [0, 1], \"op\": \"rotate\"}",
        "{\"charts\": [0, 1], \"op\": \"rotate\", \"angle\": 1, \"factor\": 2}",
        "{\"charts\": [999], \"op\": \"rotate\", \"angle\": 1}",
        "{\"charts\": [], \"op\": \"rotate\", \"angle\": 1}",
        "{\"charts\": [0], \"op\": \"rotate\", \"angle\": 1, \"pivot\": [1]}",
        "{\"charts\": [0], \"op\": \"flip\"}",
        "{\"charts\": [0], \"op\": \"flip\", \"axis\": \"w\"}",
        "{\"charts\": [0], \"op\": \"scale\", \"factor\": 0}",
        "{\"charts\": [0.5], \"op\": \"rotate\", \"angle\": 1}",
        "{\"op\": \"rotate\", \"angle\": 1}",
        "{\"charts\": [0], \"op\": \"translate\", \"dx\": 1}",
    };
    double *a = uv_now(x);
    int undo0 = scaf_drag_undo_count(x->d);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(post(x, "/api/transform", bad[i], &text), 400);
        assert_non_null(strstr(text, "\"error\""));
        free(text);
        double *b = uv_now(x);
        assert_memory_equal(a, b, bytes);
        free(b);
    }
    assert_int_equal(scaf_drag_undo_count(x->d), undo0);
    /* a mirror: refused, nothing changes */
    assert_int_equal(
        post(x, "/api/transform", "{\"charts\": [0, 1], \"op\": \"flip\", \"axis\": \"u\"}", &text),
        409);
    assert_non_null(strstr(text, "remirror"));
    free(text);
    double *b = uv_now(x);
    assert_memory_equal(a, b, bytes);
    free(b);
    const char *ops[] = {"{\"charts\": [0, 1], \"op\": \"rotate\", \"angle\": 0.8}",
                         "{\"charts\": [0, 1], \"op\": \"scale\", \"factor\": 0.9, \"pivot\": [0, "
                         "0]}",
                         "{\"charts\": [2], \"op\": \"translate\", \"dx\": 0.01, \"dy\": -0.02}",
                         "{\"charts\": [0, 1], \"op\": \"flip\", \"axis\": \"v\", \"remirror\": "
                         "true}"};
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        double *before = uv_now(x);
        assert_int_equal(post(x, "/api/transform", ops[i], &text), 200);
        assert_non_null(strstr(text, "\"reached\": "));
        free(text);
        double *after = uv_now(x);
        assert_true(memcmp(before, after, bytes) != 0);
        certified(x);
        assert_int_equal(post(x, "/api/undo", "{}", NULL), 200);
        double *u = uv_now(x);
        assert_memory_equal(before, u, bytes);
        assert_int_equal(post(x, "/api/redo", "{}", NULL), 200);
        double *r = uv_now(x);
        assert_memory_equal(after, r, bytes);
        free(before);
        free(after);
        free(u);
        free(r);
    }
    assert_int_equal(post(x, "/api/save", "{}", &text), 200);
    assert_non_null(strstr(text, "\"bijective\": true"));
    free(text);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, x->out), 0);
    remove(x->out);
    free(a);
    close_spot(x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rigid_drag_through_the_server),
        cmocka_unit_test(transforms_undo_redo_and_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
