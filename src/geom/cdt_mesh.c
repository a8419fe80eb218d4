/* geom/cdt_mesh: triangle structure, point location, Bowyer-Watson cavities, flips.
 *
 * The mutable core of the mesher (see cdt_mesh.h for the layout). Point
 * insertion is Bowyer-Watson: the cavity is grown from the triangle(s)
 * containing the new point across unconstrained edges whose far triangle's
 * circumcircle strictly contains the point (exact incircle), then replaced
 * by a fan. Before anything is changed the fan is checked with exact
 * orient2d: every new triangle must be strictly counter-clockwise, so an
 * insertion can be refused but never produces an inverted or flat
 * triangle. Point location is a stochastic visibility walk (exact
 * orient2d; a deterministic pseudo-random generator breaks cycles) with a
 * step cap and a linear scan as the last resort. Allocation failures are
 * reported as -1 return values.
 */
#include "geom/cdt_mesh.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap) return 0;
    int nc = *cap ? *cap : 16;
    while (nc < need) {
        if (nc > INT_MAX / 2) return -1;
        nc *= 2;
    }
    void *q = realloc(*p, (size_t)nc * elem);
    if (!q) return -1;
    *p = q;
    *cap = nc;
    return 0;
}

static int grow_vertices(cdt_mesh *m, int need)
{
    if (need <= m->capv) return 0;
    int cap = m->capv, nc = cap;
    if (grow((void **)&m->vt, &nc, need, sizeof(int))) return -1;
    nc = cap;
    if (grow((void **)&m->vmark, &nc, need, sizeof(int))) return -1;
    nc = cap;
    if (grow((void **)&m->xy, &nc, need, 2 * sizeof(double))) return -1;
    m->capv = nc;
    return 0;
}

static int grow_triangles(cdt_mesh *m, int need)
{
    if (need <= m->capt) return 0;
    int cap = m->capt, nc = cap;
    if (grow((void **)&m->V, &nc, need, 3 * sizeof(int))) return -1;
    nc = cap;
    if (grow((void **)&m->N, &nc, need, 3 * sizeof(int))) return -1;
    nc = cap;
    if (grow((void **)&m->S, &nc, need, 3 * sizeof(int))) return -1;
    nc = cap;
    if (grow((void **)&m->reg, &nc, need, 1)) return -1;
    nc = cap;
    if (grow((void **)&m->tmark, &nc, need, sizeof(unsigned))) return -1;
    m->capt = nc;
    return 0;
}

int cdt_mesh_init(cdt_mesh *m, int nv_hint)
{
    memset(m, 0, sizeof *m);
    m->stamp = 2;
    m->rng = 0x9e3779b9u;
    if (nv_hint < 16) nv_hint = 16;
    if (grow_vertices(m, nv_hint) || grow_triangles(m, 2 * nv_hint)) return -1;
    return 0;
}

void cdt_mesh_free(cdt_mesh *m)
{
    free(m->xy);
    free(m->vt);
    free(m->vmark);
    free(m->V);
    free(m->N);
    free(m->S);
    free(m->reg);
    free(m->tmark);
    free(m->cav);
    free(m->bnd);
    free(m->ba);
    free(m->bb);
    free(m->bn);
    free(m->bs);
    free(m->br);
    memset(m, 0, sizeof *m);
}

int cdt_mesh_add_vertex(cdt_mesh *m, double x, double y)
{
    if (m->nv == INT_MAX || grow_vertices(m, m->nv + 1)) return -1;
    int v = m->nv++;
    m->xy[2 * v] = x;
    m->xy[2 * v + 1] = y;
    m->vt[v] = -1;
    m->vmark[v] = 0;
    return v;
}

int cdt_mesh_first_triangle(cdt_mesh *m, int a, int b, int c)
{
    if (grow_triangles(m, 1)) return -1;
    m->nt = 1;
    m->V[0] = a;
    m->V[1] = b;
    m->V[2] = c;
    m->N[0] = m->N[1] = m->N[2] = -1;
    m->S[0] = m->S[1] = m->S[2] = -1;
    m->reg[0] = CDT_REG_DOMAIN;
    m->tmark[0] = 0;
    m->vt[a] = 0;
    m->vt[b] = 1;
    m->vt[c] = 2;
    return 0;
}

static unsigned next_rand(cdt_mesh *m)
{
    /* xorshift32: deterministic, state lives in the structure */
    unsigned x = m->rng;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    m->rng = x;
    return x;
}

static int scan_locate(const cdt_mesh *m, const double p[2])
{
    for (int t = 0; t < m->nt; t++) {
        const int *v = m->V + 3 * t;
        if (cdt_orient_p(m, v[0], v[1], p) >= 0 && cdt_orient_p(m, v[1], v[2], p) >= 0 &&
            cdt_orient_p(m, v[2], v[0], p) >= 0)
            return t;
    }
    return -1;
}

