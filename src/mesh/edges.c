/* mesh/edges: undirected edge table (see edges.h).
 *
 * The half-edges of the valid faces in (lo, hi, id) order
 * (base/half_edges); each run of equal endpoints is one edge. Fails only
 * on allocation.
 */
#include "mesh/edges.h"

#include "base/half_edges.h"

#include <assert.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

void mesh_edges_free(mesh_edges *e)
{
    if (!e) return;
    free(e->ev);
    free(e->he_edge);
    free(e->edge_he_start);
    free(e->edge_he);
    memset(e, 0, sizeof *e);
}

scaf_status mesh_edges_build(int n, int nf, const int *F, mesh_edges *e, scaf_error *err)
{
    memset(e, 0, sizeof *e);
    if (n < 0 || nf < 0 || nf > INT_MAX / 3)
        return err_set(err, SCAF_ERR_MESH, "edge table: %d faces over %d indices is out of range",
                       nf, n);
    size_t nh = 3 * (size_t)nf;
    unsigned char *invalid = malloc((size_t)nf + 1);
    e->he_edge = malloc((nh ? nh : 1) * sizeof *e->he_edge);
    e->edge_he = malloc((nh ? nh : 1) * sizeof *e->edge_he);
    if (!invalid || !e->he_edge || !e->edge_he) goto nomem;
    for (int f = 0; f < nf; f++) {
        invalid[f] = (unsigned char)!face_is_valid(F, f, n);
        e->invalid_faces += invalid[f];
    }

    /* ---- half-edges in (lo, hi, id) order; runs are the edges ---- */
    int nvalid = 0;
    if (half_edges_sort(n, nf, F, invalid, e->edge_he, &nvalid, err) != SCAF_OK) goto nomem;
    int ne = 0;
    for (int i = 0; i < nvalid; i++)
        if (i == 0 || !half_edges_same_edge(F, e->edge_he[i], e->edge_he[i - 1])) ne++;
    e->ev = malloc(2 * ((size_t)ne ? (size_t)ne : 1) * sizeof *e->ev);
    e->edge_he_start = malloc(((size_t)ne + 1) * sizeof *e->edge_he_start);
    if (!e->ev || !e->edge_he_start) goto nomem;
    for (size_t h = 0; h < nh; h++) e->he_edge[h] = -1;
    int edge = -1;
    for (int i = 0; i < nvalid; i++) {
        int h = e->edge_he[i];
        if (i == 0 || !half_edges_same_edge(F, h, e->edge_he[i - 1])) {
            edge++;
            e->ev[2 * edge] = half_edge_lo(F, h);
            e->ev[2 * edge + 1] = half_edge_hi(F, h);
            e->edge_he_start[edge] = i;
        }
        e->he_edge[h] = edge;
    }
    e->edge_he_start[ne] = nvalid;
    e->ne = ne;
    for (int k = 0; k < ne; k++)
        assert(e->ev[2 * k] < e->ev[2 * k + 1] && mesh_edge_valence(e, k) > 0);
    free(invalid);
    return SCAF_OK;

nomem:
    free(invalid);
    mesh_edges_free(e);
    return err_nomem(err, "edge table");
}
