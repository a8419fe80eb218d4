/* mesh/cut_graph: cut every chart into a disk (see the header). */
#include "mesh/cut_graph.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "base/min_heap.h"
#include "base/union_find.h"

static const double PI = 3.14159265358979323846;

void cut_graph_defaults(cut_graph_options *o)
{
    o->cones = 1;
    o->crease_factor = 2.0;
    o->max_cones = 16;
    o->min_cones = 4;
    o->cut_disks = 0;
}

void cut_graph_free(cut_graph *g)
{
    if (!g) return;
    free(g->FT);
    free(g->split_vertex);
    free(g->face_chart);
    memset(g, 0, sizeof *g);
}

/* ---- the working surface ------------------------------------------------- */

/* The surface being cut: vertices are the fans of corners (a vertex per
 * chart and fan), edges are the pairs of half-edges joined within a chart
 * plus the border half-edges. */
typedef struct surface {
    int nf;
    const int *F;
    const double *V;
    int *twin;      /* 3 nf: the half-edge on the other side within the chart, -1 on a border */
    int *cls;       /* 3 nf: surface vertex of each corner */
    int ns;         /* surface vertices */
    int *s_orig;    /* ns: input vertex */
    int ne;         /* surface edges */
    int *e_h;       /* ne: a half-edge of the edge (the smaller one of a pair) */
    int *e_t;       /* ne: its twin or -1 */
    double *e_w;    /* ne: weight */
    int *edge_of;   /* 3 nf: edge of each half-edge */
    int *adj_start; /* ns + 1 */
    int *adj_edge;  /* 2 ne: incident edges of each surface vertex */
    int npieces;
    int *piece;   /* nf: piece of each face */
    int *v_piece; /* ns */
} surface;

static void surface_free(surface *s)
{
    free(s->twin);
    free(s->cls);
    free(s->s_orig);
    free(s->e_h);
    free(s->e_t);
    free(s->e_w);
    free(s->edge_of);
    free(s->adj_start);
    free(s->adj_edge);
    free(s->piece);
    free(s->v_piece);
}

static int edge_other(const surface *s, int e, int v)
{
    int a = s->cls[s->e_h[e]], b = s->cls[half_edge_next(s->e_h[e])];
    return a == v ? b : a;
}

/* Corner classes: corners of one vertex linked across joined half-edges
 * whose edge is not cut (cut: NULL or per edge). Numbered by first corner. */
static scaf_status corner_classes(int nf, const int *F, const int *twin, const int *edge_of,
                                  const unsigned char *cut, int *cls, int *ncls, int **orig,
                                  scaf_error *err)
{
    int n3 = 3 * nf;
    int *parent = malloc(sizeof(int) * (size_t)n3);
    if (!parent) return err_nomem(err, "cut graph");
    uf_init(parent, n3);
    for (int h = 0; h < n3; h++) {
        int t = twin[h];
        if (t < h) continue; /* borders (-1) and each pair once */
        if (cut && cut[edge_of[h]]) continue;
        uf_union(parent, h, half_edge_next(t));
        uf_union(parent, half_edge_next(h), t);
    }
    int n = 0;
    for (int c = 0; c < n3; c++) cls[c] = -1;
    for (int c = 0; c < n3; c++) {
        int r = uf_find(parent, c);
        if (cls[r] < 0) cls[r] = n++;
        cls[c] = cls[r];
    }
    free(parent);
    *ncls = n;
    *orig = malloc(sizeof(int) * (size_t)(n ? n : 1));
    if (!*orig) return err_nomem(err, "cut graph");
    for (int c = 0; c < n3; c++) (*orig)[cls[c]] = F[c];
    return SCAF_OK;
}

static void sub3(const double *a, const double *b, double *r)
{
    for (int k = 0; k < 3; k++) r[k] = a[k] - b[k];
}
static void cross3(const double *u, const double *v, double *r)
{
    r[0] = u[1] * v[2] - u[2] * v[1];
    r[1] = u[2] * v[0] - u[0] * v[2];
    r[2] = u[0] * v[1] - u[1] * v[0];
}
static double dot3(const double *u, const double *v)
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
static double norm3(const double *u) { return sqrt(dot3(u, u)); }

static const double *vpos(const surface *s, int corner) { return s->V + 3 * (size_t)s->F[corner]; }

