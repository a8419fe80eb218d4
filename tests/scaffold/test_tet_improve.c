/* Tests for scaffold/tet_improve, scaffold/tet_scaffold and
 * geom/tet_quality: the quality measure and its gradient; each operation
 * firing where it must (a flat bipyramid 2-3 flipped, a needle ring 3-2
 * flipped, a vertex pushed against a face smoothed, a vertex next to a
 * corner contracted); and on scaffolds made bad by random valid moves of
 * their free vertices (an icosphere in its box, the bunny when the shared
 * data is present) the promises, checked independently: every tet
 * positive (exact), the surface triangles still faces with the inside on
 * one side and the outside on the other, regions changing only across
 * them, the box faces the hull, each region's volume unchanged, mesh and
 * box vertices unmoved, the adjacency the module keeps equal to one
 * rebuilt from scratch; worst quality raised; same input, same bytes. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/tet_box_mesh.h"
#include "geom/tet_orient.h"
#include "geom/tet_quality.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "opt/rng.h"
#include "scaffold/tet_improve.h"
#include "scaffold/tet_scaffold.h"
#include "support/support.h"

/* ---- quality ---- */

static const double REG[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};

static void test_quality_measure(void **state)
{
    (void)state;
    /* (1,1,1),(1,-1,-1),(-1,1,-1),(-1,-1,1) is regular; check its sign */
    double q = tet_quality(REG[0], REG[1], REG[2], REG[3]);
    int sign = tet_orientation(REG[0], REG[1], REG[2], REG[3]);
    assert_true(fabs(fabs(q) - 1) < 1e-14);
    assert_true(sign * q > 0);
    /* scale, translation invariance; odd permutation negates */
    double S[4][3];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) S[i][k] = 1e-3 * REG[i][k] + 5;
    assert_true(fabs(tet_quality(S[0], S[1], S[2], S[3]) - q) < 1e-9);
    assert_true(fabs(tet_quality(REG[1], REG[0], REG[2], REG[3]) + q) < 1e-14);
    /* a sliver: four nearly coplanar points on a square */
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {1, 1, 1e-3}, d[3] = {0, 1, 0};
    assert_true(fabs(tet_quality(a, b, c, d)) < 1e-2);
    /* the gradient against central differences */
    rng r = {7};
    for (int trial = 0; trial < 20; trial++) {
        double P[4][3], g[3];
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 3; k++) P[i][k] = rng_uniform(&r, -1, 1);
        double q0 = tet_quality_grad(P[0], P[1], P[2], P[3], g);
        assert_true(fabs(q0 - tet_quality(P[0], P[1], P[2], P[3])) < 1e-15);
        for (int k = 0; k < 3; k++) {
            double h = 1e-6, save = P[0][k];
            P[0][k] = save + h;
            double qp = tet_quality(P[0], P[1], P[2], P[3]);
            P[0][k] = save - h;
            double qm = tet_quality(P[0], P[1], P[2], P[3]);
            P[0][k] = save;
            assert_true(fabs((qp - qm) / (2 * h) - g[k]) < 1e-5 * (1 + fabs(g[k])));
        }
    }
}

static void test_quality_summary(void **state)
{
    (void)state;
    double q[40], mn, p5;
    for (int i = 0; i < 40; i++) q[i] = (double)((i * 17) % 40) / 40.0; /* 0..39/40 shuffled */
    assert_int_equal(tet_quality_summary(40, q, &mn, &p5), 0);
    assert_true(mn == 0);
    assert_true(p5 == 2.0 / 40.0); /* element floor(0.05 * 40) = 2 in increasing order */
    assert_true(q[0] == 0 && q[1] == 17.0 / 40); /* input untouched */
    assert_int_equal(tet_quality_summary(0, q, &mn, &p5), 0);
}

/* ---- small configurations ---- */

/* Orient each tet of T positively at V (swapping two corners). */
static void orient_all(const double *V, int nt, int *T)
{
    for (int t = 0; t < nt; t++) {
        int *q = T + 4 * t;
        if (tet_orientation(V + 3 * q[0], V + 3 * q[1], V + 3 * q[2], V + 3 * q[3]) < 0) {
            int x = q[2];
            q[2] = q[3], q[3] = x;
        }
    }
}

