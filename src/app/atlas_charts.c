/* app/atlas_charts: charts split for distortion and packing (see the header). */
#include "app/atlas_charts.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "geom/min_box.h"
#include "mesh/chart_segment.h"
#include "mesh/uv_charts.h"

/* A chart is split only when each half can have this many faces (small
 * charts distort too: a 60-face chart of bunny settled at E 6.3). */
#define MIN_SPLIT_FACES 8
/* Settling caps of a measuring round: enough to rank charts, far below a
 * full run's (the final atlas settles to convergence). */
#define ROUND_ITERATIONS 40
#define ROUND_TOLERANCE 1e-3

atlas_charts_options atlas_charts_options_default(void)
{
    atlas_charts_options o;
    o.max_distortion = ATLAS_CHARTS_MAX_DISTORTION;
    o.min_fill = ATLAS_CHARTS_MIN_FILL;
    o.max_rounds = 3;
    o.max_splits = 0;
    o.slit_cones = 0;
    o.merge = 0;
    return o;
}

typedef struct split_candidate {
    int chart;
    int reason; /* 0 distortion, 1 fill */
    double score;
} split_candidate;

static int candidate_cmp(const void *p, const void *q)
{
    const split_candidate *a = p, *b = q;
    if (a->score != b->score) return a->score > b->score ? -1 : 1;
    return a->chart - b->chart;
}

/* UV area / least-area bounding box area of every chart of a settled atlas. */
static int chart_fill(const atlas *a, const double *UV, double *fill)
{
    int nc = a->ncharts;
    double *area = calloc((size_t)nc, sizeof(double));
    int *start = calloc((size_t)nc + 1, sizeof(int));
    int *verts = malloc(sizeof(int) * (size_t)(a->nw > 0 ? a->nw : 1));
    double *P = malloc(sizeof(double) * 2 * (size_t)(a->nw > 0 ? a->nw : 1));
    int *hull = malloc(sizeof(int) * (size_t)(a->nw + 1));
    int ok = 0;
    if (!area || !start || !verts || !P || !hull) goto out;
    for (int f = 0; f < a->nf; f++) {
        const double *p = UV + 2 * a->Fw[3 * f], *q = UV + 2 * a->Fw[3 * f + 1],
                     *r = UV + 2 * a->Fw[3 * f + 2];
        area[a->chart[f]] +=
            fabs(0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])));
    }
    for (int w = 0; w < a->nw; w++) start[a->wchart[w] + 1]++;
    for (int c = 0; c < nc; c++) start[c + 1] += start[c];
    int *fillpos = hull; /* cursor, before the hulls need it */
    for (int c = 0; c <= nc && c <= a->nw; c++) fillpos[c] = 0;
    for (int w = 0; w < a->nw; w++) {
        int c = a->wchart[w];
        verts[start[c] + fillpos[c]++] = w;
    }
    for (int c = 0; c < nc; c++) {
        int n = start[c + 1] - start[c];
        for (int i = 0; i < n; i++) {
            P[2 * i] = UV[2 * verts[start[c] + i]];
            P[2 * i + 1] = UV[2 * verts[start[c] + i] + 1];
        }
        int nh = min_box_hull(P, n, hull);
        if (nh < 0) goto out;
        double w = 0.0, h = 0.0;
        if (nh >= 3) min_box_extent(P, hull, nh, min_box_area_angle(P, hull, nh), &w, &h);
        fill[c] = w * h > 0.0 ? area[c] / (w * h) : 1.0;
    }
    ok = 1;
out:
    free(area);
    free(start);
    free(verts);
    free(P);
    free(hull);
    return ok;
}

/* Two-way segmentation of chart c (faces with label c) in its own vt
 * index space; faces of the second part get label `fresh`. Returns 1
 * when it split, 0 when it did not, -1 when out of memory. */
static int split_chart(const mesh *m, int *label, int c, int fresh, scaf_error *err)
{
    int nf = 0;
    for (int f = 0; f < m->nf; f++) nf += label[f] == c;
    if (nf < 2 * MIN_SPLIT_FACES) return 0;
    int *map = malloc(sizeof(int) * (size_t)m->nuv);
    int *F = malloc(sizeof(int) * 3 * (size_t)nf);
    int *faces = malloc(sizeof(int) * (size_t)nf);
    int *part = malloc(sizeof(int) * (size_t)nf);
    double *V = malloc(sizeof(double) * 3 * 3 * (size_t)nf);
    int rc = -1;
    if (!map || !F || !faces || !part || !V) goto out;
    for (int i = 0; i < m->nuv; i++) map[i] = -1;
    int nv = 0, k = 0;
    for (int f = 0; f < m->nf; f++) {
        if (label[f] != c) continue;
        faces[k] = f;
        for (int j = 0; j < 3; j++) {
            int t = m->FT[3 * f + j];
            if (map[t] < 0) {
                map[t] = nv;
                memcpy(V + 3 * nv, m->V + 3 * m->F[3 * f + j], sizeof(double) * 3);
                nv++;
            }
            F[3 * k + j] = map[t];
        }
        k++;
    }
    chart_segment_options o;
    chart_segment_defaults(&o);
    o.target_charts = 2;
    int n = 0;
    if (chart_segment(nv, V, nf, F, &o, part, &n, err) != SCAF_OK) goto out;
    rc = 0;
    if (n < 2) goto out;
    /* parts beyond two (a part cut in pieces) join the second */
    for (int i = 0; i < nf; i++)
        if (part[i] != part[0]) label[faces[i]] = fresh;
    rc = 1;
out:
    free(map);
    free(F);
    free(faces);
    free(part);
    free(V);
    return rc;
}