/* Weight of edge e: its length, less on a concave crease. */
static double edge_weight(const surface *s, int e, double crease)
{
    int h = s->e_h[e], t = s->e_t[e];
    double d[3];
    sub3(vpos(s, half_edge_next(h)), vpos(s, h), d);
    double len = norm3(d);
    if (t < 0 || crease <= 0.0) return len;
    /* normals of the two faces; concave when the far vertex of the other
     * face lies above this face's plane */
    int fh = h / 3, ft = t / 3;
    double u[3], v[3], n1[3], n2[3], w[3];
    sub3(s->V + 3 * (size_t)s->F[3 * fh + 1], s->V + 3 * (size_t)s->F[3 * fh], u);
    sub3(s->V + 3 * (size_t)s->F[3 * fh + 2], s->V + 3 * (size_t)s->F[3 * fh], v);
    cross3(u, v, n1);
    sub3(s->V + 3 * (size_t)s->F[3 * ft + 1], s->V + 3 * (size_t)s->F[3 * ft], u);
    sub3(s->V + 3 * (size_t)s->F[3 * ft + 2], s->V + 3 * (size_t)s->F[3 * ft], v);
    cross3(u, v, n2);
    double l1 = norm3(n1), l2 = norm3(n2);
    if (!(l1 > 0.0) || !(l2 > 0.0)) return len;
    double c = dot3(n1, n2) / (l1 * l2);
    if (c > 1.0) c = 1.0;
    if (c < -1.0) c = -1.0;
    int far = half_edge_next(half_edge_next(t));
    sub3(vpos(s, far), vpos(s, h), w);
    if (dot3(n1, w) <= 0.0) return len; /* convex or flat */
    return len / (1.0 + crease * (1.0 - c));
}

/* Pair the half-edges of F: twin across each 2-face edge whose faces have
 * the same label, -1 otherwise. Errors name the edge. */
static scaf_status pair_half_edges(int nv, int nf, const int *F, const int *label, int *twin,
                                   scaf_error *err)
{
    int n3 = 3 * nf;
    int *order = malloc(sizeof(int) * (size_t)n3);
    if (!order) return err_nomem(err, "cut graph");
    int count = 0;
    scaf_status st = half_edges_sort(nv, nf, F, NULL, order, &count, err);
    if (st != SCAF_OK) {
        free(order);
        return st;
    }
    for (int h = 0; h < n3; h++) twin[h] = -1;
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(F, order[i], order[j])) j++;
        int a = half_edge_lo(F, order[i]), b = half_edge_hi(F, order[i]);
        if (a == b) {
            st = err_set(err, SCAF_ERR_MESH, "face %d uses vertex %d twice", order[i] / 3, a);
            break;
        }
        if (j - i > 2) {
            st = err_set(err, SCAF_ERR_MESH, "edge (%d, %d) is non-manifold: %d faces share it", a,
                         b, j - i);
            break;
        }
        if (j - i == 2) {
            int g = order[i], h = order[i + 1];
            if (F[g] == F[h]) {
                st = err_set(err, SCAF_ERR_MESH,
                             "edge (%d, %d): faces %d and %d disagree in orientation", a, b, g / 3,
                             h / 3);
                break;
            }
            if (!label || label[g / 3] == label[h / 3]) {
                twin[g] = h;
                twin[h] = g;
            }
        }
        i = j;
    }
    free(order);
    return st;
}

