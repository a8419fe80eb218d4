/* tools/edit_start: `scaf edit` opens any mesh `scaf atlas` maps. Input
 * UVs that are not bijective (spot.obj of the test data: 177 flipped
 * triangles, a mirrored chart) and meshes without UVs (a closed scan,
 * closed/bunny.obj; a generated icosphere, no data needed) start from the
 * atlas; --start input refuses the same files with the exit status and
 * message the help promises. The first layout is checked by code
 * independent of the editor: the exact bijectivity checker on its
 * positions and the exact padding certificate on the output a save would
 * write. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "edit_start.h"
#include "exit_codes.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "support/support.h"

#define PADDING (4.0 / 1024.0)

/* The layout of d is bijective (exact) and its saved form keeps the
 * padding (exact certificate on the doubles a save writes). */
static void assert_first_layout_valid(const scaf_drag_t *d)
{
    int nw = scaf_drag_uv_count(d), nf = scaf_drag_face_count(d);
    double *UV = malloc(sizeof(double) * 2 * (size_t)nw);
    double *UVn = malloc(sizeof(double) * 2 * (size_t)nw);
    int *FT = malloc(sizeof(int) * 3 * (size_t)nf), *chart = malloc(sizeof(int) * (size_t)nf);
    assert_true(UV && UVn && FT && chart);
    assert_int_equal(scaf_drag_get_uv(d, UV, FT, chart), SCAF_OK);
    bij_report r;
    assert_int_equal(bij_check(nw, UV, nf, FT, chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    double eff = 0.0, gap = 0.0;
    assert_int_equal(scaf_drag_get_output((scaf_drag_t *)d, UVn, NULL, NULL, &eff, &gap), SCAF_OK);
    assert_int_equal(bij_check(nw, UVn, nf, FT, chart, NULL, &r, NULL), SCAF_OK);
    assert_true(r.bijective);
    int *seg = NULL, nseg = 0, ok = 0;
    assert_int_equal(chart_gap_segments(nf, FT, chart, &seg, &nseg, NULL), SCAF_OK);
    assert_int_equal(chart_gap_certify(UVn, seg, nseg, PADDING, &ok, NULL, NULL), SCAF_OK);
    assert_true(ok);
    assert_true(gap >= PADDING);
    free(seg);
    free(UV);
    free(UVn);
    free(FT);
    free(chart);
}

/* auto on m starts from the atlas with several charts, valid. */
static void assert_auto_starts_from_atlas(const char *name, const mesh *m)
{
    scaf_drag_t *d = NULL;
    edit_start_kind from = EDIT_START_FROM_INPUT;
    assert_int_equal(edit_start_layout(name, m, "auto", PADDING, SCAF_SEAMS_DEFAULT, 1, &d, &from),
                     EXIT_OK);
    assert_non_null(d);
    assert_int_equal(from, EDIT_START_FROM_ATLAS);
    assert_true(scaf_drag_chart_count(d) >= 2);
    assert_int_equal(scaf_drag_iterations(d), 0);
    assert_first_layout_valid(d);
    scaf_drag_destroy(d);
}

static int read_data(const char *relative, mesh *m)
{
    char path[1024];
    if (!test_data_path(relative, path, sizeof path)) {
        test_missing(relative);
        return 0;
    }
    mesh_read_info info;
    scaf_error err;
    assert_int_equal(mesh_read(path, m, &info, &err), SCAF_OK);
    return 1;
}

/* spot's vt are not bijective: auto starts from the atlas, --start input
 * exits 4. */
static void spot_with_flipped_uvs_opens(void **state)
{
    (void)state;
    mesh m;
    if (!read_data("seams/spot.obj", &m)) skip();
    assert_true(m.nuv > 0);
    assert_auto_starts_from_atlas("spot.obj", &m);
    scaf_drag_t *d = NULL;
    edit_start_kind from;
    assert_int_equal(
        edit_start_layout("spot.obj", &m, "input", PADDING, SCAF_SEAMS_DEFAULT, 1, &d, &from),
        EXIT_MESH);
    assert_null(d);
    mesh_free(&m);
}

/* A closed scan without vt: automatic seams, the atlas. */
static void closed_bunny_opens(void **state)
{
    (void)state;
    mesh m;
    if (!read_data("closed/bunny.obj", &m)) skip();
    assert_int_equal(m.nuv, 0);
    assert_auto_starts_from_atlas("bunny.obj", &m);
    scaf_drag_t *d = NULL;
    edit_start_kind from;
    assert_int_equal(
        edit_start_layout("bunny.obj", &m, "input", PADDING, SCAF_SEAMS_DEFAULT, 1, &d, &from),
        EXIT_USAGE);
    assert_null(d);
    mesh_free(&m);
}

/* The same without test data: a closed icosphere; and the atlas's own
 * output (bijective vt, padding kept) starts from its UVs as they are. */
static void closed_icosphere_opens_and_its_atlas_starts_from_uvs(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, &err), SCAF_OK);
    free(m.UV);
    free(m.FT);
    m.UV = NULL;
    m.FT = NULL;
    m.nuv = 0;
    assert_auto_starts_from_atlas("icosphere", &m);
    /* the certified output of that start, as vt: a save's file */
    scaf_drag_t *d = NULL;
    edit_start_kind from;
    assert_int_equal(
        edit_start_layout("icosphere", &m, "atlas", PADDING, SCAF_SEAMS_DEFAULT, 1, &d, &from),
        EXIT_OK);
    int nw = scaf_drag_uv_count(d);
    m.nuv = nw;
    m.UV = malloc(sizeof(double) * 2 * (size_t)nw);
    m.FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    assert_true(m.UV && m.FT);
    assert_int_equal(scaf_drag_get_output(d, m.UV, NULL, NULL, NULL, NULL), SCAF_OK);
    double *layout = malloc(sizeof(double) * 2 * (size_t)nw);
    assert_non_null(layout);
    assert_int_equal(scaf_drag_get_uv(d, layout, m.FT, NULL), SCAF_OK);
    free(layout);
    scaf_drag_destroy(d);
    d = NULL;
    assert_int_equal(
        edit_start_layout("icosphere", &m, "auto", PADDING, SCAF_SEAMS_DEFAULT, 1, &d, &from),
        EXIT_OK);
    assert_int_equal(from, EDIT_START_FROM_INPUT);
    assert_first_layout_valid(d);
    scaf_drag_destroy(d);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spot_with_flipped_uvs_opens),
        cmocka_unit_test(closed_bunny_opens),
        cmocka_unit_test(closed_icosphere_opens_and_its_atlas_starts_from_uvs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
