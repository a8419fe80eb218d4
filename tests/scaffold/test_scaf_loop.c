/* Tests for scaffold/scaf_loop, the one SCAF driver, and its two seams:
 *   - every energy (symmetric Dirichlet, ARAP, conformal) lowers the total
 *     energy at each accepted step and keeps the map bijective (exact
 *     checker), the scaffold positively oriented;
 *   - an extra term (a soft positional constraint written here against
 *     opt/objective) plugs in with scaf_loop_add_term: its energy, proxy
 *     block and per-vertex max step are all honoured by the loop;
 *   - the 2D scaffold provider (scaffold/scaffold_cdt) on its own, and a
 *     provider of the test's own replacing it in the loop;
 *   - a misoriented start fails with SCAF_ERR_INTERNAL (as documented);
 *   - the energies a step reports are those of a fresh evaluation, bit for
 *     bit, whether the next step reuses the line search's (map unchanged)
 *     or recomputes them (the caller moved the map in between);
 *   - the chart's simplices are the faces ordered by their last vertex,
 *     and per-face values land on their faces;
 *   - the loop's own defaults are the public ones (app/param mapping).
 * Mesh: a generated curved disk (tests/opt/polar_disk.h), Tutte start. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/param.h"
#include "opt/embed.h"
#include "opt/polar_disk.h"
#include "opt/proxy_system.h"
#include "scaffold/scaf_loop.h"
#include "scaffold/scaffold_cdt.h"
#include "scaffold/scaffold_frozen.h"
#include "support/loop_valid.h"

typedef struct disk {
    polar_disk m;
    double *uv;
} disk;

static void disk_make(disk *k)
{
    assert_int_equal(polar_disk_make(&k->m, 6, 16, 1.0, 0), 0);
    k->uv = malloc(sizeof(double) * 2 * (size_t)k->m.nv);
    assert_non_null(k->uv);
    opt_chart_loops L = {1, k->m.start, k->m.loops, 0};
    assert_int_equal(
        opt_embed_chart(k->m.nv, k->m.V, k->m.nf, k->m.F, &L, OPT_EMBED_TUTTE, k->uv, NULL, NULL),
        SCAF_OK);
}

static void disk_free(disk *k)
{
    polar_disk_free(&k->m);
    free(k->uv);
}

/* The loop with default options on a fresh disk. */
static void loop_on_disk(disk *k, scaf_loop *L)
{
    disk_make(k);
    scaf_error err;
    assert_int_equal(scaf_loop_init(L, k->m.nv, k->m.V, k->m.nf, k->m.F, k->uv, NULL, &err),
                     SCAF_OK);
}

/* The loop with default options but energy e on a fresh disk. */
static void loop_with_energy(disk *k, scaf_loop *L, opt_energy e)
{
    disk_make(k);
    scaf_loop_options o = scaf_loop_options_default();
    o.energy = e;
    scaf_error err;
    assert_int_equal(scaf_loop_init(L, k->m.nv, k->m.V, k->m.nf, k->m.F, k->uv, &o, &err), SCAF_OK);
}

static void assert_state_valid(const scaf_loop *L)
{
    const scaffold_view *v = scaf_loop_scaffold_view(L);
    assert_int_equal(v->d, 2);
    assert_true(v->n > 0);
    assert_true(test_loop_state_valid(L));
}

static void each_energy_descends_bijectively(void **state)
{
    (void)state;
    const opt_energy energies[3] = {OPT_ENERGY_SYMMETRIC_DIRICHLET, OPT_ENERGY_ARAP,
                                    OPT_ENERGY_CONFORMAL};
    for (int e = 0; e < 3; e++) {
        disk k;
        scaf_loop L;
        scaf_error err;
        loop_with_energy(&k, &L, energies[e]);
        double E0 = scaf_loop_energy(&L);
        int steps = 0;
        for (int it = 0; it < 6; it++) {
            scaf_iteration_info_t info;
            assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
            assert_int_equal(info.iteration, it + 1);
            if (info.step > 0) {
                steps++;
                assert_true(info.total_after < info.total_before);
            }
            assert_state_valid(&L);
        }
        assert_true(steps > 0);
        assert_int_equal(L.iterations, 6);
        if (energies[e] == OPT_ENERGY_SYMMETRIC_DIRICHLET) assert_true(scaf_loop_energy(&L) < E0);
        scaf_loop_free(&L);
        disk_free(&k);
    }
}

