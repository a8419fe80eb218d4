/* mesh/chart_segment: automatic charts (see the header). */
#include "mesh/chart_segment.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "base/min_heap.h"
#include "base/union_find.h"

/* Step cost per unit of normal deviation (1 - n.N): a face at right angles
 * to its chart's proxy costs 1 + NORMAL_WEIGHT times its length to reach,
 * a steep normal cone (measured on bunny, spot and blub: 3 left charts of
 * E 5-9 where 10 keeps every chart below 5.4, at the same count). */
#define NORMAL_WEIGHT 10.0
/* Dihedral angle below which an edge is no crease (scan noise, tessellation
 * of smooth areas): cos(25 degrees). */
#define CREASE_COS 0.906307787036650
/* Extra cost of crossing a right-angle convex crease, in chart radii;
 * concave creases (hidden, where an artist cuts) cost twice as much, so
 * fronts stop there and seams follow them. */
#define CREASE_WEIGHT 0.5
/* Charts below this fraction of their component's average chart area are
 * absorbed by a neighbour. */
#define TINY_CHART 0.15
/* Curvature is diffused over this fraction of sqrt(area): about the radius
 * of a chart holding 1/16 of the surface, the scale at which curvature
 * decides a chart's distortion (finer bumps flatten with little of it).
 * Patches of half that side, CURVATURE_STEPS steps: a spread of
 * (side / 2) sqrt(2 steps) = the radius. */
#define CURVATURE_RADIUS 0.15
#define CURVATURE_STEPS 8
/* A chart gets at least this many faces on average. */
#define MIN_FACES_PER_CHART 16

#define PI 3.14159265358979323846

void chart_segment_defaults(chart_segment_options *o)
{
    o->target_charts = 0;
    o->curvature_per_chart = CHART_SEGMENT_CURVATURE_PER_CHART;
    o->lloyd_rounds = 8;
}

/* ---- the surface as the segmentation sees it ---- */

typedef struct seg_mesh {
    int nv, nf;
    const double *V;
    const int *F;
    int *nbr;       /* 3 nf: face across side k of f, or -1 (boundary, non-manifold) */
    double *step;   /* 3 nf: distance between the centroids of f and nbr */
    double *crease; /* 3 nf: crease measure of side k (0 smooth; concave doubled) */
    double *side;   /* 3 nf: length of side k */
    double *normal; /* 3 nf: unit face normals */
    double *area;   /* nf */
    double *weight; /* nf: metric stretch of the seeding (curvature density) */
    int *comp;      /* nf: edge-connected component */
    int ncomp;
    double *comp_area;   /* ncomp */
    double *comp_curv;   /* ncomp: sum |K| (diffused) */
    int *comp_faces;     /* ncomp: face count */
    int *comp_charts;    /* ncomp: charts wanted */
    double *comp_radius; /* ncomp: expected chart radius */
} seg_mesh;

static void seg_free(seg_mesh *s)
{
    free(s->nbr);
    free(s->step);
    free(s->crease);
    free(s->side);
    free(s->normal);
    free(s->area);
    free(s->weight);
    free(s->comp);
    free(s->comp_area);
    free(s->comp_curv);
    free(s->comp_faces);
    free(s->comp_charts);
    free(s->comp_radius);
}

static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}
static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static void centroid(const seg_mesh *s, int f, double *c)
{
    const double *a = s->V + 3 * s->F[3 * f], *b = s->V + 3 * s->F[3 * f + 1],
                 *d = s->V + 3 * s->F[3 * f + 2];
    for (int i = 0; i < 3; i++) c[i] = (a[i] + b[i] + d[i]) / 3.0;
}

