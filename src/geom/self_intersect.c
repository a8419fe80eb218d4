/* geom/self_intersect: exact self-intersection count of a triangle surface
 * (see the header for which pairs count), accelerated by a uniform grid.
 */
#include "geom/self_intersect.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geom/predicates.h"
#include "geom/simplex_arrays.h"
#include "geom/tri_intersect.h"

/* ---- pair classification ---- */

static const double *pt(const double *V, int i) { return V + 3 * (size_t)i; }

static int orient_sign(const double *const t[3], const double *p)
{
    double o = orient3d(t[0], t[1], t[2], p);
    return (o > 0) - (o < 0);
}

si_pair_kind si_classify_pair(const double *V, const int fa[3], const int fb[3])
{
    /* ia[k] = position in fb of fa[k], or -1 */
    int ia[3], shared = 0;
    for (int k = 0; k < 3; k++) {
        ia[k] = -1;
        for (int l = 0; l < 3; l++)
            if (fa[k] == fb[l]) ia[k] = l;
        shared += ia[k] >= 0;
    }
    const double *a[3] = {pt(V, fa[0]), pt(V, fa[1]), pt(V, fa[2])};
    const double *b[3] = {pt(V, fb[0]), pt(V, fb[1]), pt(V, fb[2])};
    if (shared == 0) return tri_tri_intersect(a, b) ? SI_PAIR_CROSSING : SI_PAIR_NONE;
    if (shared == 3) return SI_PAIR_DUPLICATE;
    if (shared == 1) {
        /* Both faces meet the line of the two planes (or their common
         * plane) in segments starting at v; they overlap beyond v iff the
         * far end of one, on its edge opposite v, lies in the other face. */
        int k = ia[0] >= 0 ? 0 : ia[1] >= 0 ? 1 : 2, l = ia[k];
        /* quick exit: the other two corners of one face strictly on one
         * side of the other's plane, so that face meets the plane only at v */
        int s1 = orient_sign(a, b[(l + 1) % 3]), s2 = orient_sign(a, b[(l + 2) % 3]);
        if (s1 != 0 && s1 == s2) return SI_PAIR_NONE;
        s1 = orient_sign(b, a[(k + 1) % 3]), s2 = orient_sign(b, a[(k + 2) % 3]);
        if (s1 != 0 && s1 == s2) return SI_PAIR_NONE;
        return seg_tri_intersect(a[(k + 1) % 3], a[(k + 2) % 3], b[0], b[1], b[2]) ||
                seg_tri_intersect(b[(l + 1) % 3], b[(l + 2) % 3], a[0], a[1], a[2])
            ? SI_PAIR_VERTEX
            : SI_PAIR_NONE;
    }
    /* shared edge: only coplanar faces with both apexes on one side meet
     * off the edge. */
    int k = ia[0] < 0 ? 0 : ia[1] < 0 ? 1 : 2; /* apex of a */
    int l = 0;
    while (l < 3 && (fb[l] == fa[(k + 1) % 3] || fb[l] == fa[(k + 2) % 3])) l++;
    const double *u = a[(k + 1) % 3], *w = a[(k + 2) % 3], *apex_a = a[k], *apex_b = b[l];
    if (orient3d(u, w, apex_a, apex_b) != 0) return SI_PAIR_NONE;
    int axis = tri3_projection_axis(u, w, apex_a);
    double sa = orient2d_dropping(axis, u, w, apex_a), sb = orient2d_dropping(axis, u, w, apex_b);
    return (sa > 0) == (sb > 0) ? SI_PAIR_EDGE : SI_PAIR_NONE;
}

/* ---- the grid ---- */

typedef struct si_grid {
    double lo[3], half[3]; /* half-extent per axis: hi/2 - lo/2, never overflows */
    int n[3];
} si_grid;

static int cell_coord(const si_grid *g, int k, double x)
{
    if (!(g->half[k] > 0)) return 0;
    double t = (x * 0.5 - g->lo[k] * 0.5) / g->half[k] * g->n[k];
    if (!(t > 0)) return 0;
    if (t >= g->n[k]) return g->n[k] - 1;
    return (int)t;
}

