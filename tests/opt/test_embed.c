/* Tests for opt/embed: Tutte and harmonic embeddings of generated disks
 * and an annulus (hole filled by a fan) are valid (every triangle
 * positively oriented, decided exactly), the boundary lies on the circle
 * of the chart's area, and bad loops are refused with a reason. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"
#include "opt/embed.h"
#include "polar_disk.h"

static double chart_area(const polar_disk *m)
{
    double A = 0;
    for (int f = 0; f < m->nf; f++) {
        const double *a = m->V + 3 * m->F[3 * f], *b = m->V + 3 * m->F[3 * f + 1],
                     *c = m->V + 3 * m->F[3 * f + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
               v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
               z = u[0] * v[1] - u[1] * v[0];
        A += 0.5 * sqrt(x * x + y * y + z * z);
    }
    return A;
}

static int count_nonpositive(const polar_disk *m, const double *UV)
{
    int bad = 0;
    for (int f = 0; f < m->nf; f++)
        bad += !(
            orient2d(UV + 2 * m->F[3 * f], UV + 2 * m->F[3 * f + 1], UV + 2 * m->F[3 * f + 2]) > 0);
    return bad;
}

static void check_embedding(int annulus, opt_embed_method method, int reverse_outer)
{
    polar_disk m;
    assert_int_equal(polar_disk_make(&m, 12, 40, 0.8, annulus), 0);
    if (reverse_outer)
        for (int i = 0, j = m.start[1] - 1; i < j; i++, j--) {
            int t = m.loops[i];
            m.loops[i] = m.loops[j];
            m.loops[j] = t;
        }
    opt_chart_loops L = {m.nloops, m.start, m.loops, -1};
    double *UV = malloc(2 * m.nv * sizeof *UV);
    int fb = -1;
    scaf_error e;
    scaf_status st = opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, method, UV, &fb, &e);
    if (st != SCAF_OK) print_error("%s\n", e.message);
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(count_nonpositive(&m, UV), 0);
    if (method == OPT_EMBED_TUTTE) assert_int_equal(fb, 0);
    double R = sqrt(chart_area(&m) / 3.14159265358979323846);
    for (int k = 0; k < m.start[1]; k++) {
        const double *p = UV + 2 * m.loops[k];
        assert_true(fabs(hypot(p[0], p[1]) - R) < 1e-12 * R);
    }
    /* Interior vertices strictly inside the circle. */
    for (int v = 0; v < m.nv; v++) assert_true(hypot(UV[2 * v], UV[2 * v + 1]) <= R * (1 + 1e-12));
    free(UV);
    polar_disk_free(&m);
}

static void tutte_disk(void **state)
{
    (void)state;
    check_embedding(0, OPT_EMBED_TUTTE, 0);
}
static void tutte_disk_reversed_loop(void **state)
{
    (void)state;
    check_embedding(0, OPT_EMBED_TUTTE, 1);
}
static void harmonic_disk(void **state)
{
    (void)state;
    check_embedding(0, OPT_EMBED_HARMONIC, 0);
}
static void tutte_annulus_hole_filled(void **state)
{
    (void)state;
    check_embedding(1, OPT_EMBED_TUTTE, 0);
}
static void harmonic_annulus_hole_filled(void **state)
{
    (void)state;
    check_embedding(1, OPT_EMBED_HARMONIC, 1);
}

/* Cotangent weights go negative on obtuse triangles: a harmonic map of a
 * flat fan whose every third vertex is pulled toward x = 0 folds, so the
 * embedding must fall back (to mean-value, see test_mvc) and still be valid; a squashed but
 * well-shaped mesh keeps the harmonic map. */
static void harmonic_falls_back_when_needed(void **state)
{
    (void)state;
    for (int variant = 0; variant < 2; variant++) {
        polar_disk m;
        assert_int_equal(polar_disk_make(&m, 3, 60, 0.0, 0), 0);
        for (int v = 0; v < m.nv; v++) {
            if (variant == 0 && v % 3 == 0) m.V[3 * v] *= 0.2;
            if (variant == 1) m.V[3 * v + 1] *= 0.01;
        }
        opt_chart_loops L = {m.nloops, m.start, m.loops, 0};
        double *UV = malloc(2 * m.nv * sizeof *UV);
        int fb = -1;
        assert_int_equal(
            opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_HARMONIC, UV, &fb, NULL), SCAF_OK);
        assert_int_equal(fb, variant == 0 ? 1 : 0);
        assert_int_equal(count_nonpositive(&m, UV), 0);
        free(UV);
        polar_disk_free(&m);
    }
}

static void bad_loops_are_refused(void **state)
{
    (void)state;
    polar_disk m;
    assert_int_equal(polar_disk_make(&m, 3, 8, 0.5, 0), 0);
    double UV[2 * 64];
    scaf_error e;
    opt_chart_loops L = {1, m.start, m.loops, 0};
    int saved = m.loops[2];
    m.loops[2] = 1000;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_TUTTE, UV, NULL, &e),
                     SCAF_ERR_USAGE);
    m.loops[2] = m.loops[0];
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_TUTTE, UV, NULL, &e),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "twice"));
    m.loops[2] = saved;
    /* A loop through the center: its first edge is not a boundary edge. */
    int bogus[4] = {0, 5, 2, 3}, st[2] = {0, 4};
    opt_chart_loops B = {1, st, bogus, 0};
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &B, OPT_EMBED_TUTTE, UV, NULL, &e),
                     SCAF_ERR_MESH);
    opt_chart_loops none = {0, m.start, m.loops, 0};
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &none, OPT_EMBED_TUTTE, UV, NULL, &e),
                     SCAF_ERR_MESH);
    polar_disk_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tutte_disk),
        cmocka_unit_test(tutte_disk_reversed_loop),
        cmocka_unit_test(harmonic_disk),
        cmocka_unit_test(tutte_annulus_hole_filled),
        cmocka_unit_test(harmonic_annulus_hole_filled),
        cmocka_unit_test(harmonic_falls_back_when_needed),
        cmocka_unit_test(bad_loops_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
