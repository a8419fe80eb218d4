/* Tests for geom/bijectivity: hand-made overlapping, touching, nested,
 * mirrored and degenerate UV layouts, large valid grids and their one-vertex
 * corruptions, and the grid-accelerated pair counts against brute force. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/bijectivity.h"
#include "geom/predicates.h"
#include "support/count_checks.h"

static bij_report run(int nuv, const double *UV, int nf, const int *F)
{
    bij_report r;
    scaf_error e;
    assert_int_equal(bij_check(nuv, UV, nf, F, NULL, NULL, &r, &e), SCAF_OK);
    return r;
}

/* ---- single triangles ---- */

static void ccw_triangle_is_bijective(void **state)
{
    (void)state;
    double UV[] = {0, 0, 1, 0, 0, 1};
    int F[] = {0, 1, 2};
    bij_report r = run(3, UV, 1, F);
    EXPECT_COUNTS("ccw_triangle_is_bijective", HAS(r.triangles, 1), HAS(r.positive, 1),
                  HAS(r.charts, 1), HAS(r.boundary_edges, 3), HAS(r.boundary_loops, 1));
    assert_true(r.bijective);
}

static void cw_triangle_is_a_mirrored_chart(void **state)
{
    (void)state;
    double UV[] = {0, 0, 1, 0, 0, 1};
    int F[] = {0, 2, 1};
    signed char o[1];
    bij_report r;
    assert_int_equal(bij_check(3, UV, 1, F, NULL, o, &r, NULL), SCAF_OK);
    EXPECT_COUNTS("cw_triangle_is_a_mirrored_chart", HAS(o[0], -1), HAS(r.flipped, 1),
                  HAS(r.mirrored_charts, 1), HAS(r.mixed_charts, 0));
    assert_false(r.bijective);
}

static void degenerate_triangles(void **state)
{
    (void)state;
    /* a fan around 0 with one collinear triangle, and one with a repeated index */
    double UV[] = {0, 0, 1, 0, 1, 1, 0, 1, -1, 1, 2, 2};
    int F[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 2, 5, 1, 1, 2};
    signed char o[5];
    bij_report r;
    assert_int_equal(bij_check(6, UV, 5, F, NULL, o, &r, NULL), SCAF_OK);
    EXPECT_COUNTS("degenerate_triangles", HAS(o[3], 0), /* (0,0), (1,1), (2,2) */
                  HAS(o[4], 0), HAS(r.degenerate, 2), HAS(r.flipped, 0));
    assert_false(r.bijective);
}

/* ---- segment contact ---- */

static void segment_contacts(void **state)
{
    (void)state;
    double a[2] = {0, 0}, b[2] = {2, 2}, c[2] = {0, 2}, d[2] = {2, 0};
    assert_int_equal(bij_segments_meet(a, b, c, d), 1);
    double e[2] = {1, 1}, f[2] = {3, -1};
    assert_int_equal(bij_segments_meet(a, b, e, f), 2); /* T-junction */
    double g[2] = {1, 1}, h[2] = {3, 3};
    assert_int_equal(bij_segments_meet(a, b, g, h), 2); /* collinear overlap */
    double i[2] = {3, 3}, j[2] = {4, 4};
    assert_int_equal(bij_segments_meet(a, b, i, j), 0); /* collinear apart */
    assert_int_equal(bij_segments_meet(a, b, b, j), 2); /* shared end point */
    double k[2] = {1, nextafter(1.0, 2.0)}, l[2] = {1, 5};
    assert_int_equal(bij_segments_meet(a, b, k, l), 0); /* one ulp above */
    k[1] = 1.0;
    assert_int_equal(bij_segments_meet(a, b, k, l), 2);
    k[1] = nextafter(1.0, 0.0);
    assert_int_equal(bij_segments_meet(a, b, k, l), 1);
}

/* ---- two triangles ---- */