/* ---- an extra term: w |x_v - p|^2, each step moving x_v at most `cap` ---- */

typedef struct pin {
    int v;
    double p[2], w, cap;
    int patterns, fills;
} pin;

static double pin_energy(const opt_obj_term *t, const double *X)
{
    const pin *q = t->self;
    double dx = X[2 * q->v] - q->p[0], dy = X[2 * q->v + 1] - q->p[1];
    return q->w * (dx * dx + dy * dy);
}

static void pin_energy_slope(const opt_obj_term *t, const double *X, const double *D, double *e,
                             double *slope)
{
    const pin *q = t->self;
    double dx = X[2 * q->v] - q->p[0], dy = X[2 * q->v + 1] - q->p[1];
    *e += q->w * (dx * dx + dy * dy);
    *slope += 2.0 * q->w * (dx * D[2 * q->v] + dy * D[2 * q->v + 1]);
}

static scaf_status pin_pattern(opt_obj_term *t, const int *dof, int nfree, scaf_error *err)
{
    pin *q = t->self;
    q->patterns++;
    return opt_proxy_block_pattern_vertices(&t->blk, 2, 1, &q->v, dof, nfree, err);
}

static void pin_fill(opt_obj_term *t, const int *dof, const double *X, double *rhs)
{
    (void)X;
    pin *q = t->self;
    q->fills++;
    memset(t->blk.A.val, 0, sizeof(double) * (size_t)t->blk.A.nnz);
    int k = dof[q->v];
    opt_proxy_block_add_diagonal(&t->blk, k, q->w);
    rhs[2 * k] += q->w * q->p[0];
    rhs[2 * k + 1] += q->w * q->p[1];
}

static double pin_max_step(const opt_obj_term *t, const double *X, const double *D)
{
    (void)X;
    const pin *q = t->self;
    double len = hypot(D[2 * q->v], D[2 * q->v + 1]);
    return len > 0.0 ? q->cap / len : INFINITY;
}

static const opt_obj_term_ops pin_ops = {
    pin_energy, pin_energy_slope, pin_pattern, pin_fill, pin_max_step, NULL, NULL};

/* Distance of the pinned vertex to its target after `iterations`, with
 * the term (q != NULL) or without; *max_move: its largest move in one
 * iteration. */
static double run_pinned(pin *q, int v, const double target[2], int iterations, double *max_move)
{
    disk k;
    scaf_loop L;
    scaf_error err;
    loop_on_disk(&k, &L);
    if (q) {
        opt_obj_term t = {&pin_ops, q, {0}};
        assert_int_equal(scaf_loop_add_term(&L, &t, &err), SCAF_OK);
    }
    *max_move = 0.0;
    for (int it = 0; it < iterations; it++) {
        double before[2] = {L.uv[2 * v], L.uv[2 * v + 1]};
        scaf_iteration_info_t info;
        assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
        if (info.step > 0) assert_true(info.total_after < info.total_before);
        assert_state_valid(&L);
        double mv = hypot(L.uv[2 * v] - before[0], L.uv[2 * v + 1] - before[1]);
        if (mv > *max_move) *max_move = mv;
    }
    double dist = hypot(L.uv[2 * v] - target[0], L.uv[2 * v + 1] - target[1]);
    scaf_loop_free(&L);
    disk_free(&k);
    return dist;
}

static void extra_term_plugs_in(void **state)
{
    (void)state;
    disk k;
    disk_make(&k);
    int v = 0; /* the center */
    double target[2] = {k.uv[0] + 0.2, k.uv[1] + 0.1};
    double start = hypot(0.2, 0.1);
    disk_free(&k);

    double move_free, move_pinned, move_capped;
    double free_dist = run_pinned(NULL, v, target, 8, &move_free);
    pin q = {v, {target[0], target[1]}, 50.0, INFINITY, 0, 0};
    double pinned = run_pinned(&q, v, target, 8, &move_pinned);
    assert_true(q.patterns == 8 && q.fills == 8); /* called once per iteration */
    assert_true(pinned < 0.5 * start);
    assert_true(pinned < free_dist);
    /* The per-vertex max step holds the vertex to `cap` per iteration
     * (the line search takes at most step_fraction of the bound). */
    pin c = {v, {target[0], target[1]}, 50.0, 0.25 * move_pinned, 0, 0};
    double capped = run_pinned(&c, v, target, 8, &move_capped);
    print_message("distance to target: start %.4f, free %.4f, pinned %.4f (max move %.4f), capped "
                  "%.4f (max move "
                  "%.4f, cap %.4f)\n",
                  start, free_dist, pinned, move_pinned, capped, move_capped, c.cap);
    assert_true(move_capped > 0.0);
    assert_true(move_capped <= 0.8 * c.cap * (1.0 + 1e-9));
}

