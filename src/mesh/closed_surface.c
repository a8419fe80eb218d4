/* mesh/closed_surface: the checks of closed_surface.h, read off
 * mesh/topology's report. */
#include "mesh/closed_surface.h"

#include "mesh/topology.h"

scaf_status closed_surface_check(const mesh *m, int genus0, scaf_error *err)
{
    mesh_topology t;
    scaf_status st = mesh_topology_compute(m, &t, err);
    if (st != SCAF_OK) return st;
    st = SCAF_ERR_MESH;
    if (t.faces == 0) err_set(err, st, "it has no face");
    else if (t.boundary_edges > 0)
        err_set(err, st, "the surface is open: %d boundary edges in %d loops", t.boundary_edges,
                t.boundary_loops);
    else if (!t.manifold)
        err_set(err, st,
                "the surface is not manifold: %d non-manifold edges, %d non-manifold vertices",
                t.non_manifold_edges, t.non_manifold_vertices);
    else if (t.faces < 4 || m->nv < 4) /* closed but flat: a triangle twice */
        err_set(err, st,
                "the surface encloses no volume: %d vertices and %d faces (a closed surface has "
                "at least 4 of each)",
                m->nv, t.faces);
    else if (t.degenerate_faces > 0)
        err_set(err, st, "%d faces have zero area (no cotangent weights)", t.degenerate_faces);
    else if (t.unreferenced_vertices > 0)
        err_set(err, st, "%d vertices belong to no face", t.unreferenced_vertices);
    else if (genus0 && t.components > 1)
        err_set(err, st, "the surface has %d connected components, expected one", t.components);
    else if (genus0 && t.genus_sum != 0)
        err_set(err, st,
                "the surface has genus %d, expected 0 (a sphere with no handle): the flow rounds "
                "a genus-0 surface into a sphere, but thins a handle into a ring",
                t.genus_sum);
    else st = SCAF_OK;
    mesh_topology_free(&t);
    return st;
}