static tet_improve_stats run_small(int nv, const double *V, const unsigned char *fixed, int nt,
                                   int *T, unsigned ops, tet_scaffold *s)
{
    orient_all(V, nt, T);
    signed char region[16] = {0};
    assert_int_equal(tet_scaffold_init(s, 0, nv, V, fixed, nt, T, region, 0, NULL, NULL), SCAF_OK);
    tet_improve_options o;
    tet_improve_options_default(&o);
    o.quality_goal = 1;
    o.ops = ops;
    tet_improve_stats st;
    assert_int_equal(tet_improve(s, NULL, &o, &st, NULL), SCAF_OK);
    tet_orient_report r;
    assert_int_equal(tet_orient_check(s->nv, s->P, s->nt, s->T, &r, NULL), SCAF_OK);
    assert_int_equal(r.positive, s->nt);
    return st;
}

/* Two tets on the faces of a flat triangular bipyramid: the 2-3 flip
 * makes the three tets around the short axis, better (0.13 -> 0.19). */
static void test_flip23_flat_bipyramid(void **state)
{
    (void)state;
    const double h = 0.1, s3 = sqrt(3);
    double V[] = {1, 0, 0, -0.5, s3 / 2, 0, -0.5, -s3 / 2, 0, 0, 0, h, 0, 0, -h};
    int T[] = {0, 1, 2, 3, 0, 1, 2, 4};
    tet_scaffold s;
    tet_improve_stats st = run_small(5, V, NULL, 2, T, TET_OP_FLIP23, &s);
    assert_int_equal(st.flip23, 1);
    assert_int_equal(s.nt, 3);
    assert_true(st.min_after > st.min_before + 0.05);
    for (int t = 0; t < 3; t++) { /* all around the edge 3-4 */
        const int *q = s.T + 4 * t;
        assert_true(q[0] == 3 || q[1] == 3 || q[2] == 3 || q[3] == 3);
        assert_true(q[0] == 4 || q[1] == 4 || q[2] == 4 || q[3] == 4);
    }
    tet_scaffold_free(&s);
    /* with the operation off nothing changes */
    st = run_small(5, V, NULL, 2, T, TET_OP_SMOOTH, &s);
    assert_int_equal(st.flip23 + st.flip32 + st.smooth, 0);
    assert_int_equal(s.nt, 2);
    tet_scaffold_free(&s);
}

/* Three needles around a long axis: the 3-2 flip (edge removal of the
 * axis) makes two good tets (0.30 -> 0.92). */
static void test_flip32_needles(void **state)
{
    (void)state;
    const double h = 2, s3 = sqrt(3);
    double V[] = {1, 0, 0, -0.5, s3 / 2, 0, -0.5, -s3 / 2, 0, 0, 0, h, 0, 0, -h};
    int T[] = {3, 4, 0, 1, 3, 4, 1, 2, 3, 4, 2, 0};
    tet_scaffold s;
    tet_improve_stats st = run_small(5, V, NULL, 3, T, TET_OP_EDGE_REMOVAL, &s);
    assert_int_equal(st.flip32, 1);
    assert_int_equal(s.nt, 2);
    assert_true(st.min_after > 0.9 && st.min_before < 0.31);
    tet_scaffold_free(&s);
}

/* A flat square bipyramid cut into four tets by the diagonal face: the
 * two faces sandwiched between the apexes go, four tets around the axis
 * come (0.23 -> 0.54); a 2-3 flip alone would leave a flat tet. */
