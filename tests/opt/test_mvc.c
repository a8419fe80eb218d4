/* Tests of the mean-value (MVC) start, opt/mvc and OPT_EMBED_MVC: every
 * triangle of the generated meshes exactly positive without falling back,
 * positive finite weights on obtuse and degenerate triangles (with the
 * uniform row fallback only where a corner is degenerate), a bijective
 * start on a chart with degenerate 3D triangles, harmonic falling back to
 * exactly the mean-value map, a singular system reported, linear
 * reproduction on a flat irregular disk, and on bad/plane_holes (skipped
 * without ../shared/data) a bijective start with a lower energy than
 * Tutte's. */
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
#include "geom/predicates.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "mesh/topology.h"
#include "opt/embed.h"
#include "opt/energy.h"
#include "opt/mvc.h"
#include "opt/simplices.h"
#include "polar_disk.h"
#include "support/support.h"

/* Boundary loops of a one-component mesh as vertex lists (caller frees
 * both arrays). */
static opt_chart_loops loops_of(const mesh *m, int **start, int **verts)
{
    mesh_topology t = {0};
    scaf_error e;
    assert_int_equal(mesh_topology_compute(m, &t, &e), SCAF_OK);
    assert_int_equal(t.components, 1);
    int nl = t.cx.nloops;
    *start = malloc((size_t)(nl + 1) * sizeof **start);
    *verts = malloc((size_t)(t.cx.loop_start[nl] + 1) * sizeof **verts);
    assert_non_null(*start);
    assert_non_null(*verts);
    for (int l = 0; l <= nl; l++) (*start)[l] = t.cx.loop_start[l];
    for (int l = 0; l < nl; l++) {
        assert_true(t.cx.loop_ordered[l]);
        for (int k = t.cx.loop_start[l]; k < t.cx.loop_start[l + 1]; k++)
            (*verts)[k] = m->F[t.cx.loop_he[k]];
    }
    mesh_topology_free(&t);
    opt_chart_loops L = {nl, *start, *verts, -1};
    return L;
}

static int count_nonpositive(const mesh *m, const double *UV)
{
    int bad = 0;
    for (int f = 0; f < m->nf; f++)
        bad += !(
            orient2d(UV + 2 * m->F[3 * f], UV + 2 * m->F[3 * f + 1], UV + 2 * m->F[3 * f + 2]) > 0);
    return bad;
}

static void assert_bijective(const mesh *m, const double *UV)
{
    bij_report rep;
    scaf_error e;
    assert_int_equal(bij_check(m->nv, UV, m->nf, m->F, NULL, NULL, &rep, &e), SCAF_OK);
    assert_true(rep.bijective);
}

/* MVC on a sample: no fallback (the MVC map itself is checked), every
 * triangle exactly positive, the whole map bijective. */
static void mvc_sample(const char *name, int size)
{
    mesh m = {0};
    scaf_error e;
    assert_int_equal(mesh_sample_make(name, size, &m, &e), SCAF_OK);
    int *start, *verts;
    opt_chart_loops L = loops_of(&m, &start, &verts);
    double *UV = malloc(2 * (size_t)m.nv * sizeof *UV);
    assert_non_null(UV);
    int fb = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, UV, &fb, &e),
                     SCAF_OK);
    assert_int_equal(fb, 0);
    assert_int_equal(count_nonpositive(&m, UV), 0);
    assert_bijective(&m, UV);
    free(UV);
    free(start);
    free(verts);
    mesh_free(&m);
}

static void mvc_grid(void **state)
{
    (void)state;
    mvc_sample("grid", 12);
}
static void mvc_hemisphere(void **state)
{
    (void)state;
    mvc_sample("hemisphere", 10);
}
static void mvc_holes(void **state)
{
    (void)state;
    mvc_sample("holes", 6);
}

/* A fan around vertex 0 in the plane z = 0 with: a very obtuse corner at
 * the center (179.9 degrees), a sliver (angle ~1e-9 at the center), a
 * corner with a zero-length edge (vertex 7 on top of vertex 6) and an
 * exactly collinear triangle. Every weight must come out finite and > 0;
 * the vertices with a degenerate corner, and only those, get the uniform
 * row. */