/* Normals, areas, neighbours across edges, crease measures, components. */
static int seg_geometry(seg_mesh *s, scaf_error *err)
{
    int nf = s->nf;
    const int *F = s->F;
    const double *V = s->V;
    for (int f = 0; f < nf; f++) {
        double e1[3], e2[3], n[3];
        sub3(V + 3 * F[3 * f + 1], V + 3 * F[3 * f], e1);
        sub3(V + 3 * F[3 * f + 2], V + 3 * F[3 * f], e2);
        cross3(e1, e2, n);
        double l = sqrt(dot3(n, n));
        s->area[f] = 0.5 * l;
        for (int i = 0; i < 3; i++) s->normal[3 * f + i] = l > 0 ? n[i] / l : 0.0;
        for (int k = 0; k < 3; k++) {
            double e[3];
            sub3(V + 3 * F[3 * f + (k + 1) % 3], V + 3 * F[3 * f + k], e);
            s->side[3 * f + k] = sqrt(dot3(e, e));
        }
    }
    int *order = malloc(sizeof(int) * 3 * (size_t)nf);
    if (!order) return 0;
    int count = 0;
    if (half_edges_sort(s->nv, nf, F, NULL, order, &count, err) != SCAF_OK) {
        free(order);
        return 0; /* it fails only for want of memory */
    }
    for (int h = 0; h < 3 * nf; h++) {
        s->nbr[h] = -1;
        s->step[h] = 0.0;
        s->crease[h] = 0.0;
    }
    /* an edge with exactly two sides links their faces */
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(F, order[i], order[j])) j++;
        if (j - i == 2 && half_edge_lo(F, order[i]) != half_edge_hi(F, order[i])) {
            int g = order[i], h = order[i + 1];
            s->nbr[g] = h / 3;
            s->nbr[h] = g / 3;
        }
        i = j;
    }
    free(order);
    for (int f = 0; f < nf; f++) {
        double cf[3];
        centroid(s, f, cf);
        for (int k = 0; k < 3; k++) {
            int g = s->nbr[3 * f + k];
            if (g < 0) continue;
            double cg[3], d[3];
            centroid(s, g, cg);
            sub3(cg, cf, d);
            s->step[3 * f + k] = sqrt(dot3(d, d));
            double c = dot3(s->normal + 3 * f, s->normal + 3 * g);
            if (c < CREASE_COS) {
                /* 0 at the threshold, 1 at a right angle, 2 folded flat */
                double m = (CREASE_COS - c) / CREASE_COS;
                /* concave when g's centroid lies above f's plane */
                if (dot3(d, s->normal + 3 * f) > 0) m *= 2.0;
                s->crease[3 * f + k] = m;
            }
        }
    }
    /* components through shared edges, numbered by first face */
    int *parent = malloc(sizeof(int) * (size_t)nf);
    if (!parent) return 0;
    uf_init(parent, nf);
    for (int h = 0; h < 3 * nf; h++)
        if (s->nbr[h] >= 0) uf_union(parent, h / 3, s->nbr[h]);
    for (int f = 0; f < nf; f++) s->comp[f] = -1;
    int nc = 0;
    for (int f = 0; f < nf; f++) {
        int r = uf_find(parent, f);
        if (s->comp[r] < 0) s->comp[r] = nc++;
        s->comp[f] = s->comp[r];
    }
    free(parent);
    s->ncomp = nc;
    return 1;
}

/* A patch of the curvature measure: a cubic cell of a component. */
typedef struct cell_key {
    int comp, x, y, z, face;
} cell_key;

static int cell_cmp(const void *p, const void *q)
{
    const cell_key *a = p, *b = q;
    if (a->comp != b->comp) return a->comp < b->comp ? -1 : 1;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->z != b->z) return a->z < b->z ? -1 : 1;
    return (a->face > b->face) - (a->face < b->face);
}

static int pair_cmp(const void *p, const void *q)
{
    const int *a = p, *b = q;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* Angle defects at interior vertices, summed over patches (cubic cells of
 * side CURVATURE_RADIUS sqrt(area) / 2, per component: noise of either
 * sign cancels inside a patch) and diffused, mass-conserving, over the
 * patches' adjacency for CURVATURE_STEPS steps (a spread of about
 * CURVATURE_RADIUS sqrt(area)). Then per component sum |K|, and per face
 * the curvature-density stretch of the seeding metric. O(n log n) (one
 * sort), whatever the resolution. Returns 0 when out of memory. */
