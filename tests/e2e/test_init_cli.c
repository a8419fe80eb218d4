/* End-to-end: `--init mvc` of `scaf param` and `scaf atlas` runs and its
 * output passes `scaf check` and carries "mvc" in the report; an unknown
 * init name is refused with exit 2 and leaves no output file. A 12-face
 * fan whose input UVs lie almost on a line (the case of issue #29 item 5,
 * found on a public robustness set) maps with every start: never exit 6. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "support/support.h"

/* One command with --init mvc on a generated sample: it runs, the output
 * passes `scaf check`, the report names the start; a bad init name is a
 * usage error (exit 2) with no output. */
typedef struct init_case {
    const char *name;   /* file name stem */
    const char *sample; /* `scaf gen` arguments */
    const char *cmd;    /* param / atlas */
    const char *caps;   /* iteration options */
    const char *bad;    /* an init name that is refused */
} init_case;

static void run_init_case(const init_case *c)
{
    char in[512], out[512], rep[512], name[256];
    snprintf(name, sizeof name, "e2e_init_%s_in.obj", c->name);
    test_tmp_path(name, in, sizeof in);
    snprintf(name, sizeof name, "e2e_init_%s_out.obj", c->name);
    test_tmp_path(name, out, sizeof out);
    snprintf(name, sizeof name, "e2e_init_%s.json", c->name);
    test_tmp_path(name, rep, sizeof rep);
    remove(out);
    assert_int_equal(test_run("%s gen %s -o %s", SCAF_BINARY, c->sample, in), 0);
    assert_int_equal(test_run("%s %s %s -o %s --init mvc %s --quiet --report %s", SCAF_BINARY,
                              c->cmd, in, out, c->caps, rep),
                     0);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    char *json = test_slurp(rep);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"mvc\""));
    free(json);
    remove(out);
    assert_int_equal(test_run("%s %s %s -o %s --init %s --quiet 2> /dev/null", SCAF_BINARY, c->cmd,
                              in, out, c->bad),
                     2);
    assert_false(test_exists(out));
}

static void param_init_mvc(void **state)
{
    (void)state;
    init_case c = {"param", "holes --size 4", "param", "--iterations 3 --verify", "meanvalue"};
    run_init_case(&c);
}

static void atlas_init_mvc(void **state)
{
    (void)state;
    init_case c = {"atlas", "cubesphere --size 3", "atlas", "--iterations 2 --compact-iterations 2",
                   "MVC"};
    run_init_case(&c);
}

/* A 12-face fan around one vertex whose UVs are a counter-clockwise but
 * ever thinner ellipse around x = 1.6185 (width w, height 2.035): valid
 * input UVs whose triangles are slivers down to w = 1e-15, i.e. the
 * corners agree in their first 15 digits. The default start, --init
 * input and --init input --padding 0 must all give a bijective atlas. */
static void atlas_sliver_fan(void **state)
{
    (void)state;
    const double widths[] = {1e-3, 1e-7, 1e-11, 1e-15};
    const char *starts[] = {"", "--init input", "--init input --padding 0"};
    char in[512], out[512];
    test_tmp_path("e2e_init_fan_in.obj", in, sizeof in);
    test_tmp_path("e2e_init_fan_out.obj", out, sizeof out);
    for (size_t w = 0; w < sizeof widths / sizeof *widths; w++) {
        FILE *f = fopen(in, "w");
        assert_non_null(f);
        const int n = 12;
        const double pi = 3.14159265358979323846;
        fprintf(f, "v 0 0 0\n");
        for (int i = 0; i < n; i++)
            fprintf(f, "v %.17g %.17g %.17g\n", cos(2 * pi * i / n), sin(2 * pi * i / n),
                    0.2 * sin(3.0 * i));
        fprintf(f, "vt 1.6185 -1.915\n");
        for (int i = 0; i < n; i++)
            fprintf(f, "vt %.17g %.17g\n", 1.6185 + widths[w] * cos(2 * pi * i / n),
                    -1.915 + 2.035 * sin(2 * pi * i / n));
        for (int i = 0; i < n; i++) {
            int a = i + 2, b = (i + 1) % n + 2;
            fprintf(f, "f 1/1 %d/%d %d/%d\n", a, a, b, b);
        }
        assert_int_equal(fclose(f), 0);
        for (size_t s = 0; s < sizeof starts / sizeof *starts; s++) {
            remove(out);
            int rc = test_run("%s atlas %s -o %s %s --iterations 20 --quiet", SCAF_BINARY, in, out,
                              starts[s]);
            if (rc != 0)
                fprintf(stderr, "width %g, start '%s': exit %d\n", widths[w], starts[s], rc);
            assert_int_equal(rc, 0);
            assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_init_mvc),
        cmocka_unit_test(atlas_init_mvc),
        cmocka_unit_test(atlas_sliver_fan),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
