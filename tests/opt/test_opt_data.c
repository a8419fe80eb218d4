/* The starting embedding on the shared meshes (skipped when ../shared/data
 * is absent): read, boundary loops from the topology module, harmonic start
 * (Tutte fallback); the kernel's checker must find the map bijective and
 * its energy finite. Includes a chart with 27 holes (fan-filled for the
 * start). The SCAF iterations from such starts are tested through the
 * shipped loop (e2e/test_param, e2e/test_param_disks). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "opt/embed.h"
#include "opt/energy.h"
#include "support/support.h"

static void assert_bijective(const mesh *m, const double *UV)
{
    bij_report rep;
    scaf_error e;
    assert_int_equal(bij_check(m->nv, UV, m->nf, m->F, NULL, NULL, &rep, &e), SCAF_OK);
    if (!rep.bijective)
        print_error("flipped %d degenerate %d crossings %lld touchings %lld\n", rep.flipped,
                    rep.degenerate, rep.boundary_crossings, rep.boundary_touchings);
    assert_true(rep.bijective);
}

static void run_file(const char *rel)
{
    char path[4096];
    if (!test_data_path(rel, path, sizeof path)) skip();
    mesh m = {0};
    mesh_topology t = {0};
    scaf_error e;
    assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_OK);
    assert_int_equal(mesh_topology_compute(&m, &t, &e), SCAF_OK);
    assert_int_equal(t.components, 1);
    /* Loops as vertex lists. */
    int nl = t.cx.nloops;
    int *start = malloc((nl + 1) * sizeof *start);
    int *verts = malloc((t.cx.loop_start[nl] + 1) * sizeof *verts);
    for (int l = 0; l <= nl; l++) start[l] = t.cx.loop_start[l];
    for (int l = 0; l < nl; l++) {
        assert_true(t.cx.loop_ordered[l]);
        for (int k = t.cx.loop_start[l]; k < t.cx.loop_start[l + 1]; k++)
            verts[k] = m.F[t.cx.loop_he[k]];
    }
    opt_chart_loops L = {nl, start, verts, -1};
    double *X = malloc(2 * m.nv * sizeof *X);
    int fb = 0;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_HARMONIC, X, &fb, &e),
                     SCAF_OK);
    assert_bijective(&m, X);
    opt_simplices S;
    assert_int_equal(opt_simplices_from_surface(&S, m.nv, m.V, m.nf, m.F, &e), SCAF_OK);
    opt_term term = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    double E0 = opt_term_mean_energy(&term, X);
    print_message("%s: %s start E = %.4f\n", rel, fb ? "Tutte (harmonic fell back)" : "harmonic",
                  E0);
    assert_true(isfinite(E0));
    opt_simplices_free(&S);
    free(X);
    free(start);
    free(verts);
    mesh_topology_free(&t);
    mesh_free(&m);
}

static void hand(void **state)
{
    (void)state;
    run_file("disk/hand_lowres.obj");
}
static void camel_b(void **state)
{
    (void)state;
    run_file("disk/camel_b.obj");
}
static void camelhead(void **state)
{
    (void)state;
    run_file("disk/camelhead.off");
}
static void plane_with_27_holes(void **state)
{
    (void)state;
    run_file("bad/plane_holes.obj");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand),
        cmocka_unit_test(camel_b),
        cmocka_unit_test(camelhead),
        cmocka_unit_test(plane_with_27_holes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