static int seg_curvature(seg_mesh *s)
{
    int nv = s->nv, nf = s->nf;
    const int *F = s->F;
    const double *V = s->V;
    double *K = calloc((size_t)nv, sizeof(double));
    unsigned char *on_boundary = calloc((size_t)nv, 1);
    unsigned char *used = calloc((size_t)nv, 1);
    cell_key *key = malloc(sizeof *key * (size_t)nf);
    int *patch = malloc(sizeof(int) * (size_t)nf);
    int *pairs = malloc(sizeof(int) * 6 * (size_t)nf);
    double *Kp = NULL, *Kq = NULL, *Ap = NULL;
    int *pcomp = NULL, *deg = NULL, *start = NULL;
    int ok = 0;
    if (!K || !on_boundary || !used || !key || !patch || !pairs) goto out;
    double total_area = 0.0, lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    for (int f = 0; f < nf; f++) {
        total_area += s->area[f];
        for (int k = 0; k < 3; k++) {
            int a = F[3 * f + k], b = F[3 * f + (k + 1) % 3], c = F[3 * f + (k + 2) % 3];
            double u[3], w[3];
            sub3(V + 3 * b, V + 3 * a, u);
            sub3(V + 3 * c, V + 3 * a, w);
            double lu = sqrt(dot3(u, u)), lw = sqrt(dot3(w, w));
            double cs = lu > 0 && lw > 0 ? dot3(u, w) / (lu * lw) : 1.0;
            if (cs > 1) cs = 1;
            if (cs < -1) cs = -1;
            K[a] -= acos(cs);
            used[a] = 1;
            if (s->nbr[3 * f + k] < 0) on_boundary[a] = on_boundary[b] = 1;
            for (int i = 0; i < 3; i++)
                if (V[3 * a + i] < lo[i]) lo[i] = V[3 * a + i];
        }
    }
    /* interior vertex: 2 pi minus its angles; the boundary carries none */
    for (int v = 0; v < nv; v++) K[v] = used[v] && !on_boundary[v] ? K[v] + 2.0 * PI : 0.0;
    double cell = 0.5 * CURVATURE_RADIUS * sqrt(total_area);
    if (!(cell > 0)) cell = 1.0;
    for (int f = 0; f < nf; f++) {
        double c[3];
        centroid(s, f, c);
        double q[3];
        for (int i = 0; i < 3; i++) {
            q[i] = floor((c[i] - lo[i]) / cell);
            if (q[i] > 1e9) q[i] = 1e9; /* far-out coordinates share a cell */
            if (!(q[i] >= 0)) q[i] = 0;
        }
        key[f] = (cell_key){s->comp[f], (int)q[0], (int)q[1], (int)q[2], f};
    }
    qsort(key, (size_t)nf, sizeof *key, cell_cmp);
    int np = 0;
    for (int i = 0; i < nf; i++) {
        if (i > 0 &&
            cell_cmp(&(cell_key){key[i].comp, key[i].x, key[i].y, key[i].z, 0},
                     &(cell_key){key[i - 1].comp, key[i - 1].x, key[i - 1].y, key[i - 1].z, 0}) !=
                0)
            np++;
        patch[key[i].face] = np;
    }
    np++;
    Kp = calloc((size_t)np, sizeof(double));
    Kq = calloc((size_t)np, sizeof(double));
    Ap = calloc((size_t)np, sizeof(double));
    pcomp = malloc(sizeof(int) * (size_t)np);
    deg = calloc((size_t)np + 1, sizeof(int));
    if (!Kp || !Kq || !Ap || !pcomp || !deg) goto out;
    /* a vertex counts once, in the patch of its first face */
    for (int v = 0; v < nv; v++) used[v] = 0;
    for (int f = 0; f < nf; f++) {
        Ap[patch[f]] += s->area[f];
        pcomp[patch[f]] = s->comp[f];
        for (int k = 0; k < 3; k++) {
            int v = F[3 * f + k];
            if (!used[v]) {
                used[v] = 1;
                Kp[patch[f]] += K[v];
            }
        }
    }
    /* patch adjacency: distinct pairs of patches of neighbouring faces */
    int npairs = 0;
    for (int h = 0; h < 3 * nf; h++) {
        int g = s->nbr[h];
        if (g < 0 || patch[g] == patch[h / 3]) continue;
        pairs[2 * npairs] = patch[h / 3];
        pairs[2 * npairs + 1] = patch[g];
        npairs++;
    }
    qsort(pairs, (size_t)npairs, 2 * sizeof(int), pair_cmp);
    int nu = 0;
    for (int i = 0; i < npairs; i++) {
        if (nu > 0 && pairs[2 * i] == pairs[2 * (nu - 1)] &&
            pairs[2 * i + 1] == pairs[2 * (nu - 1) + 1])
            continue;
        pairs[2 * nu] = pairs[2 * i];
        pairs[2 * nu + 1] = pairs[2 * i + 1];
        nu++;
    }
    for (int i = 0; i < nu; i++) deg[pairs[2 * i] + 1]++;
    for (int p = 0; p < np; p++) deg[p + 1] += deg[p];
    /* pairs are sorted by first patch: pairs[2 * deg[p] ..] are p's */
    for (int t = 0; t < CURVATURE_STEPS; t++) {
        for (int p = 0; p < np; p++) Kq[p] = deg[p + 1] > deg[p] ? 0.5 * Kp[p] : Kp[p];
        for (int p = 0; p < np; p++) {
            int d = deg[p + 1] - deg[p];
            if (d == 0) continue;
            double share = 0.5 * Kp[p] / d;
            for (int i = deg[p]; i < deg[p + 1]; i++) Kq[pairs[2 * i + 1]] += share;
        }
        double *tmp = Kp;
        Kp = Kq;
        Kq = tmp;
    }
    for (int c = 0; c < s->ncomp; c++) {
        s->comp_area[c] = 0.0;
        s->comp_curv[c] = 0.0;
        s->comp_faces[c] = 0;
    }
    for (int f = 0; f < nf; f++) {
        s->comp_area[s->comp[f]] += s->area[f];
        s->comp_faces[s->comp[f]]++;
    }
    for (int p = 0; p < np; p++) s->comp_curv[pcomp[p]] += fabs(Kp[p]);
    /* stretch so that a chart of the seeding gets an equal share of
     * (area / component area + |K| / component |K|) */
    for (int f = 0; f < nf; f++) {
        int c = s->comp[f], p = patch[f];
        double dens = Ap[p] > 0 ? fabs(Kp[p]) / Ap[p] : 0.0;
        double mean = s->comp_curv[c] > 0 ? s->comp_curv[c] / s->comp_area[c] : 1.0;
        s->weight[f] = sqrt(1.0 + dens / mean);
    }
    ok = 1;
out:
    free(K);
    free(on_boundary);
    free(used);
    free(key);
    free(patch);
    free(pairs);
    free(Kp);
    free(Kq);
    free(Ap);
    free(pcomp);
    free(deg);
    free(start);
    return ok;
}

