/* End-to-end tests of extreme but valid numbers (issue 9, section 4): the
 * built `scaf` (SCAF_BINARY) on meshes whose coordinates are subnormal,
 * tiny or near the largest double, and on option values at the edge of
 * their range. JSON output is read back with Python's strict parser
 * (NaN / Infinity tokens refused); finite inputs get finite answers or a
 * usage error naming the allowed range, never an internal error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mesh/samples.h"
#include "support/support.h"

#ifndef SCAF_BINARY
#define SCAF_BINARY "scaf"
#endif

/* Python: exit 0 when argv[1] is strict JSON whose keys argv[2:] all hold
 * finite numbers; 3 on a NaN/Infinity token, 4 on a missing or non-number
 * value, 1 on other parse errors. */
#define STRICT_JSON_NUMBERS                                                                        \
    "python3 -c 'import json,sys\n"                                                                \
    "def bad(c): sys.exit(3)\n"                                                                    \
    "d = json.load(open(sys.argv[1]), parse_constant=bad)\n"                                       \
    "ok = all(isinstance(d.get(k), (int, float)) and not isinstance(d.get(k), bool) for k in "     \
    "sys.argv[2:])\n"                                                                              \
    "sys.exit(0 if ok else 4)'"

/* One triangle with UVs (0,0) (s,0) (0,s), as text s. */
static const char *write_triangle(const char *name, const char *s, char *path, size_t size)
{
    test_tmp_path(name, path, size);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt %s 0\nvt 0 %s\nf 1/1 2/2 3/3\n", s, s);
    fclose(f);
    return path;
}

static void check_json_is_strict_for_extreme_uvs(void **state)
{
    (void)state;
    if (!test_have_program("python3")) skip();
    const char *scales[] = {"1e-310", "1e155", "1e-200", "1e308", "4.9e-324"};
    for (size_t i = 0; i < sizeof scales / sizeof *scales; i++) {
        char obj[512], json[512];
        write_triangle("extreme_tri.obj", scales[i], obj, sizeof obj);
        test_tmp_path("extreme_tri.json", json, sizeof json);
        assert_int_equal(test_run("%s check --json %s > %s", SCAF_BINARY, obj, json), 0);
        /* one chart: min_chart_gap is null; the efficiency is a number */
        assert_int_equal(test_run(STRICT_JSON_NUMBERS " %s packing_efficiency", json), 0);
    }
}

static void check_gap_of_two_far_charts_is_a_number(void **state)
{
    (void)state;
    if (!test_have_program("python3")) skip();
    char obj[512], json[512];
    test_tmp_path("extreme_two.obj", obj, sizeof obj);
    FILE *f = fopen(obj, "w");
    assert_non_null(f);
    fprintf(f,
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 2 1 0\n"
            "vt 0 0\nvt 1e154 0\nvt 0 1e154\nvt 4e154 0\nvt 5e154 0\nvt 4e154 1e154\n"
            "f 1/1 2/2 3/3\nf 4/4 5/5 6/6\n");
    fclose(f);
    test_tmp_path("extreme_two.json", json, sizeof json);
    assert_int_equal(test_run("%s check --json %s > %s", SCAF_BINARY, obj, json), 0);
    assert_int_equal(test_run(STRICT_JSON_NUMBERS " %s min_chart_gap packing_efficiency", json), 0);
}

/* Paddings below 2^-200 (the exact certificate's range), directly or as
 * texels / resolution, are usage errors naming the range, found before the
 * input is read (a missing input would be exit 3). */
