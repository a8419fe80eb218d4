/* Tests for scaffold/scaffold_build: every scaffold triangle is exactly
 * counter-clockwise, mesh + scaffold tile the box (areas add up, and the
 * kernel's checker finds no overlap in the union), chart boundary edges
 * appear whole with the chart's vertex ids, box vertices are flagged, and
 * eps = l^2/4. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "geom/bijectivity.h"
#include "geom/predicates.h"
#include "scaffold/scaffold_build.h"

/* A chart: an annulus (ring of n outer and n inner vertices) centered at
 * c, radius r (outer) and r/2 (inner), triangulated counter-clockwise;
 * appended to uv/F. */
static void add_annulus(double *uv, int *nv, int *F, int *nf, double cx, double cy, double r, int n)
{
    int base = *nv;
    for (int i = 0; i < n; i++) {
        double a = 2 * 3.14159265358979 * i / n;
        uv[2 * (base + i)] = cx + r * cos(a);
        uv[2 * (base + i) + 1] = cy + r * sin(a);
        uv[2 * (base + n + i)] = cx + 0.5 * r * cos(a + 0.3);
        uv[2 * (base + n + i) + 1] = cy + 0.5 * r * sin(a + 0.3);
    }
    *nv += 2 * n;
    int k = *nf;
    for (int i = 0; i < n; i++) {
        int o0 = base + i, o1 = base + (i + 1) % n, i0 = base + n + i, i1 = base + n + (i + 1) % n;
        F[3 * k] = o0;
        F[3 * k + 1] = o1;
        F[3 * k + 2] = i0;
        k++;
        F[3 * k] = o1;
        F[3 * k + 1] = i1;
        F[3 * k + 2] = i0;
        k++;
    }
    *nf = k;
}

/* Boundary edges (chart on the left) of F by brute force (small meshes). */
static int boundary(const int *F, int nf, int *E)
{
    int n = 0;
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j], b = F[3 * f + (j + 1) % 3], twin = 0;
            for (int g = 0; g < nf && !twin; g++)
                for (int k = 0; k < 3; k++)
                    if (F[3 * g + k] == b && F[3 * g + (k + 1) % 3] == a) twin = 1;
            if (!twin) {
                E[2 * n] = a;
                E[2 * n + 1] = b;
                n++;
            }
        }
    return n;
}

