/* End-to-end tests of `scaf param` and of the SCAF loop on real meshes.
 *
 * CLI: a generated sample goes through `scaf param` (OBJ + report + SVG),
 * the output is proved bijective by `scaf check`, its `v` lines are the
 * input's; bad input gives the documented exit status and no output file.
 * Shared meshes (../shared/data, skipped when absent): the map is checked
 * with the kernel's checker after EVERY iteration (zero flipped, zero
 * degenerate, zero crossings), every accepted step lowers the total energy,
 * and the final E is below the initial one; camel_b with a harmonic start
 * is compared with the reference implementation's E after 30 iterations. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "app/param.h"
#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "scaf/scaf.h"
#include "support/param_watch.h"
#include "support/support.h"

static void cli_param_on_generated_sample(void **state)
{
    (void)state;
    char in[512], out[512], rep[512], svg[512];
    test_tmp_path("e2e_param_in.obj", in, sizeof in);
    test_tmp_path("e2e_param_out.obj", out, sizeof out);
    test_tmp_path("e2e_param_report.json", rep, sizeof rep);
    test_tmp_path("e2e_param.svg", svg, sizeof svg);
    remove(out);
    assert_int_equal(test_run("%s gen hemisphere --size 6 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s param %s -o %s --iterations 4 --quiet --verify --report %s --svg "
                              "%s --svg-scaffold",
                              SCAF_BINARY, in, out, rep, svg),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    /* v lines untouched, UVs present */
    mesh a, b;
    scaf_error err;
    assert_int_equal(mesh_read(in, &a, NULL, &err), SCAF_OK);
    assert_int_equal(mesh_read(out, &b, NULL, &err), SCAF_OK);
    assert_int_equal(a.nv, b.nv);
    assert_int_equal(a.nf, b.nf);
    assert_memory_equal(a.V, b.V, sizeof(double) * 3 * (size_t)a.nv);
    assert_memory_equal(a.F, b.F, sizeof(int) * 3 * (size_t)a.nf);
    assert_true(mesh_has_uv(&b));
    mesh_free(&a);
    mesh_free(&b);
    char *r = test_slurp(rep);
    assert_non_null(r);
    assert_non_null(strstr(r, "\"iterations\""));
    assert_non_null(strstr(r, "\"phase_seconds\""));
    assert_non_null(strstr(r, "\"factorization\""));
    assert_non_null(strstr(r, "\"options\""));
    free(r);
    char *s = test_slurp(svg);
    assert_non_null(s);
    assert_true(strncmp(s, "<?xml", 5) == 0);
    assert_non_null(strstr(s, "<polygon"));
    assert_non_null(strstr(s, "</svg>"));
    free(s);
    /* a mesh with UV seams: charts by seams */
    assert_int_equal(test_run("%s gen cubesphere --size 3 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s param %s -o %s --iterations 3 --quiet", SCAF_BINARY, in, out), 0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
}

static void cli_bad_input_leaves_no_output(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("e2e_param_bad.obj", in, sizeof in);
    test_tmp_path("e2e_param_bad_out.obj", out, sizeof out);
    remove(out);
    assert_int_equal(test_run("%s gen tetrahedron -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(
        test_run("%s param %s -o %s --seams input --quiet 2> /dev/null", SCAF_BINARY, in, out), 4);
    assert_false(test_exists(out));
    assert_int_equal(
        test_run("%s param %s -o %s --seams nonsense 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_false(test_exists(out));
    assert_int_equal(test_run("%s param %s/no-such-file.obj -o %s 2> /dev/null", SCAF_BINARY,
                              SCAF_TEST_TMPDIR, out),
                     3);
    assert_false(test_exists(out));
    assert_int_equal(test_run("%s param %s 2> /dev/null", SCAF_BINARY, in), 2);
    assert_int_equal(
        test_run("%s param %s -o %s --energy nonsense 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_int_equal(
        test_run("%s param %s -o %s --iterations -3 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_int_equal(
        test_run("%s param %s -o %s --box-scale 0.5 2> /dev/null", SCAF_BINARY, in, out), 2);
    assert_int_equal(test_run("%s param --help > /dev/null", SCAF_BINARY), 0);
    assert_false(test_exists(out));
    /* output folder that does not exist: exit 5, nothing written */
    char hemi[512];
    test_tmp_path("e2e_param_hemi.obj", hemi, sizeof hemi);
    assert_int_equal(test_run("%s gen hemisphere --size 3 -o %s", SCAF_BINARY, hemi), 0);
    assert_int_equal(test_run("%s param %s -o %s/missing-dir/x.obj --iterations 1 --quiet 2> "
                              "/dev/null",
                              SCAF_BINARY, hemi, SCAF_TEST_TMPDIR),
                     5);
}

/* ---- shared meshes, checked after every iteration ---------------------- */

static void camel_b_matches_reference(void **state)
{
    (void)state;
    double e = param_run_watched("disk/camel_b.obj", 30, SCAF_INIT_HARMONIC, NULL, 0);
    if (isnan(e)) skip();
    /* libigl's igl::triangle::scaf, same start, same E: 4.1238 after 30.
     * Our trajectory depends on rounding (the fill-reducing ordering alone
     * moves E after 30 iterations within 4.1235..4.1250), so the test
     * allows 0.05% above the reference; the value reached is printed and
     * recorded in bench/RESULTS-param.md. */
    print_message("camel_b harmonic, 30 iterations: E = %.5f (reference 4.1238)\n", e);
    assert_true(e <= 4.1238 * 1.0005);
}

static void disk_meshes_bijective_every_iteration(void **state)
{
    (void)state;
    int ran = 0;
    ran += !isnan(param_run_watched("disk/hand_lowres.obj", 10, SCAF_INIT_TUTTE, NULL, 0));
    ran += !isnan(param_run_watched("disk/camelhead.off", 3, SCAF_INIT_HARMONIC, NULL, 0));
    if (!ran) skip();
}

static void seam_meshes_by_charts(void **state)
{
    (void)state;
    const char *files[] = {"seams/myles_knot1_seamed.obj", "seams/myles_eight_seamed.obj",
                           "seams/blub.obj", "seams/spot.obj", "seams/human_neutral.obj"};
    int ran = 0;
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        /* Every seam mesh of the data set has charts that are disks once
         * pinch points (one vt shared by two fans) are split: all must run. */
        double e = param_run_watched(files[i], 4, SCAF_INIT_TUTTE, NULL, 0);
        ran += !isnan(e);
    }
    if (!ran) skip();
}

static void plane_with_27_holes(void **state)
{
    (void)state;
    double e = param_run_watched("bad/plane_holes.obj", 4, SCAF_INIT_TUTTE, NULL, 0);
    if (isnan(e)) skip();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cli_param_on_generated_sample),
        cmocka_unit_test(cli_bad_input_leaves_no_output),
        cmocka_unit_test(camel_b_matches_reference),
        cmocka_unit_test(disk_meshes_bijective_every_iteration),
        cmocka_unit_test(seam_meshes_by_charts),
        cmocka_unit_test(plane_with_27_holes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
