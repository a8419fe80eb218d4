/* tools/cmd_check: `scaf check [--json] FILE`, the bijectivity verifier.
 *
 * Reads a mesh with UVs (OBJ `vt` + `f v/vt`) and reports, decided with
 * exact predicates (geom/bijectivity): flipped / degenerate UV triangles,
 * mirrored charts, crossing and touching UV boundary segment pairs, folds
 * and nested charts. A closed surface without UVs, or any surface with
 * --3d, gets the 3D self-intersection check instead (tools/check_surface);
 * a Medit .mesh the tet orientation check (tools/check_tets).
 * Exit status: 0 bijective, 1 not bijective,
 * 3 unreadable or malformed file, 4 readable but without UVs, 2 usage.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check_surface.h"
#include "check_tets.h"
#include "cli_mesh_io.h"
#include "commands.h"
#include "base/json_write.h"
#include "exit_codes.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/mesh_io.h"
#include "mesh/uv_verdict.h"

static void about(FILE *out)
{
    fputs("Checks whether the UV map of FILE (.obj with vt, .ply with texcoord or s,t,\n"
          "optionally .gz; \"-\": the standard input) is bijective,\n"
          "with exact arithmetic: every UV triangle counter-clockwise with nonzero area,\n"
          "and no two triangles overlapping (boundary segments neither cross nor touch,\n"
          "no chart inside another). FILE.mesh, a tetrahedral mesh (Medit): every tet\n"
          "must be positively oriented (exact orient3d); exit 1 when one is inverted or\n"
          "flat. JSON keys: tets, positive, inverted, degenerate, first_bad, valid.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fputs("\n"
          "min_chart_gap: the smallest distance between two different charts (triangles\n"
          "sharing a UV index are one chart; null with fewer than two charts).\n"
          "packing_efficiency: total UV area of the triangles / (longest side of the UV\n"
          "bounding box)^2, the fraction of the square the layout fills.\n"
          "energy: E of the map with its UVs scaled to the surface's area, the figure\n"
          "every command reports (4 at an isometry; docs/energy.md).\n"
          "A chart whose triangles are all clockwise is reported as mirrored; it counts\n"
          "as flipped (the map does not preserve orientation), so it is not bijective.\n"
          "\n",
          out);
    exit_codes_print(out);
}

static void print_json(const char *path, const bij_report *r, double gap, double eff, double energy)
{
    json_write_report_head(stdout, "check");
    printf(",\n  \"input\": ");
    json_write_string(stdout, path);
    printf(",\n  \"check\": \"uv_bijectivity\", \"triangles\": %d, \"positive\": %d, \"flipped\": "
           "%d, \"degenerate\": %d, "
           "\"charts\": %d, \"mirrored_charts\": %d, \"mixed_charts\": %d, "
           "\"boundary_edges\": %d, \"boundary_loops\": %d, \"boundary_crossings\": %lld, "
           "\"boundary_touchings\": %lld, \"boundary_foldbacks\": %lld, \"folded_edges\": %d, "
           "\"nonmanifold_edges\": %d, "
           "\"nested_loops\": %d, \"corner_overlaps\": %d, \"bijective\": %s, ",
           r->triangles, r->positive, r->flipped, r->degenerate, r->charts, r->mirrored_charts,
           r->mixed_charts, r->boundary_edges, r->boundary_loops, r->boundary_crossings,
           r->boundary_touchings, r->boundary_foldbacks, r->folded_edges, r->nonmanifold_edges,
           r->nested_loops, r->corner_overlaps, r->bijective ? "true" : "false");
    printf("\"min_chart_gap\": ");
    json_write_number(stdout, gap);
    printf(", \"packing_efficiency\": ");
    json_write_number(stdout, eff);
    printf(", \"energy\": ");
    json_write_number(stdout, energy);
    printf("}\n");
}

static void print_text(const char *path, const bij_report *r, double gap, double eff, double energy)
{
    printf("%s: %s\n", path, r->bijective ? "bijective" : "NOT bijective");
    printf("  triangles            %d\n", r->triangles);
    printf("  positive (ccw)       %d\n", r->positive);
    printf("  flipped (cw)         %d\n", r->flipped);
    printf("  degenerate (0 area)  %d\n", r->degenerate);
    printf("  charts               %d (%d mirrored, %d mixed orientation)\n", r->charts,
           r->mirrored_charts, r->mixed_charts);
    printf("  boundary edges       %d in %d loops\n", r->boundary_edges, r->boundary_loops);
    printf("  boundary crossings   %lld\n", r->boundary_crossings);
    printf("  boundary touchings   %lld\n", r->boundary_touchings);
    printf("  boundary fold-backs  %lld\n", r->boundary_foldbacks);
    printf("  folded edges         %d\n", r->folded_edges);
    printf("  non-manifold edges   %d\n", r->nonmanifold_edges);
    printf("  nested loops         %d\n", r->nested_loops);
    printf("  corner overlaps      %d\n", r->corner_overlaps);
    if (isfinite(gap)) printf("  min chart gap        %.6g\n", gap);
    else printf("  min chart gap        none (fewer than two charts)\n");
    printf("  packing efficiency   %.4f\n", eff);
    if (isfinite(energy)) printf("  E (area-matched)     %.6f\n", energy);
    else printf("  E (area-matched)     none (a triangle is flipped or flat)\n");
}

int cmd_check(int argc, char **argv)
{
    int json = 0, surface3d = 0;
    const char *path = NULL;
    const cli_option options[] = {
        CLI_GROUP("options:"),
        CLI_FLAG("json", 0, &json,
                 "print one JSON object (docs/reports.md; keys: schema, command, input, "
                 "triangles, positive, flipped, degenerate, charts, mirrored_charts, "
                 "mixed_charts, boundary_edges, boundary_loops, boundary_crossings, "
                 "boundary_touchings, boundary_foldbacks, folded_edges, nonmanifold_edges, "
                 "nested_loops, corner_overlaps, bijective, min_chart_gap, "
                 "packing_efficiency, energy)"),
        CLI_FLAG("3d", 0, &surface3d,
                 "check the 3D surface for self-intersections instead (exact "
                 "triangle-triangle tests; the default for a closed surface without vt); exit 1 "
                 "when two faces meet in more than the vertices or edge they share, or a face "
                 "has zero area. JSON keys: faces, closed, manifold, degenerate_faces, "
                 "intersecting_pairs, crossing_pairs, vertex_pairs, edge_pairs, "
                 "duplicate_pairs, first_pairs, intersection_free",
                 .alias = "self-intersections"),
        CLI_INPUT_FORMAT_OPTIONS,
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "check",
                                     .usage = "usage: scaf check [--json] [--3d] FILE\n"
                                              "       scaf check [--json] FILE.mesh\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .help_column = 21,
                                     .positionals = &path,
                                     .max_positionals = 1,
                                     .positional_name = "FILE"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) return cli_options_done(&cmd, parsed);
    if (!path) {
        cli_options_help(&cmd, stderr);
        return EXIT_USAGE;
    }

    if (check_tets_applies(path)) return check_tets_run(path, json);

    mesh m;
    mesh_read_info info;
    scaf_error err;
    err_clear(&err);
    int read_rc = cli_read_mesh("check", path, 1, &m, &info);
    if (read_rc != EXIT_OK) return read_rc;
    scaf_status s;
    if (surface3d || (!mesh_has_uv(&m) && check_surface_is_closed(&m))) {
        int status = check_surface_run(path, &m, json);
        mesh_free(&m);
        return status;
    }
    if (!mesh_has_uv(&m)) {
        if (info.faces_without_uv > 0)
            fprintf(stderr, "scaf check: %s: %d faces have no UV indices: no UV map to check\n",
                    path, info.faces_without_uv);
        else fprintf(stderr, "scaf check: %s: no UV coordinates (vt) to check\n", path);
        mesh_free(&m);
        return EXIT_MESH;
    }
    bij_report r;
    s = mesh_uv_verdict(&m, &r, &err); /* the verdict scaf atlas --init input quotes */
    double gap = INFINITY, eff = 0.0;
    if (s == SCAF_OK) s = chart_gap_min(m.nuv, m.UV, m.nf, m.FT, NULL, 0.0, &gap, NULL, &err);
    if (s == SCAF_OK) eff = chart_packing_efficiency(m.nuv, m.UV, m.nf, m.FT);
    double energy = NAN; /* docs/energy.md; stays NaN for faces without vt */
    if (s == SCAF_OK) scaf_area_matched_energy(m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT, &energy);
    mesh_free(&m);
    if (s != SCAF_OK) {
        fprintf(stderr, "scaf check: %s: %s\n", path, err.message);
        return exit_code_for(s);
    }
    if (json) print_json(path, &r, gap, eff, energy);
    else print_text(path, &r, gap, eff, energy);
    return r.bijective ? EXIT_OK : EXIT_NOT_BIJECTIVE;
}