static scaf_status surface_build(int nv, const double *V, int nf, const int *F, const int *label,
                                 double crease, surface *s, scaf_error *err)
{
    memset(s, 0, sizeof *s);
    s->nf = nf;
    s->F = F;
    s->V = V;
    int n3 = 3 * nf;
    s->twin = malloc(sizeof(int) * (size_t)n3);
    s->cls = malloc(sizeof(int) * (size_t)n3);
    s->edge_of = malloc(sizeof(int) * (size_t)n3);
    s->piece = malloc(sizeof(int) * (size_t)nf);
    if (!s->twin || !s->cls || !s->edge_of || !s->piece) return err_nomem(err, "cut graph");
    scaf_status st = pair_half_edges(nv, nf, F, label, s->twin, err);
    if (st != SCAF_OK) return st;
    st = corner_classes(nf, F, s->twin, s->edge_of, NULL, s->cls, &s->ns, &s->s_orig, err);
    if (st != SCAF_OK) return st;
    /* edges */
    int ne = 0;
    for (int h = 0; h < n3; h++)
        if (s->twin[h] < 0 || h < s->twin[h]) ne++;
    s->ne = ne;
    s->e_h = malloc(sizeof(int) * (size_t)(ne ? ne : 1));
    s->e_t = malloc(sizeof(int) * (size_t)(ne ? ne : 1));
    s->e_w = malloc(sizeof(double) * (size_t)(ne ? ne : 1));
    s->adj_start = calloc((size_t)s->ns + 1, sizeof(int));
    s->adj_edge = malloc(sizeof(int) * 2 * (size_t)(ne ? ne : 1));
    s->v_piece = malloc(sizeof(int) * (size_t)(s->ns ? s->ns : 1));
    if (!s->e_h || !s->e_t || !s->e_w || !s->adj_start || !s->adj_edge || !s->v_piece)
        return err_nomem(err, "cut graph");
    ne = 0;
    for (int h = 0; h < n3; h++) {
        int t = s->twin[h];
        if (t >= 0 && t < h) {
            s->edge_of[h] = s->edge_of[t];
            continue;
        }
        s->e_h[ne] = h;
        s->e_t[ne] = t;
        s->edge_of[h] = ne;
        ne++;
    }
    for (int e = 0; e < ne; e++) s->e_w[e] = edge_weight(s, e, crease);
    for (int e = 0; e < ne; e++) {
        s->adj_start[s->cls[s->e_h[e]] + 1]++;
        s->adj_start[s->cls[half_edge_next(s->e_h[e])] + 1]++;
    }
    for (int v = 0; v < s->ns; v++) s->adj_start[v + 1] += s->adj_start[v];
    int *fill = malloc(sizeof(int) * (size_t)(s->ns ? s->ns : 1));
    int *parent = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    if (!fill || !parent) {
        free(fill);
        free(parent);
        return err_nomem(err, "cut graph");
    }
    memcpy(fill, s->adj_start, sizeof(int) * (size_t)s->ns);
    for (int e = 0; e < ne; e++) {
        s->adj_edge[fill[s->cls[s->e_h[e]]]++] = e;
        s->adj_edge[fill[s->cls[half_edge_next(s->e_h[e])]]++] = e;
    }
    /* pieces: faces joined across paired half-edges */
    uf_init(parent, nf);
    for (int h = 0; h < n3; h++)
        if (s->twin[h] > h) uf_union(parent, h / 3, s->twin[h] / 3);
    for (int f = 0; f < nf; f++) s->piece[f] = -1;
    int np = 0;
    for (int f = 0; f < nf; f++) {
        int r = uf_find(parent, f);
        if (s->piece[r] < 0) s->piece[r] = np++;
        s->piece[f] = s->piece[r];
    }
    s->npieces = np;
    for (int c = 0; c < n3; c++) s->v_piece[s->cls[c]] = s->piece[c / 3];
    free(fill);
    free(parent);
    return SCAF_OK;
}

/* ---- topology of pieces ---------------------------------------------------- */

scaf_status cut_graph_chart_topology(int nf, const int *FT, int *face_chart, int *ncharts, int *chi,
                                     int *loops, scaf_error *err)
{
    int n3 = 3 * nf, n = half_edges_index_count(nf, FT);
    int *twin = malloc(sizeof(int) * (size_t)(n3 ? n3 : 1));
    int *parent = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    int *vc = malloc(sizeof(int) * (size_t)(n ? n : 1));
    int *out = malloc(sizeof(int) * (size_t)(n ? n : 1));
    unsigned char *seen = calloc((size_t)(n3 ? n3 : 1), 1);
    scaf_status st = SCAF_OK;
    if (!twin || !parent || !vc || !out || !seen) {
        st = err_nomem(err, "chart topology");
        goto done;
    }
    st = pair_half_edges(n, nf, FT, NULL, twin, err);
    if (st != SCAF_OK) goto done;
    uf_init(parent, nf);
    for (int h = 0; h < n3; h++)
        if (twin[h] > h) uf_union(parent, h / 3, twin[h] / 3);
    int nc = 0;
    for (int f = 0; f < nf; f++) face_chart[f] = -1;
    for (int f = 0; f < nf; f++) {
        int r = uf_find(parent, f);
        if (face_chart[r] < 0) face_chart[r] = nc++;
        face_chart[f] = face_chart[r];
    }
    *ncharts = nc;
    for (int c = 0; c < nc; c++) chi[c] = loops[c] = 0;
    for (int i = 0; i < n; i++) vc[i] = -1, out[i] = -1;
    for (int h = 0; h < n3; h++) {
        int c = face_chart[h / 3];
        if (h % 3 == 0) chi[c]++; /* F */
        if (vc[FT[h]] < 0) {
            vc[FT[h]] = c;
            chi[c]++; /* V */
        } else if (vc[FT[h]] != c) {
            st = err_set(err, SCAF_ERR_MESH, "index %d is used by charts %d and %d", FT[h],
                         vc[FT[h]], c);
            goto done;
        }
        if (twin[h] < 0 || h < twin[h]) chi[c]--; /* E */
        if (twin[h] < 0) {
            if (out[FT[h]] >= 0) {
                st =
                    err_set(err, SCAF_ERR_MESH,
                            "index %d has two boundary fans (a chart touches itself there)", FT[h]);
                goto done;
            }
            out[FT[h]] = h;
        }
    }
    for (int h = 0; h < n3; h++) {
        if (twin[h] >= 0 || seen[h]) continue;
        loops[face_chart[h / 3]]++;
        for (int g = h; g >= 0 && !seen[g]; g = out[FT[half_edge_next(g)]]) seen[g] = 1;
    }
done:
    free(twin);
    free(parent);
    free(vc);
    free(out);
    free(seen);
    return st;
}

