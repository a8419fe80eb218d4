/* tools/cmd_info: `scaf info [--json] FILE`, the topological report of a mesh.
 *
 * Reads the mesh (any format mesh_read knows), computes mesh/topology and
 * the UV charts (mesh/uv_charts), and prints them as aligned text or as
 * one JSON object. Exit status: 0 on success whatever the defects (they are
 * reported, not judged), 2 on a bad command line, 3 when the file is
 * missing or malformed, 7 when out of memory.
 */
#include <stdio.h>
#include <string.h>

#include "cli_mesh_io.h"
#include "commands.h"
#include "base/json_write.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "mesh/uv_charts.h"

/* Per-component lists longer than this are cut short (a triangle soup
 * could have millions of components). */
#define INFO_MAX_LISTED 1000

static void about(FILE *out)
{
    fprintf(out,
            "Print the topology of a mesh (.obj, .off, .ply, optionally .gz):\n"
            "vertices (those referenced by faces), faces, edges, connected components\n"
            "(faces joined through shared vertices), boundary loops (components of the\n"
            "graph of edges with one face), Euler characteristic V - E + F, genus,\n"
            "non-manifold edges (> 2 faces) and vertices (faces around it form several\n"
            "fans), misoriented edges (a directed edge used twice), degenerate faces\n"
            "(zero area, exact test, or a repeated vertex), duplicate faces,\n"
            "unreferenced vertices, UV charts (faces joined through shared vt edges; one\n"
            "per component without vt) and seam edges (interior edges whose two sides\n"
            "use different vt), and what each chart is (disk, disk with holes, ...).\n"
            "UVs: OBJ vt, PLY face texcoord lists or vertex s,t / u,v / texture_u,v /\n"
            "texture_s,t (uv_source says which), glTF TEXCOORD_n.\n"
            "\n"
            "Genus: per component (2 - chi - b) / 2, defined when the component is\n"
            "manifold and orientable. The top-level `genus` is the SUM over the\n"
            "components (the genus of their connected sum), or null as soon as one\n"
            "component's genus is undefined; `components_detail` lists each one\n"
            "(first %d components).\n"
            "\n",
            INFO_MAX_LISTED);
}

static void after(FILE *out)
{
    fputs("\nExit status: 0 reported (defects do not fail), 2 usage, 3 file missing or\n"
          "malformed, 7 out of memory.\n",
          out);
}

static const char *format_name(mesh_format f)
{
    switch (f) {
    case MESH_FORMAT_OBJ: return "OBJ";
    case MESH_FORMAT_OFF: return "OFF";
    case MESH_FORMAT_PLY: return "PLY";
    case MESH_FORMAT_GLTF: return "glTF";
    default: return "unknown";
    }
}

static void json_genus(FILE *out, int g)
{
    if (g < 0) fputs("null", out);
    else fprintf(out, "%d", g);
}

static int ordered_loops(const tri_complex *cx)
{
    int n = 0;
    for (int l = 0; l < cx->nloops; l++) n += cx->loop_ordered[l];
    return n;
}