static void test_multi_face_square(void **state)
{
    (void)state;
    const double h = 0.15;
    double V[] = {0.5, 0.5,  0, -0.5, 0.5,  0, -0.5,  -0.5, 0,
                  0.5, -0.5, 0, 0.05, 0.02, h, -0.03, 0.01, -h};
    int T[] = {0, 1, 2, 4, 0, 2, 3, 4, 0, 1, 2, 5, 0, 2, 3, 5};
    tet_scaffold s;
    tet_improve_stats st = run_small(6, V, NULL, 4, T, TET_OP_FLIP23 | TET_OP_MULTI_FACE, &s);
    assert_int_equal(st.multi_face, 1);
    assert_int_equal(st.flip23, 0);
    assert_int_equal(s.nt, 4);
    assert_true(st.min_before < 0.24 && st.min_after > 0.5);
    for (int t = 0; t < 4; t++) { /* all around the edge 4-5 */
        const int *q = s.T + 4 * t;
        assert_true(q[0] == 4 || q[1] == 4 || q[2] == 4 || q[3] == 4);
        assert_true(q[0] == 5 || q[1] == 5 || q[2] == 5 || q[3] == 5);
    }
    tet_scaffold_free(&s);
}

/* A regular octahedron (fixed corners) coned to a free centre vertex. */
static void octahedron(double *V, int *T)
{
    static const double C[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    memcpy(V, C, sizeof C);
    for (int k = 0; k < 3; k++) V[18 + k] = 0;
    int n = 0;
    for (int x = 0; x < 2; x++)
        for (int y = 2; y < 4; y++)
            for (int z = 4; z < 6; z++)
                T[4 * n] = 6, T[4 * n + 1] = x, T[4 * n + 2] = y, T[4 * n + 3] = z, n++;
}

/* The centre pushed almost onto a face: smoothing brings the worst tet
 * back up (the authors' smoothing never fires: it must here). */
static void test_smooth_centre(void **state)
{
    (void)state;
    double V[21];
    int T[32];
    unsigned char fixed[7] = {1, 1, 1, 1, 1, 1, 0};
    octahedron(V, T);
    for (int k = 0; k < 3; k++) V[18 + k] = 0.3; /* near the face (1,0,0),(0,1,0),(0,0,1) */
    tet_scaffold s;
    tet_improve_stats st = run_small(7, V, fixed, 8, T, TET_OP_SMOOTH, &s);
    assert_true(st.smooth >= 1);
    assert_true(st.min_before < 0.35);
    assert_true(st.min_after > 0.75); /* the centre: 0.83 */
    for (int v = 0; v < 6; v++) assert_memory_equal(s.P + 3 * v, V + 3 * v, 3 * sizeof(double));
    tet_scaffold_free(&s);
    /* a fixed centre is never moved */
    fixed[6] = 1;
    st = run_small(7, V, fixed, 8, T, TET_OP_SMOOTH, &s);
    assert_int_equal(st.smooth, 0);
    assert_memory_equal(s.P, V, sizeof V);
    tet_scaffold_free(&s);
}

/* The centre next to a corner: contraction removes it, the octahedron
 * becomes four tets around an axis; the vertex map says so. */
static void test_contract_centre(void **state)
{
    (void)state;
    double V[21];
    int T[32];
    unsigned char fixed[7] = {1, 1, 1, 1, 1, 1, 0};
    octahedron(V, T);
    V[20] = 0.97;
    tet_scaffold s;
    tet_improve_stats st = run_small(7, V, fixed, 8, T, TET_OP_CONTRACT, &s);
    assert_int_equal(st.contract, 1);
    assert_int_equal(s.nv, 6);
    assert_int_equal(s.nt, 4);
    assert_int_equal(s.nv_before, 7);
    for (int v = 0; v < 6; v++) assert_int_equal(s.vertex_map[v], v);
    assert_int_equal(s.vertex_map[6], -1);
    assert_true(st.min_after > st.min_before + 0.2);
    tet_scaffold_free(&s);
}

/* ---- the invariants on real scaffolds ---- */

typedef struct face_key {
    int v[3];
    int region; /* of the tet holding it */
} face_key;

static int cmp_key(const void *pa, const void *pb)
{
    const face_key *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a->v[k] != b->v[k]) return a->v[k] < b->v[k] ? -1 : 1;
    return a->region - b->region;
}

static void sort3(int *v)
{
    int t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
    if (v[1] > v[2]) t = v[1], v[1] = v[2], v[2] = t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
}