/* ---- the cut --------------------------------------------------------------- */

/* Scratch for the shortest paths of one piece. */
typedef struct paths {
    double *dist; /* ns */
    int *pred;    /* ns: edge it was reached by, -1 at a source */
    int *owner;   /* ns: source it was reached from */
    min_heap heap;
    /* ns, or NULL: the outgoing border half-edge of each border vertex.
     * When set, each boundary loop counts as one point: the first of its
     * vertices reached brings all the others at the same distance, along
     * the loop (so the tree holds all of a loop's border edges but one). */
    const int *border_out;
} paths;

/* The loop of border vertex v, reached first of its loop: every other
 * vertex of it joins the tree at v's distance by the border edge before
 * it. Returns 0 out of memory. */
static int paths_contract_loop(const surface *s, paths *P, int v)
{
    int h = P->border_out[v];
    for (int guard = 0; guard < s->ns; guard++) {
        int u = s->cls[half_edge_next(h)];
        if (u == v) break;
        P->dist[u] = P->dist[v];
        P->pred[u] = s->edge_of[h];
        P->owner[u] = P->owner[v];
        if (!min_heap_push(&P->heap, P->dist[u], u)) return 0;
        h = P->border_out[u];
    }
    return 1;
}

static int is_border_edge(const surface *s, int e) { return e >= 0 && s->e_t[e] < 0; }

/* Add source v (owner o) and relax: Dijkstra from all sources so far
 * (distances only decrease). */
static int paths_add(const surface *s, paths *P, int v, int o)
{
    P->dist[v] = 0.0;
    P->pred[v] = -1;
    P->owner[v] = o;
    if (!min_heap_push(&P->heap, 0.0, v)) return 0;
    while (P->heap.n > 0) {
        min_heap_item it = min_heap_pop(&P->heap);
        if (it.key > P->dist[it.id]) continue;
        /* the first vertex of its loop (a later one has a border edge as
         * its predecessor: the loop was brought in whole) */
        if (P->border_out && P->border_out[it.id] >= 0 && !is_border_edge(s, P->pred[it.id]) &&
            !paths_contract_loop(s, P, it.id))
            return 0;
        for (int k = s->adj_start[it.id]; k < s->adj_start[it.id + 1]; k++) {
            int e = s->adj_edge[k], u = edge_other(s, e, it.id);
            double nd = it.key + s->e_w[e];
            if (nd < P->dist[u]) {
                P->dist[u] = nd;
                P->pred[u] = e;
                P->owner[u] = P->owner[it.id];
                if (!min_heap_push(&P->heap, nd, u)) return 0;
            }
        }
    }
    return 1;
}

static void paths_reset(paths *P, const int *verts, int n)
{
    for (int i = 0; i < n; i++) {
        P->dist[verts[i]] = INFINITY;
        P->pred[verts[i]] = -1;
        P->owner[verts[i]] = -1;
    }
}

typedef struct keyed {
    double key;
    int id;
} keyed;

static int keyed_desc(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    if (x->key != y->key) return x->key > y->key ? -1 : 1;
    return (x->id > y->id) - (x->id < y->id);
}

/* Angle defect 2 pi - sum of corner angles at each surface vertex of the
 * piece (only meaningful at interior vertices: a closed piece). */
static void angle_defects(const surface *s, const int *faces, int nfaces, double *K)
{
    for (int i = 0; i < nfaces; i++)
        for (int j = 0; j < 3; j++) K[s->cls[3 * faces[i] + j]] = 2.0 * PI;
    for (int i = 0; i < nfaces; i++) {
        int f = faces[i];
        for (int j = 0; j < 3; j++) {
            double u[3], v[3];
            sub3(vpos(s, 3 * f + (j + 1) % 3), vpos(s, 3 * f + j), u);
            sub3(vpos(s, 3 * f + (j + 2) % 3), vpos(s, 3 * f + j), v);
            double c[3];
            cross3(u, v, c);
            K[s->cls[3 * f + j]] -= atan2(norm3(c), dot3(u, v));
        }
    }
}

/* Pieces: faces and vertices of each, CSR. */
typedef struct piece_lists {
    int *f_start, *faces, *v_start, *verts;
} piece_lists;

static void piece_lists_free(piece_lists *L)
{
    free(L->f_start);
    free(L->faces);
    free(L->v_start);
    free(L->verts);
}