static void atlas_padding_range_checked_up_front(void **state)
{
    (void)state;
    char out[512], err[512];
    test_tmp_path("extreme_out.obj", out, sizeof out);
    test_tmp_path("extreme_err.txt", err, sizeof err);
    const char *opts[] = {"--padding 1e-61", "--resolution 1e300 --padding-texels 1",
                          "--padding 0.5", "--padding-texels 512 --resolution 1024"};
    for (size_t i = 0; i < sizeof opts / sizeof *opts; i++) {
        assert_int_equal(
            test_run("%s atlas /nonexistent/in.obj -o %s %s 2> %s", SCAF_BINARY, out, opts[i], err),
            2);
        char *msg = test_slurp(err);
        assert_non_null(msg);
        assert_non_null(strstr(msg, "must be 0 or in [2^-200, 0.5)"));
        free(msg);
        assert_false(test_exists(out));
    }
}

/* The smallest padding accepted runs to the end and is certified. */
static void atlas_smallest_padding_runs(void **state)
{
    (void)state;
    char in[512], out[512];
    test_tmp_path("extreme_cs.obj", in, sizeof in);
    test_tmp_path("extreme_cs_out.obj", out, sizeof out);
    assert_int_equal(test_run("%s gen cubesphere --size 2 -o %s", SCAF_BINARY, in), 0);
    assert_int_equal(test_run("%s atlas %s -o %s -q --padding 6.3e-61", SCAF_BINARY, in, out), 0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
}

/* The hemisphere sample with every position times s, face 0 made
 * degenerate (its third vertex moved onto its first) when
 * degenerate is set; written as OBJ with round-trip precision. */
static const char *write_scaled_hemisphere(const char *name, double s, int degenerate, char *path,
                                           size_t size)
{
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("hemisphere", 4, &m, &err), SCAF_OK);
    if (degenerate) {
        const double *a = m.V + 3 * m.F[0], *b = m.V + 3 * m.F[1];
        double *c = m.V + 3 * m.F[2];
        /* c = a: a repeated position, zero area at every scale */
        (void)b;
        for (int k = 0; k < 3; k++) c[k] = a[k];
    }
    test_tmp_path(name, path, size);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int v = 0; v < m.nv; v++)
        fprintf(f, "v %.17g %.17g %.17g\n", m.V[3 * v] * s, m.V[3 * v + 1] * s, m.V[3 * v + 2] * s);
    for (int t = 0; t < m.nf; t++)
        fprintf(f, "f %d %d %d\n", m.F[3 * t] + 1, m.F[3 * t + 1] + 1, m.F[3 * t + 2] + 1);
    fclose(f);
    mesh_free(&m);
    return path;
}

/* info, param and atlas agree on what is degenerate, at any scale; a
 * mesh without degenerate faces is parametrized at 1e80 and 1e-80 (was
 * "chart has 3D area inf" / "face 0 is degenerate (zero 3D area)"). */
static void one_degeneracy_verdict_at_any_scale(void **state)
{
    (void)state;
    const double scales[] = {1.0, 1e80, 1e-80, 1e300, 1e-300};
    for (size_t i = 0; i < sizeof scales / sizeof *scales; i++)
        for (int deg = 0; deg < 2; deg++) {
            char obj[512], out[512], txt[512];
            write_scaled_hemisphere("extreme_hemi.obj", scales[i], deg, obj, sizeof obj);
            test_tmp_path("extreme_hemi_out.obj", out, sizeof out);
            test_tmp_path("extreme_hemi.txt", txt, sizeof txt);
            assert_int_equal(test_run("%s info --json %s > %s", SCAF_BINARY, obj, txt), 0);
            char *info = test_slurp(txt);
            assert_non_null(info);
            /* faces 0 and 1 share the moved vertex: both degenerate */
            assert_non_null(
                strstr(info, deg ? "\"degenerate_faces\": 2," : "\"degenerate_faces\": 0,"));
            free(info);
            const char *cmd[] = {"param", "atlas"};
            for (int c = 0; c < 2; c++) {
                int rc = test_run("%s %s %s -o %s -q 2> %s", SCAF_BINARY, cmd[c], obj, out, txt);
                if (!deg) {
                    assert_int_equal(rc, 0);
                    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
                    continue;
                }
                assert_int_equal(rc, 4);
                char *msg = test_slurp(txt);
                assert_non_null(msg);
                assert_non_null(strstr(msg, "face 0 is degenerate"));
                free(msg);
            }
        }
}