static size_t cell_index(const si_grid *g, const int c[3])
{
    return ((size_t)c[2] * (size_t)g->n[1] + (size_t)c[1]) * (size_t)g->n[0] + (size_t)c[0];
}

/* Number of cells a box covers, saturating at SIZE_MAX. */
static size_t box_cells(const si_grid *g, const double *bl, const double *bh)
{
    size_t cells = 1;
    for (int k = 0; k < 3; k++) {
        size_t w = (size_t)(cell_coord(g, k, bh[k]) - cell_coord(g, k, bl[k]) + 1);
        if (cells > SIZE_MAX / w) return SIZE_MAX;
        cells *= w;
    }
    return cells;
}

/* Per-axis resolution from the mean face extent, at most max_cells cells. */
static void grid_size(si_grid *g, double mean_extent, double max_cells)
{
    double n[3], prod = 1;
    for (int k = 0; k < 3; k++) {
        n[k] = mean_extent > 0 ? g->half[k] / mean_extent : 1;
        if (!(n[k] >= 1)) n[k] = 1;
        if (n[k] > max_cells) n[k] = max_cells;
        prod *= n[k];
    }
    if (prod > max_cells) {
        double s = cbrt(max_cells / prod);
        for (int k = 0; k < 3; k++) n[k] = n[k] * s < 1 ? 1 : n[k] * s;
    }
    for (int k = 0; k < 3; k++) g->n[k] = (int)n[k];
    while ((double)g->n[0] * g->n[1] * g->n[2] > max_cells) {
        int big = g->n[0] >= g->n[1] && g->n[0] >= g->n[2] ? 0 : g->n[1] >= g->n[2] ? 1 : 2;
        g->n[big] = (g->n[big] + 1) / 2;
    }
}

/* ---- recording ---- */

static void record(si_report *r, si_pair_kind kind, int i, int j)
{
    switch (kind) {
    case SI_PAIR_NONE: return;
    case SI_PAIR_CROSSING: r->crossing_pairs++; break;
    case SI_PAIR_VERTEX: r->vertex_pairs++; break;
    case SI_PAIR_EDGE: r->edge_pairs++; break;
    case SI_PAIR_DUPLICATE: r->duplicate_pairs++; break;
    }
    r->pairs++;
    /* keep the SI_FIRST_MAX smallest (i, j), sorted */
    int pos = r->nfirst;
    while (pos > 0 &&
           (r->first[pos - 1][0] > i || (r->first[pos - 1][0] == i && r->first[pos - 1][1] > j)))
        pos--;
    if (pos >= SI_FIRST_MAX) return;
    int last = r->nfirst < SI_FIRST_MAX ? r->nfirst : SI_FIRST_MAX - 1;
    memmove(r->first[pos + 1], r->first[pos], sizeof r->first[0] * (size_t)(last - pos));
    r->first[pos][0] = i;
    r->first[pos][1] = j;
    if (r->nfirst < SI_FIRST_MAX) r->nfirst++;
}

/* ---- the check ---- */

