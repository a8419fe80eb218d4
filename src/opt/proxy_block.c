/* opt/proxy_block: one term's share of the SLIM proxy system, cached pattern.
 *
 * Pattern: every local corner pair (i <= j) of every simplex whose corners
 * are both free gives a vertex-level entry (min dof, max dof); entries are
 * bucketed by column, sorted by row and deduplicated once, and the
 * simplex -> entry map recorded. Because unknowns are interleaved, vertex
 * entry (I, J) owns in scalar column J*d + a' the d consecutive rows
 * I*d + 0..d-1 (only rows up to a' when I == J, which sorts last), so a
 * scalar position is colptr[J*d + a'] + (entry - vcolptr[J]) * d + a.
 * A simplex block keeps that position for a' = 0 per corner pair (pos)
 * and per vertex column the step to its next scalar column (stride): the
 * fill needs no search and no lookup of the column's scalar starts.
 */
#include "opt/proxy_block.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"
#include "opt/sd2_lanes.h"

int opt_dof_numbering(int nv, const unsigned char *fixed, int *dof)
{
    int k = 0;
    for (int v = 0; v < nv; v++) dof[v] = (fixed && fixed[v]) ? -1 : k++;
    return k;
}

void opt_proxy_block_free(opt_proxy_block *b)
{
    if (!b) return;
    free(b->vcolptr);
    free(b->vrowidx);
    free(b->map);
    free(b->pos);
    free(b->stride);
    free(b->first);
    opt_csc_free(&b->A);
    opt_fill_split_free(&b->split);
    unsigned v = b->version;
    memset(b, 0, sizeof *b);
    b->version = v;
}

typedef struct row_id {
    int row, id;
} row_id;

static int cmp_row_id(const void *pa, const void *pb)
{
    const row_id *a = pa, *b = pb;
    return (a->row > b->row) - (a->row < b->row);
}

/* Entries ent, bucketed by column (b->vcolptr: bucket starts, nfree + 1),
 * sorted by row and deduplicated in place; b->map[id] gets the vertex-level
 * entry of each, b->vcolptr the deduplicated column starts. fill: scratch
 * of nfree + 1. */
static void sort_columns(opt_proxy_block *b, row_id *ent, int *fill)
{
    int nfree = b->nfree, out = 0;
    for (int c = 0; c < nfree; c++) {
        int lo = b->vcolptr[c], hi = b->vcolptr[c + 1];
        if (hi - lo > 24) {
            qsort(ent + lo, (size_t)(hi - lo), sizeof *ent, cmp_row_id);
        } else {
            for (int i = lo + 1; i < hi; i++) {
                row_id x = ent[i];
                int j = i - 1;
                while (j >= lo && ent[j].row > x.row) {
                    ent[j + 1] = ent[j];
                    j--;
                }
                ent[j + 1] = x;
            }
        }
        fill[c] = out;
        for (int i = lo; i < hi; i++) {
            if (i == lo || ent[i].row != ent[i - 1].row) ent[out++].row = ent[i].row;
            b->map[ent[i].id] = out - 1;
        }
    }
    fill[nfree] = out;
    memcpy(b->vcolptr, fill, ((size_t)nfree + 1) * sizeof *fill);
}

/* The scalar upper CSC of the vertex-level pattern, values zeroed; frees
 * the block on failure. */
static scaf_status expand_scalar(opt_proxy_block *b, scaf_error *err)
{
    scaf_status st =
        opt_csc_expand_vertex_pattern(&b->A, b->d, b->nfree, b->vcolptr, b->vrowidx, 1, err);
    if (st != SCAF_OK) {
        opt_proxy_block_free(b);
        return st;
    }
    b->version++;
    return SCAF_OK;
}

/* The end of a pattern build: entries ent bucketed by column (b->vcolptr)
 * sorted, deduplicated and mapped (sort_columns), the row indices stored
 * and the scalar pattern expanded. Frees ent and fill; frees the block on
 * failure. */