static void weights_positive_on_bad_triangles(void **state)
{
    (void)state;
    const double V[] = {
        0,  0,           0,  /* 0 center */
        1,  0,           0,  /* 1 */
        -1, 1e-3,        0,  /* 2: angle 1-0-2 is ~179.94 degrees */
        -1, 1e-3 + 1e-9, 0,  /* 3: sliver 2-0-3 */
        0,  -1,          0,  /* 4 */
        5,  5,           1,  /* 5: a well-shaped triangle 4-5-6 away from the center */
        6,  4,           0,  /* 6 */
        6,  4,           0,  /* 7: same position as 6 */
        7,  3,           -1, /* 8: 6, 7, 8 collinear too */
    };
    const int F[] = {
        0, 1, 2,                            /* obtuse at 0 */
        0, 2, 3,                            /* sliver at 0 */
        0, 3, 4, 0, 4, 1, 4, 5, 6, 5, 7, 6, /* zero-length edge 6-7 */
        6, 7, 8,                            /* zero area */
    };
    int nv = 9, nf = 7;
    double W[6 * 7];
    unsigned char uni[9];
    int nbad = opt_mvc_corner_weights(nv, V, nf, F, W, uni);
    for (int k = 0; k < 6 * nf; k++) {
        assert_true(isfinite(W[k]));
        assert_true(W[k] > 0);
    }
    /* Degenerate corners: at 6 and 7 (zero edge), at 8 (zero angle); at 5
     * the corner of face 5 has edges to 7 and 6 that coincide: angle 0. */
    assert_int_equal(uni[6], 1);
    assert_int_equal(uni[7], 1);
    assert_int_equal(uni[8], 1);
    assert_int_equal(uni[5], 1);
    /* The obtuse and sliver corners are valid: mean-value weights kept,
     * and the obtuse corner's half-angle tangent is large. */
    assert_int_equal(uni[0], 0);
    assert_int_equal(uni[1], 0);
    assert_int_equal(uni[2], 0);
    assert_int_equal(uni[3], 0);
    assert_int_equal(uni[4], 0);
    assert_int_equal(nbad, 4);
    assert_true(W[0] > 100.0); /* corner 0 of face 0, toward vertex 1 (length 1) */
    /* Without the row flags (NULL) the weights are still all positive. */
    double W2[6 * 7];
    opt_mvc_corner_weights(nv, V, nf, F, W2, NULL);
    for (int k = 0; k < 6 * nf; k++) assert_true(isfinite(W2[k]) && W2[k] > 0);
}

/* A chart whose 3D surface has degenerate triangles (a zero-length edge,
 * a vertex on its opposite edge) still gets a bijective mean-value start
 * without falling back: the rows of those vertices are uniform, the others
 * mean-value, all positive. */
