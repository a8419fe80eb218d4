/* app/check_api: the exact checks of scaf/volume.h, scaf_check_surface
 * (geom/self_intersect plus the topology facts that say whether the count
 * means anything for a solid: closed, manifold; mesh/topology) and
 * scaf_check_tets (geom/tet_orient). The work `scaf check` does on a
 * surface without UVs and on a Medit tet mesh.
 */
#include <string.h>

#include "geom/self_intersect.h"
#include "geom/simplex_arrays.h"
#include "geom/tet_orient.h"
#include "mesh/topology.h"
#include "scaf/volume.h"

/* The report's header (struct_size, message) must be there to say anything. */
#define REPORT_MIN (sizeof(size_t) + SCAF_REPORT_MESSAGE_MAX)

/* full (with its message from err) into the caller's r, up to its size. */
static scaf_status give(void *r, void *full, size_t full_size, scaf_status st,
                        const scaf_error *err)
{
    size_t n = *(size_t *)r;
    char *msg = (char *)full + sizeof(size_t);
    size_t len = st == SCAF_OK ? 0 : strnlen(err->message, SCAF_REPORT_MESSAGE_MAX - 1);
    memcpy(msg, err->message, len); /* cut to the report's room */
    msg[len] = '\0';
    *(size_t *)full = n;
    memcpy(r, full, n < full_size ? n : full_size);
    return st;
}

static int report_size_ok(const void *r, size_t full)
{
    if (!r) return 0;
    size_t n = *(const size_t *)r;
    return n >= REPORT_MIN && n <= full;
}

scaf_status scaf_check_surface(const double *V, int nv, const int *F, int nf,
                               scaf_surface_report_t *r)
{
    if (!report_size_ok(r, sizeof *r)) return SCAF_ERR_USAGE;
    scaf_surface_report_t full;
    memset(&full, 0, sizeof full);
    full.first_degenerate = -1;
    scaf_error err;
    err_clear(&err);
    scaf_status st = simplex_arrays_check(nv, V, nf, F, 3, "face", &err);
    mesh m = {nv, (double *)V, nf, (int *)F, 0, NULL, NULL};
    mesh_topology t;
    si_report s;
    if (st == SCAF_OK) st = mesh_topology_compute(&m, &t, &err);
    if (st == SCAF_OK) {
        st = si_check(nv, V, nf, F, &s, &err);
        full.vertices = t.vertices;
        full.boundary_edges = t.boundary_edges;
        full.closed = t.boundary_edges == 0;
        full.manifold = t.manifold;
        mesh_topology_free(&t);
    }
    if (st == SCAF_OK) {
        full.faces = s.faces;
        full.degenerate_faces = s.degenerate_faces;
        full.first_degenerate = s.first_degenerate;
        full.pairs = s.pairs;
        full.crossing_pairs = s.crossing_pairs;
        full.vertex_pairs = s.vertex_pairs;
        full.edge_pairs = s.edge_pairs;
        full.duplicate_pairs = s.duplicate_pairs;
        full.nfirst = s.nfirst < SCAF_SURFACE_FIRST_PAIRS ? s.nfirst : SCAF_SURFACE_FIRST_PAIRS;
        for (int i = 0; i < full.nfirst; i++) {
            full.first[i][0] = s.first[i][0];
            full.first[i][1] = s.first[i][1];
        }
        full.intersection_free = s.intersection_free;
    }
    return give(r, &full, sizeof full, st, &err);
}

scaf_status scaf_check_tets(const double *V, int nv, const int *T, int nt, scaf_tets_report_t *r)
{
    if (!report_size_ok(r, sizeof *r)) return SCAF_ERR_USAGE;
    scaf_tets_report_t full;
    memset(&full, 0, sizeof full);
    full.first_bad = -1;
    scaf_error err;
    err_clear(&err);
    scaf_status st = simplex_arrays_check(nv, V, nt, T, 4, "tet", &err);
    tet_orient_report o;
    if (st == SCAF_OK) st = tet_orient_check(nv, V, nt, T, &o, &err);
    if (st == SCAF_OK) {
        full.tets = o.tets;
        full.positive = o.positive;
        full.inverted = o.inverted;
        full.degenerate = o.degenerate;
        full.first_bad = o.first_bad;
        full.valid = o.positive == o.tets;
    }
    return give(r, &full, sizeof full, st, &err);
}
