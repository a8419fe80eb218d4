/* End-to-end tests of `scaf atlas --seams auto` on the topologies the
 * automatic charts must take, each output proved bijective by `scaf
 * check` (exact): an open plate with six holes; the same plate made solid
 * (a closed surface of genus 6: top, bottom and a wall around every
 * loop); fertility (genus 4, shared data, skipped when absent). And the
 * outputs a user reuses: `--chart-groups` puts every face under `g
 * chart_N` with N its chart in the report's face_chart, for an OBJ input
 * (rewritten) and an OFF input (plain writer), and our own grouped OBJ
 * reads back into `scaf atlas`; `--png-seams` draws the surface beside
 * the atlas (three 512-pixel panels). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/mesh_io.h"
#include "support/support.h"

#define QUICK "--iterations 20 --compact-iterations 5"

/* `scaf atlas IN -o OUT --seams auto EXTRA` exits 0, says "seams: auto",
 * and OUT is bijective by `scaf check`. */
static void atlas_ok(const char *in, const char *out, const char *extra)
{
    char err[512];
    test_tmp_path("e2e_auto_err.txt", err, sizeof err);
    remove(out);
    int rc = test_run("%s atlas %s -o %s --seams auto %s %s 2> %s", SCAF_BINARY, in, out, QUICK,
                      extra, err);
    char *text = test_slurp(err);
    assert_non_null(text);
    if (rc != 0) print_error("%s", text);
    assert_int_equal(rc, 0);
    assert_non_null(strstr(text, "seams: auto"));
    free(text);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
}

/* The plate of `scaf gen holes` (a height field) made solid: the top at
 * +h, the bottom at -h with its faces turned, and two triangles per
 * boundary edge joining them. Returns the number of boundary edges. */
static int write_solid(const mesh *p, double h, const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < p->nv; i++)
            fprintf(f, "v %.17g %.17g %.17g\n", p->V[3 * i], p->V[3 * i + 1],
                    p->V[3 * i + 2] + (s ? -h : h));
    int n = p->nv, walls = 0;
    for (int t = 0; t < p->nf; t++) {
        const int *F = p->F + 3 * t;
        fprintf(f, "f %d %d %d\n", F[0] + 1, F[1] + 1, F[2] + 1);
        fprintf(f, "f %d %d %d\n", n + F[0] + 1, n + F[2] + 1, n + F[1] + 1);
        /* a boundary edge a -> b: no other face has b -> a */
        for (int j = 0; j < 3; j++) {
            int a = F[j], b = F[(j + 1) % 3], inner = 0;
            for (int u = 0; u < p->nf && !inner; u++)
                for (int k = 0; k < 3; k++)
                    if (p->F[3 * u + k] == b && p->F[3 * u + (k + 1) % 3] == a) inner = 1;
            if (inner) continue;
            /* top edge a -> b; the wall goes down outside it */
            fprintf(f, "f %d %d %d\nf %d %d %d\n", b + 1, a + 1, n + a + 1, b + 1, n + a + 1,
                    n + b + 1);
            walls++;
        }
    }
    fclose(f);
    return walls;
}

static void open_plate_and_solid_genus_six(void **state)
{
    (void)state;
    char plate[512], solid[512], out[512], info[512];
    test_tmp_path("e2e_auto_plate.obj", plate, sizeof plate);
    test_tmp_path("e2e_auto_solid.obj", solid, sizeof solid);
    test_tmp_path("e2e_auto_out.obj", out, sizeof out);
    test_tmp_path("e2e_auto_info.txt", info, sizeof info);
    assert_int_equal(test_run("%s gen holes --size 5 -o %s", SCAF_BINARY, plate), 0);
    /* open, seven boundary loops: automatic seams all the same */
    atlas_ok(plate, out, "");
    mesh p;
    scaf_error e;
    assert_int_equal(mesh_read(plate, &p, NULL, &e), SCAF_OK);
    assert_true(write_solid(&p, 0.05, solid) > 0);
    mesh_free(&p);
    assert_int_equal(test_run("%s info %s > %s", SCAF_BINARY, solid, info), 0);
    char *text = test_slurp(info);
    assert_non_null(text);
    if (!strstr(text, "genus           6")) print_error("%s", text);
    assert_non_null(strstr(text, "genus           6"));
    assert_non_null(strstr(text, "boundary loops  0"));
    free(text);
    atlas_ok(solid, out, "");
}

static void fertility_genus_four(void **state)
{
    (void)state;
    char buf[1024], out[512];
    const char *in = test_data_path("closed/fertility.off", buf, sizeof buf);
    if (!in) {
        test_missing("closed/fertility.off");
        skip();
    }
    test_tmp_path("e2e_auto_fertility.obj", out, sizeof out);
    /* the cuts are the point here: no chart splitting, few iterations (the
     * whole run under ASan stays within the test's time) */
    atlas_ok(in, out, "--max-distortion 0 --no-split-charts --iterations 3 --compact-iterations 0");
}

/* Every `f` line of OBJ text lies under `g chart_N` with N = chart[f];
 * returns the number of `g` lines. */
