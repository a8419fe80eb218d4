/* mesh/uv_charts: charts, their loops, and the embeddability check
 * (see uv_charts.h).
 *
 * Chart labels: union-find on faces across every vt edge with two or more
 * faces. Then mesh/complex analyzes FT (or F) with those labels, and the
 * loops are translated to vertex and vt indices and sorted per chart by 3D
 * length. Fails only on allocation.
 */
#include "mesh/uv_charts.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/edges.h"
#include "base/union_find.h"

void mesh_charts_free(mesh_charts *c)
{
    if (!c) return;
    tri_complex_free(&c->cx);
    free(c->loop_v);
    free(c->loop_vt);
    free(c->loop_length);
    free(c->chart_loop_start);
    free(c->chart_loops);
    free(c->chart_vertex_start);
    free(c->chart_vertices);
    memset(c, 0, sizeof *c);
}

scaf_status mesh_uv_chart_labels(const mesh *m, int *face_chart, int *ncharts, scaf_error *err)
{
    int nf = m->nf;
    *ncharts = 0;
    if (!mesh_has_uv(m)) {
        int nc = tri_components(m->nv, nf, m->F, face_chart, err);
        if (nc < 0) return SCAF_ERR_NOMEM;
        *ncharts = nc;
        return SCAF_OK;
    }
    mesh_edges E;
    scaf_status st = mesh_edges_build(m->nuv, nf, m->FT, &E, err);
    if (st) return st;
    int *parent = malloc(((size_t)nf + 1) * sizeof *parent);
    int *label = malloc(((size_t)nf + 1) * sizeof *label);
    if (!parent || !label) {
        free(parent);
        free(label);
        mesh_edges_free(&E);
        return err_nomem(err, "chart labels");
    }
    uf_init(parent, nf);
    for (int e = 0; e < E.ne; e++)
        for (int i = E.edge_he_start[e] + 1; i < E.edge_he_start[e + 1]; i++)
            uf_union(parent, E.edge_he[E.edge_he_start[e]] / 3, E.edge_he[i] / 3);
    int n = 0;
    for (int f = 0; f < nf; f++) label[f] = -1;
    for (int f = 0; f < nf; f++) {
        int r = uf_find(parent, f);
        if (label[r] < 0) label[r] = n++;
        face_chart[f] = label[r];
    }
    *ncharts = n;
    free(parent);
    free(label);
    mesh_edges_free(&E);
    return SCAF_OK;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Distinct indices of each chart (CSR), ascending. */
static scaf_status chart_vertex_lists(mesh_charts *c, const int *IF, int n, scaf_error *err)
{
    const tri_complex *cx = &c->cx;
    int total = 0;
    for (int g = 0; g < c->ncharts; g++) total += cx->group_vertices[g];
    c->chart_vertex_start = malloc(((size_t)c->ncharts + 1) * sizeof(int));
    c->chart_vertices = malloc(((size_t)total + 1) * sizeof(int));
    int *stamp = malloc(((size_t)n + 1) * sizeof *stamp);
    if (!c->chart_vertex_start || !c->chart_vertices || !stamp) {
        free(stamp);
        return err_nomem(err, "chart vertex lists");
    }
    for (int i = 0; i < n; i++) stamp[i] = -1;
    int k = 0;
    for (int g = 0; g < c->ncharts; g++) {
        c->chart_vertex_start[g] = k;
        for (int i = cx->group_face_start[g]; i < cx->group_face_start[g + 1]; i++) {
            int f = cx->group_faces[i];
            if (cx->edges.he_edge[3 * f] < 0) continue; /* invalid face */
            for (int q = 0; q < 3; q++) {
                int v = IF[3 * f + q];
                if (stamp[v] == g) continue;
                stamp[v] = g;
                c->chart_vertices[k++] = v;
            }
        }
        qsort(c->chart_vertices + c->chart_vertex_start[g], (size_t)(k - c->chart_vertex_start[g]),
              sizeof(int), cmp_int);
    }
    c->chart_vertex_start[c->ncharts] = k;
    free(stamp);
    if (k != total)
        return err_set(err, SCAF_ERR_INTERNAL, "chart vertex lists: %d indices, expected %d", k,
                       total);
    return SCAF_OK;
}

/* qsort context-free: sort loop ids of one chart by decreasing length,
 * ties by id, using (length, id) pairs. */
typedef struct loop_key {
    double len;
    int id;
} loop_key;

static int cmp_loop(const void *a, const void *b)
{
    const loop_key *x = a, *y = b;
    if (x->len != y->len) return x->len < y->len ? 1 : -1;
    return (x->id > y->id) - (x->id < y->id);
}

scaf_status mesh_charts_compute(const mesh *m, mesh_charts *c, scaf_error *err)
{
    memset(c, 0, sizeof *c);
    int nf = m->nf;
    if (nf > INT_MAX / 3)
        return err_set(err, SCAF_ERR_MESH, "%d faces: more than this build can index (%d)", nf,
                       INT_MAX / 3);
    for (int i = 0; i < 3 * nf; i++)
        if (m->F[i] < 0 || m->F[i] >= m->nv)
            return err_set(err, SCAF_ERR_MESH,
                           "face %d references vertex %d, but the mesh has %d vertices", i / 3,
                           m->F[i], m->nv);
    c->uses_uv = mesh_has_uv(m);
    const int *IF = c->uses_uv ? m->FT : m->F;
    int n = c->uses_uv ? m->nuv : m->nv;
    loop_key *keys = NULL;
    int *label = malloc(((size_t)nf + 1) * sizeof *label);
    if (!label) return err_nomem(err, "chart labels");
    scaf_status st = mesh_uv_chart_labels(m, label, &c->ncharts, err);
    if (!st) st = tri_complex_build(n, nf, IF, c->ncharts, label, &c->cx, err);
    free(label);
    if (st) goto fail;

    /* ---- loops in vertex and vt indices, with 3D length ---- */
    const tri_complex *cx = &c->cx;
    int nl = cx->nloops, nb = cx->loop_start[nl];
    c->loop_v = malloc(((size_t)nb + 1) * sizeof *c->loop_v);
    c->loop_vt = malloc(((size_t)nb + 1) * sizeof *c->loop_vt);
    c->loop_length = calloc((size_t)nl + 1, sizeof *c->loop_length);
    c->chart_loop_start = calloc((size_t)c->ncharts + 2, sizeof *c->chart_loop_start);
    c->chart_loops = malloc(((size_t)nl + 1) * sizeof *c->chart_loops);
    keys = malloc(((size_t)nl + 1) * sizeof *keys);
    if (!c->loop_v || !c->loop_vt || !c->loop_length || !c->chart_loop_start || !c->chart_loops ||
        !keys) {
        st = err_nomem(err, "chart loops");
        goto fail;
    }
    for (int l = 0; l < nl; l++) {
        double len = 0;
        for (int i = cx->loop_start[l]; i < cx->loop_start[l + 1]; i++) {
            int h = cx->loop_he[i];
            int h_next = 3 * (h / 3) + (h % 3 + 1) % 3; /* corner at the half-edge's end */
            c->loop_v[i] = m->F[h];
            c->loop_vt[i] = c->uses_uv ? m->FT[h] : -1;
            const double *a = m->V + 3 * m->F[h], *b = m->V + 3 * m->F[h_next];
            len += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                        (a[2] - b[2]) * (a[2] - b[2]));
        }
        c->loop_length[l] = len;
        c->chart_loop_start[cx->loop_group[l] + 1]++;
    }
    for (int g = 0; g < c->ncharts; g++) c->chart_loop_start[g + 1] += c->chart_loop_start[g];
    {
        int *fill = malloc(((size_t)c->ncharts + 1) * sizeof *fill);
        if (!fill) {
            st = err_nomem(err, "chart loops");
            goto fail;
        }
        memcpy(fill, c->chart_loop_start, (size_t)c->ncharts * sizeof *fill);
        for (int l = 0; l < nl; l++) c->chart_loops[fill[cx->loop_group[l]]++] = l;
        free(fill);
    }
    for (int g = 0; g < c->ncharts; g++) {
        int s = c->chart_loop_start[g], t = c->chart_loop_start[g + 1];
        if (t - s < 2) continue;
        for (int i = s; i < t; i++) {
            keys[i - s].len = c->loop_length[c->chart_loops[i]];
            keys[i - s].id = c->chart_loops[i];
        }
        qsort(keys, (size_t)(t - s), sizeof *keys, cmp_loop);
        for (int i = s; i < t; i++) c->chart_loops[i] = keys[i - s].id;
    }
    free(keys);
    keys = NULL;
    st = chart_vertex_lists(c, IF, n, err);
    if (st) goto fail;
    return SCAF_OK;

fail:
    free(keys);
    mesh_charts_free(c);
    return st;
}