static double volume6(const double *V, const int *q)
{
    const double *a = V + 3 * q[0], *b = V + 3 * q[1], *c = V + 3 * q[2], *d = V + 3 * q[3];
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = d[k] - a[k];
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
        u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/* What must not change: the hull faces, each region's volume. */
typedef struct invariants {
    int nhull;
    face_key *hull;
    double vol[2];
} invariants;

/* All faces (4 nt) sorted; hull faces are those seen once. Checks every
 * face is seen at most twice, and that two tets sharing a face have the
 * same region unless the face is protected (prot sorted keys). */
static invariants faces_check(const tet_scaffold *s, int nprot, const face_key *prot)
{
    invariants inv = {0, NULL, {0, 0}};
    size_t n = 4 * (size_t)s->nt;
    face_key *all = malloc(sizeof *all * n);
    inv.hull = malloc(sizeof *inv.hull * n);
    assert_non_null(all);
    assert_non_null(inv.hull);
    static const int fc[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    for (int t = 0; t < s->nt; t++) {
        inv.vol[s->region[t]] += volume6(s->P, s->T + 4 * t) / 6;
        for (int f = 0; f < 4; f++) {
            face_key *k = &all[4 * (size_t)t + f];
            for (int c = 0; c < 3; c++) k->v[c] = s->T[4 * t + fc[f][c]];
            sort3(k->v);
            k->region = s->region[t];
        }
    }
    qsort(all, n, sizeof *all, cmp_key);
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && !memcmp(all[j].v, all[i].v, sizeof all[i].v); j++) {}
        assert_true(j - i <= 2);
        if (j - i == 1) {
            inv.hull[inv.nhull++] = all[i];
            continue;
        }
        face_key probe = all[i];
        probe.region = 0;
        int is_prot = bsearch(&probe, prot, (size_t)nprot, sizeof *prot, cmp_key) != NULL;
        /* the surface separates regions; nothing else does */
        assert_int_equal(all[i].region != all[i + 1].region, is_prot);
    }
    for (int p = 0; p < nprot; p++) { /* every protected face present, twice */
        face_key probe = prot[p];
        probe.region = 0;
        face_key *hit = bsearch(&probe, all, n, sizeof *all, cmp_key);
        assert_non_null(hit);
        assert_true(hit + 1 < all + n && !memcmp(hit[1].v, probe.v, sizeof probe.v) &&
                    hit[1].region == 1);
    }
    free(all);
    return inv;
}

/* The module's adjacency equals one rebuilt from its own output. */
static void adjacency_check(const tet_scaffold *s, int nprot, const int *prot)
{
    tet_scaffold r;
    assert_int_equal(tet_scaffold_init(&r, s->nmesh, s->nv, s->P, s->fixed, s->nt, s->T, s->region,
                                       nprot, prot, NULL),
                     SCAF_OK);
    assert_memory_equal(r.nbr, s->nbr, sizeof(int) * 4 * (size_t)s->nt);
    assert_memory_equal(r.protect, s->protect, (size_t)s->nt);
    for (int v = 0; v < s->nv; v++) {
        int t = s->vtet[v];
        assert_true(t >= 0 && t < s->nt);
        const int *q = s->T + 4 * t;
        assert_true(q[0] == v || q[1] == v || q[2] == v || q[3] == v);
    }
    tet_scaffold_free(&r);
}

/* Random valid moves of the vertices that are not fixed (mesh vertices
 * included), each toward a random neighbour by a random fraction up to
 * `reach`, kept only when every tet around the vertex stays positive
 * (exact): a valid but badly shaped scaffold, as a step of the loop
 * leaves it. */
static void perturb(tet_scaffold *s, double reach, uint64_t seed)
{
    rng r = {seed};
    for (int t = 0; t < s->nt; t++) {
        int v = s->T[4 * t + (int)rng_uniform(&r, 0, 4)];
        int u = s->T[4 * t + (int)rng_uniform(&r, 0, 4)];
        if (s->fixed[v] || u == v) continue;
        double old[3], f = rng_uniform(&r, 0, reach);
        memcpy(old, s->P + 3 * v, sizeof old);
        for (int k = 0; k < 3; k++) s->P[3 * v + k] += f * (s->P[3 * u + k] - old[k]);
        int ok = 1;
        for (int t2 = 0; t2 < s->nt && ok; t2++) {
            const int *q = s->T + 4 * t2;
            if (q[0] == v || q[1] == v || q[2] == v || q[3] == v)
                ok = tet_orientation(s->P + 3 * q[0], s->P + 3 * q[1], s->P + 3 * q[2],
                                     s->P + 3 * q[3]) > 0;
        }
        if (!ok) memcpy(s->P + 3 * v, old, sizeof old);
    }
}