static void mvc_degenerate_3d_triangles(void **state)
{
    (void)state;
    mesh m = {0};
    scaf_error e;
    assert_int_equal(mesh_sample_make("grid", 8, &m, &e), SCAF_OK);
    double lo = INFINITY, hi = -INFINITY;
    for (int v = 0; v < m.nv; v++) {
        lo = fmin(lo, m.V[3 * v]);
        hi = fmax(hi, m.V[3 * v]);
    }
    /* faces with all three vertices strictly inside */
    int picked[2] = {-1, -1}, np = 0;
    for (int f = 0; f < m.nf && np < 2; f++) {
        int inside = 1;
        for (int k = 0; k < 3; k++) {
            const double *p = m.V + 3 * m.F[3 * f + k];
            inside &= p[0] > lo && p[0] < hi && p[1] > lo && p[1] < hi;
        }
        if (!inside) continue;
        if (np == 1) { /* far from the first one: no shared vertex */
            int shares = 0;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) shares |= m.F[3 * f + a] == m.F[3 * picked[0] + b];
            if (shares) continue;
        }
        picked[np++] = f;
    }
    assert_int_equal(np, 2);
    int *F0 = m.F + 3 * picked[0], *F1 = m.F + 3 * picked[1];
    memcpy(m.V + 3 * F0[1], m.V + 3 * F0[0], 3 * sizeof(double)); /* zero-length edge */
    for (int r = 0; r < 3; r++) /* vertex 0 onto the midpoint of edge 1-2: angle pi */
        m.V[3 * F1[0] + r] = 0.5 * (m.V[3 * F1[1] + r] + m.V[3 * F1[2] + r]);
    double *W = malloc(6 * (size_t)m.nf * sizeof *W);
    unsigned char *uni = malloc((size_t)m.nv);
    assert_non_null(W);
    assert_non_null(uni);
    assert_true(opt_mvc_corner_weights(m.nv, m.V, m.nf, m.F, W, uni) >= 3);
    for (int k = 0; k < 6 * m.nf; k++) assert_true(isfinite(W[k]) && W[k] > 0);
    int *start, *verts;
    opt_chart_loops L = loops_of(&m, &start, &verts);
    double *UV = malloc(2 * (size_t)m.nv * sizeof *UV);
    assert_non_null(UV);
    int fb = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, UV, &fb, &e),
                     SCAF_OK);
    assert_int_equal(fb, 0);
    assert_int_equal(count_nonpositive(&m, UV), 0);
    assert_bijective(&m, UV);
    free(W);
    free(uni);
    free(UV);
    free(start);
    free(verts);
    mesh_free(&m);
}

/* Mean-value coordinates reproduce linear functions: a flat disk whose
 * boundary is fixed at its own positions maps to itself. Tutte does not on
 * an irregular mesh, so this tells the weights and the solve apart from
 * uniform ones. */
static void mvc_reproduces_flat_irregular_grid(void **state)
{
    (void)state;
    mesh m = {0};
    scaf_error e;
    int n = 10;
    assert_int_equal(mesh_sample_make("grid", n, &m, &e), SCAF_OK);
    unsigned char *fixed = calloc((size_t)m.nv, 1);
    double *UV = malloc(2 * (size_t)m.nv * sizeof *UV), *X = malloc(2 * (size_t)m.nv * sizeof *X);
    assert_non_null(fixed);
    assert_non_null(UV);
    assert_non_null(X);
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int v = 0; v < m.nv; v++) {
        xmin = fmin(xmin, m.V[3 * v]);
        xmax = fmax(xmax, m.V[3 * v]);
        ymin = fmin(ymin, m.V[3 * v + 1]);
        ymax = fmax(ymax, m.V[3 * v + 1]);
    }
    double h = (xmax - xmin) / n;
    unsigned s = 12345u;
    for (int v = 0; v < m.nv; v++) {
        double *p = m.V + 3 * v;
        int onb = p[0] == xmin || p[0] == xmax || p[1] == ymin || p[1] == ymax;
        fixed[v] = (unsigned char)onb;
        if (!onb) { /* shift interior vertices by up to 0.3 cells, deterministically */
            s = s * 1103515245u + 12345u;
            p[0] += 0.3 * h * ((double)(s >> 16 & 0x7fff) / 32767.0 - 0.5) * 2;
            s = s * 1103515245u + 12345u;
            p[1] += 0.3 * h * ((double)(s >> 16 & 0x7fff) / 32767.0 - 0.5) * 2;
        }
        X[2 * v] = p[0];
        X[2 * v + 1] = p[1];
        UV[2 * v] = fixed[v] ? p[0] : 0;
        UV[2 * v + 1] = fixed[v] ? p[1] : 0;
    }
    assert_int_equal(opt_mvc_solve(m.nv, m.V, m.nf, m.F, fixed, UV, &e), SCAF_OK);
    double worst = 0;
    for (int k = 0; k < 2 * m.nv; k++) worst = fmax(worst, fabs(UV[k] - X[k]));
    assert_true(worst < 1e-9 * (xmax - xmin));
    assert_int_equal(count_nonpositive(&m, UV), 0);
    free(fixed);
    free(UV);
    free(X);
    mesh_free(&m);
}