/* ---- slits: a cut from a chart's boundary to its worst cone ---- */

/* Per vt index: the area-weighted excess sum A_f (E_f - 4) of its faces. */
static void vertex_excess(const mesh *m, const double *fe, const double *farea, double *ex)
{
    for (int t = 0; t < m->nuv; t++) ex[t] = 0.0;
    for (int f = 0; f < m->nf; f++) {
        double x = farea[f] * (fe[f] - 4.0);
        if (!(x > 0)) continue;
        for (int k = 0; k < 3; k++) ex[m->FT[3 * f + k]] += x;
    }
}

typedef struct vt_graph {
    int *twin;               /* 3 nf: half-edge across the same vt edge, or -1 */
    int *first;              /* nuv + 1: half-edges leaving t, CSR */
    int *out;                /* 3 nf */
    unsigned char *boundary; /* nuv: t on a chart boundary */
} vt_graph;

static void vt_graph_free(vt_graph *g)
{
    free(g->twin);
    free(g->first);
    free(g->out);
    free(g->boundary);
}

static int vt_graph_build(const mesh *m, vt_graph *g, scaf_error *err)
{
    int nf = m->nf, nuv = m->nuv;
    g->twin = malloc(sizeof(int) * 3 * (size_t)nf);
    g->first = calloc((size_t)nuv + 1, sizeof(int));
    g->out = malloc(sizeof(int) * 3 * (size_t)nf);
    g->boundary = calloc((size_t)nuv, 1);
    int *order = malloc(sizeof(int) * 3 * (size_t)nf);
    int ok = g->twin && g->first && g->out && g->boundary && order;
    int count = 0;
    if (ok && half_edges_sort(nuv, nf, m->FT, NULL, order, &count, err) != SCAF_OK) ok = 0;
    if (!ok) {
        free(order);
        vt_graph_free(g);
        return 0;
    }
    for (int h = 0; h < 3 * nf; h++) g->twin[h] = -1;
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(m->FT, order[i], order[j])) j++;
        /* two sides in opposite directions: an inside edge */
        if (j - i == 2 && m->FT[order[i]] == m->FT[half_edge_next(order[i + 1])]) {
            g->twin[order[i]] = order[i + 1];
            g->twin[order[i + 1]] = order[i];
        }
        i = j;
    }
    free(order);
    for (int h = 0; h < 3 * nf; h++) {
        g->first[m->FT[h] + 1]++;
        if (g->twin[h] < 0) g->boundary[m->FT[h]] = g->boundary[m->FT[half_edge_next(h)]] = 1;
    }
    for (int t = 0; t < nuv; t++) g->first[t + 1] += g->first[t];
    int *pos = malloc(sizeof(int) * (size_t)(nuv > 0 ? nuv : 1));
    if (!pos) {
        vt_graph_free(g);
        return 0;
    }
    for (int t = 0; t < nuv; t++) pos[t] = g->first[t];
    for (int h = 0; h < 3 * nf; h++) g->out[pos[m->FT[h]]++] = h;
    free(pos);
    return 1;
}