static void print_json(FILE *out, const char *path, const mesh_read_info *ri, const mesh *m,
                       const mesh_topology *t, const mesh_charts *ch)
{
    const tri_complex *cx = &t->cx;
    int kinds[MESH_CHART_NON_ORIENTABLE + 1] = {0};
    for (int c = 0; c < ch->ncharts; c++) kinds[mesh_chart_classify(ch, c)]++;
    json_write_report_head(out, "info");
    fputs(",\n  \"input\": ", out);
    json_write_string(out, path);
    fprintf(out, ",\n  \"format\": \"%s\",\n", format_name(ri->format));
    fprintf(out, "  \"vertices\": %d,\n", t->vertices);
    fprintf(out, "  \"vertices_in_file\": %d,\n", m->nv);
    fprintf(out, "  \"faces\": %d,\n", t->faces);
    fprintf(out, "  \"polygons_triangulated\": %d,\n", ri->polygons_triangulated);
    fprintf(out, "  \"edges\": %d,\n", t->edges);
    fprintf(out, "  \"boundary_edges\": %d,\n", t->boundary_edges);
    fprintf(out, "  \"components\": %d,\n", t->components);
    fprintf(out, "  \"boundary_loops\": %d,\n", t->boundary_loops);
    fprintf(out, "  \"ordered_boundary_loops\": %d,\n", ordered_loops(cx));
    fprintf(out, "  \"euler_characteristic\": %d,\n", t->euler_characteristic);
    fputs("  \"genus\": ", out);
    json_genus(out, t->genus_sum);
    fprintf(out, ",\n  \"manifold\": %s,\n", t->manifold ? "true" : "false");
    fprintf(out, "  \"orientable\": %s,\n", t->orientable ? "true" : "false");
    fprintf(out, "  \"non_manifold_edges\": %d,\n", t->non_manifold_edges);
    fprintf(out, "  \"non_manifold_vertices\": %d,\n", t->non_manifold_vertices);
    fprintf(out, "  \"misoriented_edges\": %d,\n", t->misoriented_edges);
    fprintf(out, "  \"degenerate_faces\": %d,\n", t->degenerate_faces);
    fprintf(out, "  \"repeated_index_faces\": %d,\n", t->repeated_index_faces);
    fprintf(out, "  \"duplicate_faces\": %d,\n", t->duplicate_faces);
    fprintf(out, "  \"unreferenced_vertices\": %d,\n", t->unreferenced_vertices);
    fprintf(out, "  \"has_uv\": %s,\n", t->has_uv ? "true" : "false");
    fprintf(out, "  \"uv_coordinates\": %d,\n", m->nuv);
    fputs("  \"uv_source\": ", out);
    if (t->has_uv && ri->uv_source) json_write_string(out, ri->uv_source);
    else fputs("null", out);
    fputs(",\n", out);
    fprintf(out, "  \"uv_charts\": %d,\n", t->uv_charts);
    fprintf(out, "  \"seam_edges\": %d,\n", t->seam_edges);
    fputs("  \"chart_kinds\": {", out);
    int first = 1;
    for (int k = 0; k <= MESH_CHART_NON_ORIENTABLE; k++) {
        if (!kinds[k]) continue;
        fprintf(out, "%s\"%s\": %d", first ? "" : ", ", mesh_chart_kind_name((mesh_chart_kind)k),
                kinds[k]);
        first = 0;
    }
    fputs("},\n  \"genus_per_component\": [", out);
    int listed = t->components < INFO_MAX_LISTED ? t->components : INFO_MAX_LISTED;
    for (int c = 0; c < listed; c++) {
        if (c) fputs(", ", out);
        json_genus(out, cx->group_genus[c]);
    }
    fputs("],\n  \"components_detail\": [", out);
    for (int c = 0; c < listed; c++) {
        fprintf(out,
                "%s\n    {\"faces\": %d, \"vertices\": %d, \"edges\": %d, \"boundary_loops\": %d, "
                "\"euler_characteristic\": %d, \"genus\": ",
                c ? "," : "", cx->group_face_start[c + 1] - cx->group_face_start[c],
                cx->group_vertices[c], cx->group_edges[c], cx->group_loops[c], cx->group_euler[c]);
        json_genus(out, cx->group_genus[c]);
        fprintf(out, ", \"manifold\": %s, \"orientable\": %s, \"misoriented_edges\": %d}",
                !cx->group_nm_edges[c] && !cx->group_nm_vertices[c] ? "true" : "false",
                cx->group_orientable[c] ? "true" : "false", cx->group_misoriented[c]);
    }
    fprintf(out, "%s],\n  \"components_listed\": %d\n}\n", listed ? "\n  " : "", listed);
}

