/* Tests for geom/self_intersect, geom/tri_intersect and geom/tet_orient:
 * hand-made pairs of each kind (crossing, touching, coplanar, folded
 * edge, shared vertex, duplicate, degenerate), closed solids with and
 * without a vertex pushed through, the same cases at extreme scales, the
 * grid against brute force on random soups, and the shared closed meshes
 * (skipped when ../shared/data is absent). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/self_intersect.h"
#include "geom/tet_orient.h"
#include "geom/tri_intersect.h"
#include "mesh/mesh_io.h"
#include "opt/rng.h"
#include "support/count_checks.h"
#include "support/support.h"

static si_report check(int nv, const double *V, int nf, const int *F)
{
    si_report r;
    scaf_error e;
    err_clear(&e);
    scaf_status s = si_check(nv, V, nf, F, &r, &e);
    if (s) print_error("%s\n", e.message);
    assert_int_equal(s, SCAF_OK);
    return r;
}

/* ---- pairs of triangles ---- */

static void crossing_triangles(void **state)
{
    (void)state;
    /* one in z = 0, one vertical through its middle */
    double V[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5, 0.5, -1, 0.5, 0.5, 1, 3, 3, 0.5};
    int F[] = {0, 1, 2, 3, 4, 5};
    si_report r = check(6, V, 2, F);
    EXPECT_COUNTS("crossing", HAS(r.pairs, 1), HAS(r.crossing_pairs, 1), HAS(r.nfirst, 1),
                  HAS(r.first[0][0], 0), HAS(r.first[0][1], 1), HAS(r.intersection_free, 0));
    /* moved up by 2: apart */
    for (int i = 3; i < 6; i++) V[3 * i + 2] += 2;
    r = check(6, V, 2, F);
    EXPECT_COUNTS("apart", HAS(r.pairs, 0), HAS(r.intersection_free, 1));
}

static void touching_at_a_vertex(void **state)
{
    (void)state;
    /* vertex 3 of the second face lies exactly on the first face's vertex
     * 0 (distinct indices): closed triangles touch, which counts */
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 1, 0, -1, 1};
    int F[] = {0, 1, 2, 3, 4, 5};
    si_report r = check(6, V, 2, F);
    EXPECT_COUNTS("touch by position", HAS(r.crossing_pairs, 1), HAS(r.pairs, 1));
    /* the same faces sharing the index: they meet only there */
    int G[] = {0, 1, 2, 0, 4, 5};
    r = check(6, V, 2, G);
    EXPECT_COUNTS("shared vertex only", HAS(r.pairs, 0), HAS(r.intersection_free, 1));
    /* touching at an interior point of the other face's edge */
    double W[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 0, 1, -1, 1, 1, 1, 1};
    r = check(6, W, 2, F);
    EXPECT_COUNTS("vertex on an edge", HAS(r.crossing_pairs, 1));
}

static void coplanar_overlap(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 1, 0, -1, 1, 0, 1, -1, 0};
    int F[] = {0, 1, 2, 3, 4, 5};
    si_report r = check(6, V, 2, F);
    EXPECT_COUNTS("coplanar overlap", HAS(r.crossing_pairs, 1));
    /* a small triangle strictly inside the other: no edge crosses */
    double W[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 2, 1, 0, 1, 2, 0};
    r = check(6, W, 2, F);
    EXPECT_COUNTS("coplanar nested", HAS(r.crossing_pairs, 1));
    /* in the plane x = y + z (no axis-aligned projection is trivial), apart */
    double U[] = {0, 0, 0, 1, 1, 0, 1, 0, 1, 3, 3, 0, 4, 4, 0, 4, 3, 1};
    r = check(6, U, 2, F);
    EXPECT_COUNTS("coplanar apart", HAS(r.pairs, 0));
}