/* ---- growing charts ---- */

enum grow_mode {
    GROW_SEEDING, /* curvature-stretched distance, labels of the nearest seed */
    GROW_CHARTS,  /* normal cone and crease costs against each chart's proxy */
    GROW_DEPTH    /* distance from the chart's boundary, inside each chart */
};

typedef struct grower {
    seg_mesh *s;
    double *dist;   /* nf */
    int *label;     /* nf */
    double *proxy;  /* 3 per chart */
    double *radius; /* per chart: the component's expected chart radius */
    min_heap heap;
} grower;

static double step_cost(const grower *g, enum grow_mode mode, int f, int k, int to)
{
    const seg_mesh *s = g->s;
    double d = s->step[3 * f + k];
    if (mode == GROW_SEEDING) return d * 0.5 * (s->weight[f] + s->weight[to]);
    if (mode == GROW_DEPTH) return d;
    const double *N = g->proxy + 3 * g->label[f];
    double dev = 1.0 - dot3(s->normal + 3 * to, N);
    return d * (1.0 + NORMAL_WEIGHT * dev) +
        CREASE_WEIGHT * s->crease[3 * f + k] * g->radius[g->label[f]];
}

/* Dijkstra from the faces already in the heap (dist and label set). In
 * GROW_DEPTH a front stays inside its label. Returns 0 when out of memory. */