static void add_term_checks(void **state)
{
    (void)state;
    disk k;
    scaf_loop L;
    scaf_error err;
    loop_on_disk(&k, &L);
    opt_obj_term_ops no_fill = pin_ops;
    no_fill.fill = NULL;
    pin q = {0, {0, 0}, 1.0, INFINITY, 0, 0};
    opt_obj_term bad = {&no_fill, &q, {0}};
    assert_int_equal(scaf_loop_add_term(&L, &bad, &err), SCAF_ERR_USAGE);
    opt_obj_term t = {&pin_ops, &q, {0}};
    int added = 0;
    while (scaf_loop_add_term(&L, &t, &err) == SCAF_OK) added++;
    assert_int_equal(err.code, SCAF_ERR_USAGE);
    assert_int_equal(added, OPT_PROXY_MAX_BLOCKS - 2); /* after mesh and scaffold */
    scaf_loop_free(&L);
    disk_free(&k);
}

static void misoriented_start_is_internal(void **state)
{
    (void)state;
    disk k;
    disk_make(&k);
    for (int i = 0; i < k.m.nv; i++)
        k.uv[2 * i] = -k.uv[2 * i]; /* mirror: every triangle clockwise */
    scaf_loop L;
    scaf_error err;
    assert_int_equal(scaf_loop_init(&L, k.m.nv, k.m.V, k.m.nf, k.m.F, k.uv, NULL, &err),
                     SCAF_ERR_INTERNAL);
    assert_non_null(strstr(err.message, "not positively oriented"));
    disk_free(&k);
}

/* The CDT provider alone: a square's boundary in a box, refreshed twice
 * with different options. */