static void shared_edge(void **state)
{
    (void)state;
    /* faces (0,1,2) and (1,0,3) on edge 0-1 */
    int F[] = {0, 1, 2, 1, 0, 3};
    double flat[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, -1, 0};
    si_report r = check(4, flat, 2, F);
    EXPECT_COUNTS("flat", HAS(r.pairs, 0));
    double bent[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.3, 1};
    r = check(4, bent, 2, F);
    EXPECT_COUNTS("bent", HAS(r.pairs, 0));
    double folded[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.3, 0};
    r = check(4, folded, 2, F);
    EXPECT_COUNTS("folded", HAS(r.edge_pairs, 1), HAS(r.pairs, 1));
    /* same apex position, different index: folded exactly onto itself */
    double onto[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};
    r = check(4, onto, 2, F);
    EXPECT_COUNTS("folded onto itself", HAS(r.edge_pairs, 1));
}

static void shared_vertex(void **state)
{
    (void)state;
    /* faces (0,1,2) and (0,3,4) sharing vertex 0; the second one's far
     * edge passes through the first face */
    double V[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0.5, -1, 0.5, 1, 1};
    int F[] = {0, 1, 2, 0, 3, 4};
    si_report r = check(5, V, 2, F);
    EXPECT_COUNTS("through", HAS(r.vertex_pairs, 1), HAS(r.pairs, 1));
    /* coplanar wedges overlapping around the shared vertex */
    double W[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 1, 0, 1, 2, 0};
    r = check(5, W, 2, F);
    EXPECT_COUNTS("coplanar wedges", HAS(r.vertex_pairs, 1));
    /* coplanar wedges on either side: only the vertex in common */
    double X[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, -2, 0, 0, 0, -2, 0};
    r = check(5, X, 2, F);
    EXPECT_COUNTS("opposite wedges", HAS(r.pairs, 0));
    /* a common edge direction (collinear edges from the shared vertex) */
    double Y[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1};
    r = check(5, Y, 2, F);
    EXPECT_COUNTS("collinear edges", HAS(r.vertex_pairs, 1));
}

static void duplicate_and_degenerate(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 2, 2, 3, 3, 3};
    int F[] = {0, 1, 2, 2, 1, 0, 0, 3, 4, 1, 1, 3};
    si_report r = check(5, V, 4, F);
    EXPECT_COUNTS("dup/degenerate", HAS(r.duplicate_pairs, 1), HAS(r.degenerate_faces, 2),
                  HAS(r.first_degenerate, 2), HAS(r.pairs, 1), HAS(r.intersection_free, 0));
}

/* ---- closed solids ---- */