static int grow_run(grower *g, enum grow_mode mode)
{
    seg_mesh *s = g->s;
    while (g->heap.n > 0) {
        min_heap_item e = min_heap_pop(&g->heap);
        int f = e.id;
        if (e.key > g->dist[f]) continue;
        for (int k = 0; k < 3; k++) {
            int to = s->nbr[3 * f + k];
            if (to < 0) continue;
            if (mode == GROW_DEPTH && g->label[to] != g->label[f]) continue;
            double nd = g->dist[f] + step_cost(g, mode, f, k, to);
            if (nd < g->dist[to]) {
                g->dist[to] = nd;
                if (mode != GROW_DEPTH) g->label[to] = g->label[f];
                if (!min_heap_push(&g->heap, nd, to)) return 0;
            }
        }
    }
    return 1;
}

/* Area-weighted mean normal of every chart (the seed's normal when the
 * mean vanishes, as on a closed sphere in one chart). */
static void fit_proxies(grower *g, const int *seed, int n)
{
    seg_mesh *s = g->s;
    for (int i = 0; i < 3 * n; i++) g->proxy[i] = 0.0;
    for (int f = 0; f < s->nf; f++)
        for (int i = 0; i < 3; i++)
            g->proxy[3 * g->label[f] + i] += s->area[f] * s->normal[3 * f + i];
    for (int c = 0; c < n; c++) {
        double *N = g->proxy + 3 * c, l = sqrt(dot3(N, N));
        if (l > 1e-12 * (1.0 + s->comp_area[s->comp[seed[c]]])) {
            for (int i = 0; i < 3; i++) N[i] /= l;
        } else {
            for (int i = 0; i < 3; i++) N[i] = s->normal[3 * seed[c] + i];
        }
    }
}

/* Grow all charts from their seeds. */
static int grow_charts(grower *g, const int *seed, int n)
{
    seg_mesh *s = g->s;
    for (int f = 0; f < s->nf; f++) g->dist[f] = HUGE_VAL;
    g->heap.n = 0;
    for (int c = 0; c < n; c++) {
        g->dist[seed[c]] = 0.0;
        g->label[seed[c]] = c;
        if (!min_heap_push(&g->heap, 0.0, seed[c])) return 0;
    }
    return grow_run(g, GROW_CHARTS);
}

/* Move every seed to the face of its chart farthest from the chart's
 * boundary (ties: lowest index); a chart without boundary keeps its seed. */
static int recenter_seeds(grower *g, int *seed, int n)
{
    seg_mesh *s = g->s;
    g->heap.n = 0;
    for (int f = 0; f < s->nf; f++) {
        g->dist[f] = HUGE_VAL;
        for (int k = 0; k < 3; k++) {
            int to = s->nbr[3 * f + k];
            if (to < 0 || g->label[to] != g->label[f]) {
                g->dist[f] = 0.5 * sqrt(s->area[f]);
                if (!min_heap_push(&g->heap, g->dist[f], f)) return 0;
                break;
            }
        }
    }
    if (!grow_run(g, GROW_DEPTH)) return 0;
    double *best = g->proxy; /* reuse: proxies are re-fitted after this */
    for (int c = 0; c < n; c++) best[c] = -1.0;
    for (int f = 0; f < s->nf; f++) {
        int c = g->label[f];
        if (g->dist[f] == HUGE_VAL) continue;
        if (g->dist[f] > best[c]) {
            best[c] = g->dist[f];
            seed[c] = f;
        }
    }
    return 1;
}

/* Farthest-point seeds, n_c per component; labels the faces by nearest
 * seed. Returns the number of seeds, or -1 when out of memory. */