static scaf_status piece_lists_build(const surface *s, piece_lists *L, scaf_error *err)
{
    int np = s->npieces;
    L->f_start = calloc((size_t)np + 1, sizeof(int));
    L->v_start = calloc((size_t)np + 1, sizeof(int));
    L->faces = malloc(sizeof(int) * (size_t)(s->nf ? s->nf : 1));
    L->verts = malloc(sizeof(int) * (size_t)(s->ns ? s->ns : 1));
    if (!L->f_start || !L->v_start || !L->faces || !L->verts) return err_nomem(err, "cut graph");
    for (int f = 0; f < s->nf; f++) L->f_start[s->piece[f] + 1]++;
    for (int v = 0; v < s->ns; v++) L->v_start[s->v_piece[v] + 1]++;
    for (int p = 0; p < np; p++) {
        L->f_start[p + 1] += L->f_start[p];
        L->v_start[p + 1] += L->v_start[p];
    }
    int *fill = malloc(sizeof(int) * (size_t)(np ? np : 1));
    if (!fill) return err_nomem(err, "cut graph");
    memcpy(fill, L->f_start, sizeof(int) * (size_t)np);
    for (int f = 0; f < s->nf; f++) L->faces[fill[s->piece[f]]++] = f;
    memcpy(fill, L->v_start, sizeof(int) * (size_t)np);
    for (int v = 0; v < s->ns; v++) L->verts[fill[s->v_piece[v]]++] = v;
    free(fill);
    return SCAF_OK;
}

/* State shared by the cuts of all pieces. */
typedef struct cutter {
    const surface *s;
    const cut_graph_options *o;
    paths P;
    unsigned char *mark;    /* ne: edge in the cut graph (border edges included) */
    unsigned char *in_tree; /* ne */
    int *deg;               /* ns */
    int *dual;              /* nf + loops: union-find of the dual */
    int *loop_of;           /* 3 nf: dual node of the hole of each border half-edge */
    int *border_out;        /* ns: outgoing border half-edge of a border vertex, or -1 */
    double *K;              /* ns */
    keyed *keys;            /* ne */
    int *queue;             /* ns */
    cut_graph *g;
} cutter;

/* Remove the dangling branches of the marked edges of a piece. */
static void prune(cutter *c, const int *verts, int nverts)
{
    const surface *s = c->s;
    int nq = 0;
    for (int i = 0; i < nverts; i++) c->deg[verts[i]] = 0;
    for (int i = 0; i < nverts; i++) {
        int v = verts[i];
        for (int k = s->adj_start[v]; k < s->adj_start[v + 1]; k++)
            if (c->mark[s->adj_edge[k]]) c->deg[v]++;
    }
    for (int i = 0; i < nverts; i++)
        if (c->deg[verts[i]] == 1) c->queue[nq++] = verts[i];
    while (nq > 0) {
        int v = c->queue[--nq];
        if (c->deg[v] != 1) continue;
        for (int k = s->adj_start[v]; k < s->adj_start[v + 1]; k++) {
            int e = s->adj_edge[k];
            if (!c->mark[e]) continue;
            c->mark[e] = 0;
            int u = edge_other(s, e, v);
            c->deg[v]--;
            c->deg[u]--;
            if (c->deg[u] == 1) c->queue[nq++] = u;
            break;
        }
    }
}

/* Cut the handles of a piece: mark the pruned union of its 2g greedy
 * loops. Returns the number of loops, or -1 out of memory. */
static int cut_handles(cutter *c, int p, const piece_lists *L)
{
    const surface *s = c->s;
    const int *verts = L->verts + L->v_start[p];
    int nverts = L->v_start[p + 1] - L->v_start[p];
    paths_reset(&c->P, verts, nverts);
    /* a shortest-path tree in which each boundary loop is one point: the
     * loops below may run along a hole for free, and each hole leaves
     * exactly one of its border edges out of the tree */
    c->P.border_out = c->border_out;
    int added = paths_add(s, &c->P, verts[0], 0);
    c->P.border_out = NULL;
    if (!added) return -1;
    /* the edges of the piece, tree edges flagged */
    int nk = 0;
    for (int i = 0; i < nverts; i++) {
        int v = verts[i];
        if (c->P.pred[v] >= 0) c->in_tree[c->P.pred[v]] = 1;
    }
    for (int i = L->f_start[p]; i < L->f_start[p + 1]; i++) {
        int f = L->faces[i];
        for (int j = 0; j < 3; j++) {
            int h = 3 * f + j, e = s->edge_of[h];
            if (s->e_h[e] != h || c->in_tree[e]) continue;
            int a = s->cls[h], b = s->cls[half_edge_next(h)];
            c->keys[nk].key = c->P.dist[a] + c->P.dist[b] + s->e_w[e];
            c->keys[nk].id = e;
            nk++;
        }
    }
    /* maximum spanning tree of the dual (Kruskal, longest loops first),
     * over the faces only: the border edge each hole leaves out of the
     * tree closes that hole's own loop, which is already a border. (Holes
     * were once dual nodes too: then two sides of a cut handle could be
     * held together by a hole alone, and the cut split the chart.) */
    qsort(c->keys, (size_t)nk, sizeof *c->keys, keyed_desc);
    int loops = 0;
    for (int i = 0; i < nk; i++) {
        int e = c->keys[i].id, h = s->e_h[e], t = s->e_t[e];
        if (t < 0) continue;
        if (uf_union(c->dual, h / 3, t / 3)) continue;
        /* a generator: its loop through the tree */
        loops++;
        c->mark[e] = 1;
        int ends[2] = {s->cls[h], s->cls[half_edge_next(h)]};
        for (int k = 0; k < 2; k++)
            for (int v = ends[k]; c->P.pred[v] >= 0; v = edge_other(s, c->P.pred[v], v))
                c->mark[c->P.pred[v]] = 1;
    }
    for (int i = 0; i < nverts; i++)
        if (c->P.pred[verts[i]] >= 0) c->in_tree[c->P.pred[verts[i]]] = 0;
    prune(c, verts, nverts);
    return loops;
}