static double corner_length(const mesh *m, int h)
{
    const double *a = m->V + 3 * m->F[h], *b = m->V + 3 * m->F[half_edge_next(h)];
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Cut chart c open from its boundary to its vertex of largest excess
 * along the shortest inside path (Dijkstra over vt edges). New vt
 * indices are appended to the lists *newFT (a copy of FT, updated) and
 * the count *nuv. Returns 1 when it cut, 0 when there was nothing to cut
 * (no interior vertex with excess), -1 when out of memory. */
static int slit_chart(const mesh *m, const vt_graph *g, const int *label, int c, const double *ex,
                      int *FT, int *nuv, int **src)
{
    int cone = -1;
    for (int f = 0; f < m->nf; f++) {
        if (label[f] != c) continue;
        for (int k = 0; k < 3; k++) {
            int t = m->FT[3 * f + k];
            if (!g->boundary[t] && ex[t] > 0 &&
                (cone < 0 || ex[t] > ex[cone] || (ex[t] == ex[cone] && t < cone)))
                cone = t;
        }
    }
    if (cone < 0) return 0;
    int nt = m->nuv;
    double *dist = malloc(sizeof(double) * (size_t)nt);
    int *prev = malloc(sizeof(int) * (size_t)nt); /* half-edge into t on the path */
    unsigned char *done = calloc((size_t)nt, 1);
    if (!dist || !prev || !done) {
        free(dist);
        free(prev);
        free(done);
        return -1;
    }
    for (int t = 0; t < nt; t++) {
        dist[t] = HUGE_VAL;
        prev[t] = -1;
    }
    /* Dijkstra with a linear scan of the front: the front is the rim of a
     * disk around the cone, stopped at the first boundary vertex */
    int *front = malloc(sizeof(int) * (size_t)nt), nfront = 0;
    if (!front) {
        free(dist);
        free(prev);
        free(done);
        return -1;
    }
    dist[cone] = 0.0;
    front[nfront++] = cone;
    int end = -1;
    while (nfront > 0) {
        int bi = 0;
        for (int i = 1; i < nfront; i++)
            if (dist[front[i]] < dist[front[bi]] ||
                (dist[front[i]] == dist[front[bi]] && front[i] < front[bi]))
                bi = i;
        int t = front[bi];
        front[bi] = front[--nfront];
        if (done[t]) continue;
        done[t] = 1;
        if (g->boundary[t]) {
            end = t;
            break;
        }
        for (int i = g->first[t]; i < g->first[t + 1]; i++) {
            int h = g->out[i], u = m->FT[half_edge_next(h)];
            double nd = dist[t] + corner_length(m, h);
            if (!done[u] && nd < dist[u]) {
                if (dist[u] == HUGE_VAL) front[nfront++] = u;
                dist[u] = nd;
                prev[u] = h;
            }
        }
    }
    free(front);
    free(done);
    free(dist);
    if (end < 0) {
        free(prev);
        return 0;
    }
    /* the path w0 = end (on the boundary), w1, ..., wk = cone: prev[w] is
     * the half-edge from the path's next vertex into w */
    int k = 0;
    for (int w = end; w != cone; w = m->FT[prev[w]]) k++;
    int *path = malloc(sizeof(int) * (size_t)(k + 1));
    if (!path) {
        free(prev);
        return -1;
    }
    k = 0;
    for (int w = end;; w = m->FT[prev[w]]) {
        path[k++] = w;
        if (w == cone) break;
    }
    int rc = 1;
    /* every path vertex but the cone gets a new vt on one side of the
     * path: the faces from the one holding w -> next (the path's left
     * side), turning about w, up to the previous path edge (or the
     * boundary at w0). Consecutive vertices agree: the face holding
     * w_i -> w_i+1 is the first of w_i and the last of w_i+1. */
    for (int i = 0; i + 1 < k; i++) {
        int w = path[i], before = i > 0 ? path[i - 1] : -1;
        int id = (*nuv)++;
        int *grown = realloc(*src, sizeof(int) * (size_t)*nuv);
        if (!grown) {
            rc = -1;
            break;
        }
        *src = grown;
        (*src)[id] = w;
        int h = g->twin[prev[w]];
        for (int guard = 0; h >= 0 && guard < 3 * m->nf; guard++) {
            FT[h] = id;
            int hp = h - h % 3 + (h % 3 + 2) % 3; /* the side into w */
            if (m->FT[hp] == before) break;
            h = g->twin[hp];
        }
    }
    free(path);
    free(prev);
    return rc;
}

/* m's vt indices and UVs become FT (3 nf) and UV (n): both owned by m
 * from now on, the old ones freed. */
static void mesh_take_uvs(mesh *m, int *FT, double *UV, int n)
{
    free(m->FT);
    free(m->UV);
    m->FT = FT;
    m->UV = UV;
    m->nuv = n;
}

/* m's vt indices and UVs become the settled atlas's working vertices and
 * layout (pinch points split, as the atlas splits them): the start of the
 * next round and of the final atlas. */
static int take_layout(mesh *m, const atlas *a)
{
    int *FT = malloc(sizeof(int) * 3 * (size_t)a->nf);
    double *UV = malloc(sizeof(double) * 2 * (size_t)(a->nw > 0 ? a->nw : 1));
    if (!FT || !UV) {
        free(FT);
        free(UV);
        return 0;
    }
    memcpy(FT, a->Fw, sizeof(int) * 3 * (size_t)a->nf);
    memcpy(UV, a->loop.uv, sizeof(double) * 2 * (size_t)a->nw);
    mesh_take_uvs(m, FT, UV, a->nw);
    return 1;
}

/* New vt indices: one per (old vt, label) pair; UVs copied, so both sides
 * of a new seam keep their place in the layout. */
static int relabel_uvs(mesh *m, const int *label)
{
    int *first = malloc(sizeof(int) * (size_t)m->nuv);
    int *next = malloc(sizeof(int) * 3 * (size_t)m->nf);
    int *key_label = malloc(sizeof(int) * 3 * (size_t)m->nf);
    int *key_vt = malloc(sizeof(int) * 3 * (size_t)m->nf);
    int *FT = malloc(sizeof(int) * 3 * (size_t)m->nf);
    double *UV = NULL;
    int ok = 0;
    if (!first || !next || !key_label || !key_vt || !FT) goto out;
    for (int t = 0; t < m->nuv; t++) first[t] = -1;
    int n = 0;
    for (int h = 0; h < 3 * m->nf; h++) {
        int t = m->FT[h], l = label[h / 3], id = first[t];
        while (id >= 0 && key_label[id] != l) id = next[id];
        if (id < 0) {
            id = n++;
            key_label[id] = l;
            key_vt[id] = t;
            next[id] = first[t];
            first[t] = id;
        }
        FT[h] = id;
    }
    UV = malloc(sizeof(double) * 2 * (size_t)(n > 0 ? n : 1));
    if (!UV) goto out;
    for (int i = 0; i < n; i++) {
        UV[2 * i] = m->UV[2 * key_vt[i]];
        UV[2 * i + 1] = m->UV[2 * key_vt[i] + 1];
    }
    mesh_take_uvs(m, FT, UV, n);
    FT = NULL;
    UV = NULL;
    ok = 1;
out:
    free(first);
    free(next);
    free(key_label);
    free(key_vt);
    free(FT);
    free(UV);
    return ok;
}

/* ---- merges: two neighbours whose union settles within the bound ---- */

/* A joined chart must settle below this (and its parts' mean E must
 * predict so): a quarter of the bound's room above an isometry is left
 * for the compaction, which raises E by up to 5% after settling. */
#define MERGE_LIMIT(bound) (4.0 + 0.75 * ((bound)-4.0))
/* Pairs tried: their area-weighted mean E below this (a union settles
 * above its parts' mean: the common seam no longer relieves it). */
#define MERGE_PREDICT(bound) (4.0 + 0.5 * ((bound)-4.0))

static int uf_find(int *parent, int x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

typedef struct merge_pair {
    int a, b;       /* charts, a < b */
    double shared;  /* 3D length of their common seam */
    double predict; /* area-weighted mean of their E */
} merge_pair;

static int merge_pair_cmp(const void *p, const void *q)
{
    const merge_pair *x = p, *y = q;
    if (x->predict != y->predict) return x->predict < y->predict ? -1 : 1;
    if (x->shared != y->shared) return x->shared > y->shared ? -1 : 1;
    if (x->a != y->a) return x->a - y->a;
    return x->b - y->b;
}

/* Join the chart pairs chosen in partner[] (partner[c]: the chart c joins,
 * or -1): the vt on both sides of their common seam become one, labels of
 * b become a's, and the joined charts' UVs NaN (their two shapes do not
 * fit together: they start from Tutte). A pair whose union is not a disk
 * (they meet along more than one stretch) is not joined: partner reset.
 * Returns 1, or 0 out of memory. */
static int join_pairs(mesh *m, int *label, int *partner, scaf_error *err)
{
    int nf = m->nf, ok = 0, undo = 0;
    int *order = malloc(sizeof(int) * 3 * (size_t)nf), count = 0;
    int *parent = malloc(sizeof(int) * (size_t)(m->nuv > 0 ? m->nuv : 1));
    int *newid = malloc(sizeof(int) * (size_t)(m->nuv > 0 ? m->nuv : 1));
    int *FT = malloc(sizeof(int) * 3 * (size_t)nf);
    int *trial = malloc(sizeof(int) * (size_t)(nf > 0 ? nf : 1));
    double *UV = NULL;
    mesh_charts ch;
    memset(&ch, 0, sizeof ch);
    if (!order || !parent || !newid || !FT || !trial) goto out;
    if (half_edges_sort(m->nv, nf, m->F, NULL, order, &count, err) != SCAF_OK) goto out;
    for (int t = 0; t < m->nuv; t++) parent[t] = t;
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(m->F, order[i], order[j])) j++;
        if (j - i == 2) {
            int g = order[i], h = order[i + 1], la = label[g / 3], lb = label[h / 3];
            if (la != lb && partner[la] == lb) {
                /* g: u -> v in one face, h: v -> u in the other */
                int gu = g, gv = half_edge_next(g), hv = h, hu = half_edge_next(h);
                int x = uf_find(parent, m->FT[gu]), y = uf_find(parent, m->FT[hu]);
                if (x != y) parent[x < y ? y : x] = x < y ? x : y;
                x = uf_find(parent, m->FT[gv]);
                y = uf_find(parent, m->FT[hv]);
                if (x != y) parent[x < y ? y : x] = x < y ? x : y;
            }
        }
        i = j;
    }
    int n = 0;
    for (int t = 0; t < m->nuv; t++) newid[t] = -1;
    for (int t = 0; t < m->nuv; t++) {
        int r = uf_find(parent, t);
        if (newid[r] < 0) newid[r] = n++;
        newid[t] = newid[r];
    }
    for (int h = 0; h < 3 * nf; h++) FT[h] = newid[m->FT[h]];
    for (int f = 0; f < nf; f++) {
        int l = label[f];
        trial[f] = partner[l] >= 0 && partner[l] < l ? partner[l] : l;
    }
    /* every joined chart must be a disk: else leave the pair apart */
    mesh tm = *m;
    tm.FT = FT;
    tm.nuv = n;
    if (mesh_charts_compute(&tm, &ch, err) != SCAF_OK) goto out;
    for (int f = 0; f < nf; f++) {
        int l = label[f];
        if (partner[l] < 0 || partner[l] < l) continue;
        int c = ch.cx.face_group[f];
        if (mesh_chart_classify(&ch, c) != MESH_CHART_DISK) {
            partner[partner[l]] = -1;
            partner[l] = -1;
            undo = 1;
        }
    }
    if (undo) goto out; /* again with the pairs left */
    UV = malloc(sizeof(double) * 2 * (size_t)(n > 0 ? n : 1));
    if (!UV) goto out;
    for (int t = 0; t < m->nuv; t++) {
        UV[2 * newid[t]] = m->UV[2 * t];
        UV[2 * newid[t] + 1] = m->UV[2 * t + 1];
    }
    for (int h = 0; h < 3 * nf; h++)
        if (partner[label[h / 3]] >= 0) UV[2 * FT[h]] = UV[2 * FT[h] + 1] = NAN;
    memcpy(label, trial, sizeof(int) * (size_t)nf);
    mesh_take_uvs(m, FT, UV, n);
    FT = NULL;
    UV = NULL;
    ok = 1;
out:
    mesh_charts_free(&ch);
    free(order);
    free(parent);
    free(newid);
    free(FT);
    free(trial);
    free(UV);
    if (undo) return join_pairs(m, label, partner, err);
    return ok;
}

