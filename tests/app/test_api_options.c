/* The options of the public constructors (scaf_param_new, scaf_atlas_new,
 * scaf_drag_new): a bad option, each one in turn, makes the constructor
 * return NULL, the *_options_check function fail with SCAF_ERR_USAGE and
 * a message naming the field, and *_set_options fail and keep the options
 * in force; a struct_size this library does not know (0: a struct not
 * started from *_default(), or another version's size) is refused naming
 * struct_size; the defaults and NULL are accepted. Nothing is silently
 * replaced by a default. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "scaf/scaf.h"

/* bad_T_name(o): one option of o made invalid. */
#define BAD(T, name, expr)                                                                         \
    static void bad_##T##_##name(T *o) { expr; }

BAD(scaf_options_t, energy, o->energy = (scaf_energy)scaf_energy_count())
BAD(scaf_options_t, energy_neg, o->energy = (scaf_energy)-1)
BAD(scaf_options_t, init, o->init = (scaf_init)7)
BAD(scaf_options_t, max_iterations, o->max_iterations = -1)
BAD(scaf_options_t, tolerance, o->tolerance = NAN)
BAD(scaf_options_t, box_scale, o->box_scale = 0.5)
BAD(scaf_options_t, box_points_per_side, o->box_points_per_side = 0)
BAD(scaf_options_t, lambda_ratio, o->lambda_ratio = 0.0)
BAD(scaf_options_t, min_angle_deg, o->min_angle_deg = 40.0)
BAD(scaf_options_t, step_fraction, o->step_fraction = 1.0)
BAD(scaf_options_t, solver, o->solver = (scaf_solver)9)
BAD(scaf_options_t, seams, o->seams = (scaf_seams)-2)
BAD(scaf_options_t, size0, o->struct_size = 0)
BAD(scaf_options_t, size_big, o->struct_size += 8)

static void param_refuses_each_bad_option(void **state)
{
    (void)state;
    static const struct {
        const char *field;
        void (*set)(scaf_options_t *);
    } cases[] = {
        {"energy", bad_scaf_options_t_energy},
        {"energy", bad_scaf_options_t_energy_neg},
        {"init", bad_scaf_options_t_init},
        {"max_iterations", bad_scaf_options_t_max_iterations},
        {"tolerance", bad_scaf_options_t_tolerance},
        {"box_scale", bad_scaf_options_t_box_scale},
        {"box_points_per_side", bad_scaf_options_t_box_points_per_side},
        {"lambda_ratio", bad_scaf_options_t_lambda_ratio},
        {"min_angle_deg", bad_scaf_options_t_min_angle_deg},
        {"step_fraction", bad_scaf_options_t_step_fraction},
        {"solver", bad_scaf_options_t_solver},
        {"seams", bad_scaf_options_t_seams},
        {"scaf_options_t.struct_size", bad_scaf_options_t_size0},
        {"scaf_options_t.struct_size", bad_scaf_options_t_size_big},
    };
    scaf_options_t good = scaf_options_default();
    assert_int_equal(good.struct_size, sizeof good);
    char msg[256];
    assert_int_equal(scaf_options_check(&good, msg, sizeof msg), SCAF_OK);
    assert_string_equal(msg, "");
    assert_int_equal(scaf_options_check(NULL, msg, sizeof msg), SCAF_ERR_USAGE);
    scaf_param_t *p = scaf_param_new(NULL);
    assert_non_null(p);
    good.max_iterations = 7; /* a valid change, to see that a bad one keeps it */
    assert_int_equal(scaf_param_set_options(p, &good), SCAF_OK);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scaf_options_t o = scaf_options_default();
        cases[k].set(&o);
        assert_null(scaf_param_new(&o));
        assert_int_equal(scaf_options_check(&o, msg, sizeof msg), SCAF_ERR_USAGE);
        if (!strstr(msg, cases[k].field)) fail_msg("'%s' lacks '%s'", msg, cases[k].field);
        assert_int_equal(scaf_options_check(&o, NULL, 0), SCAF_ERR_USAGE);
        assert_int_equal(scaf_param_set_options(p, &o), SCAF_ERR_USAGE);
        if (!strstr(scaf_param_error(p), cases[k].field))
            fail_msg("'%s' lacks '%s'", scaf_param_error(p), cases[k].field);
    }
    /* the options in force are still the valid ones: a run stops at 7 */
    static const double V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.2};
    static const int F[] = {0, 1, 2, 1, 3, 2};
    assert_int_equal(scaf_param_set_mesh(p, V, 4, F, 2, NULL, 0, NULL), SCAF_OK);
    assert_int_equal(scaf_param_run(p, 0, NULL, NULL), SCAF_OK);
    assert_true(scaf_param_iterations(p) <= 7);
    scaf_param_destroy(p);
}

BAD(scaf_atlas_options_t, padding, o->padding = 0.5)
BAD(scaf_atlas_options_t, energy, o->energy = (scaf_energy)scaf_energy_count())
BAD(scaf_atlas_options_t, init, o->init = (scaf_init)-1)
BAD(scaf_atlas_options_t, init_input, o->init_input = 2)
BAD(scaf_atlas_options_t, settle_iterations, o->settle_iterations = -3)
BAD(scaf_atlas_options_t, settle_tolerance, o->settle_tolerance = -1.0)
BAD(scaf_atlas_options_t, compact_iterations, o->compact_iterations = -1)
BAD(scaf_atlas_options_t, distortion_tolerance, o->distortion_tolerance = INFINITY)
BAD(scaf_atlas_options_t, repack, o->repack = 5)
BAD(scaf_atlas_options_t, pack_cells, o->pack_cells = 8)
BAD(scaf_atlas_options_t, box_scale, o->box_scale = 2e6)
BAD(scaf_atlas_options_t, lambda_ratio, o->lambda_ratio = -1.0)
BAD(scaf_atlas_options_t, compact_lambda_ratio, o->compact_lambda_ratio = 0.0)
BAD(scaf_atlas_options_t, seams, o->seams = (scaf_seams)9)
BAD(scaf_atlas_options_t, size0, o->struct_size = 0)

