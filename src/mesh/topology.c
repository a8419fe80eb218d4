/* mesh/topology: the topological report of a mesh (see topology.h).
 *
 * Components come from union-find on vertices; everything per component
 * from mesh/complex; UV charts from mesh/uv_charts. What is computed here
 * besides: degenerate faces (exact zero-area test, mesh/degenerate),
 * duplicate faces (bucket sort of sorted vertex triples) and seam edges.
 */
#include "mesh/topology.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort_u64.h"
#include "mesh/degenerate.h"
#include "mesh/uv_charts.h"

void mesh_topology_free(mesh_topology *t)
{
    if (!t) return;
    tri_complex_free(&t->cx);
    memset(t, 0, sizeof *t);
}

/* Faces whose vertex set equals that of an earlier face: bucket by the
 * smallest vertex, then sort (middle << 32 | largest) within the bucket. */
static int count_duplicates(const mesh *m, scaf_error *err)
{
    int nv = m->nv, nf = m->nf;
    int *start = calloc((size_t)nv + 2, sizeof *start);
    uint64_t *keys = malloc(((size_t)nf + 1) * sizeof *keys);
    if (!start || !keys) {
        free(start);
        free(keys);
        err_nomem(err, "duplicate faces");
        return -1;
    }
    for (int f = 0; f < nf; f++) {
        const int *t = m->F + 3 * f;
        int lo = t[0] < t[1] ? (t[0] < t[2] ? t[0] : t[2]) : (t[1] < t[2] ? t[1] : t[2]);
        start[lo + 1]++;
    }
    for (int v = 0; v < nv; v++) start[v + 1] += start[v];
    for (int f = 0; f < nf; f++) {
        int a = m->F[3 * f], b = m->F[3 * f + 1], c = m->F[3 * f + 2], x;
        if (a > b) {
            x = a;
            a = b;
            b = x;
        }
        if (b > c) {
            x = b;
            b = c;
            c = x;
        }
        if (a > b) {
            x = a;
            a = b;
            b = x;
        }
        keys[start[a]++] = ((uint64_t)(uint32_t)b << 32) | (uint32_t)c;
    }
    /* start[v] now holds the end of bucket v (= start of bucket v+1) */
    int dup = 0, s = 0;
    for (int v = 0; v < nv; v++) {
        int t = start[v];
        sort_u64(keys + s, t - s);
        for (int i = s + 1; i < t; i++) dup += keys[i] == keys[i - 1];
        s = t;
    }
    free(start);
    free(keys);
    return dup;
}

/* 2-face edges whose two faces give an endpoint different vt indices. */
static int count_seams(const mesh *m, const mesh_edges *E)
{
    int seams = 0;
    for (int e = 0; e < E->ne; e++) {
        if (mesh_edge_valence(E, e) != 2) continue;
        int s = E->edge_he_start[e];
        int h1 = E->edge_he[s], h2 = E->edge_he[s + 1];
        for (int end = 0; end < 2; end++) {
            int v = E->ev[2 * e + end];
            int c1 = m->F[h1] == v ? h1 : 3 * (h1 / 3) + (h1 % 3 + 1) % 3;
            int c2 = m->F[h2] == v ? h2 : 3 * (h2 / 3) + (h2 % 3 + 1) % 3;
            if (m->FT[c1] != m->FT[c2] || m->FT[c1] < 0) {
                seams++;
                break;
            }
        }
    }
    return seams;
}

scaf_status mesh_topology_compute(const mesh *m, mesh_topology *t, scaf_error *err)
{
    memset(t, 0, sizeof *t);
    int nv = m->nv, nf = m->nf;
    if (nf > INT_MAX / 3)
        return err_set(err, SCAF_ERR_MESH, "%d faces: more than this build can index (%d)", nf,
                       INT_MAX / 3);
    for (int i = 0; i < 3 * nf; i++)
        if (m->F[i] < 0 || m->F[i] >= nv)
            return err_set(err, SCAF_ERR_MESH,
                           "face %d references vertex %d, but the mesh has %d vertices", i / 3,
                           m->F[i], nv);

    scaf_status st = SCAF_OK;
    int *label = malloc(((size_t)nf + 1) * sizeof *label);
    if (!label) return err_nomem(err, "component labels");
    int nc = tri_components(nv, nf, m->F, label, err);
    if (nc < 0) {
        free(label);
        return SCAF_ERR_NOMEM;
    }
    st = tri_complex_build(nv, nf, m->F, nc, label, &t->cx, err);
    if (st) {
        free(label);
        memset(t, 0, sizeof *t);
        return st;
    }
    const tri_complex *cx = &t->cx;
    t->vertices = cx->referenced;
    t->faces = nf;
    t->edges = cx->edges.ne;
    t->boundary_edges = cx->boundary_edges;
    t->components = nc;
    t->boundary_loops = cx->nloops;
    t->non_manifold_edges = cx->nm_edges;
    t->non_manifold_vertices = cx->nm_vertices;
    t->misoriented_edges = cx->misoriented;
    t->manifold = !cx->nm_edges && !cx->nm_vertices;
    t->orientable = 1;
    t->genus_sum = 0;
    for (int c = 0; c < nc; c++) {
        t->euler_characteristic += cx->group_euler[c];
        if (!cx->group_orientable[c]) t->orientable = 0;
        if (cx->group_genus[c] < 0 || t->genus_sum < 0) t->genus_sum = -1;
        else t->genus_sum += cx->group_genus[c];
    }

    /* unreferenced: vertices used by no face at all (repeated-index faces
     * still reference their vertices) */
    unsigned char *used = calloc((size_t)nv + 1, 1);
    if (!used) {
        st = err_nomem(err, "vertex flags");
        goto fail;
    }
    for (int i = 0; i < 3 * nf; i++) used[m->F[i]] = 1;
    int nused = 0;
    for (int v = 0; v < nv; v++) nused += used[v];
    free(used);
    t->unreferenced_vertices = nv - nused;
    /* V = referenced vertices; also those only used by repeated-index faces */
    t->vertices = nused;

    for (int f = 0; f < nf; f++) {
        const int *tri = m->F + 3 * f;
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            t->repeated_index_faces++;
            t->degenerate_faces++;
        } else if (tri3_is_degenerate(m->V + 3 * tri[0], m->V + 3 * tri[1], m->V + 3 * tri[2])) {
            t->degenerate_faces++;
        }
    }
    t->duplicate_faces = count_duplicates(m, err);
    if (t->duplicate_faces < 0) {
        st = SCAF_ERR_NOMEM;
        goto fail;
    }

    t->has_uv = mesh_has_uv(m);
    if (t->has_uv) {
        st = mesh_uv_chart_labels(m, label, &t->uv_charts, err);
        if (st) goto fail;
        t->seam_edges = count_seams(m, &cx->edges);
    } else {
        t->uv_charts = nc;
    }
    free(label);
    return SCAF_OK;

fail:
    free(label);
    mesh_topology_free(t);
    return st;
}