static int place_seeds(grower *g, int *seed)
{
    seg_mesh *s = g->s;
    int n = 0;
    for (int f = 0; f < s->nf; f++) {
        g->dist[f] = HUGE_VAL;
        g->label[f] = -1;
    }
    /* the first seed of a component: farthest from its first face */
    int *first = malloc(sizeof(int) * (size_t)(s->ncomp > 0 ? s->ncomp : 1));
    if (!first) return -1;
    for (int c = 0; c < s->ncomp; c++) first[c] = -1;
    for (int f = 0; f < s->nf; f++)
        if (first[s->comp[f]] < 0) first[s->comp[f]] = f;
    g->heap.n = 0;
    for (int c = 0; c < s->ncomp; c++) {
        g->dist[first[c]] = 0.0;
        g->label[first[c]] = c;
        if (!min_heap_push(&g->heap, 0.0, first[c])) {
            free(first);
            return -1;
        }
    }
    if (!grow_run(g, GROW_SEEDING)) {
        free(first);
        return -1;
    }
    for (int f = 0; f < s->nf; f++) {
        int c = s->comp[f];
        if (g->dist[f] > g->dist[first[c]]) first[c] = f;
    }
    for (int f = 0; f < s->nf; f++) g->dist[f] = HUGE_VAL;
    g->heap.n = 0;
    for (int c = 0; c < s->ncomp; c++) {
        seed[n] = first[c];
        g->dist[first[c]] = 0.0;
        g->label[first[c]] = n++;
        if (!min_heap_push(&g->heap, 0.0, first[c])) {
            free(first);
            return -1;
        }
    }
    if (!grow_run(g, GROW_SEEDING)) {
        free(first);
        return -1;
    }
    /* then, round by round, every component that wants more gets the face
     * farthest from its seeds */
    int *have = first; /* reuse: seeds per component */
    for (int c = 0; c < s->ncomp; c++) have[c] = 1;
    for (;;) {
        int added = 0;
        for (int c = 0; c < s->ncomp; c++) {
            if (have[c] >= s->comp_charts[c]) continue;
            int far = -1;
            for (int f = 0; f < s->nf; f++)
                if (s->comp[f] == c && g->dist[f] > 0 && (far < 0 || g->dist[f] > g->dist[far]))
                    far = f;
            if (far < 0) {
                have[c] = s->comp_charts[c];
                continue;
            }
            seed[n] = far;
            g->dist[far] = 0.0;
            g->label[far] = n++;
            have[c]++;
            added = 1;
            if (!min_heap_push(&g->heap, 0.0, far) || !grow_run(g, GROW_SEEDING)) {
                free(first);
                return -1;
            }
        }
        if (!added) break;
    }
    free(first);
    return n;
}

/* Faces a front never reached (costs that overflowed on a degenerate
 * input) join a labelled neighbour, pass by pass: every label stays
 * edge-connected. A component always holds a seed, so all get one. */
static void fill_unreached(const seg_mesh *s, int *label)
{
    for (int changed = 1; changed;) {
        changed = 0;
        for (int f = 0; f < s->nf; f++) {
            if (label[f] >= 0) continue;
            for (int k = 0; k < 3; k++) {
                int to = s->nbr[3 * f + k];
                if (to >= 0 && label[to] >= 0) {
                    label[f] = label[to];
                    changed = 1;
                    break;
                }
            }
        }
    }
}

/* ---- cleaning up ---- */

/* A face whose neighbours in one other chart outnumber those in its own
 * joins that chart, until nothing changes; not across a crease, where a
 * seam belongs. Such a face has at most one neighbour in its own chart,
 * so leaving never disconnects it. */
static void smooth_boundaries(const seg_mesh *s, int *label)
{
    for (int pass = 0; pass < 32; pass++) {
        int changed = 0;
        for (int f = 0; f < s->nf; f++) {
            int l[3], own = 0;
            for (int k = 0; k < 3; k++) {
                int to = s->nbr[3 * f + k];
                /* a seam on a crease stays there */
                l[k] = to < 0 || s->crease[3 * f + k] > 0 ? -1 : label[to];
                if (to >= 0 && label[to] == label[f]) own++;
            }
            if (own > 1) continue;
            int to = -1;
            for (int k = 0; k < 3 && to < 0; k++)
                for (int j = k + 1; j < 3; j++)
                    if (l[k] >= 0 && l[k] == l[j] && l[k] != label[f]) to = l[k];
            if (to >= 0) {
                label[f] = to;
                changed = 1;
            }
        }
        if (!changed) break;
    }
}

/* Charts below TINY_CHART of their component's mean chart area join the
 * neighbour they share the longest boundary with (smallest first). */