static void two_triangles_crossing(void **state)
{
    (void)state;
    /* a hexagram: each edge of one triangle crosses two of the other */
    double UV[] = {0, 4, -4, -2, 4, -2, 0, -4, 4, 2, -4, 2};
    int F[] = {0, 1, 2, 3, 4, 5};
    bij_report r = run(6, UV, 2, F);
    EXPECT_COUNTS("two_triangles_crossing", HAS(r.positive, 2), HAS(r.charts, 2),
                  HAS(r.boundary_crossings, 6), HAS(r.boundary_touchings, 0));
    assert_false(r.bijective);
}

static void touching_at_shared_vertex_index_is_fine(void **state)
{
    (void)state;
    /* bow tie through UV index 0: the triangles share the point by index */
    double UV[] = {0, 0, 1, -1, 1, 1, -1, 1, -1, -1};
    int F[] = {0, 1, 2, 0, 3, 4};
    bij_report r = run(5, UV, 2, F);
    EXPECT_COUNTS("touching_at_shared_vertex_index_is_fine", HAS(r.charts, 2),
                  HAS(r.boundary_crossings, 0), HAS(r.boundary_touchings, 0),
                  HAS(r.nested_loops, 0));
    assert_true(r.bijective);
}

static void touching_at_coincident_distinct_vertices(void **state)
{
    (void)state;
    /* same bow tie, but the middle point is two distinct UV indices */
    double UV[] = {0, 0, 1, -1, 1, 1, -1, 1, -1, -1, 0, 0};
    int F[] = {0, 1, 2, 5, 3, 4};
    bij_report r = run(6, UV, 2, F);
    EXPECT_COUNTS("touching_at_coincident_distinct_vertices", HAS(r.boundary_crossings, 0),
                  HAS(r.boundary_touchings, 4), /* 2 segments at each copy */
                  HAS(r.nested_loops, 0));
    assert_false(r.bijective);
}

static void collinear_overlapping_edges(void **state)
{
    (void)state;
    double UV[] = {0, 0, 2, 0, 1, 1, 1, 0, 2, -1, 3, 0};
    int F[] = {0, 1, 2, 3, 4, 5};
    bij_report r = run(6, UV, 2, F);
    EXPECT_COUNTS("collinear_overlapping_edges", HAS(r.positive, 2), HAS(r.boundary_crossings, 0));
    /* (0,0)-(2,0) overlaps (3,0)-(1,0); (1,0) lies on it; (2,0) lies on
     * (3,0)-(1,0) as the end of (2,0)-(1,1) */
    assert_int_equal(r.boundary_touchings, 3);
    assert_false(r.bijective);
}

static void boundary_folding_back(void **state)
{
    (void)state;
    /* two triangles sharing vertex 0; their boundary edges 0-1 and 0-3 lie
     * on one ray (a 360-degree slit at 0), without overlapping area */
    double UV[] = {0, 0, 2, 0, 1, 1, 1, 0, 1, -1};
    int F[] = {0, 1, 2, 0, 4, 3};
    bij_report r = run(5, UV, 2, F);
    EXPECT_COUNTS("boundary_folding_back", HAS(r.positive, 2), HAS(r.boundary_crossings, 0),
                  HAS(r.boundary_foldbacks, 1),
                  HAS(r.boundary_touchings, 1)); /* 4-3 ends at (1,0), inside 0-1 */
    assert_false(r.bijective);
}

static void folded_and_nonmanifold_edges(void **state)
{
    (void)state;
    /* both triangles left of edge 0->1: they overlap along it */
    double UV[] = {0, 0, 2, 0, 1, 1, 1, 2, 1, -1};
    int F[] = {0, 1, 2, 0, 1, 3};
    bij_report r = run(5, UV, 2, F);
    EXPECT_COUNTS("folded_and_nonmanifold_edges", HAS(r.positive, 2), HAS(r.folded_edges, 1));
    assert_false(r.bijective);
    int G[] = {0, 1, 2, 1, 0, 4, 0, 1, 3};
    r = run(5, UV, 3, G);
    assert_int_equal(r.nonmanifold_edges, 1);
    assert_false(r.bijective);
    int H[] = {0, 1, 2, 1, 0, 4};
    r = run(5, UV, 2, H);
    assert_int_equal(r.charts, 1);
    assert_true(r.bijective);
}