int cdt_mesh_locate(cdt_mesh *m, int t, const double p[2])
{
    if (t < 0 || t >= m->nt) t = m->nt - 1;
    int from = -1;
    long limit = 4L * m->nt + 64;
    for (long step = 0; step < limit; step++) {
        static const int rot[7] = {0, 1, 2, 0, 1, 2, 0};
        int k0 = (int)(next_rand(m) % 3u), moved = 0;
        for (int kk = 0; kk < 3; kk++) {
            int c = 3 * t + rot[k0 + kk];
            if (c == from) continue;
            if (cdt_orient_p(m, m->V[3 * t + rot[k0 + kk + 1]], m->V[3 * t + rot[k0 + kk + 2]], p) <
                0) {
                int n = m->N[c];
                if (n < 0) return -1;
                t = n / 3;
                from = n;
                moved = 1;
                break;
            }
        }
        if (!moved) return t;
    }
    return scan_locate(m, p);
}

int cdt_mesh_walk_constrained(cdt_mesh *m, int t, const double p[2], int *blocker)
{
    int from = -1;
    long limit = 4L * m->nt + 64;
    *blocker = -1;
    for (long step = 0; step < limit; step++) {
        int exits[2], nexits = 0, blocked = -1;
        for (int k = 0; k < 3; k++) {
            int c = 3 * t + k;
            if (c == from) continue;
            if (cdt_orient_p(m, m->V[cdt_next(c)], m->V[cdt_prev(c)], p) < 0) {
                if (m->S[c] >= 0 || m->N[c] < 0) blocked = c;
                else if (nexits < 2) exits[nexits++] = c;
            }
        }
        if (nexits == 0) {
            if (blocked >= 0) {
                *blocker = blocked;
                return -1;
            }
            return t;
        }
        int c = exits[nexits == 2 ? (int)(next_rand(m) & 1u) : 0];
        from = m->N[c];
        t = from / 3;
    }
    return -1; /* cycling: treat as unreachable (the caller refuses the point) */
}

static inline int push_int(int **a, int *n, int *cap, int v)
{
    if (*n >= *cap && grow((void **)a, cap, *n + 1, sizeof(int))) return -1;
    (*a)[(*n)++] = v;
    return 0;
}

int cdt_mesh_cavity(cdt_mesh *m, const double p[2], int seed0, int seed1)
{
    if (m->stamp > UINT_MAX - 8) {
        memset(m->tmark, 0, (size_t)m->nt * sizeof(unsigned));
        m->stamp = 2;
    }
    unsigned in = m->stamp, out = m->stamp + 1;
    m->stamp += 2;
    m->ncav = m->nbnd = 0;
    int split_c = -1, split_n = -1;
    if (push_int(&m->cav, &m->ncav, &m->capcav, seed0)) return -1;
    m->tmark[seed0] = in;
    if (seed1 >= 0) {
        for (int k = 0; k < 3; k++)
            if (m->N[3 * seed0 + k] >= 0 && m->N[3 * seed0 + k] / 3 == seed1) {
                split_c = 3 * seed0 + k;
                split_n = m->N[split_c];
            }
        if (split_c < 0) return 0;
        if (push_int(&m->cav, &m->ncav, &m->capcav, seed1)) return -1;
        m->tmark[seed1] = in;
    }
    /* breadth-first: the cavity list is its own queue */
    for (int q = 0; q < m->ncav; q++) {
        int t = m->cav[q];
        for (int k = 0; k < 3; k++) {
            int c = 3 * t + k, n = m->N[c];
            if (n < 0) {
                if (push_int(&m->bnd, &m->nbnd, &m->capbnd, c)) return -1;
                continue;
            }
            int u = n / 3;
            if (m->tmark[u] == in) {
                /* an edge inside the cavity: only the split edge may be constrained */
                if (m->S[c] >= 0 && c != split_c && c != split_n) return 0;
                continue;
            }
            if (m->S[c] < 0 && m->tmark[u] != out) {
                if (cdt_incircle_t(m, u, p) > 0) {
                    m->tmark[u] = in;
                    if (push_int(&m->cav, &m->ncav, &m->capcav, u)) return -1;
                    continue;
                }
                m->tmark[u] = out;
            }
            if (push_int(&m->bnd, &m->nbnd, &m->capbnd, c)) return -1;
        }
    }
    /* the fan must be a single cycle of strictly counter-clockwise triangles */
    if (m->nbnd != m->ncav + 2) return 0;
    int mark = -(int)((in >> 1) & 0x3fffffff) - 1;
    for (int j = 0; j < m->nbnd; j++) {
        int c = m->bnd[j], a = m->V[cdt_next(c)], b = m->V[cdt_prev(c)];
        if (m->vmark[a] == mark) return 0;
        m->vmark[a] = mark;
        if (!(cdt_orient_p(m, a, b, p) > 0)) return 0;
    }
    return 1;
}