static scaf_status finish_pattern(opt_proxy_block *b, row_id *ent, int *fill, scaf_error *err)
{
    sort_columns(b, ent, fill);
    free(fill);
    int out = b->vcolptr[b->nfree];
    b->vrowidx = malloc(((size_t)out + 1) * sizeof *b->vrowidx);
    if (!b->vrowidx) {
        free(ent);
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    for (int k = 0; k < out; k++) b->vrowidx[k] = ent[k].row;
    free(ent);
    return expand_scalar(b, err);
}

/* A simplex block's vertex-level entries (map) turned in place into the
 * positions of their values (pos), and the columns' strides: the fill
 * used to look up vcolptr and two colptr entries per corner pair
 * (aphrodite, one thread: the chart's fill 6.7-7.5 -> 5.4-6.3 ms with
 * scatter_triangle). Frees the block on failure. */
static scaf_status simplex_positions(opt_proxy_block *b, const opt_simplices *S, const int *dof,
                                     scaf_error *err)
{
    int d = b->d, nc = d + 1, P = (d + 1) * (d + 2) / 2;
    const int *cp = b->A.colptr;
    b->stride = malloc(((size_t)b->nfree + 1) * sizeof *b->stride);
    if (!b->stride) {
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    for (int c = 0; c < b->nfree; c++) b->stride[c] = d > 1 ? cp[c * d + 1] - cp[c * d] : 0;
    /* each entry's first writer, while map still holds entries */
    unsigned char *seen = calloc((size_t)b->vcolptr[b->nfree] + 1, 1);
    b->first = malloc(((size_t)S->n + 1) * sizeof *b->first);
    if (!seen || !b->first) {
        free(seen);
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    for (int s = 0; s < S->n; s++) {
        const int *mp = b->map + (size_t)s * P;
        unsigned f = 0;
        for (int p = 0; p < P; p++)
            if (mp[p] >= 0 && !seen[mp[p]]) {
                seen[mp[p]] = 1;
                f |= 1u << p;
            }
        b->first[s] = (unsigned short)f;
    }
    free(seen);
    for (int s = 0; s < S->n; s++) {
        const int *ix = S->idx + (size_t)s * nc;
        int *mp = b->map + (size_t)s * P, p = 0;
        for (int i = 0; i < nc; i++)
            for (int j = i; j < nc; j++, p++) {
                if (mp[p] < 0) continue;
                int di = dof[ix[i]], dj = dof[ix[j]], col = di > dj ? di : dj;
                mp[p] = cp[col * d] + (mp[p] - b->vcolptr[col]) * d;
            }
    }
    b->pos = b->map;
    b->map = NULL;
    return SCAF_OK;
}

scaf_status opt_proxy_block_pattern(opt_proxy_block *b, const opt_simplices *S, const int *dof,
                                    int nfree, scaf_error *err)
{
    opt_proxy_block_free(b);
    int d = S->d, nc = d + 1, P = (d + 1) * (d + 2) / 2;
    size_t ne = (size_t)S->n * P;
    int top = -1;
    for (size_t k = 0; k < (size_t)S->n * nc; k++) {
        int v = dof[S->idx[k]];
        if (v >= nfree)
            return err_set(err, SCAF_ERR_INTERNAL, "simplex %zu: dof %d outside [0, %d)", k / nc, v,
                           nfree);
        if (v > top) top = v;
    }
    nfree = top + 1;
    b->d = d;
    b->ns = S->n;
    b->nfree = nfree;
    b->vcolptr = calloc((size_t)nfree + 1, sizeof *b->vcolptr);
    b->map = malloc((ne ? ne : 1) * sizeof *b->map);
    row_id *ent = malloc((ne ? ne : 1) * sizeof *ent);
    int *fill = malloc(((size_t)nfree + 1) * sizeof *fill);
    if (!b->vcolptr || !b->map || !ent || !fill) {
        free(ent);
        free(fill);
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    /* Count entries per vertex column. */
    for (int s = 0; s < S->n; s++) {
        const int *ix = S->idx + (size_t)s * nc;
        for (int i = 0; i < nc; i++)
            for (int j = i; j < nc; j++) {
                int di = dof[ix[i]], dj = dof[ix[j]];
                if (di < 0 || dj < 0) continue;
                b->vcolptr[(di > dj ? di : dj) + 1]++;
            }
    }
    for (int c = 0; c < nfree; c++) b->vcolptr[c + 1] += b->vcolptr[c];
    memcpy(fill, b->vcolptr, ((size_t)nfree + 1) * sizeof *fill);
    for (int s = 0; s < S->n; s++) {
        const int *ix = S->idx + (size_t)s * nc;
        int p = 0;
        for (int i = 0; i < nc; i++)
            for (int j = i; j < nc; j++, p++) {
                int di = dof[ix[i]], dj = dof[ix[j]];
                size_t id = (size_t)s * P + p;
                b->map[id] = -1;
                if (di < 0 || dj < 0) continue;
                int col = di > dj ? di : dj, row = di < dj ? di : dj;
                ent[fill[col]].row = row;
                ent[fill[col]++].id = (int)id;
            }
    }
    scaf_status st = finish_pattern(b, ent, fill, err);
    if (st != SCAF_OK) return st;
    return simplex_positions(b, S, dof, err);
}

scaf_status opt_proxy_block_pattern_vertices(opt_proxy_block *b, int d, int n, const int *verts,
                                             const int *dof, int nfree, scaf_error *err)
{
    opt_proxy_block_free(b);
    int top = -1;
    for (int i = 0; i < n; i++) {
        int v = dof[verts[i]];
        if (v >= nfree)
            return err_set(err, SCAF_ERR_INTERNAL, "vertex %d: dof %d outside [0, %d)", verts[i], v,
                           nfree);
        if (v > top) top = v;
    }
    b->d = d;
    b->nfree = top + 1;
    b->vcolptr = calloc((size_t)b->nfree + 1, sizeof *b->vcolptr);
    b->vrowidx = malloc(((size_t)n + 1) * sizeof *b->vrowidx);
    if (!b->vcolptr || !b->vrowidx) {
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    for (int i = 0; i < n; i++)
        if (dof[verts[i]] >= 0) b->vcolptr[dof[verts[i]] + 1] = 1; /* once per vertex */
    for (int c = 0; c < b->nfree; c++) {
        if (b->vcolptr[c + 1]) b->vrowidx[b->vcolptr[c]] = c;
        b->vcolptr[c + 1] += b->vcolptr[c];
    }
    return expand_scalar(b, err);
}

scaf_status opt_proxy_block_pattern_pairs(opt_proxy_block *b, int d, int n, const int *pairs,
                                          const int *dof, int nfree, scaf_error *err)
{
    opt_proxy_block_free(b);
    int top = -1;
    for (size_t k = 0; k < 2 * (size_t)n; k++) {
        int v = dof[pairs[k]];
        if (v >= nfree)
            return err_set(err, SCAF_ERR_INTERNAL, "pair %zu: dof %d outside [0, %d)", k / 2, v,
                           nfree);
        if (v > top) top = v;
    }
    nfree = top + 1;
    /* entries: the n pairs, then the diagonal of every free vertex they touch */
    size_t ne = (size_t)n + (size_t)nfree;
    b->d = d;
    b->nfree = nfree;
    b->vcolptr = calloc((size_t)nfree + 1, sizeof *b->vcolptr);
    b->map = malloc((ne ? ne : 1) * sizeof *b->map);
    row_id *ent = malloc((ne ? ne : 1) * sizeof *ent);
    int *fill = malloc(((size_t)nfree + 1) * sizeof *fill);
    unsigned char *used = calloc((size_t)nfree + 1, 1);
    if (!b->vcolptr || !b->map || !ent || !fill || !used) {
        free(ent);
        free(fill);
        free(used);
        opt_proxy_block_free(b);
        return err_nomem(err, "proxy system pattern");
    }
    for (int k = 0; k < n; k++) {
        int di = dof[pairs[2 * k]], dj = dof[pairs[2 * k + 1]];
        if (di < 0 || dj < 0) continue;
        b->vcolptr[(di > dj ? di : dj) + 1]++;
        used[di] = used[dj] = 1;
    }
    for (int c = 0; c < nfree; c++) b->vcolptr[c + 1] += b->vcolptr[c] + used[c];
    memcpy(fill, b->vcolptr, ((size_t)nfree + 1) * sizeof *fill);
    for (int k = 0; k < n; k++) {
        int di = dof[pairs[2 * k]], dj = dof[pairs[2 * k + 1]];
        b->map[k] = -1;
        if (di < 0 || dj < 0) continue;
        int col = di > dj ? di : dj;
        ent[fill[col]].row = di < dj ? di : dj;
        ent[fill[col]++].id = k;
    }
    for (int c = 0; c < nfree; c++) {
        b->map[n + c] = -1;
        if (!used[c]) continue;
        ent[fill[c]].row = c;
        ent[fill[c]++].id = n + c;
    }
    free(used);
    return finish_pattern(b, ent, fill, err);
}

void opt_proxy_block_add_pair(opt_proxy_block *b, int k, const int *dof, const int *pairs, double w)
{
    int e = b->map[k];
    if (e < 0) return;
    int di = dof[pairs[2 * k]], dj = dof[pairs[2 * k + 1]], col = di > dj ? di : dj;
    int d = b->d, off = (e - b->vcolptr[col]) * d;
    int *cp = b->A.colptr;
    for (int a = 0; a < d; a++) b->A.val[cp[col * d + a] + off + a] += w;
}

void opt_proxy_block_add_diagonal(opt_proxy_block *b, int k, double w)
{
    for (int a = 0; a < b->d; a++) b->A.val[b->A.colptr[k * b->d + a + 1] - 1] += w;
}

/* <G row i, G row j> (rows of d), summed in order. */
static inline double dot_rows(const double *G, int i, int j, int d)
{
    double gg = 0;
    for (int q = 0; q < d; q++) gg += G[i * d + q] * G[j * d + q];
    return gg;
}

/* Accumulate one simplex: coefficient matrix M (d by d, symmetric) and
 * per-corner linear terms lin ((d+1) by d); only into the columns and rhs
 * entries of free vertices with dofs in [lo, hi) (a thread's share of a
 * parallel fill; the serial fill passes everything). */
static inline void scatter_d(opt_proxy_block *b, const opt_simplices *S, int s, const int *dof,
                             const double *X, const double *M, const double *lin, double *rhs,
                             int d, int lo, int hi)
{
    int nc = d + 1, P = (d + 1) * (d + 2) / 2;
    const int *ix = S->idx + (size_t)s * nc;
    const double *G = S->grad + (size_t)s * nc * d;
    const int *pp = b->pos + (size_t)s * P;
    double w = S->weight[s];
    double *val = b->A.val;
    for (int i = 0; i < nc; i++) {
        int di = dof[ix[i]];
        if (di >= lo && di < hi)
            for (int a = 0; a < d; a++) rhs[(size_t)di * d + a] += w * lin[i * d + a];
    }
    int p = 0;
    for (int i = 0; i < nc; i++)
        for (int j = i; j < nc; j++, p++) {
            int di = dof[ix[i]], dj = dof[ix[j]];
            if (pp[p] < 0) {
                /* One corner fixed: its coupling moves to the right side. */
                if (i == j || (di < 0 && dj < 0)) continue;
                int fr = di >= 0 ? di : dj;
                if (fr < lo || fr >= hi) continue;
                double c = w * dot_rows(G, i, j, d);
                const double *xf = X + (size_t)ix[di >= 0 ? j : i] * d;
                for (int a = 0; a < d; a++) {
                    double acc = 0;
                    for (int q = 0; q < d; q++) acc += M[a * d + q] * xf[q];
                    rhs[(size_t)fr * d + a] -= c * acc;
                }
                continue;
            }
            int col = di > dj ? di : dj, row = di < dj ? di : dj;
            if (col < lo || col >= hi) continue;
            double c = w * dot_rows(G, i, j, d);
            double *v0 = val + pp[p];
            int st = b->stride[col], fst = b->first[s] >> p & 1;
            if (row != col) {
                for (int a2 = 0; a2 < d; a2++) {
                    double *v = v0 + a2 * st + a2 * (a2 - 1) / 2;
                    for (int a = 0; a < d; a++) v[a] = (fst ? 0.0 : v[a]) + c * M[a * d + a2];
                }
            } else {
                /* Diagonal block; a repeated vertex (i != j) counts twice. */
                double cc = i == j ? c : 2.0 * c;
                for (int a2 = 0; a2 < d; a2++) {
                    double *v = v0 + a2 * st + a2 * (a2 - 1) / 2;
                    for (int a = 0; a <= a2; a++) v[a] = (fst ? 0.0 : v[a]) + cc * M[a * d + a2];
                }
            }
        }
}

/* scatter_d for a triangle whose corners are free, distinct and all in
 * the range (dofs d3): the same operations in the same order, without its
 * per-pair tests (aphrodite, one thread: assembly 8.2 -> 7.7 ms). */
static inline void scatter_triangle(opt_proxy_block *b, const opt_simplices *S, int s,
                                    const int *d3, const double *M, const double *lin, double *rhs)
{
    const double *G = S->grad + (size_t)s * 6;
    const int *pp = b->pos + (size_t)s * 6;
    double w = S->weight[s], *val = b->A.val;
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 2; a++) rhs[(size_t)d3[i] * 2 + a] += w * lin[i * 2 + a];
    int p = 0;
    unsigned f = b->first[s];
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++, p++) {
            double c = w * dot_rows(G, i, j, 2);
            double *v0 = val + pp[p], *v1 = v0 + b->stride[d3[i] > d3[j] ? d3[i] : d3[j]];
            if (f >> p & 1) { /* the entry's first writer: 0 + x, as after zeroing */
                v0[0] = 0.0 + c * M[0];
                if (i != j) v0[1] = 0.0 + c * M[2];
                v1[0] = 0.0 + c * M[1];
                v1[1] = 0.0 + c * M[3];
            } else {
                v0[0] += c * M[0];
                if (i != j) v0[1] += c * M[2];
                v1[0] += c * M[1];
                v1[1] += c * M[3];
            }
        }
}

/* The same code with d a compile-time constant in the hot 2D case (the
 * compiler unrolls the small loops; the operations and their order are
 * unchanged, so results are bit-identical). */
static void scatter(opt_proxy_block *b, const opt_simplices *S, int s, const int *dof,
                    const double *X, const double *M, const double *lin, double *rhs, int lo,
                    int hi)
{
    if (S->d == 2) {
        const int *ix = S->idx + (size_t)s * 3;
        int d3[3] = {dof[ix[0]], dof[ix[1]], dof[ix[2]]};
        if (d3[0] >= lo && d3[1] >= lo && d3[2] >= lo && d3[0] < hi && d3[1] < hi && d3[2] < hi &&
            d3[0] != d3[1] && d3[1] != d3[2] && d3[0] != d3[2])
            scatter_triangle(b, S, s, d3, M, lin, rhs);
        else scatter_d(b, S, s, dof, X, M, lin, rhs, 2, lo, hi);
    } else {
        scatter_d(b, S, s, dof, X, M, lin, rhs, S->d, lo, hi);
    }
}

/* SLIM proxy of simplex s: M = W^T W, lin = M T G^T per corner; returns w^2. */
static inline double proxy_d(const opt_term *t, int s, const double *X, double w2_cap, double *M,
                             double *lin, int d)
{
    const opt_simplices *S = t->s;
    int nc = d + 1;
    double J[9], W[9], T[9], MT[9];
    opt_jacobian(S, s, X, J);
    double w2 = opt_slim_proxy_capped(t->energy, d, J, w2_cap, W, T);
    for (int a = 0; a < d; a++)
        for (int c = 0; c < d; c++) {
            double acc = 0;
            for (int q = 0; q < d; q++) acc += W[q * d + a] * W[q * d + c];
            M[a * d + c] = acc;
        }
    for (int a = 0; a < d; a++)
        for (int c = 0; c < d; c++) {
            double acc = 0;
            for (int q = 0; q < d; q++) acc += M[a * d + q] * T[q * d + c];
            MT[a * d + c] = acc;
        }
    opt_pullback(d, S->grad + (size_t)s * nc * d, MT, lin);
    return w2;
}

void opt_proxy_block_fill(opt_proxy_block *b, const opt_term *t, const int *dof, const double *X,
                          double *rhs)
{
    opt_proxy_block_fill_capped(b, t, dof, X, rhs, INFINITY);
}

typedef struct zero_job {
    double *val;
    size_t n;
    int nc;
} zero_job;

/* Chunk k of a parallel zeroing of a block's values. */
static void zero_chunk(void *ctx, int k)
{
    const zero_job *z = ctx;
    size_t lo = par_chunk_begin(z->n, z->nc, k), hi = par_chunk_begin(z->n, z->nc, k + 1);
    memset(z->val + lo, 0, (hi - lo) * sizeof *z->val);
}

void opt_proxy_block_zero(opt_proxy_block *b)
{
    zero_job z = {b->A.val, (size_t)b->A.nnz, par_chunks((size_t)b->A.nnz)};
    par_run(z.nc, zero_chunk, &z);
}

/* Simplices whose proxies are computed together (opt_sd2_proxy_range's
 * lanes), then scattered while still in cache. */
#define SD2_BATCH 64

/* Values of one simplex's proxy, M then lin: d*d + (d+1)*d, at most 21 (3D). */
#define PROXY_VALUES_MAX 21

typedef struct fill_job {
    opt_proxy_block *b;
    const opt_term *t;
    const int *dof;
    const double *X;
    double *rhs, w2_cap;
    size_t b0, m;
    int nc;
    const int *cb; /* the batch's column ranges (opt/fill_split) */
    double w2k[PAR_MAX_CHUNKS];
} fill_job;

/* Whether t's proxies go through opt/sd2_lanes (the same values). */
static int sd2(const opt_term *t)
{
    return t->s->d == 2 && t->energy == OPT_ENERGY_SYMMETRIC_DIRICHLET;
}

/* The proxies of simplices [s0, s1) (at most SD2_BATCH) into loc, M then
 * lin per simplex (d*d + (d+1)*d values); returns their largest w^2. */
static double proxies(const opt_term *t, const double *X, double w2_cap, size_t s0, size_t s1,
                      double *loc)
{
    int d = t->s->d, ml = d * d + (d + 1) * d;
    if (sd2(t)) return opt_sd2_proxy_range(t->s, X, s0, s1, w2_cap, loc);
    double w2max = 0;
    for (size_t s = s0; s < s1; s++) {
        double *M = loc + (s - s0) * ml, *lin = M + d * d;
        double w2 = d == 2 ? proxy_d(t, (int)s, X, w2_cap, M, lin, 2)
                           : proxy_d(t, (int)s, X, w2_cap, M, lin, d);
        if (w2 > w2max) w2max = w2;
    }
    return w2max;
}

/* Whether simplex s has no free corner (it writes nothing, but its
 * weight still counts in the largest one). */
static int no_free_corner(const opt_simplices *S, int s, const int *dof)
{
    const int *ix = S->idx + (size_t)s * (S->d + 1);
    for (int i = 0; i <= S->d; i++)
        if (dof[ix[i]] >= 0) return 0;
    return 1;
}

/* Range k of columns over the batch, as the serial fill runs: every run of
 * SD2_BATCH simplices with one that touches the range gets its proxies
 * computed and those simplices scattered at once, while in cache. A run
 * that straddles two ranges is computed by both threads (the same bits);
 * range 0 also takes the runs with a simplex that has no free corner. */
static void fill_range(void *ctx, int k)
{
    fill_job *j = ctx;
    const opt_simplices *S = j->t->s;
    int d = S->d, ml = d * d + (d + 1) * d, lo = j->cb[k], hi = j->cb[k + 1];
    double loc[SD2_BATCH * PROXY_VALUES_MAX];
    for (size_t g0 = j->b0; g0 < j->b0 + j->m; g0 += SD2_BATCH) {
        size_t g1 = g0 + SD2_BATCH < j->b0 + j->m ? g0 + SD2_BATCH : j->b0 + j->m;
        unsigned long long mine = 0;
        int needed = 0;
        for (size_t s = g0; s < g1; s++) {
            if (opt_fill_split_touches(S, (int)s, j->dof, lo, hi)) mine |= 1ull << (s - g0);
            else if (k == 0 && no_free_corner(S, (int)s, j->dof)) needed = 1;
        }
        if (!mine && !needed) continue;
        double w2 = proxies(j->t, j->X, j->w2_cap, g0, g1, loc);
        if (w2 > j->w2k[k]) j->w2k[k] = w2;
        for (size_t s = g0; s < g1; s++)
            if (mine >> (s - g0) & 1) {
                const double *M = loc + (s - g0) * ml;
                scatter(j->b, S, (int)s, j->dof, j->X, M, M + d * d, j->rhs, lo, hi);
            }
    }
}

/* The SLIM fill with nc > 1 chunks (base/parallel), simplices in batches:
 * each thread fills its own columns and rhs entries of the batch
 * (opt/fill_split, the batch's own cut), computing the proxies it needs
 * and scattering them at once, as the serial fill does. Every value still
 * receives its terms in simplex order, so the result is the serial fill's
 * bit for bit, for any thread count. Returns -1 (nothing done) when the
 * column ranges cannot be had; the caller then fills serially. */
static double fill_parallel(opt_proxy_block *b, const opt_term *t, const int *dof, const double *X,
                            double *rhs, double w2_cap, int nc)
{
    size_t n = (size_t)t->s->n;
    fill_job j = {.b = b, .t = t, .dof = dof, .X = X, .rhs = rhs, .w2_cap = w2_cap, .nc = nc};
    if (opt_fill_split_prepare(&b->split, t->s, dof, nc, OPT_FILL_BATCH) != 0) return -1.0;
    /* no zeroing: every entry's first writer stores (b->first) */
    for (j.b0 = 0; j.b0 < n; j.b0 += OPT_FILL_BATCH) {
        j.m = n - j.b0 < OPT_FILL_BATCH ? n - j.b0 : OPT_FILL_BATCH;
        j.cb = opt_fill_split_ranges(&b->split, j.b0);
        par_run(nc, fill_range, &j);
    }
    double w2max = 0;
    for (int k = 0; k < nc; k++)
        if (j.w2k[k] > w2max) w2max = j.w2k[k];
    return w2max;
}

double opt_proxy_block_fill_capped(opt_proxy_block *b, const opt_term *t, const int *dof,
                                   const double *X, double *rhs, double w2_cap)
{
    const opt_simplices *S = t->s;
    int d = S->d, nc = par_chunks((size_t)S->n);
    if (nc > 1) {
        double w2max = fill_parallel(b, t, dof, X, rhs, w2_cap, nc);
        if (w2max >= 0) return w2max;
    }
    /* no zeroing: every entry's first writer stores (b->first) */
    double M[9], lin[12], w2max = 0;
    if (sd2(t)) { /* proxies of SD2_BATCH simplices at a time, scattered in order */
        double loc[SD2_BATCH * 10];
        for (int s0 = 0; s0 < S->n; s0 += SD2_BATCH) {
            int m = S->n - s0 < SD2_BATCH ? S->n - s0 : SD2_BATCH;
            double w2 = opt_sd2_proxy_range(S, X, (size_t)s0, (size_t)(s0 + m), w2_cap, loc);
            if (w2 > w2max) w2max = w2;
            for (int l = 0; l < m; l++)
                scatter(b, S, s0 + l, dof, X, loc + 10 * l, loc + 10 * l + 4, rhs, 0, INT_MAX);
        }
        return w2max;
    }
    for (int s = 0; s < S->n; s++) {
        double w2 =
            d == 2 ? proxy_d(t, s, X, w2_cap, M, lin, 2) : proxy_d(t, s, X, w2_cap, M, lin, d);
        if (w2 > w2max) w2max = w2;
        scatter(b, S, s, dof, X, M, lin, rhs, 0, INT_MAX);
    }
    return w2max;
}

void opt_proxy_block_add_local(opt_proxy_block *b, const opt_simplices *S, int s, const int *dof,
                               const double *K)
{
    opt_proxy_block_add_local_range(b, S, s, dof, K, 0, INT_MAX);
}

void opt_proxy_block_add_local_range(opt_proxy_block *b, const opt_simplices *S, int s,
                                     const int *dof, const double *K, int lo, int hi)
{
    int d = S->d, nc = d + 1, nd = nc * d, P = (d + 1) * (d + 2) / 2;
    const int *ix = S->idx + (size_t)s * nc;
    const int *pp = b->pos + (size_t)s * P;
    double *val = b->A.val;
    int p = 0;
    for (int i = 0; i < nc; i++)
        for (int j = i; j < nc; j++, p++) {
            if (pp[p] < 0) continue;
            int di = dof[ix[i]], dj = dof[ix[j]];
            /* The stored block couples row vertex min(di, dj) with column
             * vertex max(di, dj): corner r gives its rows, corner c its columns. */
            int r = di <= dj ? i : j, c = di <= dj ? j : i, col = di > dj ? di : dj;
            if (col < lo || col >= hi) continue;
            for (int a2 = 0; a2 < d; a2++) {
                double *v = val + pp[p] + a2 * b->stride[col] + a2 * (a2 - 1) / 2;
                if (di != dj) {
                    for (int a = 0; a < d; a++) v[a] += K[(r * d + a) * nd + c * d + a2];
                } else if (i == j) {
                    for (int a = 0; a <= a2; a++) v[a] += K[(i * d + a) * nd + i * d + a2];
                } else { /* a vertex repeated in the simplex: both orders */
                    for (int a = 0; a <= a2; a++)
                        v[a] += K[(i * d + a) * nd + j * d + a2] + K[(j * d + a) * nd + i * d + a2];
                }
            }
        }
}