/* A closed piece: join cones by a tree of shortest paths to the cut graph
 * (the handle loops) or to the first cone. Returns the cone count, -1 out
 * of memory. */
static int on_border(const surface *s, int v)
{
    for (int k = s->adj_start[v]; k < s->adj_start[v + 1]; k++)
        if (s->e_t[s->adj_edge[k]] < 0) return 1;
    return 0;
}

static int cut_cones(cutter *c, int p, const piece_lists *L, int genus, int has_border)
{
    const surface *s = c->s;
    const int *verts = L->verts + L->v_start[p];
    int nverts = L->v_start[p + 1] - L->v_start[p];
    const int *faces = L->faces + L->f_start[p];
    int nfaces = L->f_start[p + 1] - L->f_start[p];
    angle_defects(s, faces, nfaces, c->K);
    /* the angle defect is Gaussian curvature only inside */
    if (has_border)
        for (int i = 0; i < nverts; i++)
            if (on_border(s, verts[i])) c->K[verts[i]] = 0.0;
    /* geodesic regions by farthest point sampling */
    int want = c->o->cones ? 64 : 2;
    if (want > nverts) want = nverts;
    int *sample = malloc(sizeof(int) * (size_t)want);
    keyed *rk = malloc(sizeof *rk * (size_t)want);
    int *cone = malloc(sizeof(int) * (size_t)want);
    unsigned char *joined = calloc((size_t)want, 1);
    int ncone = 0;
    if (!sample || !rk || !cone || !joined) goto oom;
    paths_reset(&c->P, verts, nverts);
    if (!paths_add(s, &c->P, verts[0], 0)) goto oom;
    int ns = 0;
    for (; ns < want; ns++) {
        int far = -1;
        for (int i = 0; i < nverts; i++)
            if (far < 0 || c->P.dist[verts[i]] > c->P.dist[far]) far = verts[i];
        if (ns > 0 && !(c->P.dist[far] > 0.0)) break;
        sample[ns] = far;
        if (ns == 0) paths_reset(&c->P, verts, nverts);
        if (!paths_add(s, &c->P, far, ns)) goto oom;
    }
    double total = 0.0;
    for (int k = 0; k < ns; k++) rk[k].key = 0.0, rk[k].id = k;
    for (int i = 0; i < nverts; i++) rk[c->P.owner[verts[i]]].key += c->K[verts[i]];
    for (int k = 0; k < ns; k++) {
        total += fabs(rk[k].key);
        rk[k].key = fabs(rk[k].key);
    }
    qsort(rk, (size_t)ns, sizeof *rk, keyed_desc);
    /* how many: regions of at least a quarter turn of defect, no more
     * than the total |curvature| in half turns; two at least on a sphere */
    int cap = (int)floor(total / PI);
    if (cap > c->o->max_cones) cap = c->o->max_cones;
    int minimum = genus == 0 && !has_border ? (c->o->cones ? c->o->min_cones : 2) : 0;
    if (minimum > ns) minimum = ns;
    if (!c->o->cones) cap = minimum;
    for (int k = 0; k < ns && ncone < cap && rk[k].key >= 0.5 * PI; k++)
        cone[ncone++] = sample[rk[k].id];
    /* too few where curvature concentrates (a round sphere): the first
     * samples, which are far apart (farthest point order) */
    for (int k = 0; k < ns && ncone < minimum; k++) {
        int dup = 0;
        for (int i = 0; i < ncone; i++) dup |= cone[i] == sample[k];
        if (!dup) cone[ncone++] = sample[k];
    }
    if (ncone == 0) goto done;
    /* the Steiner tree: grow from the cut graph, or the first cone */
    paths_reset(&c->P, verts, nverts);
    int sources = 0;
    for (int i = 0; i < nverts; i++) {
        int v = verts[i];
        for (int k = s->adj_start[v]; k < s->adj_start[v + 1]; k++)
            if (c->mark[s->adj_edge[k]] || s->e_t[s->adj_edge[k]] < 0) {
                if (!paths_add(s, &c->P, v, 0)) goto oom;
                sources++;
                break;
            }
    }
    if (sources == 0) {
        if (!paths_add(s, &c->P, cone[0], 0)) goto oom;
        joined[0] = 1;
    }
    for (;;) {
        int best = -1;
        for (int k = 0; k < ncone; k++)
            if (!joined[k] && (best < 0 || c->P.dist[cone[k]] < c->P.dist[cone[best]])) best = k;
        if (best < 0) break;
        joined[best] = 1;
        /* its path back to the tree, marked whole before its vertices
         * become sources (which changes the predecessors) */
        int n = 0;
        for (int v = cone[best]; c->P.pred[v] >= 0; v = edge_other(s, c->P.pred[v], v)) {
            c->mark[c->P.pred[v]] = 1;
            c->queue[n++] = v;
        }
        for (int i = 0; i < n; i++)
            if (!paths_add(s, &c->P, c->queue[i], 0)) goto oom;
    }
done:
    free(sample);
    free(rk);
    free(cone);
    free(joined);
    return ncone;
oom:
    free(sample);
    free(rk);
    free(cone);
    free(joined);
    return -1;
}

