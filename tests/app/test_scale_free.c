/* Results that do not depend on the units of the input (issue 9, section
 * 4): param and atlas on one mesh at scale 1, 2^200, 2^-200 (bit for bit,
 * up to the scale), 1e80 and 1e-80 (same run, up to rounding of the
 * scaled input); and one verdict on degenerate faces: the exact test
 * `scaf info` counts (mesh_topology) is the one param and atlas refuse;
 * and the 3D checker of UV pictures, the same at any scale. */
#include <math.h>
#include <stdio.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/atlas.h"
#include "app/uv_png.h"
#include "geom/coord_scale.h"
#include "mesh/samples.h"
#include "mesh/topology.h"
#include "scaf/scaf.h"
#include "support/support.h"

/* param on m with its positions multiplied by s (ldexp by k when s == 0):
 * returns the status, *uv (malloc'd) the UVs, *E the energy. */
static scaf_status param_scaled(const mesh *m, double s, int k, int iterations, double **uv,
                                int *nuv, double *E, char *msg, size_t size)
{
    double *V = malloc(sizeof(double) * 3 * (size_t)m->nv);
    assert_non_null(V);
    for (int i = 0; i < 3 * m->nv; i++) V[i] = s != 0.0 ? m->V[i] * s : ldexp(m->V[i], k);
    scaf_options_t o = scaf_options_default();
    o.max_iterations = iterations;
    scaf_param_t *p = scaf_param_new(&o);
    assert_non_null(p);
    scaf_status st = scaf_param_set_mesh(p, V, m->nv, m->F, m->nf, NULL, 0, NULL);
    if (st == SCAF_OK) st = scaf_param_run(p, 0, NULL, NULL);
    *uv = NULL;
    if (st == SCAF_OK) {
        *nuv = scaf_param_uv_count(p);
        *uv = malloc(sizeof(double) * 2 * (size_t)*nuv);
        assert_non_null(*uv);
        st = scaf_param_get_uv(p, *uv, NULL);
        *E = scaf_param_energy(p);
    }
    if (msg) snprintf(msg, size, "%s", scaf_param_error(p));
    scaf_param_destroy(p);
    free(V);
    return st;
}

static void param_is_scale_free(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("hemisphere", 4, &m, &err), SCAF_OK);
    double *uv0, E0;
    int n0 = 0;
    assert_int_equal(param_scaled(&m, 1.0, 0, 8, &uv0, &n0, &E0, NULL, 0), SCAF_OK);
    const int k[] = {200, -200, 1, -3, 700, -700};
    for (size_t t = 0; t < sizeof k / sizeof *k; t++) {
        double *uv, E;
        int n = 0;
        assert_int_equal(param_scaled(&m, 0.0, k[t], 8, &uv, &n, &E, NULL, 0), SCAF_OK);
        assert_int_equal(n, n0);
        for (int i = 0; i < 2 * n; i++) assert_true(uv[i] == ldexp(uv0[i], k[t]));
        assert_true(E == E0);
        free(uv);
    }
    /* not a power of two: the scaled input rounds, the run is the same up
     * to that (it used to fail: area inf at 1e80, zero at 1e-80) */
    const double s[] = {1e80, 1e-80, 1e150, 1e-150};
    for (size_t t = 0; t < sizeof s / sizeof *s; t++) {
        double *uv, E;
        int n = 0;
        assert_int_equal(param_scaled(&m, s[t], 0, 8, &uv, &n, &E, NULL, 0), SCAF_OK);
        assert_true(fabs(E - E0) <= 1e-6 * E0);
        /* the map is defined up to a rigid motion, which drifts with the
         * input's last bits: compare energies (1e-10 relative measured) */
        for (int i = 0; i < 2 * n; i++) assert_true(isfinite(uv[i] / s[t]));
        free(uv);
    }
    /* at 2^-1060 the UVs in the mesh's units would be subnormal (rounded,
     * no longer the map proved bijective): a specific error, not a
     * silently different map */
    double *uv, E;
    int n = 0;
    char msg[256];
    assert_int_equal(param_scaled(&m, 0.0, -1060, 2, &uv, &n, &E, msg, sizeof msg),
                     SCAF_ERR_NUMERIC);
    assert_non_null(strstr(msg, "subnormal"));
    free(uv);
    free(uv0);
    mesh_free(&m);
}

static void atlas_is_scale_free(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("cubesphere", 2, &m, &err), SCAF_OK);
    atlas_options o = atlas_options_default();
    o.settle_iterations = 3;
    o.compact_iterations = 3;
    double *V0 = m.V, *uv0 = NULL;
    int nw0 = 0;
    const int k[] = {0, 200, -200, -1000};
    for (size_t t = 0; t < sizeof k / sizeof *k; t++) {
        double *V = malloc(sizeof(double) * 3 * (size_t)m.nv);
        assert_non_null(V);
        for (int i = 0; i < 3 * m.nv; i++) V[i] = ldexp(V0[i], k[t]);
        m.V = V;
        atlas a;
        assert_int_equal(atlas_init(&a, &m, &o, &err), SCAF_OK);
        assert_int_equal(atlas_run(&a, NULL, NULL, &err), SCAF_OK);
        if (t == 0) {
            nw0 = a.nw;
            uv0 = malloc(sizeof(double) * 2 * (size_t)a.nw);
            assert_non_null(uv0);
            memcpy(uv0, a.loop.uv, sizeof(double) * 2 * (size_t)a.nw);
        } else {
            /* the working layout itself is the same bits: no scale shows */
            assert_int_equal(a.nw, nw0);
            assert_memory_equal(a.loop.uv, uv0, sizeof(double) * 2 * (size_t)a.nw);
        }
        atlas_free(&a);
        m.V = V0;
        free(V);
    }
    free(uv0);
    mesh_free(&m);
}