/* A free vertex not connected to any fixed one: singular, reported. */
static void mvc_singular_is_an_error(void **state)
{
    (void)state;
    const double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int F[] = {0, 1, 2};
    unsigned char fixed[3] = {0, 0, 0};
    double UV[6] = {0};
    scaf_error e;
    assert_int_equal(opt_mvc_solve(3, V, 1, F, fixed, UV, &e), SCAF_ERR_NUMERIC);
    assert_true(strlen(e.message) > 0);
}

/* A flat fan whose every third vertex is pulled toward the center: the
 * cotangent map folds, so harmonic falls back, and the chain's next step is
 * mean-value: the result is the mean-value map bit for bit, and positive. */
static void harmonic_falls_back_to_mvc(void **state)
{
    (void)state;
    polar_disk m;
    assert_int_equal(polar_disk_make(&m, 3, 60, 0.0, 0), 0);
    for (int v = 0; v < m.nv; v++)
        if (v % 3 == 0) m.V[3 * v] *= 0.2;
    opt_chart_loops L = {m.nloops, m.start, m.loops, 0};
    double *Uh = malloc(2 * (size_t)m.nv * sizeof *Uh), *Um = malloc(2 * (size_t)m.nv * sizeof *Um);
    assert_non_null(Uh);
    assert_non_null(Um);
    int fbh = -1, fbm = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_HARMONIC, Uh, &fbh, NULL),
                     SCAF_OK);
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, Um, &fbm, NULL),
                     SCAF_OK);
    assert_int_equal(fbh, 1);
    assert_int_equal(fbm, 0);
    assert_memory_equal(Uh, Um, 2 * (size_t)m.nv * sizeof *Uh);
    for (int f = 0; f < m.nf; f++)
        assert_true(
            orient2d(Um + 2 * m.F[3 * f], Um + 2 * m.F[3 * f + 1], Um + 2 * m.F[3 * f + 2]) > 0);
    free(Uh);
    free(Um);
    polar_disk_free(&m);
}

/* The chart with 27 window holes: MVC must give a bijective start without
 * fallback, with a lower symmetric Dirichlet energy than Tutte's. */
static void plane_holes_mvc_beats_tutte(void **state)
{
    (void)state;
    char path[4096];
    if (!test_data_path("bad/plane_holes.obj", path, sizeof path)) skip();
    mesh m = {0};
    scaf_error e;
    assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_OK);
    int *start, *verts;
    opt_chart_loops L = loops_of(&m, &start, &verts);
    assert_true(L.nloops > 1);
    double *Ut = malloc(2 * (size_t)m.nv * sizeof *Ut), *Um = malloc(2 * (size_t)m.nv * sizeof *Um);
    assert_non_null(Ut);
    assert_non_null(Um);
    int fb = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_TUTTE, Ut, &fb, &e),
                     SCAF_OK);
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, Um, &fb, &e),
                     SCAF_OK);
    assert_int_equal(fb, 0);
    assert_int_equal(count_nonpositive(&m, Um), 0);
    assert_bijective(&m, Um);
    opt_simplices S;
    assert_int_equal(opt_simplices_from_surface(&S, m.nv, m.V, m.nf, m.F, &e), SCAF_OK);
    opt_term term = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    double Et = opt_term_mean_energy(&term, Ut), Em = opt_term_mean_energy(&term, Um);
    print_message("plane_holes start E: tutte %.4g, mvc %.4g\n", Et, Em);
    assert_true(isfinite(Em));
    assert_true(Em < Et);
    opt_simplices_free(&S);
    free(Ut);
    free(Um);
    free(start);
    free(verts);
    mesh_free(&m);
}

/* opt_embed_chart_best: the loop on the circle is the one whose start has
 * the lowest energy. On the holes sample (7 loops) every loop is embedded
 * here one by one and measured with opt/energy (independently of the
 * function's own measure); on plane_holes (27 loops, skipped without the
 * data) the best beats the longest loop, the default before. */