/* Whether some face of the chart is invalid in the index space. */
static int first_invalid_face(const mesh_charts *c, int chart)
{
    const tri_complex *cx = &c->cx;
    for (int i = cx->group_face_start[chart]; i < cx->group_face_start[chart + 1]; i++) {
        int f = cx->group_faces[i];
        if (cx->edges.he_edge[3 * f] < 0) return f;
    }
    return -1;
}

mesh_chart_kind mesh_chart_classify(const mesh_charts *c, int chart)
{
    const tri_complex *cx = &c->cx;
    if (cx->group_nm_edges[chart] || cx->group_nm_vertices[chart] ||
        first_invalid_face(c, chart) >= 0)
        return MESH_CHART_NON_MANIFOLD;
    if (!cx->group_orientable[chart]) return MESH_CHART_NON_ORIENTABLE;
    if (cx->group_misoriented[chart]) return MESH_CHART_MISORIENTED;
    if (cx->group_loops[chart] == 0) return MESH_CHART_CLOSED;
    if (cx->group_genus[chart] != 0) return MESH_CHART_HIGHER_GENUS;
    for (int i = c->chart_loop_start[chart]; i < c->chart_loop_start[chart + 1]; i++)
        if (!cx->loop_ordered[c->chart_loops[i]]) return MESH_CHART_NON_MANIFOLD;
    return cx->group_loops[chart] == 1 ? MESH_CHART_DISK : MESH_CHART_DISK_WITH_HOLES;
}