static int absorb_tiny(const seg_mesh *s, int *label, int n)
{
    double *area = calloc((size_t)n, sizeof(double));
    double *shared = calloc((size_t)n, sizeof(double));
    int *comp_of = malloc(sizeof(int) * (size_t)n);
    unsigned char *settled = calloc((size_t)n, 1); /* kept or gone */
    if (!area || !shared || !comp_of || !settled) {
        free(area);
        free(shared);
        free(comp_of);
        free(settled);
        return 0;
    }
    for (int c = 0; c < n; c++) settled[c] = 1;
    for (int f = 0; f < s->nf; f++) {
        area[label[f]] += s->area[f];
        comp_of[label[f]] = s->comp[f];
        settled[label[f]] = 0;
    }
    for (;;) {
        int tiny = -1;
        for (int c = 0; c < n; c++) {
            if (settled[c]) continue;
            int k = comp_of[c];
            double mean = s->comp_area[k] / s->comp_charts[k];
            if (area[c] < TINY_CHART * mean && (tiny < 0 || area[c] < area[tiny])) tiny = c;
        }
        if (tiny < 0) break;
        for (int c = 0; c < n; c++) shared[c] = 0.0;
        for (int f = 0; f < s->nf; f++) {
            if (label[f] != tiny) continue;
            for (int k = 0; k < 3; k++) {
                int to = s->nbr[3 * f + k];
                if (to >= 0 && label[to] != tiny) shared[label[to]] += s->side[3 * f + k];
            }
        }
        int best = -1;
        for (int c = 0; c < n; c++)
            if (shared[c] > 0 && (best < 0 || shared[c] > shared[best])) best = c;
        settled[tiny] = 1; /* alone in its component: kept */
        if (best < 0) continue;
        for (int f = 0; f < s->nf; f++)
            if (label[f] == tiny) label[f] = best;
        area[best] += area[tiny];
        area[tiny] = 0.0;
    }
    free(area);
    free(shared);
    free(comp_of);
    free(settled);
    return 1;
}

/* Number charts by first face, splitting any chart whose faces are not
 * edge-connected (a safety net: the steps above keep charts connected). */
static int renumber(const seg_mesh *s, int *label, int *ncharts)
{
    int *parent = malloc(sizeof(int) * (size_t)s->nf);
    if (!parent) return 0;
    uf_init(parent, s->nf);
    for (int f = 0; f < s->nf; f++)
        for (int k = 0; k < 3; k++) {
            int to = s->nbr[3 * f + k];
            if (to >= 0 && label[to] == label[f]) uf_union(parent, f, to);
        }
    int n = 0;
    int *id = malloc(sizeof(int) * (size_t)s->nf);
    if (!id) {
        free(parent);
        return 0;
    }
    for (int f = 0; f < s->nf; f++) id[f] = -1;
    for (int f = 0; f < s->nf; f++) {
        int r = uf_find(parent, f);
        if (id[r] < 0) id[r] = n++;
        label[f] = id[r];
    }
    free(id);
    free(parent);
    *ncharts = n;
    return 1;
}

/* How many charts each component gets. */
static void choose_counts(seg_mesh *s, const chart_segment_options *o)
{
    double budget =
        o->curvature_per_chart > 0 ? o->curvature_per_chart : CHART_SEGMENT_CURVATURE_PER_CHART;
    double total = 0.0;
    for (int c = 0; c < s->ncomp; c++) total += s->comp_curv[c];
    for (int c = 0; c < s->ncomp; c++) {
        double want = o->target_charts > 0 ? (total > 0 ? o->target_charts * s->comp_curv[c] / total
                                                        : (double)o->target_charts / s->ncomp)
                                           : s->comp_curv[c] / budget;
        int n = (int)floor(want + 0.5);
        int most = s->comp_faces[c] / MIN_FACES_PER_CHART;
        if (n > most) n = most;
        if (n < 1) n = 1;
        s->comp_charts[c] = n;
        s->comp_radius[c] = sqrt(s->comp_area[c] / (PI * n));
    }
}