int cdt_mesh_commit(cdt_mesh *m, int p, int split_seg, int split_a, int split_b)
{
    int k = m->ncav, nb = m->nbnd;
    if (grow_triangles(m, m->nt + 2)) return -1;
    if (nb > m->capbx) {
        int c0 = m->capbx, c;
        c = c0;
        if (grow((void **)&m->ba, &c, nb, sizeof(int))) return -1;
        c = c0;
        if (grow((void **)&m->bb, &c, nb, sizeof(int))) return -1;
        c = c0;
        if (grow((void **)&m->bn, &c, nb, sizeof(int))) return -1;
        c = c0;
        if (grow((void **)&m->bs, &c, nb, sizeof(int))) return -1;
        c = c0;
        if (grow((void **)&m->br, &c, nb, 1)) return -1;
        m->capbx = c;
    }
    for (int j = 0; j < nb; j++) {
        int c = m->bnd[j];
        m->ba[j] = m->V[cdt_next(c)];
        m->bb[j] = m->V[cdt_prev(c)];
        m->bn[j] = m->N[c];
        m->bs[j] = m->S[c];
        m->br[j] = m->reg[c / 3];
    }
    int base = m->nt;
    m->nt += 2;
    m->tmark[base] = m->tmark[base + 1] = 0;
#define SLOT(j) ((j) < k ? m->cav[(j)] : base + (j)-k)
    for (int j = 0; j < nb; j++) {
        int t = SLOT(j);
        m->V[3 * t] = p;
        m->V[3 * t + 1] = m->ba[j];
        m->V[3 * t + 2] = m->bb[j];
        m->N[3 * t] = m->bn[j];
        if (m->bn[j] >= 0) m->N[m->bn[j]] = 3 * t;
        m->S[3 * t] = m->bs[j];
        m->reg[t] = m->br[j];
        m->vmark[m->ba[j]] = j;
        m->vt[m->ba[j]] = 3 * t + 1;
    }
    for (int j = 0; j < nb; j++) {
        int t = SLOT(j), t2 = SLOT(m->vmark[m->bb[j]]);
        int s = (split_seg >= 0 && (m->bb[j] == split_a || m->bb[j] == split_b)) ? split_seg : -1;
        m->N[3 * t + 1] = 3 * t2 + 2;
        m->N[3 * t2 + 2] = 3 * t + 1;
        m->S[3 * t + 1] = s;
        m->S[3 * t2 + 2] = s;
    }
    m->vt[p] = 3 * SLOT(0);
#undef SLOT
    return k > 0 ? m->cav[0] : base;
}

int cdt_mesh_find_edge(const cdt_mesh *m, int a, int b)
{
    int c0 = m->vt[a];
    if (c0 < 0) return -1;
    int c = c0;
    long guard = 3L * m->nt + 3; /* a broken structure must not hang us */
    /* counter-clockwise around a */
    for (;;) {
        if (m->V[cdt_next(c)] == b) return cdt_prev(c);
        int n = m->N[cdt_next(c)];
        if (n < 0) break;
        c = cdt_next(n);
        if (c == c0 || --guard < 0) return -1;
    }
    /* hit the hull: go clockwise from the start */
    c = c0;
    for (;;) {
        int n = m->N[cdt_prev(c)];
        if (n < 0) return -1;
        c = cdt_prev(n);
        if (m->V[cdt_next(c)] == b) return cdt_prev(c);
        if (c == c0 || --guard < 0) return -1;
    }
}

static void link_corner(cdt_mesh *m, int c, int n, int s)
{
    m->N[c] = n;
    if (n >= 0) m->N[n] = c;
    m->S[c] = s;
}

void cdt_mesh_flip(cdt_mesh *m, int c)
{
    int t = c / 3, e = m->N[c], u = e / 3;
    int a = m->V[c], b = m->V[cdt_next(c)], cc = m->V[cdt_prev(c)], d = m->V[e];
    int ntb = m->N[cdt_next(c)], stb = m->S[cdt_next(c)];
    int ntc = m->N[cdt_prev(c)], stc = m->S[cdt_prev(c)];
    int nuc = m->N[cdt_next(e)], suc = m->S[cdt_next(e)];
    int nub = m->N[cdt_prev(e)], sub = m->S[cdt_prev(e)];
    int *tv = m->V + 3 * t, *uv = m->V + 3 * u;
    tv[0] = a;
    tv[1] = b;
    tv[2] = d;
    uv[0] = d;
    uv[1] = cc;
    uv[2] = a;
    link_corner(m, 3 * t + 0, nuc, suc);
    link_corner(m, 3 * t + 2, ntc, stc);
    link_corner(m, 3 * u + 0, ntb, stb);
    link_corner(m, 3 * u + 2, nub, sub);
    m->N[3 * t + 1] = 3 * u + 1;
    m->N[3 * u + 1] = 3 * t + 1;
    m->S[3 * t + 1] = m->S[3 * u + 1] = -1;
    m->vt[a] = 3 * t;
    m->vt[b] = 3 * t + 1;
    m->vt[d] = 3 * t + 2;
    m->vt[cc] = 3 * u + 1;
}