/* ---- nesting ---- */

/* A square annulus: outer [0,10]^2, hole [4,6]^2, 8 points, 8 triangles. */
static const double annulus_uv[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 6, 4, 6, 6, 4, 6};
static const int annulus_f[] = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                                2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static void chart_nested_in_a_hole(void **state)
{
    (void)state;
    double UV[22];
    int F[27];
    memcpy(UV, annulus_uv, sizeof annulus_uv);
    memcpy(F, annulus_f, sizeof annulus_f);
    double small[] = {4.5, 4.5, 5.5, 4.5, 5, 5.5};
    memcpy(UV + 16, small, sizeof small);
    F[24] = 8, F[25] = 9, F[26] = 10;
    bij_report r = run(11, UV, 9, F);
    EXPECT_COUNTS("small chart in the annulus hole", HAS(r.positive, 9), HAS(r.charts, 2),
                  HAS(r.boundary_loops, 3), HAS(r.nested_loops, 0), HAS(r.boundary_crossings, 0));
    assert_true(r.bijective);
    /* the same chart moved into the annulus body: no contact, but overlap */
    for (int i = 0; i < 3; i++) UV[16 + 2 * i] -= 3.0;
    r = run(11, UV, 9, F);
    EXPECT_COUNTS("small chart moved into the annulus body", HAS(r.boundary_crossings, 0),
                  HAS(r.boundary_touchings, 0), HAS(r.nested_loops, 1));
    assert_false(r.bijective);
    /* a chart covering the whole annulus hole and more: its loop encloses
     * the annulus' inner loop, which lands inside it */
    double big[] = {-20, -20, 30, -20, 5, 30};
    memcpy(UV + 16, big, sizeof big);
    r = run(11, UV, 9, F);
    EXPECT_COUNTS("big chart around the annulus hole", HAS(r.boundary_crossings, 0),
                  HAS(r.nested_loops, 2)); /* both loops of the annulus */
    assert_false(r.bijective);
}

static void chart_inside_a_triangle(void **state)
{
    (void)state;
    double UV[] = {0, 0, 100, 0, 0, 100, 1, 1, 2, 1, 1, 2};
    int F[] = {0, 1, 2, 3, 4, 5};
    bij_report r = run(6, UV, 2, F);
    EXPECT_COUNTS("chart inside a big triangle", HAS(r.boundary_crossings, 0),
                  HAS(r.nested_loops, 1));
    assert_false(r.bijective);
    /* a square of two triangles; the small chart's vertex exactly on the
     * interior diagonal, the rest inside */
    double S[] = {0, 0, 4, 0, 4, 4, 0, 4, 2, 2, 3, 2, 3, 2.5};
    int G[] = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    r = run(7, S, 3, G);
    EXPECT_COUNTS("chart vertex on a square's diagonal", HAS(r.boundary_touchings, 0),
                  HAS(r.nested_loops, 1));
    assert_false(r.bijective);
    /* same, with the small chart outside the square */
    for (int i = 4; i < 7; i++) S[2 * i] += 10;
    r = run(7, S, 3, G);
    assert_true(r.bijective);
}

