/* tools/check_surface: `scaf check` on a 3D surface: the public
 * scaf_check_surface (exact self-intersection pairs plus the topology facts
 * that say whether the count is meaningful for a solid), printed. */
#include "check_surface.h"

#include <stdio.h>

#include "base/json_write.h"
#include "exit_codes.h"
#include "mesh/topology.h"
#include "scaf/volume.h"

int check_surface_is_closed(const mesh *m)
{
    mesh_topology t;
    if (m->nf == 0 || mesh_topology_compute(m, &t, NULL) != SCAF_OK) return 0;
    int closed = t.boundary_edges == 0;
    mesh_topology_free(&t);
    return closed;
}

static void print_json(const char *path, const scaf_surface_report_t *r)
{
    json_write_report_head(stdout, "check");
    printf(",\n  \"input\": ");
    json_write_string(stdout, path);
    printf(",\n  \"check\": \"self_intersections\", \"faces\": %d, \"vertices\": %d, "
           "\"boundary_edges\": %d, "
           "\"closed\": %s, \"manifold\": %s, \"degenerate_faces\": %d, \"intersecting_pairs\": "
           "%lld, "
           "\"crossing_pairs\": %lld, \"vertex_pairs\": %lld, \"edge_pairs\": %lld, "
           "\"duplicate_pairs\": %lld, \"first_pairs\": [",
           r->faces, r->vertices, r->boundary_edges, r->closed ? "true" : "false",
           r->manifold ? "true" : "false", r->degenerate_faces, r->pairs, r->crossing_pairs,
           r->vertex_pairs, r->edge_pairs, r->duplicate_pairs);
    for (int i = 0; i < r->nfirst; i++)
        printf("%s[%d, %d]", i ? ", " : "", r->first[i][0], r->first[i][1]);
    printf("], \"intersection_free\": %s}\n", r->intersection_free ? "true" : "false");
}

static void print_text(const char *path, const scaf_surface_report_t *r)
{
    printf("%s: %s\n", path, r->intersection_free ? "intersection-free" : "SELF-INTERSECTING");
    printf("  faces                %d\n", r->faces);
    printf("  closed               %s (%d boundary edges), %smanifold\n", r->closed ? "yes" : "no",
           r->boundary_edges, r->manifold ? "" : "NOT ");
    printf("  degenerate faces     %d", r->degenerate_faces);
    if (r->first_degenerate >= 0) printf(" (first: face %d)", r->first_degenerate);
    printf("\n  intersecting pairs   %lld\n", r->pairs);
    printf("    sharing no vertex  %lld\n", r->crossing_pairs);
    printf("    sharing a vertex   %lld\n", r->vertex_pairs);
    printf("    folded on an edge  %lld\n", r->edge_pairs);
    printf("    duplicate faces    %lld\n", r->duplicate_pairs);
    if (r->nfirst > 0) {
        printf("  first pairs (faces, 0-based):");
        for (int i = 0; i < r->nfirst; i++) printf(" %d-%d", r->first[i][0], r->first[i][1]);
        printf("\n");
    }
}

int check_surface_run(const char *path, const mesh *m, int json)
{
    scaf_surface_report_t r = {.struct_size = sizeof r};
    scaf_status s = scaf_check_surface(m->V, m->nv, m->F, m->nf, &r);
    if (s != SCAF_OK) {
        fprintf(stderr, "scaf check: %s: %s\n", path, r.message);
        return exit_code_for(s);
    }
    if (json) print_json(path, &r);
    else print_text(path, &r);
    return r.intersection_free ? EXIT_OK : EXIT_NOT_BIJECTIVE;
}
