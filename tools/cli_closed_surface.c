/* tools/cli_closed_surface: the input check of the commands that work on a
 * closed surface (see cli_closed_surface.h). */
#include "cli_closed_surface.h"

#include <stdio.h>

#include "exit_codes.h"
#include "mesh/topology.h"

int cli_check_closed_surface(const char *cmd, const char *in, const mesh *m, const char *who)
{
    mesh_topology t;
    scaf_error err;
    err_clear(&err);
    scaf_status st = mesh_topology_compute(m, &t, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf %s: %s: %s\n", cmd, in, err.message);
        return exit_code_for(st);
    }
    char why[256] = "";
    if (t.faces == 0) snprintf(why, sizeof why, "it has no face");
    else if (t.boundary_edges > 0)
        snprintf(why, sizeof why, "the surface is open: %d boundary edges in %d loops",
                 t.boundary_edges, t.boundary_loops);
    else if (!t.manifold)
        snprintf(why, sizeof why,
                 "the surface is not manifold: %d non-manifold edges, %d non-manifold vertices",
                 t.non_manifold_edges, t.non_manifold_vertices);
    else if (t.degenerate_faces > 0)
        snprintf(why, sizeof why, "%d faces have zero area (no cotangent weights)",
                 t.degenerate_faces);
    else if (t.unreferenced_vertices > 0)
        snprintf(why, sizeof why, "%d vertices belong to no face", t.unreferenced_vertices);
    mesh_topology_free(&t);
    if (!why[0]) return EXIT_OK;
    fprintf(stderr, "scaf %s: %s: %s; %s needs a closed manifold triangle surface\n", cmd, in, why,
            who);
    return EXIT_MESH;
}