/* Degenerate-face count of `scaf info` (mesh_topology) for V, F. */
static int info_degenerate(int nv, double *V, int nf, int *F)
{
    mesh m = {nv, V, nf, F, 0, NULL, NULL};
    mesh_topology t;
    scaf_error err;
    assert_int_equal(mesh_topology_compute(&m, &t, &err), SCAF_OK);
    int n = t.degenerate_faces;
    mesh_topology_free(&t);
    return n;
}

/* A fan of 4 triangles around vertex 0 (a disk); the last one is 0, 4, 5
 * with vertex 4 = (-1, 1, 0) and vertex 5 = (x, y, z), all times s. */
static void one_verdict_on_degenerate_faces(void **state)
{
    (void)state;
    struct {
        double x, y, z, s;
        int degenerate;
    } c[] = {
        {0, 1, 0, 1e-80, 0}, /* was "degenerate (zero 3D area)" in param */
        {0, 1, 0, 1e80, 0},  /* was "chart has 3D area inf" */
        {0, 1, 0, 1e-300, 0},
        {0, 1, 0, 1e300, 0},
        {-2, 2, 0, 1.0, 1}, /* collinear with vertices 0 and 4 */
        {-2, 2, 0, 1e-300, 1},
        {-2, 2, 0x1p-1074, 1.0, 0}, /* not degenerate; area far below resolution */
    };
    for (size_t t = 0; t < sizeof c / sizeof *c; t++) {
        double V[18] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.5, -1, 1, 0, c[t].x, c[t].y, c[t].z};
        for (int i = 0; i < 18; i++) V[i] *= c[t].s;
        int F[12] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5};
        int deg = info_degenerate(6, V, 4, F);
        assert_int_equal(deg > 0, c[t].degenerate);
        scaf_param_t *p = scaf_param_new(NULL);
        assert_non_null(p);
        scaf_status st = scaf_param_set_mesh(p, V, 6, F, 4, NULL, 0, NULL);
        const char *msg = scaf_param_error(p);
        if (deg > 0) {
            assert_int_equal(st, SCAF_ERR_MESH);
            assert_non_null(strstr(msg, "face 3 is degenerate"));
        } else if (c[t].z == 0.0) {
            assert_int_equal(st, SCAF_OK);
        } else {
            /* refused, but not called degenerate: info counts 0 */
            assert_int_equal(st, SCAF_ERR_MESH);
            assert_null(strstr(msg, "is degenerate"));
            assert_non_null(strstr(msg, "face 3 is not degenerate"));
        }
        scaf_param_destroy(p);
    }
}

/* The whole file at path (malloc'd), its size in *n. */
static unsigned char *read_all(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    rewind(f);
    unsigned char *b = malloc((size_t)*n + 1);
    assert_non_null(b);
    assert_int_equal(fread(b, 1, (size_t)*n, f), (size_t)*n);
    fclose(f);
    return b;
}

/* The 3D checker of a UV picture at 2^900 and 2^-1000 is the same picture
 * (its period overflowed to infinity above about 1e154: no checker). */
static void checker_picture_is_scale_free(void **state)
{
    (void)state;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_sample_make("hemisphere", 4, &m, &err), SCAF_OK);
    /* UVs: the xy projection (a valid picture input, bijectivity aside) */
    double *uv = malloc(sizeof(double) * 2 * (size_t)m.nv),
           *V = malloc(sizeof(double) * 3 * (size_t)m.nv);
    unsigned *col = malloc(sizeof(unsigned) * (size_t)m.nf);
    assert_true(uv && V && col);
    for (int v = 0; v < m.nv; v++) uv[2 * v] = m.V[3 * v], uv[2 * v + 1] = m.V[3 * v + 1];
    for (int f = 0; f < m.nf; f++) col[f] = 0xc0c0c0u;
    uv_png_options o = uv_png_options_default();
    o.size = 128;
    o.checker = 8.0;
    const int k[] = {0, 900, -1000};
    unsigned char *ref = NULL;
    long nref = 0;
    for (size_t t = 0; t < sizeof k / sizeof *k; t++) {
        for (int i = 0; i < 3 * m.nv; i++) V[i] = ldexp(m.V[i], k[t]);
        char path[512];
        test_tmp_path("scale_free_checker.png", path, sizeof path);
        assert_int_equal(uv_png_write(path, m.nv, uv, m.nf, m.F, col, m.nv, V, m.F, &o, &err),
                         SCAF_OK);
        long n;
        unsigned char *b = read_all(path, &n);
        if (!ref) {
            ref = b, nref = n;
            continue;
        }
        assert_int_equal(n, nref);
        assert_memory_equal(b, ref, (size_t)n);
        free(b);
    }
    free(ref);
    free(uv);
    free(V);
    free(col);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_is_scale_free),
        cmocka_unit_test(atlas_is_scale_free),
        cmocka_unit_test(one_verdict_on_degenerate_faces),
        cmocka_unit_test(checker_picture_is_scale_free),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
