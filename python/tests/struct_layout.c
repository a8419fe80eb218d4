/* python/tests/struct_layout: prints the C layout of the public structs.
 *
 * The Python package mirrors scaf_options_t, scaf_iteration_info_t,
 * scaf_atlas_options_t, scaf_atlas_iteration_info_t, scaf_drag_options_t,
 * scaf_drag_chart_info_t and the structs of scaf/volume.h as ctypes
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
    SIZE(scaf_energy_info_t);
    FIELD(scaf_energy_info_t, name);
    FIELD(scaf_energy_info_t, aliases);
    FIELD(scaf_energy_info_t, help);
    FIELD(scaf_energy_info_t, scale_offset);
    SIZE(scaf_options_t);
    FIELD(scaf_options_t, struct_size);
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
    FIELD(scaf_atlas_options_t, struct_size);
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
    FIELD(scaf_drag_options_t, struct_size);
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
    SIZE(scaf_drag_motion_t);
    FIELD(scaf_drag_motion_t, dx);
    FIELD(scaf_drag_motion_t, dy);
    FIELD(scaf_drag_motion_t, angle);
    FIELD(scaf_drag_motion_t, factor);
    FIELD(scaf_drag_motion_t, flip);
    FIELD(scaf_drag_motion_t, remirror);
    FIELD(scaf_drag_motion_t, has_pivot);
    FIELD(scaf_drag_motion_t, pivot);

    SIZE(scaf_inflate_options_t);
    FIELD(scaf_inflate_options_t, struct_size);
    FIELD(scaf_inflate_options_t, scale);
    FIELD(scaf_inflate_options_t, iterations);
    FIELD(scaf_inflate_options_t, box_scale);
    FIELD(scaf_inflate_options_t, solver);

    SIZE(scaf_untangle_options_t);
    FIELD(scaf_untangle_options_t, struct_size);
    FIELD(scaf_untangle_options_t, delta);
    FIELD(scaf_untangle_options_t, flow_steps);
    FIELD(scaf_untangle_options_t, iterations);
    FIELD(scaf_untangle_options_t, tolerance);
    FIELD(scaf_untangle_options_t, anchor);
    FIELD(scaf_untangle_options_t, verify);

    SIZE(scaf_flow_options_t);
    FIELD(scaf_flow_options_t, struct_size);
    FIELD(scaf_flow_options_t, steps);
    FIELD(scaf_flow_options_t, delta);
    FIELD(scaf_flow_options_t, until_free);

    SIZE(scaf_volume_step_info_t);
    FIELD(scaf_volume_step_info_t, phase);
    FIELD(scaf_volume_step_info_t, step);
    FIELD(scaf_volume_step_info_t, seconds);
    FIELD(scaf_volume_step_info_t, check_seconds);
    FIELD(scaf_volume_step_info_t, defects);
    FIELD(scaf_volume_step_info_t, pairs);
    FIELD(scaf_volume_step_info_t, degenerate_faces);
    FIELD(scaf_volume_step_info_t, energy);
    FIELD(scaf_volume_step_info_t, arap);
    FIELD(scaf_volume_step_info_t, step_length);
    FIELD(scaf_volume_step_info_t, rms);
    FIELD(scaf_volume_step_info_t, max);
    FIELD(scaf_volume_step_info_t, tets);
    FIELD(scaf_volume_step_info_t, scaffold_vertices);
    FIELD(scaf_volume_step_info_t, quality_min);
    FIELD(scaf_volume_step_info_t, quality_p5);
    FIELD(scaf_volume_step_info_t, X);

    SIZE(scaf_volume_summary_t);
    FIELD(scaf_volume_summary_t, struct_size);
    FIELD(scaf_volume_summary_t, steps);
    FIELD(scaf_volume_summary_t, iterations);
    FIELD(scaf_volume_summary_t, input_defects);
    FIELD(scaf_volume_summary_t, defects);
    FIELD(scaf_volume_summary_t, box_lo);
    FIELD(scaf_volume_summary_t, box_hi);
    FIELD(scaf_volume_summary_t, diagonal_before);
    FIELD(scaf_volume_summary_t, diagonal_after);
    FIELD(scaf_volume_summary_t, best_iteration);
    FIELD(scaf_volume_summary_t, stop);
    FIELD(scaf_volume_summary_t, flowed_rms);
    FIELD(scaf_volume_summary_t, flowed_max);
    FIELD(scaf_volume_summary_t, rms);
    FIELD(scaf_volume_summary_t, max);
    FIELD(scaf_volume_summary_t, box_vertices);
    FIELD(scaf_volume_summary_t, tets_inside);

    SIZE(scaf_tet_options_t);
    FIELD(scaf_tet_options_t, struct_size);
    FIELD(scaf_tet_options_t, box_scale);
    FIELD(scaf_tet_options_t, box_cells);

    SIZE(scaf_surface_report_t);
    FIELD(scaf_surface_report_t, struct_size);
    FIELD(scaf_surface_report_t, message);
    FIELD(scaf_surface_report_t, faces);
    FIELD(scaf_surface_report_t, vertices);
    FIELD(scaf_surface_report_t, boundary_edges);
    FIELD(scaf_surface_report_t, closed);
    FIELD(scaf_surface_report_t, manifold);
    FIELD(scaf_surface_report_t, degenerate_faces);
    FIELD(scaf_surface_report_t, first_degenerate);
    FIELD(scaf_surface_report_t, pairs);
    FIELD(scaf_surface_report_t, crossing_pairs);
    FIELD(scaf_surface_report_t, vertex_pairs);
    FIELD(scaf_surface_report_t, edge_pairs);
    FIELD(scaf_surface_report_t, duplicate_pairs);
    FIELD(scaf_surface_report_t, nfirst);
    FIELD(scaf_surface_report_t, first);
    FIELD(scaf_surface_report_t, intersection_free);

    SIZE(scaf_tets_report_t);
    FIELD(scaf_tets_report_t, struct_size);
    FIELD(scaf_tets_report_t, message);
    FIELD(scaf_tets_report_t, tets);
    FIELD(scaf_tets_report_t, positive);
    FIELD(scaf_tets_report_t, inverted);
    FIELD(scaf_tets_report_t, degenerate);
    FIELD(scaf_tets_report_t, first_bad);
    FIELD(scaf_tets_report_t, valid);

    /* enum values the binding names (it passes other ints through) */
    printf("enum SCAF_PHASE_COUNT %d\n", (int)SCAF_PHASE_COUNT);
    printf("enum SCAF_ERR_INTERNAL %d\n", (int)SCAF_ERR_INTERNAL);
    printf("enum SCAF_ERR_CANCELLED %d\n", (int)SCAF_ERR_CANCELLED);
    printf("enum SCAF_ENERGY_CONFORMAL %d\n", (int)SCAF_ENERGY_CONFORMAL);
    printf("enum SCAF_INIT_HARMONIC %d\n", (int)SCAF_INIT_HARMONIC);
    printf("enum SCAF_INIT_MVC %d\n", (int)SCAF_INIT_MVC);
    printf("enum SCAF_ATLAS_COMPACT %d\n", (int)SCAF_ATLAS_COMPACT);
    printf("enum SCAF_DRAG_START_ATLAS %d\n", (int)SCAF_DRAG_START_ATLAS);
    printf("enum SCAF_VOLUME_ITERATION %d\n", (int)SCAF_VOLUME_ITERATION);
    printf("enum SCAF_UNTANGLE_ITERATION_LIMIT %d\n", (int)SCAF_UNTANGLE_ITERATION_LIMIT);
    printf("enum SCAF_REPORT_MESSAGE_MAX %d\n", (int)SCAF_REPORT_MESSAGE_MAX);
    printf("enum SCAF_SURFACE_FIRST_PAIRS %d\n", (int)SCAF_SURFACE_FIRST_PAIRS);
    printf("enum sizeof %zu\n", sizeof(scaf_init));
    return 0;
}