scaf_status si_check(int nv, const double *V, int nf, const int *F, si_report *r, scaf_error *err)
{
    memset(r, 0, sizeof *r);
    r->faces = nf;
    r->first_degenerate = -1;
    scaf_status s = simplex_arrays_check(nv, V, nf, F, 3, "face", err);
    if (s) return s;

    /* boxes of the non-degenerate faces, the global box, the mean extent */
    double *box = malloc(sizeof(double) * 6 * (size_t)(nf > 0 ? nf : 1));
    int *live = malloc(sizeof(int) * (size_t)(nf > 0 ? nf : 1));
    if (!box || !live) {
        free(box);
        free(live);
        return err_nomem(err, "self-intersection check: face boxes");
    }
    si_grid g;
    double hi[3];
    for (int k = 0; k < 3; k++) g.lo[k] = INFINITY, hi[k] = -INFINITY;
    double mean_extent = 0;
    int nlive = 0;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * (size_t)f;
        const double *a = pt(V, t[0]), *b = pt(V, t[1]), *c = pt(V, t[2]);
        if (tri3_degenerate(a, b, c)) {
            r->degenerate_faces++;
            if (r->first_degenerate < 0) r->first_degenerate = f;
            continue;
        }
        double *bx = box + 6 * (size_t)f, ext = 0;
        for (int k = 0; k < 3; k++) {
            bx[k] = fmin(a[k], fmin(b[k], c[k]));
            bx[3 + k] = fmax(a[k], fmax(b[k], c[k]));
            g.lo[k] = fmin(g.lo[k], bx[k]);
            hi[k] = fmax(hi[k], bx[3 + k]);
            ext = fmax(ext, bx[3 + k] * 0.5 - bx[k] * 0.5);
        }
        live[nlive++] = f;
        mean_extent += (ext - mean_extent) / nlive;
    }
    for (int k = 0; k < 3; k++) g.half[k] = nlive ? hi[k] * 0.5 - g.lo[k] * 0.5 : 0;

    /* about one cell per face; coarser while the faces would cover more
     * than 16 cells each on average */
    double max_cells = fmin(2.0 * nlive + 1, (double)(1 << 28)); /* also keeps n[k] an int */
    size_t entries = 0, budget = 16 * (size_t)nlive + 1024;
    grid_size(&g, mean_extent, max_cells);
    for (;;) {
        entries = 0;
        for (int i = 0; i < nlive && entries <= budget; i++) {
            const double *bx = box + 6 * (size_t)live[i];
            size_t c = box_cells(&g, bx, bx + 3);
            entries = c > SIZE_MAX - entries ? SIZE_MAX : entries + c;
        }
        if (entries <= budget || (g.n[0] == 1 && g.n[1] == 1 && g.n[2] == 1)) break;
        max_cells = fmax(1, max_cells / 8);
        grid_size(&g, mean_extent, max_cells);
    }
    size_t ncells = (size_t)g.n[0] * g.n[1] * g.n[2];
    size_t *start = calloc(ncells + 1, sizeof *start);
    int *cell_faces = malloc(sizeof(int) * (entries > 0 ? entries : 1));
    if (!start || !cell_faces) {
        free(box);
        free(live);
        free(start);
        free(cell_faces);
        return err_nomem(err, "self-intersection check: grid");
    }
    /* counting sort of (cell, face): faces stay in increasing order per cell */
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < nlive; i++) {
            const double *bx = box + 6 * (size_t)live[i];
            int c0[3], c1[3], c[3];
            for (int k = 0; k < 3; k++)
                c0[k] = cell_coord(&g, k, bx[k]), c1[k] = cell_coord(&g, k, bx[3 + k]);
            for (c[2] = c0[2]; c[2] <= c1[2]; c[2]++)
                for (c[1] = c0[1]; c[1] <= c1[1]; c[1]++)
                    for (c[0] = c0[0]; c[0] <= c1[0]; c[0]++) {
                        size_t ci = cell_index(&g, c);
                        if (pass == 0) start[ci + 1]++;
                        else cell_faces[start[ci]++] = live[i];
                    }
        }
        if (pass == 0) {
            for (size_t ci = 0; ci < ncells; ci++) start[ci + 1] += start[ci];
        } else {
            for (size_t ci = ncells; ci > 0; ci--) start[ci] = start[ci - 1];
            start[0] = 0;
        }
    }

    /* every pair of faces in a cell, tested only in the cell holding the
     * low corner of their box overlap */
    for (size_t ci = 0; ci < ncells; ci++) {
        for (size_t x = start[ci]; x < start[ci + 1]; x++) {
            int i = cell_faces[x];
            const double *bi = box + 6 * (size_t)i;
            for (size_t y = x + 1; y < start[ci + 1]; y++) {
                int j = cell_faces[y];
                const double *bj = box + 6 * (size_t)j;
                int c[3], overlap = 1;
                for (int k = 0; k < 3 && overlap; k++) {
                    if (bi[k] > bj[3 + k] || bj[k] > bi[3 + k]) overlap = 0;
                    c[k] = cell_coord(&g, k, fmax(bi[k], bj[k]));
                }
                if (!overlap || cell_index(&g, c) != ci) continue;
                record(r, si_classify_pair(V, F + 3 * (size_t)i, F + 3 * (size_t)j), i, j);
            }
        }
    }
    free(box);
    free(live);
    free(start);
    free(cell_faces);
    r->intersection_free = r->pairs == 0 && r->degenerate_faces == 0;
    return SCAF_OK;
}