/* One tet_improve call (mesh positions X), every promise checked against
 * the scaffold before it. */
static tet_improve_stats checked_call(tet_scaffold *s, const double *X, int nf, const int *F,
                                      const face_key *prot)
{
    int nv0 = s->nv;
    double *P0 = malloc(sizeof(double) * 3 * (size_t)nv0), *stale = s->P;
    assert_non_null(P0);
    memcpy(P0, s->P, sizeof(double) * 3 * (size_t)nv0);
    if (X) memcpy(P0, X, sizeof(double) * 3 * (size_t)s->nmesh);
    unsigned char *fixed0 = malloc((size_t)nv0);
    assert_non_null(fixed0);
    memcpy(fixed0, s->fixed, (size_t)nv0);
    s->P = P0; /* the scaffold as the call should see it */
    invariants before = faces_check(s, nf, prot);
    s->P = stale;
    tet_improve_stats st;
    assert_int_equal(tet_improve(s, X, NULL, &st, NULL), SCAF_OK);
    print_message("tets %d -> %d, vertices %d -> %d, min %.4f -> %.4f, p5 %.4f -> %.4f, below "
                  "%d -> %d; flips 2-3 %lld 3-2 %lld, edge removals %lld, multi-face %lld, "
                  "smoothing %lld, "
                  "contractions %lld, splits %lld, tries %lld, passes %d\n",
                  st.tets_before, st.tets_after, st.vertices_before, st.vertices_after,
                  st.min_before, st.min_after, st.p5_before, st.p5_after, st.below_goal_before,
                  st.below_goal_after, st.flip23, st.flip32, st.edge_removal, st.multi_face,
                  st.smooth, st.contract, st.split, st.tries, st.passes);
    assert_int_equal(st.tets_after, s->nt);
    assert_int_equal(st.vertices_after, s->nv);
    /* every tet positive, exactly */
    tet_orient_report r;
    assert_int_equal(tet_orient_check(s->nv, s->P, s->nt, s->T, &r, NULL), SCAF_OK);
    assert_int_equal(r.positive, s->nt);
    /* the surface kept, regions separated by it only, same hull, volumes */
    invariants after = faces_check(s, nf, prot);
    assert_int_equal(after.nhull, before.nhull);
    for (int i = 0; i < after.nhull; i++) {
        int v[3];
        for (int k = 0; k < 3; k++) v[k] = s->vertex_map[before.hull[i].v[k]];
        sort3(v);
        assert_memory_equal(v, after.hull[i].v, sizeof v);
        assert_int_equal(after.hull[i].region, 0);
    }
    for (int g = 0; g < 2; g++)
        assert_true(fabs(after.vol[g] - before.vol[g]) <= 1e-9 * (before.vol[0] + before.vol[1]));
    /* mesh and box vertices unmoved, at their (mapped) ids */
    assert_int_equal(s->nv_before, st.vertices_before + st.split);
    for (int v = 0; v < nv0; v++) {
        int u = s->vertex_map[v];
        if (v < s->nmesh) assert_int_equal(u, v);
        if (v < s->nmesh || fixed0[v]) {
            assert_true(u >= 0);
            assert_int_equal(s->fixed[u], fixed0[v]);
            assert_memory_equal(s->P + 3 * (size_t)u, P0 + 3 * (size_t)v, 3 * sizeof(double));
        }
    }
    free(fixed0);
    adjacency_check(s, nf, F);
    /* never worse */
    assert_true(st.min_after >= st.min_before);
    free(before.hull);
    free(after.hull);
    free(P0);
    return st;
}