/* Every out-of-range option value is a usage error (2) that says the
 * allowed range, before the input is read. */
static void options_out_of_range_say_the_range(void **state)
{
    (void)state;
    struct {
        const char *cmd, *opts, *want;
    } c[] = {
        {"atlas", "--padding -1", "0 or in [2^-200, 0.5)"},
        {"atlas", "--resolution 0.5", ">= 1"},
        {"atlas", "--padding-texels -2 --resolution 10", ">= 0"},
        {"atlas", "--distortion-tolerance -1", "distortion_tolerance must be a finite number >= 0"},
        {"atlas", "--compact-lambda-ratio 0", "compact_lambda_ratio must be a finite number > 0"},
        {"atlas", "--box-scale 1e300", "box_scale must be in [1, 1e6]"},
        {"param", "--tolerance -1", "tolerance must be a finite number >= 0"},
        {"param", "--min-angle 45", "min_angle_deg must be in [0, 30]"},
    };
    char out[512], err[512];
    test_tmp_path("extreme_out.obj", out, sizeof out);
    test_tmp_path("extreme_err.txt", err, sizeof err);
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        assert_int_equal(test_run("%s %s /nonexistent/in.obj -o %s %s 2> %s", SCAF_BINARY, c[i].cmd,
                                  out, c[i].opts, err),
                         2);
        char *msg = test_slurp(err);
        assert_non_null(msg);
        if (!strstr(msg, c[i].want))
            fail_msg("%s %s: '%s' does not say '%s'", c[i].cmd, c[i].opts, msg, c[i].want);
        free(msg);
    }
}

/* A tetrahedron's surface with corners 0, s e_x, s e_y, s e_z (text s). */
static void write_tetra(const char *path, const char *s)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "v 0 0 0\nv %s 0 0\nv 0 %s 0\nv 0 0 %s\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", s, s,
            s);
    fclose(f);
}

/* issue 29: the 3D commands at 1e300 and 1e-300. `scaf tet` made TetGen
 * assert (exit 70) at 1e300 and saw "facets intersect" at 1e-300;
 * `flow` and `inflate` called face 0 "zero area". Now they work at unit
 * scale (app/unit_scale): the tets check positive, the inflated
 * surface is written in the input's units; a range a double cannot hold
 * at once, or a box beyond the largest double, is exit 4 saying so. */