static void overlap_at_a_pinch_point(void **state)
{
    (void)state;
    /* a hexagon fan (vertices 0..5 around center 6) and a triangle over it
     * made of hexagon corners 0, 2, 4: its edges are chords, so it shares
     * no edge with the fan, its vertices are the fan's, no boundary
     * segments meet except at shared indices; only the corners at the
     * pinch points 0, 2, 4 show the overlap */
    double UV[14];
    for (int i = 0; i < 6; i++) {
        UV[2 * i] = 4.0 * cos(i * 3.14159265358979 / 3);
        UV[2 * i + 1] = 4.0 * sin(i * 3.14159265358979 / 3);
    }
    UV[12] = UV[13] = 0;
    int F[21];
    for (int i = 0; i < 6; i++) F[3 * i] = 6, F[3 * i + 1] = i, F[3 * i + 2] = (i + 1) % 6;
    F[18] = 0, F[19] = 2, F[20] = 4;
    bij_report r = run(7, UV, 7, F);
    assert_int_equal(r.positive, 7);
    assert_int_equal(r.folded_edges + r.nonmanifold_edges, 0);
    assert_int_equal(r.boundary_crossings + r.boundary_touchings + r.boundary_foldbacks, 0);
    EXPECT_COUNTS("triangle on hexagon chords", HAS(r.nested_loops, 0), HAS(r.corner_overlaps, 3));
    assert_false(r.bijective);
    /* three triangles around point 0 and a fourth one joined only there:
     * inside the fan's third triangle, then in the empty quadrant */
    double V[] = {0, 0, 4, 0, 0, 4, -4, 0, 0, -4, -1, -1, -3, -1};
    int G[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 6, 5};
    r = run(7, V, 4, G);
    EXPECT_COUNTS("fourth triangle inside the fan", HAS(r.positive, 4), HAS(r.corner_overlaps, 1));
    assert_false(r.bijective);
    V[10] = 3, V[11] = -1, V[12] = 1, V[13] = -3;
    r = run(7, V, 4, G);
    EXPECT_COUNTS("fourth triangle in the empty quadrant", HAS(r.positive, 4),
                  HAS(r.corner_overlaps, 0));
    assert_true(r.bijective);
}

static void mirrored_chart_among_good_ones(void **state)
{
    (void)state;
    double UV[] = {0, 0, 1, 0, 1, 1, 0, 1, 5, 0, 6, 0, 6, 1, 5, 1};
    int F[] = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6};
    bij_report r = run(8, UV, 4, F);
    EXPECT_COUNTS("mirrored chart among good ones", HAS(r.charts, 2), HAS(r.flipped, 2),
                  HAS(r.mirrored_charts, 1), HAS(r.mixed_charts, 0), HAS(r.boundary_crossings, 0),
                  HAS(r.nested_loops, 0));
    assert_false(r.bijective);
    /* given chart ids override the computed ones */
    int chart[] = {7, 7, 7, 7};
    assert_int_equal(bij_check(8, UV, 4, F, chart, NULL, &r, NULL), SCAF_OK);
    EXPECT_COUNTS("given chart ids override", HAS(r.charts, 1), HAS(r.mixed_charts, 1));
}

static void bad_input_is_an_error(void **state)
{
    (void)state;
    double UV[] = {0, 0, 1, 0, NAN, 1};
    int F[] = {0, 1, 3};
    bij_report r;
    scaf_error e;
    assert_int_equal(bij_check(3, UV, 1, F, NULL, NULL, &r, &e), SCAF_ERR_MESH);
    UV[4] = 0;
    assert_int_equal(bij_check(3, UV, 1, F, NULL, NULL, &r, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "out of range"));
    int chart[] = {-1};
    F[2] = 2;
    assert_int_equal(bij_check(3, UV, 1, F, chart, NULL, &r, &e), SCAF_ERR_MESH);
    assert_int_equal(bij_check(3, UV, 0, F, NULL, NULL, &r, &e), SCAF_OK);
    assert_true(r.bijective);
}

/* ---- large layouts ---- */

typedef struct layout {
    int nuv, nf;
    double *UV;
    int *F;
} layout;

static uint64_t rnd(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545F4914F6CDD1DULL;
}

static double unit(uint64_t *s) { return (double)(rnd(s) >> 11) * 0x1p-53; }

/* bx * by charts, each an n x n grid of unit cells with vertices jittered
 * by at most 0.2 per coordinate (every triangle stays ccw, every boundary
 * stays simple), charts one cell apart. */