static const int tet_faces[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
static const int octa_faces[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

static void scaled(const double *V, int nv, double s, double *out)
{
    for (int i = 0; i < 3 * nv; i++) out[i] = V[i] * s;
}

static void closed_tetrahedron_and_octahedron(void **state)
{
    (void)state;
    double T[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    double O[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    /* the same answers at every scale, subnormal to near the largest double */
    const double scales[] = {1, 1e-310, 1e-150, 1e150, 1e307};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        double W[18];
        scaled(T, 4, scales[k], W);
        si_report r = check(4, W, 4, tet_faces);
        EXPECT_COUNTS("tetrahedron", HAS(r.pairs, 0), HAS(r.degenerate_faces, 0),
                      HAS(r.intersection_free, 1));
        scaled(O, 6, scales[k], W);
        r = check(6, W, 8, octa_faces);
        EXPECT_COUNTS("octahedron", HAS(r.pairs, 0), HAS(r.intersection_free, 1));
        /* push the top vertex through the bottom face (+x, +y): the top
         * face (-x, -y) now crosses it (straight down the axis would only
         * nest the upper cone around the lower one, which is no crossing) */
        W[3 * 4 + 0] = 0.2 * scales[k];
        W[3 * 4 + 1] = 0.2 * scales[k];
        W[3 * 4 + 2] = -0.9 * scales[k];
        r = check(6, W, 8, octa_faces);
        assert_true(r.crossing_pairs > 0);
        assert_false(r.intersection_free);
    }
    /* huge coordinates of both signs: the box extent itself overflows */
    double H[18];
    scaled(O, 6, 1.7e308, H);
    si_report r = check(6, H, 8, octa_faces);
    EXPECT_COUNTS("octahedron at 1.7e308", HAS(r.pairs, 0));
    H[3 * 4 + 0] = H[3 * 4 + 1] = 0.2 * 1.7e308;
    H[3 * 4 + 2] = -0.9 * 1.7e308;
    r = check(6, H, 8, octa_faces);
    assert_true(r.crossing_pairs > 0);
}

/* ---- grid against brute force ---- */

static void grid_matches_brute_force(void **state)
{
    (void)state;
    rng g = {12345};
    long long seen[5] = {0};
    for (int round = 0; round < 200; round++) {
        /* points on a small integer lattice (plenty of coplanar, touching
         * and shared-vertex cases) or continuous, a soup of faces over them */
        int nv = 6 + round % 20, nf = 2 + round % 40;
        int lattice = round % 3 != 2;
        double V[3 * 26];
        int F[3 * 42];
        for (int i = 0; i < 3 * nv; i++) {
            double x = rng_uniform(&g, 0, 4);
            V[i] = lattice ? floor(x) : x;
        }
        if (round % 5 == 4)
            for (int i = 0; i < 3 * nv; i++) V[i] *= 1e300; /* extreme but finite */
        for (int f = 0; f < nf; f++)
            for (int k = 0; k < 3; k++) F[3 * f + k] = (int)rng_uniform(&g, 0, nv);
        si_report r = check(nv, V, nf, F);
        long long count[5] = {0};
        int first[SI_FIRST_MAX][2], nfirst = 0, ndeg = 0;
        for (int i = 0; i < nf; i++) {
            const double *a = V + 3 * F[3 * i], *b = V + 3 * F[3 * i + 1],
                         *c = V + 3 * F[3 * i + 2];
            ndeg += tri3_degenerate(a, b, c);
        }
        for (int i = 0; i < nf; i++)
            for (int j = i + 1; j < nf; j++) {
                const int *fi = F + 3 * i, *fj = F + 3 * j;
                if (tri3_degenerate(V + 3 * fi[0], V + 3 * fi[1], V + 3 * fi[2]) ||
                    tri3_degenerate(V + 3 * fj[0], V + 3 * fj[1], V + 3 * fj[2]))
                    continue;
                si_pair_kind kind = si_classify_pair(V, fi, fj);
                count[kind]++;
                seen[kind]++;
                if (kind != SI_PAIR_NONE && nfirst < SI_FIRST_MAX) {
                    first[nfirst][0] = i;
                    first[nfirst++][1] = j;
                }
            }
        char label[64];
        snprintf(label, sizeof label, "random soup %d", round);
        EXPECT_COUNTS(
            label, HAS(r.degenerate_faces, ndeg), HAS(r.crossing_pairs, count[SI_PAIR_CROSSING]),
            HAS(r.vertex_pairs, count[SI_PAIR_VERTEX]), HAS(r.edge_pairs, count[SI_PAIR_EDGE]),
            HAS(r.duplicate_pairs, count[SI_PAIR_DUPLICATE]), HAS(r.nfirst, nfirst));
        for (int i = 0; i < nfirst; i++) {
            assert_int_equal(r.first[i][0], first[i][0]);
            assert_int_equal(r.first[i][1], first[i][1]);
        }
    }
    /* the soups exercised every kind */
    for (int kind = 0; kind < 5; kind++) assert_true(seen[kind] > 0);
}

/* tri_tri_intersect is symmetric and agrees with itself under vertex
 * rotation and reversal of either triangle. */
static void tri_tri_symmetric(void **state)
{
    (void)state;
    rng g = {777};
    for (int round = 0; round < 2000; round++) {
        double P[18];
        for (int i = 0; i < 18; i++) P[i] = floor(rng_uniform(&g, 0, 3));
        const double *a[3] = {P, P + 3, P + 6}, *b[3] = {P + 9, P + 12, P + 15};
        if (tri3_degenerate(a[0], a[1], a[2]) || tri3_degenerate(b[0], b[1], b[2])) continue;
        int want = tri_tri_intersect(a, b);
        const double *ar[3] = {a[1], a[2], a[0]}, *bf[3] = {b[0], b[2], b[1]};
        assert_int_equal(tri_tri_intersect(b, a), want);
        assert_int_equal(tri_tri_intersect(ar, bf), want);
        assert_int_equal(tri_tri_intersect(bf, ar), want);
    }
}

static void bad_input(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    int F[] = {0, 1, 3};
    si_report r;
    scaf_error e;
    assert_int_equal(si_check(3, V, 1, F, &r, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "face 0 references vertex 3"));
    V[4] = NAN;
    int G[] = {0, 1, 2};
    assert_int_equal(si_check(3, V, 1, G, &r, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "vertex 1 is not finite"));
    /* no faces: trivially free */
    r = check(0, NULL, 0, NULL);
    assert_true(r.intersection_free);
}

/* ---- tet orientation ---- */

static void tet_orientation_counts(void **state)
{
    (void)state;
    double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};
    int T[] = {0, 1, 2, 3, /* positive */ 0, 2, 1, 3, /* inverted */ 0, 1, 2, 4, /* flat */ 0,
               0, 1, 3};
    tet_orient_report r;
    scaf_error e;
    assert_int_equal(tet_orient_check(5, V, 4, T, &r, &e), SCAF_OK);
    EXPECT_COUNTS("tets", HAS(r.tets, 4), HAS(r.positive, 1), HAS(r.inverted, 1),
                  HAS(r.degenerate, 2), HAS(r.first_bad, 1));
    /* nearly flat at huge scale: still exact */
    double W[] = {1e300, 0, 0, 0, 1e300, 0, 0, 0, 1e300, 1e300 / 3, 1e300 / 3, 1e300 / 3};
    int U[] = {0, 1, 2, 3};
    assert_int_equal(tet_orient_check(4, W, 1, U, &r, &e), SCAF_OK);
    assert_int_equal(r.positive + r.inverted + r.degenerate, 1);
    assert_int_equal(tet_orientation(W, W + 3, W + 6, W + 9), r.positive ? 1 : r.inverted ? -1 : 0);
    int bad[] = {0, 1, 2, 4};
    assert_int_equal(tet_orient_check(4, W, 1, bad, &r, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "tet 0 references vertex 4"));
}

/* ---- shared closed meshes ---- */

static void shared_closed_meshes(void **state)
{
    (void)state;
    static const char *names[] = {"leg-intersect.off",   "leg-flow6.off", "bunny.obj",
                                  "bunnyx30.obj",        "fertility.off", "armadillo.obj",
                                  "nefertiti-lowres.obj"};
    int found = 0;
    for (size_t n = 0; n < sizeof names / sizeof *names; n++) {
        char rel[128], buf[4096];
        snprintf(rel, sizeof rel, "closed/%s", names[n]);
        const char *path = test_data_path(rel, buf, sizeof buf);
        if (!path) continue;
        found++;
        mesh m;
        mesh_read_info info;
        scaf_error e;
        assert_int_equal(mesh_read(path, &m, &info, &e), SCAF_OK);
        si_report r = check(m.nv, m.V, m.nf, m.F);
        mesh_free(&m);
        if (n == 0) {
            /* MANIFEST.md: 237 pairs sharing no vertex; two more share one */
            EXPECT_COUNTS("leg-intersect", HAS(r.crossing_pairs, 237), HAS(r.vertex_pairs, 2),
                          HAS(r.edge_pairs, 0), HAS(r.duplicate_pairs, 0), HAS(r.pairs, 239),
                          HAS(r.degenerate_faces, 0));
        } else {
            EXPECT_COUNTS(names[n], HAS(r.pairs, 0), HAS(r.degenerate_faces, 0),
                          HAS(r.intersection_free, 1));
        }
    }
    if (!found) skip();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crossing_triangles),
        cmocka_unit_test(touching_at_a_vertex),
        cmocka_unit_test(coplanar_overlap),
        cmocka_unit_test(shared_edge),
        cmocka_unit_test(shared_vertex),
        cmocka_unit_test(duplicate_and_degenerate),
        cmocka_unit_test(closed_tetrahedron_and_octahedron),
        cmocka_unit_test(grid_matches_brute_force),
        cmocka_unit_test(tri_tri_symmetric),
        cmocka_unit_test(bad_input),
        cmocka_unit_test(tet_orientation_counts),
        cmocka_unit_test(shared_closed_meshes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