static double mean_energy(const mesh *m, const double *UV)
{
    opt_simplices S;
    scaf_error e;
    assert_int_equal(opt_simplices_from_surface(&S, m->nv, m->V, m->nf, m->F, &e), SCAF_OK);
    opt_term term = {&S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    double E = opt_term_mean_energy(&term, UV);
    opt_simplices_free(&S);
    return E;
}

static void best_outer_loop(void **state)
{
    (void)state;
    mesh m = {0};
    scaf_error e;
    assert_int_equal(mesh_sample_make("holes", 8, &m, &e), SCAF_OK);
    int *start, *verts;
    opt_chart_loops L = loops_of(&m, &start, &verts);
    assert_int_equal(L.nloops, 7);
    double *U = malloc(2 * (size_t)m.nv * sizeof *U), *B = malloc(2 * (size_t)m.nv * sizeof *B);
    assert_non_null(U);
    assert_non_null(B);
    double lowest = INFINITY, highest = 0.0;
    for (int l = 0; l < L.nloops; l++) {
        opt_chart_loops one = L;
        one.outer = l;
        assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &one, OPT_EMBED_MVC, U, NULL, &e),
                         SCAF_OK);
        double E = mean_energy(&m, U);
        lowest = fmin(lowest, E);
        highest = fmax(highest, E);
    }
    double Eb = NAN;
    assert_int_equal(
        opt_embed_chart_best(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, 32, B, NULL, &Eb, &e),
        SCAF_OK);
    assert_int_equal(count_nonpositive(&m, B), 0);
    assert_bijective(&m, B);
    double E = mean_energy(&m, B);
    print_message("holes: start E over the 7 loops %.6g .. %.6g, chosen %.6g\n", lowest, highest,
                  E);
    assert_true(E <= lowest * (1.0 + 1e-9));
    assert_true(fabs(Eb - E) <= 1e-9 * E); /* the reported energy is this one */
    /* one try: the longest loop, as opt_embed_chart with outer -1 */
    opt_chart_loops longest = L;
    longest.outer = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &longest, OPT_EMBED_MVC, U, NULL, &e),
                     SCAF_OK);
    assert_int_equal(
        opt_embed_chart_best(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, 1, B, NULL, NULL, &e),
        SCAF_OK);
    assert_memory_equal(B, U, 2 * (size_t)m.nv * sizeof *U);
    free(U);
    free(B);
    free(start);
    free(verts);
    mesh_free(&m);

    char path[4096];
    if (!test_data_path("bad/plane_holes.obj", path, sizeof path)) return;
    assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_OK);
    L = loops_of(&m, &start, &verts);
    U = malloc(2 * (size_t)m.nv * sizeof *U);
    B = malloc(2 * (size_t)m.nv * sizeof *B);
    L.outer = -1;
    assert_int_equal(opt_embed_chart(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, U, NULL, &e),
                     SCAF_OK);
    assert_int_equal(
        opt_embed_chart_best(m.nv, m.V, m.nf, m.F, &L, OPT_EMBED_MVC, 32, B, NULL, NULL, &e),
        SCAF_OK);
    assert_bijective(&m, B);
    double El = mean_energy(&m, U), Ebest = mean_energy(&m, B);
    print_message("plane_holes start E: longest loop %.4g, best of %d loops %.4g\n", El, L.nloops,
                  Ebest);
    assert_true(Ebest < El);
    free(U);
    free(B);
    free(start);
    free(verts);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mvc_grid),
        cmocka_unit_test(mvc_hemisphere),
        cmocka_unit_test(mvc_holes),
        cmocka_unit_test(weights_positive_on_bad_triangles),
        cmocka_unit_test(mvc_degenerate_3d_triangles),
        cmocka_unit_test(mvc_reproduces_flat_irregular_grid),
        cmocka_unit_test(mvc_singular_is_an_error),
        cmocka_unit_test(harmonic_falls_back_to_mvc),
        cmocka_unit_test(plane_holes_mvc_beats_tutte),
        cmocka_unit_test(best_outer_loop),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
