/* geom/cdt: constrained Delaunay triangulation of the scaffold domain.
 *
 * The pipeline: check the input (finite coordinates, valid segment
 * indices); insert all points into a big enclosing triangle by
 * Bowyer-Watson in BRIO order (random rounds, each sorted along a Hilbert
 * curve, walking from the previous insertion); recover every segment by
 * edge flips (Sloan: flip the edges crossing the segment until none is
 * left, then restore the Delaunay property by Lawson flips of the new
 * edges); classify triangles as exterior (reachable from the enclosing
 * triangle), hole (reachable from the left side of a left_is_hole segment
 * or from a hole seed) or domain, flooding across unconstrained edges;
 * refine (geom/cdt_refine); copy the domain triangles out.
 *
 * Invalid input is reported with SCAF_ERR_MESH naming the culprits:
 * duplicate points, a point in a segment's interior, crossing segments,
 * non-finite coordinates, bad indices. Every geometric decision uses the
 * exact predicates, so near-degenerate but valid input (1e-12 gaps,
 * nearly collinear chains) is triangulated, never refused.
 */
#include "geom/cdt.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geom/cdt_mesh.h"
#include "geom/cdt_refine.h"
#include "geom/predicates.h"

cdt_options cdt_default_options(void)
{
    cdt_options o;
    o.min_angle_deg = 20.0;
    o.max_area = 0.0;
    o.max_steiner = 0;
    return o;
}

void cdt_output_free(cdt_output *out)
{
    if (!out) return;
    free(out->points);
    free(out->triangles);
    free(out->neighbors);
    free(out->subsegments);
    free(out->subsegment_of);
    memset(out, 0, sizeof *out);
}

/* ---------------------------------------------------------------- BRIO order */

typedef struct keyed {
    uint32_t key;
    int idx;
} keyed;

/* Stable LSD radix sort by key (4 passes of 8 bits); tmp has room for n. */
static void radix_sort(keyed *a, keyed *tmp, int n)
{
    for (int shift = 0; shift < 32; shift += 8) {
        int count[257] = {0};
        for (int i = 0; i < n; i++) count[((a[i].key >> shift) & 255u) + 1]++;
        for (int b = 0; b < 256; b++) count[b + 1] += count[b];
        for (int i = 0; i < n; i++) tmp[count[(a[i].key >> shift) & 255u]++] = a[i];
        memcpy(a, tmp, (size_t)n * sizeof *a);
    }
}