static layout grid_layout(int bx, int by, int n, uint64_t seed)
{
    layout L;
    int pv = (n + 1) * (n + 1);
    L.nuv = bx * by * pv;
    L.nf = bx * by * 2 * n * n;
    L.UV = malloc((size_t)L.nuv * 2 * sizeof *L.UV);
    L.F = malloc((size_t)L.nf * 3 * sizeof *L.F);
    assert_non_null(L.UV);
    assert_non_null(L.F);
    int f = 0;
    for (int cy = 0; cy < by; cy++)
        for (int cx = 0; cx < bx; cx++) {
            int base = (cy * bx + cx) * pv;
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++) {
                    int v = base + j * (n + 1) + i;
                    L.UV[2 * v] = cx * (n + 1) + i + 0.4 * (unit(&seed) - 0.5);
                    L.UV[2 * v + 1] = cy * (n + 1) + j + 0.4 * (unit(&seed) - 0.5);
                }
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                    int *t = L.F + 3 * f;
                    t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
                    f += 2;
                }
        }
    return L;
}

static void large_grid_layouts(void **state)
{
    (void)state;
    layout L = grid_layout(6, 5, 40, 12345);
    bij_report r = run(L.nuv, L.UV, L.nf, L.F);
    EXPECT_COUNTS("large_grid_layouts", HAS(r.charts, 30), HAS(r.boundary_loops, 30),
                  HAS(r.boundary_edges, 30 * 160));
    assert_int_equal(r.flipped + r.degenerate, 0);
    assert_int_equal(r.boundary_crossings + r.boundary_touchings, 0);
    assert_true(r.bijective);
    int n = 40, pv = 41 * 41;

    /* an interior vertex thrown far away: flips */
    double keep[2];
    int v = 7 * pv + 20 * 41 + 20;
    memcpy(keep, L.UV + 2 * v, sizeof keep);
    L.UV[2 * v] += 3.0;
    r = run(L.nuv, L.UV, L.nf, L.F);
    assert_true(r.flipped > 0);
    assert_false(r.bijective);
    memcpy(L.UV + 2 * v, keep, sizeof keep);

    /* a right-boundary vertex of chart 0 pushed into chart 1: crossings */
    v = 0 * pv + 20 * 41 + n;
    memcpy(keep, L.UV + 2 * v, sizeof keep);
    L.UV[2 * v] += 1.5;
    r = run(L.nuv, L.UV, L.nf, L.F);
    assert_int_equal(r.flipped, 0);
    assert_true(r.boundary_crossings > 0);
    assert_false(r.bijective);

    /* the same vertex put exactly onto chart 1's boundary vertex position:
     * contact without crossing */
    int w = 1 * pv + 20 * 41 + 0;
    memcpy(L.UV + 2 * v, L.UV + 2 * w, sizeof keep);
    r = run(L.nuv, L.UV, L.nf, L.F);
    assert_int_equal(r.boundary_crossings, 0);
    assert_true(r.boundary_touchings > 0);
    assert_false(r.bijective);
    memcpy(L.UV + 2 * v, keep, sizeof keep);

    /* a whole chart shifted by a translation so it lies inside another one
     * (exactly one cell off in x and y plus a bit: no boundary contact is
     * impossible here, so instead shrink it into one cell of chart 0) */
    for (int i = 0; i < pv; i++) {
        double *p = L.UV + 2 * (29 * pv + i);
        int ii = i % 41, jj = i / 41;
        p[0] = 10.3 + 0.4 * ii / 40.0;
        p[1] = 10.3 + 0.4 * jj / 40.0;
    }
    r = run(L.nuv, L.UV, L.nf, L.F);
    assert_int_equal(r.flipped + r.degenerate, 0);
    assert_true(r.nested_loops >= 1);
    assert_false(r.bijective);
    free(L.UV);
    free(L.F);
}

/* ---- grid counts against brute force ---- */

