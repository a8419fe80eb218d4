/* End-to-end cross-check of the exact self-intersection count against an
 * independent tool: Debian's `tetgen -d` on the shared closed meshes. Its
 * report repeats pairs ("facet #i intersects facet #j", 1-based); the
 * distinct pairs must be exactly scaf's: each one intersects by
 * si_classify_pair, and there are as many as si_check counts. Skipped
 * without the `tetgen` program or ../shared/data. Also on generated
 * surfaces (no data needed): the dented sphere intersects itself for both
 * tools, and `scaf untangle`'s output of it is free for both. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/self_intersect.h"
#include "mesh/mesh_io.h"
#include "support/support.h"

static int cmp_pair(const void *a, const void *b)
{
    const int *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return (p[1] > q[1]) - (p[1] < q[1]);
}

/* Distinct 0-based pairs (i < j) tetgen -d reports for the file; -1 when
 * tetgen did not run. */
static int tetgen_pairs(const char *src, const char *name, int (**pairs)[2])
{
    char copy[1024], log[1100];
    test_tmp_path(name, copy, sizeof copy);
    snprintf(log, sizeof log, "%s.tetgen.txt", copy);
    /* tetgen writes its output next to the input: work on a copy */
    if (test_run("cp '%s' '%s' && tetgen -d '%s' > '%s' 2>&1", src, copy, copy, log) != 0)
        return -1;
    char *text = test_slurp(log);
    if (!text) return -1;
    int n = 0, cap = 64;
    *pairs = malloc(sizeof **pairs * (size_t)cap);
    for (const char *p = text; (p = strstr(p, "Facet #")) != NULL; p++) {
        int a, b;
        if (sscanf(p, "Facet #%d intersects facet #%d", &a, &b) != 2) continue;
        if (n == cap) *pairs = realloc(*pairs, sizeof **pairs * (size_t)(cap *= 2));
        (*pairs)[n][0] = (a < b ? a : b) - 1;
        (*pairs)[n][1] = (a < b ? b : a) - 1;
        n++;
    }
    free(text);
    qsort(*pairs, (size_t)n, sizeof **pairs, cmp_pair);
    int u = 0;
    for (int i = 0; i < n; i++)
        if (u == 0 || cmp_pair((*pairs)[i], (*pairs)[u - 1]) != 0)
            memmove((*pairs)[u++], (*pairs)[i], sizeof **pairs);
    return u;
}

/* scaf and tetgen -d find the same pairs in the file src (OFF); want: how
 * many (-1: at least one). */
static void agree_path(const char *src, const char *name, long long want)
{
    mesh m;
    mesh_read_info info;
    scaf_error e;
    assert_int_equal(mesh_read(src, &m, &info, &e), SCAF_OK);
    si_report r;
    assert_int_equal(si_check(m.nv, m.V, m.nf, m.F, &r, &e), SCAF_OK);
    int(*pairs)[2] = NULL;
    int n = tetgen_pairs(src, name, &pairs);
    assert_true(n >= 0);
    print_message("    %s: tetgen -d %d distinct pairs, scaf %lld\n", src, n, r.pairs);
    if (want >= 0) assert_int_equal(r.pairs, want);
    else assert_true(r.pairs > 0);
    assert_int_equal(n, r.pairs);
    for (int i = 0; i < n; i++)
        assert_int_not_equal(si_classify_pair(m.V, m.F + 3 * pairs[i][0], m.F + 3 * pairs[i][1]),
                             SI_PAIR_NONE);
    free(pairs);
    mesh_free(&m);
}

static void agree(const char *rel, const char *name, long long want)
{
    char src[1024];
    if (test_data_path(rel, src, sizeof src)) agree_path(src, name, want);
}

/* The OBJ in as an OFF file out (tetgen reads OFF, not OBJ). */
static void obj_to_off(const char *in, const char *out)
{
    mesh m;
    mesh_read_info info;
    assert_int_equal(mesh_read(in, &m, &info, NULL), SCAF_OK);
    FILE *f = fopen(out, "w");
    assert_non_null(f);
    fprintf(f, "OFF\n%d %d 0\n", m.nv, m.nf);
    for (int v = 0; v < m.nv; v++)
        fprintf(f, "%.17g %.17g %.17g\n", m.V[3 * v], m.V[3 * v + 1], m.V[3 * v + 2]);
    for (int t = 0; t < m.nf; t++)
        fprintf(f, "3 %d %d %d\n", m.F[3 * t], m.F[3 * t + 1], m.F[3 * t + 2]);
    assert_int_equal(fclose(f), 0);
    mesh_free(&m);
}

static void generated_and_untangled(void **state)
{
    (void)state;
    if (!test_have_program("tetgen")) skip();
    char obj[1024], off[1024], res[1024], res_off[1024];
    test_tmp_path("agree_dented.obj", obj, sizeof obj);
    test_tmp_path("agree_dented_src.off", off, sizeof off);
    test_tmp_path("agree_dented_untangled.obj", res, sizeof res);
    test_tmp_path("agree_dented_untangled_src.off", res_off, sizeof res_off);
    assert_int_equal(test_run("'%s' gen dented -o '%s'", SCAF_BINARY, obj), 0);
    assert_int_equal(test_run("'%s' untangle '%s' -o '%s' -q", SCAF_BINARY, obj, res), 0);
    obj_to_off(obj, off);
    obj_to_off(res, res_off);
    agree_path(off, "agree_dented.off", -1);
    agree_path(res_off, "agree_dented_untangled.off", 0);
}

static void tetgen_and_scaf_agree(void **state)
{
    (void)state;
    char buf[1024];
    if (!test_have_program("tetgen") || !test_data_path("closed", buf, sizeof buf)) skip();
    agree("closed/leg-intersect.off", "agree_leg_intersect.off", 239);
    agree("closed/leg-flow6.off", "agree_leg_flow6.off", 0);
    agree("closed/fertility.off", "agree_fertility.off", 0); /* tetgen reads OFF, not OBJ */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tetgen_and_scaf_agree),
        cmocka_unit_test(generated_and_untangled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