static void atlas_refuses_each_bad_option(void **state)
{
    (void)state;
    static const struct {
        const char *field;
        void (*set)(scaf_atlas_options_t *);
    } cases[] = {
        {"padding", bad_scaf_atlas_options_t_padding},
        {"energy", bad_scaf_atlas_options_t_energy},
        {"init", bad_scaf_atlas_options_t_init},
        {"init_input", bad_scaf_atlas_options_t_init_input},
        {"settle_iterations", bad_scaf_atlas_options_t_settle_iterations},
        {"settle_tolerance", bad_scaf_atlas_options_t_settle_tolerance},
        {"compact_iterations", bad_scaf_atlas_options_t_compact_iterations},
        {"distortion_tolerance", bad_scaf_atlas_options_t_distortion_tolerance},
        {"repack", bad_scaf_atlas_options_t_repack},
        {"pack_cells", bad_scaf_atlas_options_t_pack_cells},
        {"box_scale", bad_scaf_atlas_options_t_box_scale},
        {"lambda_ratio", bad_scaf_atlas_options_t_lambda_ratio},
        {"compact_lambda_ratio", bad_scaf_atlas_options_t_compact_lambda_ratio},
        {"seams", bad_scaf_atlas_options_t_seams},
        {"scaf_atlas_options_t.struct_size", bad_scaf_atlas_options_t_size0},
    };
    scaf_atlas_options_t good = scaf_atlas_options_default();
    assert_int_equal(good.struct_size, sizeof good);
    char msg[256];
    assert_int_equal(scaf_atlas_options_check(&good, msg, sizeof msg), SCAF_OK);
    scaf_atlas_t *a = scaf_atlas_new(&good);
    assert_non_null(a);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scaf_atlas_options_t o = scaf_atlas_options_default();
        cases[k].set(&o);
        assert_null(scaf_atlas_new(&o));
        assert_int_equal(scaf_atlas_options_check(&o, msg, sizeof msg), SCAF_ERR_USAGE);
        if (!strstr(msg, cases[k].field)) fail_msg("'%s' lacks '%s'", msg, cases[k].field);
        assert_int_equal(scaf_atlas_set_options(a, &o), SCAF_ERR_USAGE);
        if (!strstr(scaf_atlas_error(a), cases[k].field))
            fail_msg("'%s' lacks '%s'", scaf_atlas_error(a), cases[k].field);
    }
    scaf_atlas_destroy(a);
}

BAD(scaf_drag_options_t, start, o->start = (scaf_drag_start)3)
BAD(scaf_drag_options_t, padding, o->padding = 0.7)
BAD(scaf_drag_options_t, weight_ratio, o->weight_ratio = NAN)
BAD(scaf_drag_options_t, solver, o->solver = (scaf_solver)-1)
BAD(scaf_drag_options_t, box_scale, o->box_scale = 0.0)
BAD(scaf_drag_options_t, lambda_ratio, o->lambda_ratio = INFINITY)
BAD(scaf_drag_options_t, undo_depth, o->undo_depth = 0)
BAD(scaf_drag_options_t, undo_depth_big, o->undo_depth = 4097)
BAD(scaf_drag_options_t, seams, o->seams = (scaf_seams)4)
BAD(scaf_drag_options_t, size_small, o->struct_size = sizeof(size_t))

static void drag_refuses_each_bad_option(void **state)
{
    (void)state;
    static const struct {
        const char *field;
        void (*set)(scaf_drag_options_t *);
    } cases[] = {
        {"start", bad_scaf_drag_options_t_start},
        {"padding", bad_scaf_drag_options_t_padding},
        {"weight_ratio", bad_scaf_drag_options_t_weight_ratio},
        {"solver", bad_scaf_drag_options_t_solver},
        {"box_scale", bad_scaf_drag_options_t_box_scale},
        {"lambda_ratio", bad_scaf_drag_options_t_lambda_ratio},
        {"undo_depth", bad_scaf_drag_options_t_undo_depth},
        {"undo_depth", bad_scaf_drag_options_t_undo_depth_big},
        {"seams", bad_scaf_drag_options_t_seams},
        {"scaf_drag_options_t.struct_size", bad_scaf_drag_options_t_size_small},
    };
    scaf_drag_options_t good = scaf_drag_options_default();
    assert_int_equal(good.struct_size, sizeof good);
    char msg[256];
    assert_int_equal(scaf_drag_options_check(&good, msg, sizeof msg), SCAF_OK);
    scaf_drag_t *d = scaf_drag_new(NULL);
    assert_non_null(d);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scaf_drag_options_t o = scaf_drag_options_default();
        cases[k].set(&o);
        assert_null(scaf_drag_new(&o));
        assert_int_equal(scaf_drag_options_check(&o, msg, sizeof msg), SCAF_ERR_USAGE);
        if (!strstr(msg, cases[k].field)) fail_msg("'%s' lacks '%s'", msg, cases[k].field);
        assert_int_equal(scaf_drag_set_options(d, &o), SCAF_ERR_USAGE);
        if (!strstr(scaf_drag_error(d), cases[k].field))
            fail_msg("'%s' lacks '%s'", scaf_drag_error(d), cases[k].field);
    }
    scaf_drag_destroy(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(param_refuses_each_bad_option),
        cmocka_unit_test(atlas_refuses_each_bad_option),
        cmocka_unit_test(drag_refuses_each_bad_option),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