/* Improve TetGen's scaffold, move its vertices (the surface's through X),
 * improve again; twice, for the same bytes. */
static void improve_and_check(const tet_box_mesh *tm, int nf, const int *F)
{
    face_key *prot = malloc(sizeof *prot * (size_t)nf);
    assert_non_null(prot);
    for (int f = 0; f < nf; f++) {
        memcpy(prot[f].v, F + 3 * f, sizeof prot[f].v);
        sort3(prot[f].v);
        prot[f].region = 0;
    }
    qsort(prot, (size_t)nf, sizeof *prot, cmp_key);
    tet_scaffold run[2];
    for (int k = 0; k < 2; k++) {
        tet_scaffold *s = &run[k];
        assert_int_equal(tet_scaffold_from_box_mesh(s, tm, nf, F, NULL), SCAF_OK);
        /* TetGen's scaffold has no free vertex: topology first, splits */
        tet_improve_stats st = checked_call(s, NULL, nf, F, prot);
        assert_true(st.min_after > 2 * st.min_before);
        assert_true(st.flip32 + st.edge_removal > 0);
        assert_true(st.split > 0);
        /* the loop's step: mesh vertices move through X, free ones in s */
        double *X = malloc(sizeof(double) * 3 * (size_t)s->nmesh);
        assert_non_null(X);
        perturb(s, 0.6, 11);
        memcpy(X, s->P, sizeof(double) * 3 * (size_t)s->nmesh);
        memcpy(s->P, tm->V, sizeof(double) * 3 * (size_t)s->nmesh); /* stale until the call */
        st = checked_call(s, X, nf, F, prot);
        assert_true(st.p5_after > 1.5 * st.p5_before);
        assert_true(st.smooth > 0);
        assert_true(st.flip32 + st.edge_removal > 0);
        free(X);
    }
    assert_int_equal(run[0].nt, run[1].nt);
    assert_int_equal(run[0].nv, run[1].nv);
    assert_memory_equal(run[0].T, run[1].T, sizeof(int) * 4 * (size_t)run[0].nt);
    assert_memory_equal(run[0].P, run[1].P, sizeof(double) * 3 * (size_t)run[0].nv);
    assert_memory_equal(run[0].region, run[1].region, (size_t)run[0].nt);
    tet_scaffold_free(&run[0]);
    tet_scaffold_free(&run[1]);
    free(prot);
}

static void box_mesh_of(const mesh *m, tet_box_mesh *tm)
{
    double lo[3], hi[3];
    tet_box_around(m->nv, m->V, 3, lo, hi);
    assert_int_equal(tet_box_mesh_build(m->nv, m->V, m->nf, m->F, lo, hi, 8, tm, NULL), SCAF_OK);
}

static void test_icosphere_perturbed(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, NULL), SCAF_OK);
    tet_box_mesh tm;
    box_mesh_of(&m, &tm);
    improve_and_check(&tm, m.nf, m.F);
    tet_box_mesh_free(&tm);
    mesh_free(&m);
}

static void test_bunny_perturbed(void **state)
{
    (void)state;
    char path[1024];
    if (!test_data_path("closed/bunny.obj", path, sizeof path)) skip();
    mesh m;
    mesh_read_info info;
    assert_int_equal(mesh_read(path, &m, &info, NULL), SCAF_OK);
    tet_box_mesh tm;
    box_mesh_of(&m, &tm);
    improve_and_check(&tm, m.nf, m.F);
    tet_box_mesh_free(&tm);
    mesh_free(&m);
}

