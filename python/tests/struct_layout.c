/* python/tests/struct_layout: prints the C layout of the public structs.
 *
 * The Python package mirrors scaf_options_t, scaf_iteration_info_t,
 * scaf_atlas_options_t, scaf_atlas_iteration_info_t, scaf_drag_options_t
 * and scaf_drag_chart_info_t as ctypes
 * structures. This test-only program prints, for each, one line
 * "STRUCT sizeof N" and one line "STRUCT FIELD OFFSET SIZE" per field, as
 * the C compiler lays them out; python/tests/test_scaf.py compares them
 * with ctypes.sizeof / ctypes offsets, so a field added to a header (it
 * changes sizeof) or reordered fails the Python test until the binding is
 * updated. Cannot fail itself: exit status 0.
 */
#include <stddef.h>
#include <stdio.h>

#include <scaf/scaf.h>

#define SIZE(T) printf("%s sizeof %zu\n", #T, sizeof(T))
#define FIELD(T, f) printf("%s %s %zu %zu\n", #T, #f, offsetof(T, f), sizeof(((T *)0)->f))

int main(void)
{
    SIZE(scaf_options_t);
    FIELD(scaf_options_t, energy);
    FIELD(scaf_options_t, init);
    FIELD(scaf_options_t, max_iterations);
    FIELD(scaf_options_t, tolerance);
    FIELD(scaf_options_t, box_scale);
    FIELD(scaf_options_t, box_square);
    FIELD(scaf_options_t, box_points_per_side);
    FIELD(scaf_options_t, lambda_ratio);
    FIELD(scaf_options_t, min_angle_deg);
    FIELD(scaf_options_t, step_fraction);
    FIELD(scaf_options_t, solver);
    FIELD(scaf_options_t, seams);

    SIZE(scaf_iteration_info_t);
    FIELD(scaf_iteration_info_t, iteration);
    FIELD(scaf_iteration_info_t, energy);
    FIELD(scaf_iteration_info_t, energy_before);
    FIELD(scaf_iteration_info_t, total_before);
    FIELD(scaf_iteration_info_t, total_after);
    FIELD(scaf_iteration_info_t, lambda);
    FIELD(scaf_iteration_info_t, step);
    FIELD(scaf_iteration_info_t, scaffold_triangles);
    FIELD(scaf_iteration_info_t, scaffold_vertices);
    FIELD(scaf_iteration_info_t, seconds);
    FIELD(scaf_iteration_info_t, phase_seconds);
    FIELD(scaf_iteration_info_t, solver);
    FIELD(scaf_iteration_info_t, decrement);
    FIELD(scaf_iteration_info_t, criterion);

    SIZE(scaf_atlas_options_t);
    FIELD(scaf_atlas_options_t, padding);
    FIELD(scaf_atlas_options_t, energy);
    FIELD(scaf_atlas_options_t, init);
    FIELD(scaf_atlas_options_t, init_input);
    FIELD(scaf_atlas_options_t, settle_iterations);
    FIELD(scaf_atlas_options_t, settle_tolerance);
    FIELD(scaf_atlas_options_t, compact_iterations);
    FIELD(scaf_atlas_options_t, distortion_tolerance);
    FIELD(scaf_atlas_options_t, repack);
    FIELD(scaf_atlas_options_t, pack_cells);
    FIELD(scaf_atlas_options_t, box_scale);
    FIELD(scaf_atlas_options_t, lambda_ratio);
    FIELD(scaf_atlas_options_t, compact_lambda_ratio);
    FIELD(scaf_atlas_options_t, seams);

    SIZE(scaf_atlas_iteration_info_t);
    FIELD(scaf_atlas_iteration_info_t, phase);
    FIELD(scaf_atlas_iteration_info_t, iteration);
    FIELD(scaf_atlas_iteration_info_t, phase_iteration);
    FIELD(scaf_atlas_iteration_info_t, energy);
    FIELD(scaf_atlas_iteration_info_t, efficiency);
    FIELD(scaf_atlas_iteration_info_t, gap);
    FIELD(scaf_atlas_iteration_info_t, seconds);
    FIELD(scaf_atlas_iteration_info_t, loop);

    SIZE(scaf_drag_options_t);
    FIELD(scaf_drag_options_t, start);
    FIELD(scaf_drag_options_t, padding);
    FIELD(scaf_drag_options_t, weight_ratio);
    FIELD(scaf_drag_options_t, solver);
    FIELD(scaf_drag_options_t, box_scale);
    FIELD(scaf_drag_options_t, lambda_ratio);
    FIELD(scaf_drag_options_t, undo_depth);
    FIELD(scaf_drag_options_t, seams);

    SIZE(scaf_drag_chart_info_t);
    FIELD(scaf_drag_chart_info_t, faces);
    FIELD(scaf_drag_chart_info_t, uvs);
    FIELD(scaf_drag_chart_info_t, centroid);
    FIELD(scaf_drag_chart_info_t, uv_area);
    FIELD(scaf_drag_chart_info_t, energy);
    FIELD(scaf_drag_chart_info_t, held);

    /* enum values the binding names (it passes other ints through) */
    printf("enum SCAF_PHASE_COUNT %d\n", (int)SCAF_PHASE_COUNT);
    printf("enum SCAF_ERR_INTERNAL %d\n", (int)SCAF_ERR_INTERNAL);
    printf("enum SCAF_ERR_CANCELLED %d\n", (int)SCAF_ERR_CANCELLED);
    printf("enum SCAF_ENERGY_CONFORMAL %d\n", (int)SCAF_ENERGY_CONFORMAL);
    printf("enum SCAF_INIT_HARMONIC %d\n", (int)SCAF_INIT_HARMONIC);
    printf("enum SCAF_INIT_MVC %d\n", (int)SCAF_INIT_MVC);
    printf("enum SCAF_ATLAS_COMPACT %d\n", (int)SCAF_ATLAS_COMPACT);
    printf("enum SCAF_DRAG_START_ATLAS %d\n", (int)SCAF_DRAG_START_ATLAS);
    printf("enum sizeof %zu\n", sizeof(scaf_init));
    return 0;
}