static int groups_match(const char *obj, const int *chart, int nf)
{
    int cur = -1, f = 0, groups = 0;
    for (const char *p = obj; *p;) {
        if (!strncmp(p, "g chart_", 8)) {
            cur = atoi(p + 8);
            groups++;
        } else if (!strncmp(p, "g ", 2)) {
            cur = -2; /* someone else's group */
        } else if (!strncmp(p, "f ", 2)) {
            assert_true(f < nf);
            assert_int_equal(cur, chart[f]);
            f++;
        }
        const char *nl = strchr(p, '\n');
        if (!nl) break;
        p = nl + 1;
    }
    assert_int_equal(f, nf);
    return groups;
}

/* face_chart of a report as an array (nf entries, caller frees). */
static int *face_chart(const char *report, int nf)
{
    char *json = test_slurp(report);
    assert_non_null(json);
    const char *p = strstr(json, "\"face_chart\": [");
    assert_non_null(p);
    p += strlen("\"face_chart\": [");
    int *c = malloc(sizeof(int) * (size_t)nf);
    assert_non_null(c);
    for (int f = 0; f < nf; f++) {
        char *end;
        c[f] = (int)strtol(p, &end, 10);
        assert_true(end != p);
        p = end;
        while (*p == ',' || *p == ' ') p++;
    }
    assert_int_equal(*p, ']');
    free(json);
    return c;
}

static void chart_groups_name_every_face(void **state)
{
    (void)state;
    char ball[512], off[512], out[512], rep[512], again[512], extra[1100];
    test_tmp_path("e2e_auto_ball.obj", ball, sizeof ball);
    test_tmp_path("e2e_auto_ball.off", off, sizeof off);
    test_tmp_path("e2e_auto_groups.obj", out, sizeof out);
    test_tmp_path("e2e_auto_groups.json", rep, sizeof rep);
    test_tmp_path("e2e_auto_again.obj", again, sizeof again);
    /* an OBJ input with a group of its own: ours replace it */
    assert_int_equal(
        test_run("(echo 'g mine'; %s gen icosphere --size 3 -o -) > %s", SCAF_BINARY, ball), 0);
    mesh b;
    scaf_error e;
    assert_int_equal(mesh_read(ball, &b, NULL, &e), SCAF_OK);
    FILE *f = fopen(off, "w");
    assert_non_null(f);
    fprintf(f, "OFF\n%d %d 0\n", b.nv, b.nf);
    for (int i = 0; i < b.nv; i++)
        fprintf(f, "%.17g %.17g %.17g\n", b.V[3 * i], b.V[3 * i + 1], b.V[3 * i + 2]);
    for (int i = 0; i < b.nf; i++)
        fprintf(f, "3 %d %d %d\n", b.F[3 * i], b.F[3 * i + 1], b.F[3 * i + 2]);
    fclose(f);
    const char *inputs[] = {ball, off};
    for (int k = 0; k < 2; k++) {
        snprintf(extra, sizeof extra, "--chart-groups --report %s", rep);
        atlas_ok(inputs[k], out, extra);
        int *chart = face_chart(rep, b.nf);
        char *obj = test_slurp(out);
        assert_non_null(obj);
        assert_true(groups_match(obj, chart, b.nf) >= 2);
        assert_null(strstr(obj, "g mine"));
        free(obj);
        free(chart);
    }
    /* our grouped OBJ reads back: its vt seams are the charts' */
    assert_int_equal(test_run("%s atlas %s -o %s --quiet %s", SCAF_BINARY, out, again, QUICK), 0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, again), 0);
    /* without the option, no chart groups */
    atlas_ok(ball, out, "");
    char *obj = test_slurp(out);
    assert_non_null(obj);
    assert_null(strstr(obj, "g chart_"));
    assert_non_null(strstr(obj, "g mine"));
    free(obj);
    mesh_free(&b);
}

static void png_seams_beside_the_atlas(void **state)
{
    (void)state;
    char ball[512], out[512], png[512], extra[1100];
    test_tmp_path("e2e_auto_ball2.obj", ball, sizeof ball);
    test_tmp_path("e2e_auto_png.obj", out, sizeof out);
    test_tmp_path("e2e_auto_seams.png", png, sizeof png);
    assert_int_equal(test_run("%s gen icosphere --size 3 -o %s", SCAF_BINARY, ball), 0);
    remove(png);
    snprintf(extra, sizeof extra, "--png-seams %s", png);
    atlas_ok(ball, out, extra);
    char *pic = test_slurp(png);
    assert_non_null(pic);
    assert_memory_equal(pic, "\x89PNG", 4);
    assert_memory_equal(pic + 16, "\0\0\x06\0\0\0\x02\0", 8); /* IHDR 1536 x 512 */
    free(pic);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(open_plate_and_solid_genus_six),
        cmocka_unit_test(fertility_genus_four),
        cmocka_unit_test(chart_groups_name_every_face),
        cmocka_unit_test(png_seams_beside_the_atlas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