static void cdt_provider_builds_and_refreshes(void **state)
{
    (void)state;
    double X[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    int E[8] = {0, 1, 1, 2, 2, 3, 3, 0}; /* counter-clockwise: the square on the left */
    scaf_error err;
    scaffold_provider *p = scaffold_cdt_create(4, E, 4, &err);
    assert_non_null(p);
    scaffold_view v;
    p->ops->view(p, &v);
    assert_int_equal(v.n, 0);
    scaffold_options o = scaffold_default_options();
    assert_int_equal(p->ops->refresh(p, X, &o, &err), SCAF_OK);
    p->ops->view(p, &v);
    assert_true(v.d == 2 && v.nmesh == 4 && v.n > 0 && v.nextra >= 4);
    int nfixed = 0;
    for (int i = 0; i < v.nextra; i++) nfixed += v.extra_fixed[i];
    assert_int_equal(nfixed, 4 * o.box_points_per_side);
    assert_true(v.box_lo[0] < 0 && v.box_hi[0] > 1 && v.box_lo[1] < 0 && v.box_hi[1] > 1);
    assert_true(fabs(v.eps - 0.25) < 1e-15); /* l = 1 */
    double w0 = v.box_hi[0] - v.box_lo[0];
    o.box_scale = 6.0;
    assert_int_equal(p->ops->refresh(p, X, &o, &err), SCAF_OK);
    p->ops->view(p, &v);
    assert_true(v.box_hi[0] - v.box_lo[0] > 1.5 * w0);
    scaffold_provider_destroy(p);
}

/* A provider of our own: the CDT one behind a wrapper that counts the
 * refreshes and records the options it was given. */
typedef struct counting {
    scaffold_provider base;
    scaffold_provider *inner;
    int refreshes, destroyed;
    double last_box_scale;
} counting;

static scaf_status counting_refresh(scaffold_provider *p, const double *X,
                                    const scaffold_options *o, scaf_error *err)
{
    counting *c = (counting *)p;
    c->refreshes++;
    c->last_box_scale = o->box_scale;
    return c->inner->ops->refresh(c->inner, X, o, err);
}

static void counting_view(const scaffold_provider *p, scaffold_view *v)
{
    const counting *c = (const counting *)p;
    c->inner->ops->view(c->inner, v);
}

static void counting_destroy(scaffold_provider *p)
{
    counting *c = (counting *)p;
    scaffold_provider_destroy(c->inner);
    c->destroyed++;
}

static const scaffold_provider_ops counting_ops = {counting_refresh, counting_view,
                                                   counting_destroy};

static void provider_plugs_in(void **state)
{
    (void)state;
    disk k;
    scaf_loop L;
    scaf_error err;
    loop_on_disk(&k, &L);
    counting c = {{&counting_ops, 2, L.nv}, NULL, 0, 0, 0.0};
    c.inner = scaffold_cdt_create(L.nv, L.bedges, L.nbedges, &err);
    assert_non_null(c.inner);
    counting wrong = c;
    wrong.base.nmesh = L.nv + 1;
    assert_int_equal(scaf_loop_set_scaffold_provider(&L, &wrong.base, &err), SCAF_ERR_USAGE);
    assert_int_equal(scaf_loop_set_scaffold_provider(&L, &c.base, &err), SCAF_OK);
    L.opt.scaffold.box_scale = 4.0;
    for (int it = 0; it < 3; it++) {
        scaf_iteration_info_t info;
        assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
        assert_state_valid(&L);
    }
    assert_int_equal(c.refreshes, 3);
    assert_true(c.last_box_scale == 4.0);
    scaf_loop_free(&L);
    assert_int_equal(c.destroyed, 1);
    disk_free(&k);
}

/* The frozen scaffold (scaffold/scaffold_frozen): the first iteration's
 * triangles and box stay for every later iteration (only positions move),
 * while the CDT provider alone re-meshes; a frozen scaffold that a caller
 * inverted behind the loop's back is refused. */
static void frozen_provider_keeps_connectivity(void **state)
{
    (void)state;
    disk k;
    scaf_loop L;
    scaf_error err;
    loop_on_disk(&k, &L);
    scaffold_provider *p =
        scaffold_frozen_create(scaffold_cdt_create(L.nv, L.bedges, L.nbedges, &err), &err);
    assert_non_null(p);
    assert_int_equal(scaf_loop_set_scaffold_provider(&L, p, &err), SCAF_OK);
    scaf_iteration_info_t info;
    assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
    const scaffold_view *v = scaf_loop_scaffold_view(&L);
    int n = v->n;
    int *T = malloc(sizeof(int) * 3 * (size_t)n);
    assert_non_null(T);
    memcpy(T, v->simplices, sizeof(int) * 3 * (size_t)n);
    double lo = v->box_lo[0], hi = v->box_hi[1];
    L.opt.scaffold.box_scale = 6.0; /* ignored once frozen */
    int moved = 0;
    for (int it = 0; it < 4; it++) {
        double before = L.uv[0];
        assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
        assert_state_valid(&L);
        v = scaf_loop_scaffold_view(&L);
        assert_int_equal(v->n, n);
        assert_memory_equal(v->simplices, T, sizeof(int) * 3 * (size_t)n);
        assert_true(v->box_lo[0] == lo && v->box_hi[1] == hi);
        moved += L.uv[0] != before;
    }
    assert_true(moved > 0);
    /* mirror the map: every frozen triangle is now inverted */
    for (int i = 0; i < L.nv; i++) L.uv[2 * i] = -L.uv[2 * i];
    assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_ERR_INTERNAL);
    assert_non_null(strstr(err.message, "frozen scaffold"));
    free(T);
    scaf_loop_free(&L);
    disk_free(&k);
}

/* E after a step and E before the next one against scaf_loop_energy at the
 * same positions, for the optimized energy being the reported one
 * (symmetric Dirichlet) or not (ARAP); between some steps the test moves
 * the map (a scaling keeps it bijective), which the loop must notice. */
static void reported_energies_are_fresh(void **state)
{
    (void)state;
    const opt_energy energies[2] = {OPT_ENERGY_SYMMETRIC_DIRICHLET, OPT_ENERGY_ARAP};
    for (int e = 0; e < 2; e++) {
        disk k;
        scaf_loop L;
        scaf_error err;
        loop_with_energy(&k, &L, energies[e]);
        double last = NAN;
        for (int it = 0; it < 6; it++) {
            int moved = it == 2 || it == 4;
            if (moved)
                for (int i = 0; i < 2 * L.nv; i++) L.uv[i] *= 1.25;
            double fresh = scaf_loop_energy(&L);
            scaf_iteration_info_t info;
            assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
            assert_true(info.energy_before == fresh);
            if (it > 0 && !moved) assert_true(info.energy_before == last);
            if (moved) assert_true(info.energy_before != last);
            last = info.energy;
            assert_true(info.energy == scaf_loop_energy(&L));
        }
        scaf_loop_free(&L);
        disk_free(&k);
    }
}