static void pair_counts_match_brute_force(void **state)
{
    (void)state;
    uint64_t s = 99;
    long long seen_cross = 0, seen_touch = 0, seen_fold = 0;
    for (int round = 0; round < 40; round++) {
        int nf = 10 + (int)(rnd(&s) % 60), nuv = nf * 2;
        double *UV = malloc((size_t)nuv * 2 * sizeof *UV);
        int *F = malloc((size_t)nf * 3 * sizeof *F);
        /* small integer coordinates: many exact touchings and collinear cases */
        for (int i = 0; i < 2 * nuv; i++) UV[i] = (double)(rnd(&s) % 12);
        for (int i = 0; i < 3 * nf; i++) F[i] = (int)(rnd(&s) % (uint64_t)nuv);
        bij_report r;
        assert_int_equal(bij_check(nuv, UV, nf, F, NULL, NULL, &r, NULL), SCAF_OK);
        /* boundary edges: undirected non-loop edges used once */
        int ne = 0;
        int(*E)[2] = malloc((size_t)nf * 3 * sizeof *E);
        for (int h = 0; h < 3 * nf; h++) {
            int a = F[h], b = F[h - h % 3 + (h % 3 + 1) % 3];
            if (a == b) continue;
            int uses = 0;
            for (int g = 0; g < 3 * nf; g++) {
                int c = F[g], d = F[g - g % 3 + (g % 3 + 1) % 3];
                if ((c == a && d == b) || (c == b && d == a)) uses++;
            }
            if (uses == 1) E[ne][0] = a, E[ne][1] = b, ne++;
        }
        assert_int_equal(r.boundary_edges, ne);
        long long cross = 0, touch = 0, fold = 0;
        for (int i = 0; i < ne; i++)
            for (int j = i + 1; j < ne; j++) {
                int a = E[i][0], b = E[i][1], c = E[j][0], d = E[j][1];
                int shared = (a == c) + (a == d) + (b == c) + (b == d);
                const double *P = UV;
                if (shared) {
                    /* adjacent: only a fold-back along a line counts */
                    int sv = (a == c || a == d) ? a : b;
                    int p = sv == a ? b : a, q = (c == sv) ? d : c;
                    if (bij_segments_meet(P + 2 * sv, P + 2 * p, P + 2 * sv, P + 2 * q) &&
                        bij_segments_meet(P + 2 * p, P + 2 * p, P + 2 * sv, P + 2 * q) +
                                bij_segments_meet(P + 2 * q, P + 2 * q, P + 2 * sv, P + 2 * p) >
                            0 &&
                        !(P[2 * p] == P[2 * sv] && P[2 * p + 1] == P[2 * sv + 1]) &&
                        !(P[2 * q] == P[2 * sv] && P[2 * q + 1] == P[2 * sv + 1]))
                        fold++;
                    continue;
                }
                int m = bij_segments_meet(P + 2 * a, P + 2 * b, P + 2 * c, P + 2 * d);
                cross += m == 1;
                touch += m == 2;
            }
        char label[64];
        snprintf(label, sizeof label, "pair counts, round %d", round);
        EXPECT_COUNTS(label, HAS(r.boundary_crossings, cross), HAS(r.boundary_touchings, touch),
                      HAS(r.boundary_foldbacks, fold));
        seen_cross += cross, seen_touch += touch, seen_fold += fold;
        free(E);
        free(UV);
        free(F);
    }
    assert_true(seen_cross > 100); /* the generator exercises both kinds */
    assert_true(seen_touch > 100);
    assert_true(seen_fold > 0);
}

/* ---- the verdict against a brute-force oracle ---- */