static double tri_area(const double *a, const double *b, const double *c)
{
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

static void check_scaffold(const double *uv, int nv, const int *F, int nf, double scale, int square)
{
    int *E = malloc(sizeof(int) * 6 * (size_t)nf);
    int ne = boundary(F, nf, E);
    double box[4];
    scaffold_box(uv, nv, scale, square, box);
    scaffold sc;
    scaf_error err;
    scaffold_options o = scaffold_default_options();
    scaf_status st = scaffold_build(uv, nv, E, ne, box, &o, &sc, &err);
    if (st != SCAF_OK) print_error("%s\n", err.message);
    assert_int_equal(st, SCAF_OK);
    assert_true(sc.ntri > 0);
    /* all positions in one array: mesh vertices, then scaffold-only */
    int nall = nv + sc.nextra;
    double *P = malloc(sizeof(double) * 2 * (size_t)nall);
    memcpy(P, uv, sizeof(double) * 2 * (size_t)nv);
    memcpy(P + 2 * nv, sc.extra_uv, sizeof(double) * 2 * (size_t)sc.nextra);
    /* 1. every scaffold triangle exactly counter-clockwise */
    double area = 0;
    for (int t = 0; t < sc.ntri; t++) {
        const int *T = sc.T + 3 * t;
        for (int j = 0; j < 3; j++) assert_true(T[j] >= 0 && T[j] < nall);
        assert_true(orient2d(P + 2 * T[0], P + 2 * T[1], P + 2 * T[2]) > 0);
        area += tri_area(P + 2 * T[0], P + 2 * T[1], P + 2 * T[2]);
    }
    for (int f = 0; f < nf; f++)
        area += tri_area(uv + 2 * F[3 * f], uv + 2 * F[3 * f + 1], uv + 2 * F[3 * f + 2]);
    /* 2. mesh + scaffold tile the box */
    double box_area = (box[2] - box[0]) * (box[3] - box[1]);
    assert_true(fabs(area - box_area) <= 1e-10 * box_area);
    /* 3. every chart boundary edge a->b is a scaffold edge b->a (whole, same ids) */
    for (int e = 0; e < ne; e++) {
        int found = 0;
        for (int t = 0; t < sc.ntri; t++)
            for (int j = 0; j < 3; j++)
                if (sc.T[3 * t + j] == E[2 * e + 1] && sc.T[3 * t + (j + 1) % 3] == E[2 * e])
                    found++;
        assert_int_equal(found, 1);
    }
    /* mesh vertex ids in the scaffold are boundary vertices only */
    for (int t = 0; t < sc.ntri; t++)
        for (int j = 0; j < 3; j++) {
            int v = sc.T[3 * t + j];
            if (v >= nv) continue;
            int onb = 0;
            for (int e = 0; e < ne && !onb; e++) onb = E[2 * e] == v || E[2 * e + 1] == v;
            assert_true(onb);
        }
    /* box flags: fixed vertices lie on the box, the box corners are present */
    int corners = 0;
    for (int i = 0; i < sc.nextra; i++) {
        const double *p = sc.extra_uv + 2 * i;
        int on = p[0] == box[0] || p[0] == box[2] || p[1] == box[1] || p[1] == box[3];
        assert_int_equal(on, sc.extra_fixed[i]);
        if ((p[0] == box[0] || p[0] == box[2]) && (p[1] == box[1] || p[1] == box[3])) corners++;
    }
    assert_int_equal(corners, 4);
    /* 4. eps = l^2/4 with l the shortest boundary edge */
    double l2 = INFINITY;
    for (int e = 0; e < ne; e++) {
        const double *a = uv + 2 * E[2 * e], *b = uv + 2 * E[2 * e + 1];
        double d = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
        if (d < l2) l2 = d;
    }
    assert_true(fabs(sc.eps - l2 / 4) <= 1e-15 * l2);
    /* 5. no overlap: the union of mesh and scaffold is one bijective map */
    int *U = malloc(sizeof(int) * 3 * (size_t)(nf + sc.ntri));
    memcpy(U, F, sizeof(int) * 3 * (size_t)nf);
    memcpy(U + 3 * nf, sc.T, sizeof(int) * 3 * (size_t)sc.ntri);
    bij_report rep;
    assert_int_equal(bij_check(nall, P, nf + sc.ntri, U, NULL, NULL, &rep, &err), SCAF_OK);
    assert_true(rep.bijective);
    assert_int_equal(rep.flipped, 0);
    assert_int_equal(rep.degenerate, 0);
    assert_int_equal(rep.boundary_loops, 1); /* only the box is left */
    free(U);
    free(P);
    free(E);
    scaffold_free(&sc);
}

static void one_triangle(void **state)
{
    (void)state;
    double uv[] = {0, 0, 1, 0, 0.3, 0.8};
    int F[] = {0, 1, 2};
    check_scaffold(uv, 3, F, 1, 3.0, 0);
    check_scaffold(uv, 3, F, 1, 1.5, 1);
}

static void annulus_hole_is_filled(void **state)
{
    (void)state;
    double uv[2 * 64];
    int F[3 * 64], nv = 0, nf = 0;
    add_annulus(uv, &nv, F, &nf, 0, 0, 1, 12);
    check_scaffold(uv, nv, F, nf, 3.0, 0);
}

static void several_charts_close_together(void **state)
{
    (void)state;
    double uv[2 * 200];
    int F[3 * 200], nv = 0, nf = 0;
    add_annulus(uv, &nv, F, &nf, 0, 0, 1, 10);
    add_annulus(uv, &nv, F, &nf, 2.0 + 1e-9, 0, 1, 10); /* nearly touching */
    add_annulus(uv, &nv, F, &nf, 1, 2.5, 0.3, 8);
    /* a chart inside the hole of the first one */
    double s = 0.1;
    int b = nv;
    uv[2 * nv] = -s;
    uv[2 * nv + 1] = -s;
    nv++;
    uv[2 * nv] = s;
    uv[2 * nv + 1] = -s;
    nv++;
    uv[2 * nv] = 0;
    uv[2 * nv + 1] = s;
    nv++;
    F[3 * nf] = b;
    F[3 * nf + 1] = b + 1;
    F[3 * nf + 2] = b + 2;
    nf++;
    check_scaffold(uv, nv, F, nf, 3.0, 0);
}

static void box_contains_flat_layout(void **state)
{
    (void)state;
    double uv[] = {0, 0, 10, 0, 5, 1e-6}, box[4];
    scaffold_box(uv, 3, 3.0, 0, box);
    assert_true(box[0] < 0 && box[2] > 10 && box[1] < 0 && box[3] > 1e-6);
    /* flat side widened: the box is not a sliver */
    assert_true((box[3] - box[1]) > 1.0);
}

static void crossing_boundaries_fail_cleanly(void **state)
{
    (void)state;
    /* two triangles overlapping: the mesher must refuse, not crash */
    double uv[] = {0, 0, 2, 0, 1, 2, 0, 1, 2, 1, 1, -1};
    int F[] = {0, 1, 2, 3, 5, 4};
    int E[12];
    int ne = boundary(F, 2, E);
    double box[4];
    scaffold_box(uv, 6, 3.0, 0, box);
    scaffold sc;
    scaf_error err;
    assert_int_not_equal(scaffold_build(uv, 6, E, ne, box, NULL, &sc, &err), SCAF_OK);
    assert_int_equal(sc.ntri, 0);
    assert_null(sc.T);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_triangle),
        cmocka_unit_test(annulus_hole_is_filled),
        cmocka_unit_test(several_charts_close_together),
        cmocka_unit_test(box_contains_flat_layout),
        cmocka_unit_test(crossing_boundaries_fail_cleanly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