/* The chart's simplices are the faces ordered by their last vertex
 * (chart_face says which face each is), rest frames and weights as built
 * face by face, and the per-face energies land on their faces. The disk's
 * faces are reversed first so that the order has work to do. */
static void chart_order_keeps_faces(void **state)
{
    (void)state;
    disk k;
    disk_make(&k);
    int nf = k.m.nf;
    int *F = malloc(sizeof(int) * 3 * (size_t)nf);
    assert_non_null(F);
    for (int f = 0; f < nf; f++) memcpy(F + 3 * f, k.m.F + 3 * (nf - 1 - f), 3 * sizeof(int));
    scaf_loop L;
    scaf_error err;
    assert_int_equal(scaf_loop_init(&L, k.m.nv, k.m.V, nf, F, k.uv, NULL, &err), SCAF_OK);
    opt_simplices by_face = {0};
    assert_int_equal(opt_simplices_from_surface(&by_face, k.m.nv, k.m.V, nf, F, &err), SCAF_OK);
    char *seen = calloc((size_t)nf, 1);
    assert_non_null(seen);
    int moved = 0, last_top = -1, last_face = -1;
    for (int s = 0; s < nf; s++) {
        int f = L.chart_face[s];
        assert_true(f >= 0 && f < nf && !seen[f]);
        seen[f] = 1;
        moved += f != s;
        assert_memory_equal(L.chart.idx + 3 * s, F + 3 * f, 3 * sizeof(int));
        assert_memory_equal(L.chart.grad + 6 * s, by_face.grad + 6 * f, 6 * sizeof(double));
        assert_true(L.chart.weight[s] == by_face.weight[f] && L.chart.vol[s] == by_face.vol[f]);
        int top = F[3 * f] > F[3 * f + 1] ? F[3 * f] : F[3 * f + 1];
        if (F[3 * f + 2] > top) top = F[3 * f + 2];
        assert_true(top > last_top || (top == last_top && f > last_face));
        last_top = top;
        last_face = f;
    }
    assert_true(moved > 0);
    scaf_iteration_info_t info;
    for (int it = 0; it < 2; it++) assert_int_equal(scaf_loop_step(&L, &info, &err), SCAF_OK);
    double *E = malloc(sizeof(double) * (size_t)nf);
    assert_non_null(E);
    scaf_loop_face_energy(&L, E);
    for (int f = 0; f < nf; f++) {
        double J[4];
        opt_jacobian(&by_face, f, L.uv, J);
        assert_true(E[f] == opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J));
    }
    free(E);
    free(seen);
    free(F);
    opt_simplices_free(&by_face);
    scaf_loop_free(&L);
    disk_free(&k);
}

static void loop_defaults_are_the_public_ones(void **state)
{
    (void)state;
    scaf_options_t pub = scaf_options_default();
    scaf_loop_options mapped = param_loop_options(&pub), own = scaf_loop_options_default();
    assert_int_equal(mapped.energy, own.energy);
    assert_true(mapped.lambda_ratio == own.lambda_ratio);
    assert_true(mapped.step_fraction == own.step_fraction);
    assert_true(mapped.scaffold.box_scale == own.scaffold.box_scale);
    assert_int_equal(mapped.scaffold.box_square, own.scaffold.box_square);
    assert_int_equal(mapped.scaffold.box_points_per_side, own.scaffold.box_points_per_side);
    assert_true(mapped.scaffold.min_angle_deg == own.scaffold.min_angle_deg);
    assert_int_equal(mapped.scaffold.box_splittable, own.scaffold.box_splittable);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_energy_descends_bijectively),
        cmocka_unit_test(extra_term_plugs_in),
        cmocka_unit_test(add_term_checks),
        cmocka_unit_test(misoriented_start_is_internal),
        cmocka_unit_test(cdt_provider_builds_and_refreshes),
        cmocka_unit_test(provider_plugs_in),
        cmocka_unit_test(frozen_provider_keeps_connectivity),
        cmocka_unit_test(reported_energies_are_fresh),
        cmocka_unit_test(chart_order_keeps_faces),
        cmocka_unit_test(loop_defaults_are_the_public_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