static void three_d_commands_at_any_scale(void **state)
{
    (void)state;
    char in[512], o[512], t[512], log[512];
    test_tmp_path("extreme_tetra.obj", in, sizeof in);
    test_tmp_path("extreme_tetra_out.obj", o, sizeof o);
    test_tmp_path("extreme_tetra.mesh", t, sizeof t);
    test_tmp_path("extreme_tetra.txt", log, sizeof log);
    static const char *const scales[] = {"1e300", "1e-300", "3e-310"};
    for (int i = 0; i < 3; i++) {
        write_tetra(in, scales[i]);
        assert_int_equal(test_run("%s tet %s -o %s -q", SCAF_BINARY, in, t), 0);
        assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, t), 0);
        assert_int_equal(test_run("%s flow %s -o %s --steps 2 -q", SCAF_BINARY, in, o), 0);
        assert_int_equal(
            test_run("%s inflate %s -o %s --scale 1.5 -n 3 -q --tets %s", SCAF_BINARY, in, o, t),
            0);
        assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, t), 0);
        /* in the input's units: the largest coordinate within 4x of s */
        char *out = test_slurp(o);
        assert_non_null(out);
        double big = 0.0, sc = strtod(scales[i], NULL);
        for (const char *p = out; (p = strstr(p, "v ")) != NULL; p += 2) {
            double x, y, z;
            if (sscanf(p, "v %lf %lf %lf", &x, &y, &z) == 3)
                big = fmax(big, fmax(fabs(x), fmax(fabs(y), fabs(z))));
        }
        free(out);
        assert_true(big > sc / 4 && big < sc * 4);
    }
    /* 1e308: the box around it is beyond the largest double */
    write_tetra(in, "1e308");
    assert_int_equal(test_run("%s tet %s -o %s -q 2> %s", SCAF_BINARY, in, t, log), 4);
    char *e = test_slurp(log);
    assert_non_null(e);
    assert_non_null(strstr(e, "beyond the largest double"));
    free(e);
    /* 1e300 and 1e-300 in one surface: more than a double holds at once */
    FILE *f = fopen(in, "w");
    assert_non_null(f);
    fputs("v 1e-300 0 0\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nf 1 3 2\nf 1 2 4\nf 1 4 "
          "3\nf 2 3 4\n",
          f);
    fclose(f);
    static const char *const cmds[] = {"tet %s -o %s -q 2> %s",
                                       "inflate %s -o %s.obj --scale 1.5 -q 2> %s"};
    for (int c = 0; c < 2; c++) {
        char fmt[128];
        snprintf(fmt, sizeof fmt, "%%s %s", cmds[c]);
        assert_int_equal(test_run(fmt, SCAF_BINARY, in, t, log), 4);
        e = test_slurp(log);
        assert_non_null(e);
        assert_non_null(strstr(e, "the coordinates range from 1e-300 to 1e+300"));
        free(e);
    }
}

/* untangle on a self-intersecting sphere at 1e300 and 1e-300 (was exit 6
 * "the surface has area -nan" / "area 0: cannot normalize it"): freed,
 * written in the input's units. */
static void untangle_at_any_scale(void **state)
{
    (void)state;
    static const double scales[] = {1e300, 1e-300};
    for (int i = 0; i < 2; i++) {
        mesh m;
        scaf_error err;
        assert_int_equal(mesh_sample_make("dented", 3, &m, &err), SCAF_OK);
        char in[512], out[512];
        test_tmp_path("extreme_dented.obj", in, sizeof in);
        test_tmp_path("extreme_dented_out.obj", out, sizeof out);
        FILE *f = fopen(in, "w");
        assert_non_null(f);
        for (int v = 0; v < m.nv; v++)
            fprintf(f, "v %.17g %.17g %.17g\n", m.V[3 * v] * scales[i], m.V[3 * v + 1] * scales[i],
                    m.V[3 * v + 2] * scales[i]);
        for (int t = 0; t < m.nf; t++)
            fprintf(f, "f %d %d %d\n", m.F[3 * t] + 1, m.F[3 * t + 1] + 1, m.F[3 * t + 2] + 1);
        fclose(f);
        mesh_free(&m);
        assert_int_not_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, in), 0);
        assert_int_equal(test_run("%s untangle %s -o %s -q", SCAF_BINARY, in, out), 0);
        assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
        char *text = test_slurp(out);
        assert_non_null(text);
        double big = 0.0;
        for (const char *p = text; (p = strstr(p, "v ")) != NULL; p += 2) {
            double x, y, z;
            if (sscanf(p, "v %lf %lf %lf", &x, &y, &z) == 3)
                big = fmax(big, fmax(fabs(x), fmax(fabs(y), fabs(z))));
        }
        free(text);
        assert_true(big > scales[i] / 4 && big < scales[i] * 4);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(check_json_is_strict_for_extreme_uvs),
        cmocka_unit_test(check_gap_of_two_far_charts_is_a_number),
        cmocka_unit_test(atlas_padding_range_checked_up_front),
        cmocka_unit_test(atlas_smallest_padding_runs),
        cmocka_unit_test(options_out_of_range_say_the_range),
        cmocka_unit_test(one_degeneracy_verdict_at_any_scale),
        cmocka_unit_test(three_d_commands_at_any_scale),
        cmocka_unit_test(untangle_at_any_scale),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