/* The pairs to try: neighbours (a common seam) both within the bound
 * whose area-weighted mean E is below 4 + 3/4 (bound - 4), lowest first,
 * each chart in one pair at most: partner[] (nc, -1: none). Returns the
 * number of pairs, -1 out of memory. */
static int choose_pairs(const mesh *m, const int *label, int nc, const double *E,
                        const double *farea, double bound, int *partner, scaf_error *err)
{
    int nf = m->nf, np = 0, cap = 0, count = 0;
    int *order = malloc(sizeof(int) * 3 * (size_t)nf);
    double *area = calloc((size_t)(nc > 0 ? nc : 1), sizeof(double));
    merge_pair *pairs = NULL;
    if (!order || !area || half_edges_sort(m->nv, nf, m->F, NULL, order, &count, err) != SCAF_OK) {
        free(order);
        free(area);
        return -1;
    }
    for (int f = 0; f < nf; f++) area[label[f]] += farea[f];
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(m->F, order[i], order[j])) j++;
        if (j - i == 2) {
            int a = label[order[i] / 3], b = label[order[i + 1] / 3];
            if (a > b) {
                int t = a;
                a = b;
                b = t;
            }
            if (a != b && E[a] <= bound && E[b] <= bound) {
                int k = 0;
                while (k < np && (pairs[k].a != a || pairs[k].b != b)) k++;
                if (k == np) {
                    if (np == cap) {
                        cap = cap ? 2 * cap : 64;
                        merge_pair *g = realloc(pairs, sizeof *pairs * (size_t)cap);
                        if (!g) {
                            free(pairs);
                            free(order);
                            free(area);
                            return -1;
                        }
                        pairs = g;
                    }
                    double w = area[a] + area[b];
                    pairs[np++] = (merge_pair){
                        a, b, 0.0, w > 0 ? (area[a] * E[a] + area[b] * E[b]) / w : E[a]};
                }
                const double *p = m->V + 3 * (size_t)m->F[order[i]],
                             *q = m->V + 3 * (size_t)m->F[half_edge_next(order[i])];
                pairs[k].shared +=
                    sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                         (p[2] - q[2]) * (p[2] - q[2]));
            }
        }
        i = j;
    }
    free(order);
    free(area);
    if (np > 0) qsort(pairs, (size_t)np, sizeof *pairs, merge_pair_cmp);
    for (int c = 0; c < nc; c++) partner[c] = -1;
    int chosen = 0;
    double limit = MERGE_PREDICT(bound);
    for (int k = 0; k < np; k++) {
        const merge_pair *q = pairs + k;
        if (q->predict > limit || partner[q->a] >= 0 || partner[q->b] >= 0) continue;
        partner[q->a] = q->b;
        partner[q->b] = q->a;
        chosen++;
    }
    free(pairs);
    return chosen;
}