/* The budget is a hard count; the goal and the mask are obeyed. */
static void test_budget_goal_mask(void **state)
{
    (void)state;
    mesh m;
    assert_int_equal(mesh_sample_make("icosphere", 3, &m, NULL), SCAF_OK);
    tet_box_mesh tm;
    box_mesh_of(&m, &tm);
    tet_improve_options o;
    tet_improve_stats st;
    for (int k = 0; k < 4; k++) {
        tet_scaffold s;
        assert_int_equal(tet_scaffold_from_box_mesh(&s, &tm, m.nf, m.F, NULL), SCAF_OK);
        tet_improve_options_default(&o);
        if (k == 0) o.max_tries = 50;
        if (k == 1) o.quality_goal = 0;                      /* nothing is below it */
        if (k == 2) o.ops = TET_OP_SMOOTH | TET_OP_CONTRACT; /* TetGen's: no free vertex */
        if (k == 3) o.max_passes = 0;
        assert_int_equal(tet_improve(&s, NULL, &o, &st, NULL), SCAF_OK);
        if (k == 0) {
            assert_int_equal(st.tries, 50);
            assert_true(st.min_after > st.min_before);
        } else {
            assert_int_equal(st.flip23 + st.flip32 + st.edge_removal + st.multi_face + st.smooth +
                                 st.contract + st.split,
                             0);
            assert_int_equal(s.nt, tm.nt);
            assert_memory_equal(s.T, tm.T, sizeof(int) * 4 * (size_t)tm.nt);
            assert_memory_equal(s.P, tm.V, sizeof(double) * 3 * (size_t)tm.nv);
            assert_true(st.min_after == st.min_before && st.p5_after == st.p5_before);
        }
        tet_scaffold_free(&s);
    }
    tet_box_mesh_free(&tm);
    mesh_free(&m);
}

/* ---- refusals ---- */

static void test_refusals(void **state)
{
    (void)state;
    double V[21];
    int T[32];
    octahedron(V, T);
    orient_all(V, 8, T);
    signed char region[8] = {0};
    tet_scaffold s;
    scaf_error e;
    /* a protected triangle that is no face */
    int bad_prot[3] = {0, 1, 2};
    assert_int_equal(tet_scaffold_init(&s, 0, 7, V, NULL, 8, T, region, 1, bad_prot, &e),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "protected triangle 0"));
    /* an inverted tet */
    int x = T[2];
    T[2] = T[3], T[3] = x;
    assert_int_equal(tet_scaffold_init(&s, 0, 7, V, NULL, 8, T, region, 0, NULL, &e),
                     SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "tet 0"));
    T[3] = T[2], T[2] = x;
    /* a bad region label, an index out of range */
    region[3] = 2;
    assert_int_equal(tet_scaffold_init(&s, 0, 7, V, NULL, 8, T, region, 0, NULL, &e),
                     SCAF_ERR_USAGE);
    region[3] = 0;
    T[5] = 7;
    assert_int_equal(tet_scaffold_init(&s, 0, 7, V, NULL, 8, T, region, 0, NULL, &e),
                     SCAF_ERR_MESH);
    T[5] = 0;
    /* tet_improve at mesh positions that invert a tet: refused, unchanged */
    assert_int_equal(tet_scaffold_init(&s, 6, 7, V, NULL, 8, T, region, 0, NULL, &e), SCAF_OK);
    double X[18];
    memcpy(X, V, sizeof X);
    X[0] = -2; /* corner 0 through the centre */
    assert_int_equal(tet_improve(&s, X, NULL, NULL, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, "not positively oriented"));
    assert_memory_equal(s.P, V, sizeof V);
    /* options out of range */
    tet_improve_options o;
    tet_improve_options_default(&o);
    o.quality_goal = NAN;
    assert_int_equal(tet_improve(&s, NULL, &o, NULL, &e), SCAF_ERR_USAGE);
    tet_improve_options_default(&o);
    o.ops = 1u << 10;
    assert_int_equal(tet_improve(&s, NULL, &o, NULL, &e), SCAF_ERR_USAGE);
    assert_non_null(strstr(e.message, "ops"));
    tet_scaffold_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quality_measure),
        cmocka_unit_test(test_quality_summary),
        cmocka_unit_test(test_flip23_flat_bipyramid),
        cmocka_unit_test(test_flip32_needles),
        cmocka_unit_test(test_multi_face_square),
        cmocka_unit_test(test_smooth_centre),
        cmocka_unit_test(test_contract_centre),
        cmocka_unit_test(test_icosphere_perturbed),
        cmocka_unit_test(test_bunny_perturbed),
        cmocka_unit_test(test_budget_goal_mask),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