scaf_status cut_graph_compute(int nv, const double *V, int nf, const int *F, const int *face_chart,
                              const cut_graph_options *o, cut_graph *g, scaf_error *err)
{
    memset(g, 0, sizeof *g);
    if (nv < 0 || nf < 0 || (nf > 0 && (!V || !F)))
        return err_set(err, SCAF_ERR_USAGE, "cut_graph: bad arguments");
    for (int i = 0; i < 3 * nf; i++)
        if (F[i] < 0 || F[i] >= nv)
            return err_set(err, SCAF_ERR_USAGE, "cut_graph: face %d uses vertex %d of %d", i / 3,
                           F[i], nv);
    cut_graph_options od;
    cut_graph_defaults(&od);
    if (!o) o = &od;
    surface s;
    piece_lists L;
    memset(&L, 0, sizeof L);
    cutter c;
    memset(&c, 0, sizeof c);
    int *chi = NULL, *loops = NULL, *fc = NULL;
    scaf_status st = surface_build(nv, V, nf, F, face_chart, o->crease_factor, &s, err);
    if (st != SCAF_OK) goto done;
    st = piece_lists_build(&s, &L, err);
    if (st != SCAF_OK) goto done;
    int n3 = 3 * nf, np = s.npieces;
    c.s = &s;
    c.o = o;
    c.g = g;
    c.P.dist = malloc(sizeof(double) * (size_t)(s.ns ? s.ns : 1));
    c.P.pred = malloc(sizeof(int) * (size_t)(s.ns ? s.ns : 1));
    c.P.owner = malloc(sizeof(int) * (size_t)(s.ns ? s.ns : 1));
    c.mark = calloc((size_t)(s.ne ? s.ne : 1), 1);
    c.in_tree = calloc((size_t)(s.ne ? s.ne : 1), 1);
    c.deg = malloc(sizeof(int) * (size_t)(s.ns ? s.ns : 1));
    c.loop_of = malloc(sizeof(int) * (size_t)(n3 ? n3 : 1));
    c.border_out = malloc(sizeof(int) * (size_t)(s.ns ? s.ns : 1));
    c.K = malloc(sizeof(double) * (size_t)(s.ns ? s.ns : 1));
    c.keys = malloc(sizeof(keyed) * (size_t)(s.ne ? s.ne : 1));
    c.queue = malloc(sizeof(int) * (size_t)(s.ns ? s.ns : 1));
    chi = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    loops = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    fc = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    if (!c.P.dist || !c.P.pred || !c.P.owner || !c.mark || !c.in_tree || !c.deg || !c.loop_of ||
        !c.border_out || !c.K || !c.keys || !c.queue || !chi || !loops || !fc) {
        st = err_nomem(err, "cut graph");
        goto done;
    }
    /* holes: a number per boundary loop, after the faces' */
    int *out = c.border_out;
    for (int v = 0; v < s.ns; v++) out[v] = -1;
    for (int h = 0; h < n3; h++) {
        c.loop_of[h] = -1;
        if (s.twin[h] < 0) out[s.cls[h]] = h;
    }
    int nloops = 0;
    for (int h = 0; h < n3; h++) {
        if (s.twin[h] >= 0 || c.loop_of[h] >= 0) continue;
        for (int q = h; q >= 0 && c.loop_of[q] < 0; q = out[s.cls[half_edge_next(q)]])
            c.loop_of[q] = nf + nloops;
        nloops++;
    }
    c.dual = malloc(sizeof(int) * ((size_t)nf + (size_t)nloops + 1));
    if (!c.dual) {
        st = err_nomem(err, "cut graph");
        goto done;
    }
    uf_init(c.dual, nf + nloops);
    /* per piece: Euler characteristic, boundary loops, genus */
    for (int p = 0; p < np; p++) chi[p] = loops[p] = 0;
    for (int p = 0; p < np; p++) chi[p] += L.v_start[p + 1] - L.v_start[p];
    for (int f = 0; f < nf; f++) chi[s.piece[f]]++;
    for (int e = 0; e < s.ne; e++) chi[s.piece[s.e_h[e] / 3]]--;
    {
        int *seen_loop = calloc((size_t)nloops + 1, sizeof(int));
        if (!seen_loop) {
            st = err_nomem(err, "cut graph");
            goto done;
        }
        for (int h = 0; h < n3; h++)
            if (s.twin[h] < 0 && !seen_loop[c.loop_of[h] - nf]) {
                seen_loop[c.loop_of[h] - nf] = 1;
                loops[s.piece[h / 3]]++;
            }
        free(seen_loop);
    }
    g->ncharts = np;
    for (int p = 0; p < np; p++) {
        int twice_genus = 2 - loops[p] - chi[p];
        if (twice_genus < 0 || twice_genus % 2) {
            st = err_set(err, SCAF_ERR_MESH,
                         "chart %d is not an orientable manifold surface (Euler characteristic "
                         "%d, %d boundary loops)",
                         p, chi[p], loops[p]);
            goto done;
        }
        int genus = twice_genus / 2;
        /* a disk, with holes or not */
        if (genus == 0 && loops[p] > 0 && !(o->cut_disks && o->cones)) continue;
        if (genus > 0) {
            int n = cut_handles(&c, p, &L);
            if (n < 0) {
                st = err_nomem(err, "cut graph");
                goto done;
            }
            g->handle_loops += n;
            g->genus_charts++;
        }
        if (loops[p] == 0 || (o->cut_disks && o->cones)) {
            int n = cut_cones(&c, p, &L, genus, loops[p] > 0);
            if (n < 0) {
                st = err_nomem(err, "cut graph");
                goto done;
            }
            g->cones += n;
            g->closed_charts += loops[p] == 0;
        }
    }
    /* the cut surface */
    for (int e = 0; e < s.ne; e++) {
        if (s.e_t[e] < 0) c.mark[e] = 0; /* already a border */
        g->cut_edges += c.mark[e];
    }
    g->FT = malloc(sizeof(int) * (size_t)(n3 ? n3 : 1));
    g->face_chart = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    if (!g->FT || !g->face_chart) {
        st = err_nomem(err, "cut graph");
        goto done;
    }
    st = corner_classes(nf, F, s.twin, s.edge_of, c.mark, g->FT, &g->nsplit, &g->split_vertex, err);
    if (st != SCAF_OK) goto done;
    /* the check: every chart a disk, possibly with holes */
    int nc = 0;
    st = cut_graph_chart_topology(nf, g->FT, fc, &nc, chi, loops, err);
    if (st != SCAF_OK) {
        st = err_set(err, SCAF_ERR_INTERNAL, "cut graph: the cut surface is wrong: %s",
                     err ? err->message : "");
        goto done;
    }
    if (nc != np) {
        st = err_set(err, SCAF_ERR_INTERNAL, "cut graph: %d charts before the cut, %d after", np,
                     nc);
        goto done;
    }
    for (int p = 0; p < nc; p++)
        if (loops[p] < 1 || 2 - loops[p] - chi[p] != 0) {
            st = err_set(err, SCAF_ERR_INTERNAL,
                         "cut graph: chart %d is not a disk after the cut (Euler characteristic "
                         "%d, %d boundary loops)",
                         p, chi[p], loops[p]);
            goto done;
        }
    memcpy(g->face_chart, fc, sizeof(int) * (size_t)nf);
done:
    surface_free(&s);
    piece_lists_free(&L);
    free(c.P.dist);
    free(c.P.pred);
    free(c.P.owner);
    min_heap_free(&c.P.heap);
    free(c.mark);
    free(c.in_tree);
    free(c.deg);
    free(c.dual);
    free(c.loop_of);
    free(c.K);
    free(c.keys);
    free(c.queue);
    free(chi);
    free(loops);
    free(fc);
    free(c.border_out);
    if (st != SCAF_OK) cut_graph_free(g);
    return st;
}