/* What one round measured of its settled atlas: per chart E and fill, the
 * split candidates, per face E and area, per vt the excess. */
typedef struct round_measure {
    double *E, *fill;      /* nc */
    split_candidate *cand; /* nc */
    double *fe, *farea;    /* nf */
    double *ex;            /* nuv */
} round_measure;

static void round_measure_free(round_measure *r)
{
    free(r->E);
    free(r->fill);
    free(r->cand);
    free(r->fe);
    free(r->farea);
    free(r->ex);
    memset(r, 0, sizeof *r);
}

scaf_status atlas_charts_refine(mesh *m, const atlas_options *base, const atlas_charts_options *o,
                                atlas_charts_info *info, scaf_error *err)
{
    atlas_charts_info local;
    if (!info) info = &local;
    memset(info, 0, sizeof *info);
    if (!m || !base || !o || !mesh_has_uv(m))
        return err_set(err, SCAF_ERR_USAGE,
                       "atlas_charts_refine: the mesh needs UV seams (vt) that cut it into charts");
    int *label = malloc(sizeof(int) * (size_t)(m->nf > 0 ? m->nf : 1));
    if (!label) return err_nomem(err, "chart refinement");
    int n = 0;
    scaf_status st = mesh_uv_chart_labels(m, label, &n, err);
    if (st != SCAF_OK) {
        free(label);
        return st;
    }
    info->charts_before = info->charts_after = n;
    atlas_options opt = *base;
    opt.compact_iterations = 0;
    opt.repack = 0;
    opt.rotate = 0;
    opt.padding = 0.0;
    opt.init_input = 0;
    if (opt.settle_iterations > ROUND_ITERATIONS) opt.settle_iterations = ROUND_ITERATIONS;
    if (opt.settle_tolerance < ROUND_TOLERANCE) opt.settle_tolerance = ROUND_TOLERANCE;
    int warm = 0; /* m's UVs are the last round's layout, its new seams opened */
    /* merges after the splitting rounds: one round tries them, the next
     * keeps those that settled within the bounds */
    int merging = 0, nmerged = 0;
    int *pre = NULL, *rep = NULL;
    double *fill_parts = NULL; /* per trial pair: its parts' area-weighted fill */
    for (int round = 0; round < o->max_rounds + (o->merge ? 2 : 0); round++) {
        atlas a;
        opt.init_warm = warm;
        st = atlas_init(&a, m, &opt, err);
        if (st != SCAF_OK) break;
        st = atlas_run(&a, NULL, NULL, err);
        if (st != SCAF_OK) {
            atlas_free(&a);
            break;
        }
        info->rounds++;
        info->warm_charts = a.warm_charts;
        int nc = a.ncharts;
        round_measure rm;
        rm.E = malloc(sizeof(double) * (size_t)nc);
        rm.fill = malloc(sizeof(double) * (size_t)nc);
        rm.cand = malloc(sizeof *rm.cand * (size_t)nc);
        rm.fe = malloc(sizeof(double) * (size_t)m->nf);
        rm.farea = calloc((size_t)m->nf, sizeof(double));
        rm.ex = malloc(sizeof(double) * (size_t)m->nuv);
        double *E = rm.E, *fill = rm.fill, *fe = rm.fe, *farea = rm.farea, *ex = rm.ex;
        split_candidate *cand = rm.cand;
        double *UV = malloc(sizeof(double) * 2 * (size_t)(a.nw > 0 ? a.nw : 1));
        int ok = E && fill && cand && fe && farea && ex && UV;
        if (ok) {
            atlas_chart_energy(&a, E);
            atlas_normalized_uv(&a, UV);
            ok = chart_fill(&a, UV, fill);
        }
        if (ok) {
            scaf_loop_face_energy(&a.loop, fe);
            for (int i = 0; i < a.nf; i++) farea[a.loop.chart_face[i]] = a.loop.chart.weight[i];
            vertex_excess(m, fe, farea, ex);
        }
        /* the atlas's charts are the mesh's UV charts (pinched vt split
         * apart keep their faces): label faces by them */
        for (int f = 0; f < m->nf; f++) label[f] = a.chart[f];
        if (ok) ok = take_layout(m, &a);
        atlas_free(&a);
        free(UV);
        if (!ok) {
            round_measure_free(&rm);
            st = err_nomem(err, "chart refinement");
            break;
        }
        if (merging) {
            /* the trial settled: a joined chart above a bound parts again
             * along its old seam (both parts keep the joined shape) */
            int undone = 0;
            for (int k = 0; k < nmerged; k++) {
                int c = label[rep[2 * k]];
                if (!(E[c] > MERGE_LIMIT(o->max_distortion)) &&
                    !(o->min_fill > 0 && fill[c] < o->min_fill) && !(fill[c] < fill_parts[k])) {
                    info->merges++;
                    continue;
                }
                for (int f = 0; f < m->nf; f++)
                    if (label[f] == c && pre[f] == pre[rep[2 * k + 1]]) label[f] = nc + undone;
                undone++;
            }
            info->charts_after = nc + undone;
            if (undone > 0 && !relabel_uvs(m, label)) st = err_nomem(err, "chart refinement");
            round_measure_free(&rm);
            break;
        }
        /* every chart above the distortion bound; of those below the fill
         * bound only the emptiest, one a round, since its halves change
         * the ranking */
        int ncand = 0, emptiest = -1;
        for (int c = 0; c < nc; c++) {
            if (o->max_distortion > 0 && E[c] > o->max_distortion)
                cand[ncand++] = (split_candidate){c, 0, 1.0 + (E[c] - o->max_distortion)};
            else if (o->min_fill > 0 && fill[c] < o->min_fill &&
                     (emptiest < 0 || fill[c] < fill[emptiest]))
                emptiest = c;
        }
        if (emptiest >= 0)
            cand[ncand++] = (split_candidate){emptiest, 1, o->min_fill - fill[emptiest]};
        qsort(cand, (size_t)ncand, sizeof *cand, candidate_cmp);
        if (o->max_splits > 0 && ncand > o->max_splits) ncand = o->max_splits;
        if (round >= o->max_rounds) ncand = 0; /* the rounds for splits are spent */
        if (ncand == 0) {
            /* nothing to split: try merges once, or stop */
            int *partner = o->merge ? malloc(sizeof(int) * (size_t)nc) : NULL;
            int np =
                partner ? choose_pairs(m, label, nc, E, farea, o->max_distortion, partner, err) : 0;
            if (o->merge && (!partner || np < 0)) st = err_nomem(err, "chart refinement");
            if (np > 0) {
                pre = malloc(sizeof(int) * (size_t)m->nf);
                rep = malloc(sizeof(int) * 2 * (size_t)np);
                fill_parts = malloc(sizeof(double) * (size_t)np);
                if (!pre || !rep || !fill_parts) st = err_nomem(err, "chart refinement");
                else {
                    memcpy(pre, label, sizeof(int) * (size_t)m->nf);
                    if (!join_pairs(m, label, partner, err))
                        st = err_nomem(err, "chart refinement");
                }
                /* a face of each joined chart and of its second part */
                nmerged = 0;
                for (int c = 0; c < nc && st == SCAF_OK; c++) {
                    if (partner[c] < 0 || partner[c] < c) continue;
                    int fa = -1, fb = -1;
                    for (int f = 0; f < m->nf && (fa < 0 || fb < 0); f++) {
                        if (pre[f] == c && fa < 0) fa = f;
                        if (pre[f] == partner[c] && fb < 0) fb = f;
                    }
                    double wa = 0.0, wb = 0.0;
                    for (int f = 0; f < m->nf; f++) {
                        if (pre[f] == c) wa += farea[f];
                        if (pre[f] == partner[c]) wb += farea[f];
                    }
                    fill_parts[nmerged] =
                        wa + wb > 0.0 ? (wa * fill[c] + wb * fill[partner[c]]) / (wa + wb) : 0.0;
                    rep[2 * nmerged] = fa;
                    rep[2 * nmerged + 1] = fb;
                    nmerged++;
                }
                if (st == SCAF_OK && nmerged > 0) {
                    if (!relabel_uvs(m, label)) st = err_nomem(err, "chart refinement");
                    merging = 1;
                    warm = 1;
                }
            }
            free(partner);
            round_measure_free(&rm);
            if (st != SCAF_OK || !merging) break;
            continue;
        }
        /* with slit_cones a distorted chart is cut open from its boundary
         * to its worst interior vertex; otherwise (and when it has no
         * interior vertex with excess) it is split in two */
        int slits = 0;
        if (o->slit_cones) {
            vt_graph g;
            memset(&g, 0, sizeof g);
            int *FT = malloc(sizeof(int) * 3 * (size_t)m->nf), *src = NULL, nuv = m->nuv;
            if (!FT || !vt_graph_build(m, &g, err)) {
                free(FT);
                round_measure_free(&rm);
                st = err_nomem(err, "chart refinement");
                break;
            }
            memcpy(FT, m->FT, sizeof(int) * 3 * (size_t)m->nf);
            for (int i = 0; i < ncand && st == SCAF_OK; i++) {
                int c = cand[i].chart;
                if (cand[i].reason != 0) continue;
                int r = slit_chart(m, &g, label, c, ex, FT, &nuv, &src);
                if (r < 0) st = err_nomem(err, "chart refinement");
                if (r != 1) continue;
                cand[i].reason = 2; /* done */
                slits++;
            }
            if (st == SCAF_OK && slits > 0) {
                double *UVn = realloc(m->UV, sizeof(double) * 2 * (size_t)nuv);
                if (!UVn) st = err_nomem(err, "chart refinement");
                else {
                    m->UV = UVn;
                    for (int t = m->nuv; t < nuv; t++) {
                        m->UV[2 * t] = m->UV[2 * src[t]];
                        m->UV[2 * t + 1] = m->UV[2 * src[t] + 1];
                    }
                    memcpy(m->FT, FT, sizeof(int) * 3 * (size_t)m->nf);
                    m->nuv = nuv;
                    info->distortion_slits += slits;
                }
            }
            free(FT);
            free(src);
            vt_graph_free(&g);
        }
        int split = 0;
        for (int i = 0; i < ncand && st == SCAF_OK; i++) {
            if (cand[i].reason == 2) continue;
            int r = split_chart(m, label, cand[i].chart, nc + split, err);
            if (r < 0) {
                st = err_nomem(err, "chart refinement");
                break;
            }
            if (r == 0) continue;
            split++;
            if (cand[i].reason == 0) info->distortion_splits++;
            else info->fill_splits++;
        }
        round_measure_free(&rm);
        if (st != SCAF_OK || split + slits == 0) break;
        /* a slit leaves its two sides at one place: that chart cannot
         * start from its layout, and the others need not */
        warm = slits == 0;
        if (split > 0 && !relabel_uvs(m, label)) {
            st = err_nomem(err, "chart refinement");
            break;
        }
        info->charts_after = nc + split;
    }
    free(label);
    free(pre);
    free(rep);
    free(fill_parts);
    return st;
}