scaf_status chart_segment(int nv, const double *V, int nf, const int *F,
                          const chart_segment_options *o, int *face_chart, int *ncharts,
                          scaf_error *err)
{
    if (nv < 0 || nf < 0 || (nf > 0 && (!F || !V || !face_chart)) || !ncharts)
        return err_set(err, SCAF_ERR_USAGE, "chart_segment: bad arguments");
    *ncharts = 0;
    if (nf == 0) return SCAF_OK;
    for (int i = 0; i < 3 * nf; i++)
        if (F[i] < 0 || F[i] >= nv)
            return err_set(err, SCAF_ERR_USAGE,
                           "chart_segment: face %d has vertex index %d outside [0, %d)", i / 3,
                           F[i], nv);
    chart_segment_options def;
    if (!o) {
        chart_segment_defaults(&def);
        o = &def;
    }
    /* work on V scaled by a power of two into [-1, 1] (exact): the
     * segmentation is scale-free, and areas of huge or tiny meshes would
     * overflow or underflow */
    double big = 0.0;
    for (int i = 0; i < 3 * nv; i++)
        if (fabs(V[i]) > big && isfinite(V[i])) big = fabs(V[i]);
    int e = 0;
    if (big > 0) frexp(big, &e);
    double *Vs = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    if (!Vs) return err_nomem(err, "chart segmentation");
    for (int i = 0; i < 3 * nv; i++) Vs[i] = ldexp(V[i], -e);
    seg_mesh s;
    memset(&s, 0, sizeof s);
    s.nv = nv;
    s.nf = nf;
    s.V = Vs;
    s.F = F;
    size_t h3 = 3 * (size_t)nf;
    s.nbr = malloc(sizeof(int) * h3);
    s.step = malloc(sizeof(double) * h3);
    s.crease = malloc(sizeof(double) * h3);
    s.side = malloc(sizeof(double) * h3);
    s.normal = malloc(sizeof(double) * h3);
    s.area = malloc(sizeof(double) * (size_t)nf);
    s.weight = malloc(sizeof(double) * (size_t)nf);
    s.comp = malloc(sizeof(int) * (size_t)nf);
    grower g;
    memset(&g, 0, sizeof g);
    g.s = &s;
    g.dist = malloc(sizeof(double) * (size_t)nf);
    g.label = face_chart;
    int *seed = NULL;
    scaf_status st = SCAF_OK;
    if (!s.nbr || !s.step || !s.crease || !s.side || !s.normal || !s.area || !s.weight || !s.comp ||
        !g.dist)
        goto nomem;
    if (!seg_geometry(&s, err)) goto nomem;
    size_t nc = (size_t)s.ncomp;
    s.comp_area = malloc(sizeof(double) * nc);
    s.comp_curv = malloc(sizeof(double) * nc);
    s.comp_faces = malloc(sizeof(int) * nc);
    s.comp_charts = malloc(sizeof(int) * nc);
    s.comp_radius = malloc(sizeof(double) * nc);
    if (!s.comp_area || !s.comp_curv || !s.comp_faces || !s.comp_charts || !s.comp_radius)
        goto nomem;
    if (!seg_curvature(&s)) goto nomem;
    choose_counts(&s, o);
    int total = 0;
    for (int c = 0; c < s.ncomp; c++) total += s.comp_charts[c];
    seed = malloc(sizeof(int) * (size_t)total);
    g.proxy = malloc(sizeof(double) * 3 * (size_t)total);
    g.radius = malloc(sizeof(double) * (size_t)total);
    if (!seed || !g.proxy || !g.radius) goto nomem;
    int n = place_seeds(&g, seed);
    if (n < 0) goto nomem;
    fill_unreached(&s, face_chart);
    for (int c = 0; c < n; c++) g.radius[c] = s.comp_radius[s.comp[seed[c]]];
    int rounds = o->lloyd_rounds > 0 ? o->lloyd_rounds : 8;
    for (int it = 0; it < rounds; it++) {
        fit_proxies(&g, seed, n);
        for (int f = 0; f < nf; f++) face_chart[f] = -1;
        if (!grow_charts(&g, seed, n)) goto nomem;
        fill_unreached(&s, face_chart);
        if (it + 1 < rounds && !recenter_seeds(&g, seed, n)) goto nomem;
    }
    smooth_boundaries(&s, face_chart);
    if (!absorb_tiny(&s, face_chart, n)) goto nomem;
    smooth_boundaries(&s, face_chart);
    if (!renumber(&s, face_chart, ncharts)) goto nomem;
    goto done;
nomem:
    st = err_nomem(err, "chart segmentation");
done:
    seg_free(&s);
    free(Vs);
    free(g.dist);
    free(g.proxy);
    free(g.radius);
    min_heap_free(&g.heap);
    free(seed);
    return st;
}