static uint32_t hilbert_key(uint32_t x, uint32_t y)
{
    const uint32_t n = 1u << 16;
    uint32_t d = 0;
    for (uint32_t s = n / 2; s > 0; s /= 2) {
        uint32_t rx = (x & s) > 0, ry = (y & s) > 0;
        d += s * s * ((3u * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            uint32_t t = x;
            x = y;
            y = t;
        }
    }
    return d;
}

/* Insertion order of the n points: a deterministic shuffle cut into rounds
 * of doubling size, each round sorted along a Hilbert curve. */
static int brio_order(const double *p, int n, const double lo[2], double ext, int *order)
{
    keyed *k = malloc((size_t)(n > 0 ? n : 1) * 2 * sizeof *k);
    if (!k) return -1;
    unsigned r = 0x2545f491u;
    for (int i = 0; i < n; i++) order[i] = i;
    for (int i = n - 1; i > 0; i--) {
        r ^= r << 13;
        r ^= r >> 17;
        r ^= r << 5;
        int j = (int)(r % (unsigned)(i + 1));
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    double sc = ext > 0 ? 65535.0 / ext : 0.0;
    int end = n;
    while (end > 0) {
        int start = end < 128 ? 0 : end / 2;
        int m = end - start;
        for (int i = 0; i < m; i++) {
            int v = order[start + i];
            double fx = (p[2 * v] - lo[0]) * sc, fy = (p[2 * v + 1] - lo[1]) * sc;
            uint32_t qx = fx <= 0 ? 0u : fx >= 65535.0 ? 65535u : (uint32_t)fx;
            uint32_t qy = fy <= 0 ? 0u : fy >= 65535.0 ? 65535u : (uint32_t)fy;
            k[i].key = hilbert_key(qx, qy);
            k[i].idx = v;
        }
        radix_sort(k, k + n, m);
        for (int i = 0; i < m; i++) order[start + i] = k[i].idx;
        end = start;
    }
    free(k);
    return 0;
}

/* ---------------------------------------------------------- segment recovery */

typedef struct pairs {
    int *v; /* 2 per pair */
    int n, cap, head;
} pairs;

static int pairs_push(pairs *q, int a, int b)
{
    if (q->n >= q->cap) {
        int nc = q->cap ? 2 * q->cap : 64;
        int *nv = realloc(q->v, (size_t)nc * 2 * sizeof(int));
        if (!nv) return -1;
        q->v = nv;
        q->cap = nc;
    }
    q->v[2 * q->n] = a;
    q->v[2 * q->n + 1] = b;
    q->n++;
    return 0;
}

typedef struct recover_ctx {
    cdt_mesh *m;
    const cdt_input *in;
    unsigned char *split; /* effective splittable flags (merged for duplicates) */
    pairs cross, fresh;
} recover_ctx;

static scaf_status err_point_on_segment(scaf_error *err, const cdt_input *in, int s, int v)
{
    return err_set(err, SCAF_ERR_MESH,
                   "point %d (%.17g, %.17g) lies in the interior of segment %d (%d->%d)", v,
                   in->points[2 * v], in->points[2 * v + 1], s, in->segments[2 * s],
                   in->segments[2 * s + 1]);
}

static scaf_status err_crossing(scaf_error *err, const cdt_input *in, int s, int s2)
{
    return err_set(err, SCAF_ERR_MESH, "segment %d (%d->%d) crosses segment %d (%d->%d)", s,
                   in->segments[2 * s], in->segments[2 * s + 1], s2, in->segments[2 * s2],
                   in->segments[2 * s2 + 1]);
}

/* Is v (collinear with a->b, on the b side of a) strictly before b? */
static int before_b(const cdt_mesh *m, int a, int b, int v)
{
    const double *pa = m->xy + 2 * a, *pb = m->xy + 2 * b, *pv = m->xy + 2 * v;
    int ax = fabs(pb[0] - pa[0]) >= fabs(pb[1] - pa[1]) ? 0 : 1;
    return pb[ax] > pa[ax] ? pv[ax] < pb[ax] : pv[ax] > pb[ax];
}

/* Lawson flips of the edges in ctx->fresh until each is locally Delaunay. */
static scaf_status restore_delaunay(recover_ctx *ctx, scaf_error *err)
{
    cdt_mesh *m = ctx->m;
    pairs *q = &ctx->fresh;
    long budget = 64L * m->nt + 1024; /* Lawson terminates; this only guards bugs */
    while (q->n > 0) {
        if (--budget < 0) return err_set(err, SCAF_ERR_INTERNAL, "Delaunay flips did not converge");
        q->n--;
        int u = q->v[2 * q->n], w = q->v[2 * q->n + 1];
        int c = cdt_mesh_find_edge(m, u, w);
        if (c < 0 || m->S[c] >= 0 || m->N[c] < 0) continue;
        int e = m->N[c];
        if (!(cdt_incircle_t(m, c / 3, m->xy + 2 * m->V[e]) > 0)) continue;
        int x = m->V[c], y = m->V[e];
        cdt_mesh_flip(m, c);
        /* the four outer edges of the new pair may now be non-Delaunay */
        if (pairs_push(q, x, u) || pairs_push(q, u, y) || pairs_push(q, y, w) ||
            pairs_push(q, w, x))
            return err_nomem(err, "constrained Delaunay flips");
    }
    return SCAF_OK;
}

static scaf_status recover_segment(recover_ctx *ctx, int s, scaf_error *err)
{
    cdt_mesh *m = ctx->m;
    const cdt_input *in = ctx->in;
    int a = in->segments[2 * s], b = in->segments[2 * s + 1];
    int c = cdt_mesh_find_edge(m, a, b);
    if (c < 0) c = cdt_mesh_find_edge(m, b, a);
    if (c >= 0) {
        if (m->S[c] >= 0) { /* the same segment given twice: keep one, merged */
            int s0 = m->S[c] >> 1;
            ctx->split[s0] = ctx->split[s0] && ctx->split[s];
            return SCAF_OK;
        }
        m->S[c] = 2 * s;
        if (m->N[c] >= 0) m->S[m->N[c]] = 2 * s;
        return SCAF_OK;
    }

    /* find the triangle at a that the segment enters */
    int c0 = m->vt[a], ca = c0, found = -1;
    int u = -1, w = -1;
    long guard = 0;
    do {
        u = m->V[cdt_next(ca)];
        w = m->V[cdt_prev(ca)];
        double ou = cdt_orient(m, a, b, u), ow = cdt_orient(m, a, b, w);
        if (ou == 0 && u < in->npoints && before_b(m, a, b, u) &&
            ((m->xy[2 * u] - m->xy[2 * a]) * (m->xy[2 * b] - m->xy[2 * a]) +
             (m->xy[2 * u + 1] - m->xy[2 * a + 1]) * (m->xy[2 * b + 1] - m->xy[2 * a + 1])) > 0)
            return err_point_on_segment(err, in, s, u);
        if (ou < 0 && ow > 0) {
            found = ca;
            break;
        }
        int n = m->N[cdt_next(ca)];
        if (n < 0) break;
        ca = cdt_next(n);
    } while (ca != c0 && ++guard < 3L * m->nt + 3);
    if (found < 0)
        return err_set(err, SCAF_ERR_INTERNAL,
                       "segment %d (%d->%d): no triangle at point %d "
                       "points towards point %d",
                       s, a, b, a, b);

    /* walk to b collecting the crossed edges */
    ctx->cross.n = ctx->cross.head = 0;
    int cc = found; /* corner at a; the crossed edge faces it: u -> w */
    for (;;) {
        if (m->S[cc] >= 0) return err_crossing(err, in, s, m->S[cc] >> 1);
        if (pairs_push(&ctx->cross, u, w)) return err_nomem(err, "segment recovery");
        int e = m->N[cc];
        if (e < 0) return err_set(err, SCAF_ERR_INTERNAL, "segment %d left the triangulation", s);
        int x = m->V[e];
        if (x == b) break;
        double ox = cdt_orient(m, a, b, x);
        if (ox == 0) {
            if (x < in->npoints) return err_point_on_segment(err, in, s, x);
            return err_set(err, SCAF_ERR_INTERNAL, "segment %d runs through a helper vertex", s);
        }
        if (ox > 0) { /* x left: leave through u -> x, facing w */
            w = x;
            cc = cdt_next(e);
        } else { /* x right: leave through x -> w, facing u */
            u = x;
            cc = cdt_prev(e);
        }
    }

    /* Sloan: flip crossing edges whose quadrilateral is convex */
    pairs *q = &ctx->cross;
    ctx->fresh.n = 0;
    long budget = 64L * q->n * (q->n + 4) + 1024;
    while (q->head < q->n) {
        if (--budget < 0)
            return err_set(err, SCAF_ERR_INTERNAL,
                           "segment %d (%d->%d): recovery did not "
                           "converge",
                           s, a, b);
        int eu = q->v[2 * q->head], ew = q->v[2 * q->head + 1];
        q->head++;
        int ce = cdt_mesh_find_edge(m, eu, ew);
        if (ce < 0 || m->N[ce] < 0)
            return err_set(err, SCAF_ERR_INTERNAL, "segment %d: lost a crossing edge", s);
        int x = m->V[ce], y = m->V[m->N[ce]];
        double o1 = cdt_orient(m, x, y, eu), o2 = cdt_orient(m, x, y, ew);
        int convex = (o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0);
        if (!convex) {
            /* compact the queue now and then so it cannot grow without bound */
            if (q->head > 4096 && q->head * 2 > q->n) {
                memmove(q->v, q->v + 2 * q->head, (size_t)(q->n - q->head) * 2 * sizeof(int));
                q->n -= q->head;
                q->head = 0;
            }
            if (pairs_push(q, eu, ew)) return err_nomem(err, "segment recovery");
            continue;
        }
        cdt_mesh_flip(m, ce);
        int still = 0;
        if (x != a && x != b && y != a && y != b) {
            double ox = cdt_orient(m, a, b, x), oy = cdt_orient(m, a, b, y);
            still = (ox > 0 && oy < 0) || (ox < 0 && oy > 0);
        }
        if (pairs_push(still ? q : &ctx->fresh, x, y)) return err_nomem(err, "segment recovery");
    }
    c = cdt_mesh_find_edge(m, a, b);
    if (c < 0) return err_set(err, SCAF_ERR_INTERNAL, "segment %d (%d->%d) not recovered", s, a, b);
    m->S[c] = 2 * s;
    if (m->N[c] >= 0) m->S[m->N[c]] = 2 * s;
    return restore_delaunay(ctx, err);
}

/* ----------------------------------------------------------- regions */

static int flood(cdt_mesh *m, int t0, unsigned char from, unsigned char to, int **stk, int *cap)
{
    if (m->reg[t0] != from) return 0;
    int n = 0;
    m->reg[t0] = to;
    if (*cap < 1) {
        *stk = malloc(64 * sizeof(int));
        if (!*stk) return -1;
        *cap = 64;
    }
    (*stk)[n++] = t0;
    while (n > 0) {
        int t = (*stk)[--n];
        for (int k = 0; k < 3; k++) {
            int c = 3 * t + k, nb = m->N[c];
            if (nb < 0 || m->S[c] >= 0 || m->reg[nb / 3] != from) continue;
            m->reg[nb / 3] = to;
            if (n >= *cap) {
                int *ns = realloc(*stk, (size_t)(*cap) * 2 * sizeof(int));
                if (!ns) return -1;
                *stk = ns;
                *cap *= 2;
            }
            (*stk)[n++] = nb / 3;
        }
    }
    return 0;
}

static int classify(cdt_mesh *m, const cdt_input *in, int n)
{
    int *stk = NULL, cap = 0;
    for (int t = 0; t < m->nt; t++) m->reg[t] = CDT_REG_DOMAIN;
    for (int t = 0; t < m->nt; t++) {
        const int *v = m->V + 3 * t;
        if (v[0] >= n || v[1] >= n || v[2] >= n)
            if (flood(m, t, CDT_REG_DOMAIN, CDT_REG_EXTERIOR, &stk, &cap)) {
                free(stk);
                return -1;
            }
    }
    if (in->left_is_hole)
        for (int s = 0; s < in->nsegments; s++) {
            if (!in->left_is_hole[s]) continue;
            int c = cdt_mesh_find_edge(m, in->segments[2 * s], in->segments[2 * s + 1]);
            if (c >= 0 && flood(m, c / 3, CDT_REG_DOMAIN, CDT_REG_HOLE, &stk, &cap)) {
                free(stk);
                return -1;
            }
        }
    for (int h = 0; h < in->nholes; h++) {
        int t = cdt_mesh_locate(m, m->nt - 1, in->holes + 2 * h);
        if (t >= 0 && flood(m, t, CDT_REG_DOMAIN, CDT_REG_HOLE, &stk, &cap)) {
            free(stk);
            return -1;
        }
    }
    free(stk);
    return 0;
}

/* ------------------------------------------------------------- output */

static scaf_status write_output(const cdt_mesh *m, const cdt_input *in, cdt_output *out,
                                scaf_error *err)
{
    int n = in->npoints, nout = m->nv - 3;
    int *map = malloc((size_t)(m->nt > 0 ? m->nt : 1) * sizeof(int));
    if (!map) return err_nomem(err, "triangulation output");
    int nt = 0, nss = 0;
    for (int t = 0; t < m->nt; t++) map[t] = m->reg[t] == CDT_REG_DOMAIN ? nt++ : -1;
    for (int t = 0; t < m->nt; t++) {
        if (map[t] < 0) continue;
        for (int k = 0; k < 3; k++) {
            int c = 3 * t + k, nb = m->N[c];
            if (m->S[c] >= 0 && (nb < 0 || map[nb / 3] < 0 || nb / 3 > t)) nss++;
        }
    }
    out->npoints = nout;
    out->ntriangles = nt;
    out->nsubsegments = nss;
    out->points = malloc((size_t)(nout > 0 ? nout : 1) * 2 * sizeof(double));
    out->triangles = malloc((size_t)(nt > 0 ? nt : 1) * 3 * sizeof(int));
    out->neighbors = malloc((size_t)(nt > 0 ? nt : 1) * 3 * sizeof(int));
    out->subsegments = malloc((size_t)(nss > 0 ? nss : 1) * 2 * sizeof(int));
    out->subsegment_of = malloc((size_t)(nss > 0 ? nss : 1) * sizeof(int));
    if (!out->points || !out->triangles || !out->neighbors || !out->subsegments ||
        !out->subsegment_of) {
        free(map);
        return err_nomem(err, "triangulation output");
    }
    memcpy(out->points, m->xy, (size_t)n * 2 * sizeof(double));
    if (nout > n)
        memcpy(out->points + 2 * n, m->xy + 2 * (n + 3), (size_t)(nout - n) * 2 * sizeof(double));
#define OUTV(v) ((v) < n ? (v) : (v)-3)
    int j = 0;
    for (int t = 0; t < m->nt; t++) {
        if (map[t] < 0) continue;
        int o = map[t];
        for (int k = 0; k < 3; k++) {
            int c = 3 * t + k, nb = m->N[c];
            out->triangles[3 * o + k] = OUTV(m->V[c]);
            out->neighbors[3 * o + k] = nb >= 0 ? map[nb / 3] : -1;
            if (m->S[c] >= 0 && (nb < 0 || map[nb / 3] < 0 || nb / 3 > t)) {
                int s = m->S[c] >> 1;
                int u = m->V[cdt_next(c)], w = m->V[cdt_prev(c)];
                const double *pa = in->points + 2 * in->segments[2 * s];
                const double *pb = in->points + 2 * in->segments[2 * s + 1];
                double dot = (m->xy[2 * w] - m->xy[2 * u]) * (pb[0] - pa[0]) +
                    (m->xy[2 * w + 1] - m->xy[2 * u + 1]) * (pb[1] - pa[1]);
                if (dot < 0) {
                    int tmp = u;
                    u = w;
                    w = tmp;
                }
                out->subsegments[2 * j] = OUTV(u);
                out->subsegments[2 * j + 1] = OUTV(w);
                out->subsegment_of[j] = s;
                j++;
            }
        }
    }
#undef OUTV
    free(map);
#ifndef NDEBUG
    /* every output triangle counter-clockwise (exactly), neighbours mutual */
    for (int t = 0; t < nt; t++) {
        const int *v = out->triangles + 3 * t;
        assert(orient2d(out->points + 2 * v[0], out->points + 2 * v[1], out->points + 2 * v[2]) >
               0.0);
        for (int k = 0; k < 3; k++) {
            int nb = out->neighbors[3 * t + k];
            assert(nb < 0 || out->neighbors[3 * nb] == t || out->neighbors[3 * nb + 1] == t ||
                   out->neighbors[3 * nb + 2] == t);
        }
    }
#endif
    return SCAF_OK;
}

/* ------------------------------------------------------------- driver */

static scaf_status check_input(const cdt_input *in, const cdt_options *opt, scaf_error *err)
{
    if (in->npoints < 0 || in->nsegments < 0 || in->nholes < 0 ||
        (in->npoints > 0 && !in->points) || (in->nsegments > 0 && !in->segments) ||
        (in->nholes > 0 && !in->holes))
        return err_set(err, SCAF_ERR_USAGE, "cdt: negative count or missing array");
    if (in->npoints > (1 << 28))
        return err_set(err, SCAF_ERR_USAGE, "cdt: %d points is more than supported (2^28)",
                       in->npoints);
    if (!(opt->min_angle_deg >= 0 && opt->min_angle_deg < 60) || !(opt->max_area >= 0) ||
        opt->max_steiner < 0)
        return err_set(err, SCAF_ERR_USAGE,
                       "cdt: options out of range (min angle %g must be in "
                       "[0, 60), max area %g >= 0, max Steiner %d >= 0)",
                       opt->min_angle_deg, opt->max_area, opt->max_steiner);
    for (int i = 0; i < in->npoints; i++)
        if (!isfinite(in->points[2 * i]) || !isfinite(in->points[2 * i + 1]))
            return err_set(err, SCAF_ERR_MESH,
                           "point %d has a non-finite coordinate "
                           "(%g, %g)",
                           i, in->points[2 * i], in->points[2 * i + 1]);
        else if (fabs(in->points[2 * i]) > 0x1p500 || fabs(in->points[2 * i + 1]) > 0x1p500)
            /* the enclosing triangle is 64 times larger: keep it finite */
            return err_set(err, SCAF_ERR_MESH,
                           "point %d (%g, %g) is too large (|coordinate| "
                           "> 2^500)",
                           i, in->points[2 * i], in->points[2 * i + 1]);
    for (int s = 0; s < in->nsegments; s++) {
        int a = in->segments[2 * s], b = in->segments[2 * s + 1];
        if (a < 0 || b < 0 || a >= in->npoints || b >= in->npoints)
            return err_set(err, SCAF_ERR_MESH,
                           "segment %d (%d->%d) references a point "
                           "outside 0..%d",
                           s, a, b, in->npoints - 1);
        if (a == b)
            return err_set(err, SCAF_ERR_MESH,
                           "segment %d is degenerate: both ends are "
                           "point %d",
                           s, a);
    }
    for (int h = 0; h < in->nholes; h++)
        if (!isfinite(in->holes[2 * h]) || !isfinite(in->holes[2 * h + 1]))
            return err_set(err, SCAF_ERR_MESH, "hole seed %d has a non-finite coordinate", h);
    return SCAF_OK;
}

static scaf_status build(const cdt_input *in, const cdt_options *opt, cdt_mesh *m,
                         unsigned char *split, cdt_refine_stats *st, scaf_error *err)
{
    int n = in->npoints;
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            double x = in->points[2 * i + k];
            if (i == 0 || x < lo[k]) lo[k] = x;
            if (i == 0 || x > hi[k]) hi[k] = x;
        }
    double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    double big = ext > 0 ? 64.0 * ext : 1.0;
    big = fmax(big, 1e-300 + 1e-10 * fmax(fabs(cx), fabs(cy)));

    if (cdt_mesh_init(m, n + 3 + n / 2 + 64)) return err_nomem(err, "triangulation");
    for (int i = 0; i < n; i++) cdt_mesh_add_vertex(m, in->points[2 * i], in->points[2 * i + 1]);
    int s0 = cdt_mesh_add_vertex(m, cx - big, cy - big);
    int s1 = cdt_mesh_add_vertex(m, cx + big, cy - big);
    int s2 = cdt_mesh_add_vertex(m, cx, cy + big);
    if (s2 < 0 || cdt_mesh_first_triangle(m, s0, s1, s2)) return err_nomem(err, "triangulation");

    /* ---- Delaunay triangulation of the points ---- */
    int *order = malloc((size_t)(n > 0 ? n : 1) * sizeof(int));
    if (!order || brio_order(in->points, n, lo, ext, order)) {
        free(order);
        return err_nomem(err, "triangulation");
    }
    int last = 0;
    for (int i = 0; i < n; i++) {
        int v = order[i];
        const double *p = m->xy + 2 * v;
        int t = cdt_mesh_locate(m, last, p);
        if (t < 0) {
            free(order);
            return err_set(err, SCAF_ERR_INTERNAL, "point %d outside the enclosing triangle", v);
        }
        for (int k = 0; k < 3; k++) {
            int w = m->V[3 * t + k];
            if (m->xy[2 * w] == p[0] && m->xy[2 * w + 1] == p[1]) {
                free(order);
                return err_set(err, SCAF_ERR_MESH, "points %d and %d coincide at (%.17g, %.17g)",
                               w < v ? w : v, w < v ? v : w, p[0], p[1]);
            }
        }
        int ok = cdt_mesh_cavity(m, p, t, -1);
        if (ok != 1) {
            free(order);
            return ok < 0 ? err_nomem(err, "triangulation")
                          : err_set(err, SCAF_ERR_INTERNAL, "point %d: invalid cavity", v);
        }
        last = cdt_mesh_commit(m, v, -1, -1, -1);
        if (last < 0) {
            free(order);
            return err_nomem(err, "triangulation");
        }
    }
    free(order);

    /* ---- segments ---- */
    recover_ctx rc;
    memset(&rc, 0, sizeof rc);
    rc.m = m;
    rc.in = in;
    rc.split = split;
    scaf_status status = SCAF_OK;
    for (int s = 0; s < in->nsegments && status == SCAF_OK; s++)
        status = recover_segment(&rc, s, err);
    free(rc.cross.v);
    free(rc.fresh.v);
    if (status != SCAF_OK) return status;

    /* ---- regions and refinement ---- */
    if (classify(m, in, n)) return err_nomem(err, "triangulation regions");
    if (opt->min_angle_deg > 0 || opt->max_area > 0) {
        double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        double cap = opt->max_steiner > 0 ? opt->max_steiner : 64.0 * n + 100000.0;
        if (opt->max_steiner <= 0 && opt->max_area > 0) cap += 4.0 * area / opt->max_area;
        if (cap > (double)((1 << 29) - n)) cap = (double)((1 << 29) - n);
        cdt_refine_params prm = {n,        in->segments, split, opt->min_angle_deg, opt->max_area,
                                 (long)cap};
        if (cdt_refine(m, &prm, st)) return err_nomem(err, "triangulation refinement");
    }
    return SCAF_OK;
}

scaf_status cdt_triangulate(const cdt_input *in, const cdt_options *opt, cdt_output *out,
                            scaf_error *err)
{
    if (!out) return err_set(err, SCAF_ERR_USAGE, "cdt: no output");
    memset(out, 0, sizeof *out);
    if (!in) return err_set(err, SCAF_ERR_USAGE, "cdt: no input");
    cdt_options def = cdt_default_options();
    if (!opt) opt = &def;
    scaf_status status = check_input(in, opt, err);
    if (status != SCAF_OK) return status;
    unsigned char *split = malloc((size_t)(in->nsegments > 0 ? in->nsegments : 1));
    if (!split) return err_nomem(err, "triangulation");
    for (int s = 0; s < in->nsegments; s++)
        split[s] = in->splittable ? (in->splittable[s] != 0) : 0;
    cdt_mesh m;
    memset(&m, 0, sizeof m);
    cdt_refine_stats st = {0, 0, 0};
    status = build(in, opt, &m, split, &st, err);
    if (status == SCAF_OK) status = write_output(&m, in, out, err);
    cdt_mesh_free(&m);
    free(split);
    if (status != SCAF_OK) {
        cdt_output_free(out);
        return status;
    }
    out->nsteiner = out->npoints - in->npoints;
    out->nrejected = st.nrejected;
    out->capped = st.capped;
    return SCAF_OK;
}