scaf_status atlas_charts_apply(mesh *planned, const atlas_options *opt, seam_plan *plan,
                               scaf_error *err)
{
    int automatic = plan->used != SCAF_SEAMS_INPUT;
    atlas_charts_options o = atlas_charts_options_default();
    o.max_distortion = opt->max_distortion < 0.0 ? (automatic ? ATLAS_CHARTS_MAX_DISTORTION : 0.0)
                                                 : opt->max_distortion;
    int split = opt->split_charts < 0 ? automatic : opt->split_charts;
    o.min_fill = split ? ATLAS_CHARTS_MIN_FILL : 0.0;
    o.merge = automatic && o.max_distortion > 0.0; /* never join the input's charts */
    if ((o.max_distortion <= 0.0 && o.min_fill <= 0.0) || opt->init_input || !mesh_has_uv(planned))
        return SCAF_OK;
    mesh work = *planned;
    work.FT = malloc(sizeof(int) * 3 * (size_t)planned->nf);
    work.UV = malloc(sizeof(double) * 2 * (size_t)(planned->nuv > 0 ? planned->nuv : 1));
    if (!work.FT || !work.UV) {
        free(work.FT);
        free(work.UV);
        return err_nomem(err, "chart refinement");
    }
    memcpy(work.FT, planned->FT, sizeof(int) * 3 * (size_t)planned->nf);
    memcpy(work.UV, planned->UV, sizeof(double) * 2 * (size_t)planned->nuv);
    /* the measuring runs take these seams as they are and split nothing */
    atlas_options inner = *opt;
    inner.base.seams = SCAF_SEAMS_INPUT;
    inner.max_distortion = 0.0;
    inner.split_charts = 0;
    atlas_charts_info info;
    scaf_status st = atlas_charts_refine(&work, &inner, &o, &info, err);
    if (st != SCAF_OK || info.rounds == 0) {
        free(work.FT);
        free(work.UV);
        return st;
    }
    /* the charts and their last layout: the atlas starts from it */
    free(plan->FT);
    free(plan->UV);
    plan->FT = work.FT;
    plan->UV = work.UV;
    plan->nuv = work.nuv;
    plan->changed = 1;
    plan->uv_start = 1;
    planned->FT = work.FT;
    planned->UV = work.UV;
    planned->nuv = work.nuv;
    return SCAF_OK;
}