/* Closed ccw triangle abc contains p. */
static int in_closed(const double *a, const double *b, const double *c, const double *p)
{
    return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

static int sgn(double x) { return (x > 0) - (x < 0); }

/* Do two ccw triangles meet anywhere beyond the vertices and edges they
 * share by index? Decided pair by pair from the definition. */
static int conflict(const double *UV, const int *t1, const int *t2)
{
    int in2[3], in1[3], shared = 0;
    for (int i = 0; i < 3; i++) {
        in2[i] = t1[i] == t2[0] || t1[i] == t2[1] || t1[i] == t2[2];
        in1[i] = t2[i] == t1[0] || t2[i] == t1[1] || t2[i] == t1[2];
        shared += in2[i];
    }
    if (shared == 3) return 1;
    if (shared == 2) {
        int a = -1, b = -1, c = -1, d = -1;
        for (int i = 0; i < 3; i++) {
            if (in2[i]) {
                if (a < 0) a = t1[i];
                else b = t1[i];
            } else {
                c = t1[i];
            }
            if (!in1[i]) d = t2[i];
        }
        return sgn(orient2d(UV + 2 * a, UV + 2 * b, UV + 2 * c)) ==
            sgn(orient2d(UV + 2 * a, UV + 2 * b, UV + 2 * d));
    }
    for (int i = 0; i < 3; i++) {
        if (!in2[i] && in_closed(UV + 2 * t2[0], UV + 2 * t2[1], UV + 2 * t2[2], UV + 2 * t1[i]))
            return 1;
        if (!in1[i] && in_closed(UV + 2 * t1[0], UV + 2 * t1[1], UV + 2 * t1[2], UV + 2 * t2[i]))
            return 1;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int p1 = t1[i], p2 = t1[(i + 1) % 3], q1 = t2[j], q2 = t2[(j + 1) % 3];
            int inc1 = in2[i] || in2[(i + 1) % 3], inc2 = in1[j] || in1[(j + 1) % 3];
            if (shared == 1 && inc1 && inc2) {
                /* both edges leave the shared point: overlap only if they
                 * run along the same ray */
                int v = in2[i] ? p1 : p2, p = v == p1 ? p2 : p1, q = v == q1 ? q2 : q1;
                const double *V = UV + 2 * v, *P = UV + 2 * p, *Q = UV + 2 * q;
                if (orient2d(V, P, Q) == 0 && sgn(P[0] - V[0]) == sgn(Q[0] - V[0]) &&
                    sgn(P[1] - V[1]) == sgn(Q[1] - V[1]))
                    return 1;
                continue;
            }
            if (bij_segments_meet(UV + 2 * p1, UV + 2 * p2, UV + 2 * q1, UV + 2 * q2)) return 1;
        }
    return 0;
}

static int oracle_bijective(const double *UV, int nf, const int *F)
{
    for (int t = 0; t < nf; t++)
        if (!(orient2d(UV + 2 * F[3 * t], UV + 2 * F[3 * t + 1], UV + 2 * F[3 * t + 2]) > 0))
            return 0;
    for (int t = 0; t < nf; t++)
        for (int u = t + 1; u < nf; u++)
            if (conflict(UV, F + 3 * t, F + 3 * u)) return 0;
    return 1;
}

/* Random small layouts on an integer lattice: patches of grid cells (some
 * with a hole), vertices sometimes moved by a lattice step or half a step,
 * coincident vertices of different patches sometimes welded into one UV
 * index. Exact contacts, nestings, pinch points, shared edges, folds and
 * flips all occur; the checker's verdict must equal the oracle's. */
static void verdict_matches_brute_force_oracle(void **state)
{
    (void)state;
    uint64_t s = 2024;
    int agree_yes = 0, agree_no = 0;
    for (int round = 0; round < 3000; round++) {
        double UV[2 * 200];
        int F[3 * 200], nuv = 0, nf = 0;
        int npatch = 1 + (int)(rnd(&s) % 4);
        for (int k = 0; k < npatch; k++) {
            int ring = rnd(&s) % 4 == 0;
            int w = ring ? 3 : 1 + (int)(rnd(&s) % 3), h = ring ? 3 : 1 + (int)(rnd(&s) % 3);
            int ox = (int)(rnd(&s) % 7), oy = (int)(rnd(&s) % 7);
            int base = nuv;
            for (int j = 0; j <= h; j++)
                for (int i = 0; i <= w; i++) {
                    UV[2 * nuv] = ox + i;
                    UV[2 * nuv + 1] = oy + j;
                    nuv++;
                }
            for (int j = 0; j < h; j++)
                for (int i = 0; i < w; i++) {
                    if (ring && i == 1 && j == 1) continue;
                    int a = base + j * (w + 1) + i, b = a + 1, c = a + w + 2, d = a + w + 1;
                    int *t = F + 3 * nf;
                    if (rnd(&s) & 1) t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
                    else t[0] = a, t[1] = b, t[2] = d, t[3] = b, t[4] = c, t[5] = d;
                    nf += 2;
                }
        }
        if (rnd(&s) % 3 == 0) { /* move one vertex */
            int v = (int)(rnd(&s) % (uint64_t)nuv);
            double step = (rnd(&s) & 1) ? 1.0 : 0.5;
            UV[2 * v] += step * (double)((int)(rnd(&s) % 3) - 1);
            UV[2 * v + 1] += step * (double)((int)(rnd(&s) % 3) - 1);
        }
        if (rnd(&s) % 3 == 0) { /* weld coincident vertices of the layout */
            for (int t = 0; t < 3 * nf; t++)
                for (int v = 0; v < F[t]; v++)
                    if (UV[2 * v] == UV[2 * F[t]] && UV[2 * v + 1] == UV[2 * F[t] + 1]) {
                        F[t] = v;
                        break;
                    }
        }
        bij_report r;
        assert_int_equal(bij_check(nuv, UV, nf, F, NULL, NULL, &r, NULL), SCAF_OK);
        int want = oracle_bijective(UV, nf, F);
        if (r.bijective != want) {
            print_error("round %d: checker says %d, oracle %d (nf %d)\n", round, r.bijective, want,
                        nf);
            for (int t = 0; t < nf; t++)
                print_error("  t%d: %d(%g,%g) %d(%g,%g) %d(%g,%g)\n", t, F[3 * t], UV[2 * F[3 * t]],
                            UV[2 * F[3 * t] + 1], F[3 * t + 1], UV[2 * F[3 * t + 1]],
                            UV[2 * F[3 * t + 1] + 1], F[3 * t + 2], UV[2 * F[3 * t + 2]],
                            UV[2 * F[3 * t + 2] + 1]);
        }
        assert_int_equal(r.bijective, want);
        if (want) agree_yes++;
        else agree_no++;
    }
    print_message("oracle: %d bijective, %d not\n", agree_yes, agree_no);
    assert_true(agree_yes > 300);
    assert_true(agree_no > 300);
}

/* A layout whose bounding box has an aspect ratio beyond the largest
 * double (1.5e34 wide, 1.25e-321 high): the grid size is clamped before
 * any conversion (was undefined behaviour, found by fuzz_uv_numbers). */
static void extreme_aspect_ratio(void **state)
{
    (void)state;
    int F[3] = {2, 1, 0};
    bij_report r;
    scaf_error err;
    for (int k = -16; k <= 16; k++) {
        double UV[6] = {
            ldexp(1.4920950996161134e+34, k), ldexp(1.25e-321, k < 0 ? 0 : k), 0, 0, 0, 0};
        assert_int_equal(bij_check(3, UV, 1, F, NULL, NULL, &r, &err), SCAF_OK);
        assert_int_equal(r.triangles, 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ccw_triangle_is_bijective),
        cmocka_unit_test(cw_triangle_is_a_mirrored_chart),
        cmocka_unit_test(degenerate_triangles),
        cmocka_unit_test(segment_contacts),
        cmocka_unit_test(two_triangles_crossing),
        cmocka_unit_test(touching_at_shared_vertex_index_is_fine),
        cmocka_unit_test(touching_at_coincident_distinct_vertices),
        cmocka_unit_test(collinear_overlapping_edges),
        cmocka_unit_test(boundary_folding_back),
        cmocka_unit_test(folded_and_nonmanifold_edges),
        cmocka_unit_test(chart_nested_in_a_hole),
        cmocka_unit_test(chart_inside_a_triangle),
        cmocka_unit_test(overlap_at_a_pinch_point),
        cmocka_unit_test(mirrored_chart_among_good_ones),
        cmocka_unit_test(bad_input_is_an_error),
        cmocka_unit_test(large_grid_layouts),
        cmocka_unit_test(pair_counts_match_brute_force),
        cmocka_unit_test(verdict_matches_brute_force_oracle),
        cmocka_unit_test(extreme_aspect_ratio),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