static void print_text(FILE *out, const char *path, const mesh_read_info *ri, const mesh *m,
                       const mesh_topology *t, const mesh_charts *ch)
{
    const tri_complex *cx = &t->cx;
    fprintf(out, "file            %s (%s)\n", path, format_name(ri->format));
    fprintf(out, "vertices        %d referenced (%d in file, %d unreferenced)\n", t->vertices,
            m->nv, t->unreferenced_vertices);
    fprintf(out, "faces           %d", t->faces);
    if (ri->polygons_triangulated)
        fprintf(out, " (%d polygons fan-triangulated)", ri->polygons_triangulated);
    fprintf(out, "\nedges           %d (%d on the boundary)\n", t->edges, t->boundary_edges);
    fprintf(out, "components      %d\n", t->components);
    fprintf(out, "boundary loops  %d (%d simple cycles)\n", t->boundary_loops, ordered_loops(cx));
    fprintf(out, "euler char.     %d\n", t->euler_characteristic);
    if (t->genus_sum >= 0)
        fprintf(out, "genus           %d%s\n", t->genus_sum,
                t->components > 1 ? " (sum over components)" : "");
    else
        fprintf(out, "genus           undefined (a component is non-manifold or non-orientable)\n");
    fprintf(out, "manifold        %s (%d non-manifold edges, %d non-manifold vertices)\n",
            t->manifold ? "yes" : "no", t->non_manifold_edges, t->non_manifold_vertices);
    fprintf(out, "orientation     %s (%d misoriented edges)%s\n",
            t->misoriented_edges ? "inconsistent" : "consistent", t->misoriented_edges,
            t->orientable ? "" : ", not orientable");
    fprintf(out, "degenerate      %d faces (%d with a repeated vertex), %d duplicate faces\n",
            t->degenerate_faces, t->repeated_index_faces, t->duplicate_faces);
    if (t->has_uv)
        fprintf(out, "uv              %d vt (%s), %d charts, %d seam edges\n", m->nuv,
                ri->uv_source ? ri->uv_source : "input", t->uv_charts, t->seam_edges);
    else fprintf(out, "uv              none (%d charts = components)\n", t->uv_charts);
    int kinds[MESH_CHART_NON_ORIENTABLE + 1] = {0};
    for (int c = 0; c < ch->ncharts; c++) kinds[mesh_chart_classify(ch, c)]++;
    fprintf(out, "chart kinds    ");
    for (int k = 0; k <= MESH_CHART_NON_ORIENTABLE; k++)
        if (kinds[k]) fprintf(out, " %d %s;", kinds[k], mesh_chart_kind_name((mesh_chart_kind)k));
    fputc('\n', out);
    if (t->components > 1) {
        int listed = t->components < INFO_MAX_LISTED ? t->components : INFO_MAX_LISTED;
        fprintf(out, "\n%9s %9s %9s %6s %6s %6s  %s\n", "component", "faces", "vertices", "loops",
                "chi", "genus", "manifold");
        for (int c = 0; c < listed; c++) {
            char g[16];
            if (cx->group_genus[c] >= 0) snprintf(g, sizeof g, "%d", cx->group_genus[c]);
            else snprintf(g, sizeof g, "-");
            fprintf(out, "%9d %9d %9d %6d %6d %6s  %s\n", c,
                    cx->group_face_start[c + 1] - cx->group_face_start[c], cx->group_vertices[c],
                    cx->group_loops[c], cx->group_euler[c], g,
                    !cx->group_nm_edges[c] && !cx->group_nm_vertices[c] ? "yes" : "no");
        }
        if (listed < t->components)
            fprintf(out, "(%d more components not listed)\n", t->components - listed);
    }
}

int cmd_info(int argc, char **argv)
{
    int json = 0;
    const char *path = NULL;
    const cli_option options[] = {
        CLI_GROUP("options:"),
        CLI_FLAG("json", 0, &json, "one JSON object on stdout instead of text"),
        CLI_INPUT_FORMAT_OPTIONS,
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "info",
                                     .usage = "usage: scaf info [--json] FILE\n\n",
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
        fprintf(stderr, "scaf info: missing FILE\n");
        cli_options_help(&cmd, stderr);
        return EXIT_USAGE;
    }

    mesh m;
    mesh_read_info ri;
    int read_rc = cli_read_mesh("info", path, 0, &m, &ri);
    if (read_rc != EXIT_OK) return read_rc;
    scaf_error err;
    err_clear(&err);
    scaf_status st;

    mesh_topology t;
    mesh_charts ch;
    memset(&ch, 0, sizeof ch);
    st = mesh_topology_compute(&m, &t, &err);
    if (!st) st = mesh_charts_compute(&m, &ch, &err);
    if (st) {
        fprintf(stderr, "scaf info: %s: %s\n", path, err.message);
        mesh_topology_free(&t);
        mesh_free(&m);
        return exit_code_for(st);
    }
    if (json) print_json(stdout, path, &ri, &m, &t, &ch);
    else print_text(stdout, path, &ri, &m, &t, &ch);
    mesh_charts_free(&ch);
    mesh_topology_free(&t);
    mesh_free(&m);
    if (fflush(stdout) != 0) {
        fprintf(stderr, "scaf info: cannot write the report\n");
        return EXIT_OUTPUT;
    }
    return EXIT_OK;
}