int mesh_chart_loop(const mesh_charts *c, int chart, int i, const int **v, const int **vt, int *id)
{
    if (chart < 0 || chart >= c->ncharts || i < 0 ||
        i >= c->chart_loop_start[chart + 1] - c->chart_loop_start[chart])
        return 0;
    int l = c->chart_loops[c->chart_loop_start[chart] + i];
    int s = c->cx.loop_start[l];
    if (v) *v = c->loop_v + s;
    if (vt) *vt = c->loop_vt + s;
    if (id) *id = l;
    return c->cx.loop_start[l + 1] - s;
}

const char *mesh_chart_kind_name(mesh_chart_kind kind)
{
    switch (kind) {
    case MESH_CHART_DISK: return "disk";
    case MESH_CHART_DISK_WITH_HOLES: return "disk with holes";
    case MESH_CHART_CLOSED: return "closed surface";
    case MESH_CHART_HIGHER_GENUS: return "surface with handles";
    case MESH_CHART_NON_MANIFOLD: return "non-manifold";
    case MESH_CHART_MISORIENTED: return "inconsistently oriented";
    case MESH_CHART_NON_ORIENTABLE: return "non-orientable";
    }
    return "unknown";
}

scaf_status mesh_chart_check(const mesh_charts *c, int chart, int allow_holes, scaf_error *err)
{
    const tri_complex *cx = &c->cx;
    const char *what = c->uses_uv ? "vt" : "vertex";
    if (chart < 0 || chart >= c->ncharts)
        return err_set(err, SCAF_ERR_USAGE, "chart %d does not exist (%d charts)", chart,
                       c->ncharts);
    mesh_chart_kind kind = mesh_chart_classify(c, chart);
    int f = first_invalid_face(c, chart);
    switch (kind) {
    case MESH_CHART_DISK: return SCAF_OK;
    case MESH_CHART_DISK_WITH_HOLES:
        if (allow_holes) return SCAF_OK;
        return err_set(err, SCAF_ERR_MESH,
                       "chart %d is a disk with %d holes (%d boundary loops), not a disk", chart,
                       cx->group_loops[chart] - 1, cx->group_loops[chart]);
    case MESH_CHART_NON_MANIFOLD:
        if (f >= 0)
            return err_set(err, SCAF_ERR_MESH,
                           "chart %d: face %d has a missing or repeated %s index", chart, f, what);
        if (cx->group_bad_edge[chart] >= 0) {
            int e = cx->group_bad_edge[chart];
            return err_set(err, SCAF_ERR_MESH,
                           "chart %d is not manifold: edge %s %d-%d has %d faces (%d non-manifold "
                           "edges)",
                           chart, what, cx->edges.ev[2 * e], cx->edges.ev[2 * e + 1],
                           mesh_edge_valence(&cx->edges, e), cx->group_nm_edges[chart]);
        }
        if (cx->group_bad_vertex[chart] >= 0)
            return err_set(err, SCAF_ERR_MESH,
                           "chart %d is not manifold: the faces around %s %d form several fans "
                           "(a pinch point, or shared with another chart; %d such)",
                           chart, what, cx->group_bad_vertex[chart], cx->group_nm_vertices[chart]);
        return err_set(err, SCAF_ERR_MESH,
                       "chart %d: a boundary loop touches itself (not a simple cycle)", chart);
    case MESH_CHART_NON_ORIENTABLE:
        return err_set(err, SCAF_ERR_MESH, "chart %d is not orientable (like a Moebius strip)",
                       chart);
    case MESH_CHART_MISORIENTED: {
        int e = cx->group_bad_orient[chart];
        return err_set(err, SCAF_ERR_MESH,
                       "chart %d has inconsistently oriented faces: %s edge %d-%d is used twice in "
                       "one "
                       "direction (%d such edges); reorient the faces",
                       chart, what, cx->edges.ev[2 * e], cx->edges.ev[2 * e + 1],
                       cx->group_misoriented[chart]);
    }
    case MESH_CHART_CLOSED:
        return err_set(err, SCAF_ERR_MESH,
                       "chart %d is a closed surface (no boundary, Euler characteristic %d): cut "
                       "it open first (automatic seams: --seams auto or extend)",
                       chart, cx->group_euler[chart]);
    case MESH_CHART_HIGHER_GENUS:
        if (cx->group_genus[chart] > 0)
            return err_set(err, SCAF_ERR_MESH,
                           "chart %d has genus %d (%d boundary loops): cut its handles first "
                           "(automatic seams: --seams auto or extend)",
                           chart, cx->group_genus[chart], cx->group_loops[chart]);
        return err_set(err, SCAF_ERR_MESH,
                       "chart %d has an invalid Euler characteristic %d with %d boundary loops",
                       chart, cx->group_euler[chart], cx->group_loops[chart]);
    }
    return err_set(err, SCAF_ERR_INTERNAL, "chart %d: unknown kind", chart);
}
