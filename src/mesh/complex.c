/* mesh/complex: per-group topology of a triangle list (see complex.h).
 *
 * Everything is linear in the number of faces: the edge table (bucket
 * sort), one pass per statistic, union-find on corners for the fans around
 * vertices, a breadth-first flip propagation for orientability, union-find
 * on boundary half-edges for the loops. Fails only on allocation or on a
 * group label out of range.
 */
#include "mesh/complex.h"

#include "base/sort_u64.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/union_find.h"

void tri_complex_free(tri_complex *c)
{
    if (!c) return;
    mesh_edges_free(&c->edges);
    int **arrays[] = {
        &c->face_group,        &c->group_face_start,  &c->group_faces,      &c->group_vertices,
        &c->group_edges,       &c->group_loops,       &c->group_euler,      &c->group_nm_edges,
        &c->group_nm_vertices, &c->group_misoriented, &c->group_orientable, &c->group_genus,
        &c->group_bad_edge,    &c->group_bad_vertex,  &c->group_bad_orient, &c->loop_group,
        &c->loop_ordered,      &c->loop_start,        &c->loop_he};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) free(*arrays[i]);
    memset(c, 0, sizeof *c);
}

int tri_components(int n, int nf, const int *F, int *face_comp, scaf_error *err)
{
    int *parent = malloc(((size_t)n + 1) * sizeof *parent);
    int *label = malloc(((size_t)n + 1) * sizeof *label);
    if (!parent || !label) {
        free(parent);
        free(label);
        err_nomem(err, "components");
        return -1;
    }
    uf_init(parent, n);
    for (int f = 0; f < nf; f++) {
        int first = -1;
        for (int k = 0; k < 3; k++) {
            int v = F[3 * f + k];
            if (v < 0 || v >= n) continue;
            if (first < 0) first = v;
            else uf_union(parent, first, v);
        }
    }
    for (int v = 0; v < n; v++) label[v] = -1;
    int nc = 0;
    for (int f = 0; f < nf; f++) {
        int v = -1;
        for (int k = 0; k < 3 && v < 0; k++)
            if (F[3 * f + k] >= 0 && F[3 * f + k] < n) v = F[3 * f + k];
        if (v < 0) { /* no usable index at all: a component of its own */
            face_comp[f] = nc++;
            continue;
        }
        int r = uf_find(parent, v);
        if (label[r] < 0) label[r] = nc++;
        face_comp[f] = label[r];
    }
    free(parent);
    free(label);
    return nc;
}

/* Corner of half-edge h's face that sits at index v (v is an endpoint). */
static int corner_at(const int *F, int h, int v)
{
    return F[h] == v ? h : 3 * (h / 3) + (h % 3 + 1) % 3;
}

/* ---- groups: copy labels, face lists ---- */
static scaf_status build_groups(tri_complex *c, int ngroups, const int *face_group, scaf_error *err)
{
    int nf = c->nf;
    c->ngroups = ngroups;
    c->face_group = malloc(((size_t)nf + 1) * sizeof(int));
    c->group_face_start = calloc((size_t)ngroups + 1, sizeof(int));
    c->group_faces = malloc(((size_t)nf + 1) * sizeof(int));
    if (!c->face_group || !c->group_face_start || !c->group_faces)
        return err_nomem(err, "face groups");
    for (int f = 0; f < nf; f++) {
        int g = face_group[f];
        if (g < 0 || g >= ngroups)
            return err_set(err, SCAF_ERR_INTERNAL, "face %d has group %d outside [0, %d)", f, g,
                           ngroups);
        c->face_group[f] = g;
        c->group_face_start[g + 1]++;
    }
    for (int g = 0; g < ngroups; g++) c->group_face_start[g + 1] += c->group_face_start[g];
    int *fill = malloc(((size_t)ngroups + 1) * sizeof *fill);
    if (!fill) return err_nomem(err, "face groups");
    memcpy(fill, c->group_face_start, (size_t)ngroups * sizeof *fill);
    for (int f = 0; f < nf; f++) c->group_faces[fill[c->face_group[f]]++] = f;
    free(fill);
    return SCAF_OK;
}

/* ---- edges: valence, non-manifold, misoriented, per-group edge counts ---- */
static void edge_stats(tri_complex *c, const int *F)
{
    const mesh_edges *E = &c->edges;
    for (int e = 0; e < E->ne; e++) {
        int s = E->edge_he_start[e], t = E->edge_he_start[e + 1];
        int g = c->face_group[E->edge_he[s] / 3];
        c->group_edges[g]++;
        if (t - s == 1) c->boundary_edges++;
        if (t - s > 2) {
            c->nm_edges++;
            c->group_nm_edges[g]++;
            if (c->group_bad_edge[g] < 0) c->group_bad_edge[g] = e;
        }
        int fwd = 0, bwd = 0;
        for (int i = s; i < t; i++) {
            if (F[E->edge_he[i]] == E->ev[2 * e]) fwd++;
            else bwd++;
        }
        int mis = (fwd >= 2) + (bwd >= 2);
        if (mis) {
            c->misoriented += mis;
            c->group_misoriented[g] += mis;
            if (c->group_bad_orient[g] < 0) c->group_bad_orient[g] = e;
        }
    }
}

/* ---- vertices: referenced counts and fans (non-manifold vertices) ---- */
static scaf_status vertex_stats(tri_complex *c, const int *F, scaf_error *err)
{
    int n = c->n, nf = c->nf;
    const mesh_edges *E = &c->edges;
    size_t nc = 3 * (size_t)nf;
    int *parent = malloc((nc ? nc : 1) * sizeof *parent);
    int *fans = calloc((size_t)n + 1, sizeof *fans);
    int *stamp = malloc(((size_t)n + 1) * sizeof *stamp);
    if (!parent || !fans || !stamp) {
        free(parent);
        free(fans);
        free(stamp);
        return err_nomem(err, "vertex fans");
    }
    uf_init(parent, (int)nc);
    /* fans(v) = corners at v - successful merges at v */
    for (int f = 0; f < nf; f++)
        if (E->he_edge[3 * f] >= 0)
            for (int k = 0; k < 3; k++) fans[F[3 * f + k]]++;
    for (int e = 0; e < E->ne; e++) {
        int s = E->edge_he_start[e], t = E->edge_he_start[e + 1];
        for (int end = 0; end < 2; end++) {
            int v = E->ev[2 * e + end];
            int c0 = corner_at(F, E->edge_he[s], v);
            for (int i = s + 1; i < t; i++)
                fans[v] -= uf_union(parent, c0, corner_at(F, E->edge_he[i], v));
        }
    }
    for (int v = 0; v < n; v++) {
        stamp[v] = -1;
        if (fans[v] > 0) c->referenced++;
        if (fans[v] > 1) c->nm_vertices++;
    }
    for (int g = 0; g < c->ngroups; g++) {
        for (int i = c->group_face_start[g]; i < c->group_face_start[g + 1]; i++) {
            int f = c->group_faces[i];
            if (E->he_edge[3 * f] < 0) continue;
            for (int k = 0; k < 3; k++) {
                int v = F[3 * f + k];
                if (stamp[v] == g) continue;
                stamp[v] = g;
                c->group_vertices[g]++;
                if (fans[v] > 1) {
                    c->group_nm_vertices[g]++;
                    if (c->group_bad_vertex[g] < 0) c->group_bad_vertex[g] = v;
                }
            }
        }
    }
    free(parent);
    free(fans);
    free(stamp);
    return SCAF_OK;
}

/* ---- orientability: propagate face flips across 2-face edges ----
 * A group without misoriented edges is consistently oriented as given, so
 * orientable: only groups with misoriented edges need the search. */
static scaf_status orientability(tri_complex *c, const int *F, scaf_error *err)
{
    int nf = c->nf;
    const mesh_edges *E = &c->edges;
    signed char *flip = malloc((size_t)nf + 1);
    int *queue = malloc(((size_t)nf + 1) * sizeof *queue);
    if (!flip || !queue) {
        free(flip);
        free(queue);
        return err_nomem(err, "orientation");
    }
    memset(flip, -1, (size_t)nf + 1);
    for (int g = 0; g < c->ngroups; g++) c->group_orientable[g] = 1;
    for (int i0 = 0; i0 < nf; i0++) {
        int seed = c->group_faces[i0];
        int g = c->face_group[seed];
        if (flip[seed] >= 0 || !c->group_misoriented[g]) continue;
        int head = 0, tail = 0;
        flip[seed] = 0;
        queue[tail++] = seed;
        while (head < tail) {
            int f = queue[head++];
            for (int k = 0; k < 3; k++) {
                int h = 3 * f + k, e = E->he_edge[h];
                if (e < 0 || mesh_edge_valence(E, e) != 2) continue;
                int s = E->edge_he_start[e];
                int h2 = E->edge_he[s] == h ? E->edge_he[s + 1] : E->edge_he[s];
                int f2 = h2 / 3;
                int want = flip[f] ^ (F[h] == F[h2]); /* same direction: flip one */
                if (flip[f2] < 0) {
                    flip[f2] = (signed char)want;
                    queue[tail++] = f2;
                } else if (flip[f2] != want) {
                    c->group_orientable[g] = 0;
                }
            }
        }
    }
    free(flip);
    free(queue);
    return SCAF_OK;
}

/* ---- boundary loops ---- */
static scaf_status boundary_loops(tri_complex *c, const int *F, scaf_error *err)
{
    const mesh_edges *E = &c->edges;
    int n = c->n;
    size_t nh = 3 * (size_t)c->nf;
    int nb = c->boundary_edges;
    scaf_status st = SCAF_OK;
    int *bhe = malloc(((size_t)nb + 1) * sizeof *bhe);   /* boundary half-edges, ascending */
    int *vstart = calloc((size_t)n + 2, sizeof *vstart); /* per-index incidence (CSR) */
    int *vlist = malloc((2 * (size_t)nb + 1) * sizeof *vlist);
    int *parent = malloc(((size_t)nb + 1) * sizeof *parent);
    int *bad = calloc((size_t)nb + 1, sizeof *bad);
    int *next = malloc(((size_t)nb + 1) * sizeof *next);
    int *loop_of = malloc(((size_t)nb + 1) * sizeof *loop_of);
    int *fill = NULL;
    uint64_t *scratch = NULL;
    if (!bhe || !vstart || !vlist || !parent || !bad || !next || !loop_of) goto nomem;

    int m = 0;
    for (size_t h = 0; h < nh; h++) {
        int e = E->he_edge[h];
        if (e >= 0 && mesh_edge_valence(E, e) == 1) bhe[m++] = (int)h;
    }
    for (int i = 0; i < nb; i++) {
        vstart[he_from(F, bhe[i]) + 1]++;
        vstart[he_to(F, bhe[i]) + 1]++;
    }
    for (int v = 0; v < n; v++) vstart[v + 1] += vstart[v];
    fill = malloc(((size_t)n + 1) * sizeof *fill);
    if (!fill) goto nomem;
    memcpy(fill, vstart, ((size_t)n + 1) * sizeof *fill);
    for (int i = 0; i < nb; i++) {
        vlist[fill[he_from(F, bhe[i])]++] = i;
        vlist[fill[he_to(F, bhe[i])]++] = i;
    }

    /* Per index v, its incident boundary half-edges are sorted (by group,
     * then by loop) so that each step is O(k log k) even when thousands of
     * boundary edges meet at one index: no quadratic scan. */
    int maxk = 0;
    for (int v = 0; v < n; v++)
        if (vstart[v + 1] - vstart[v] > maxk) maxk = vstart[v + 1] - vstart[v];
    scratch = malloc(((size_t)maxk + 1) * sizeof *scratch);
    if (!scratch) goto nomem;

    /* link boundary half-edges meeting at an index within one group */
    uf_init(parent, nb);
    for (int v = 0; v < n; v++) {
        int k = 0;
        for (int i = vstart[v]; i < vstart[v + 1]; i++)
            scratch[k++] =
                ((uint64_t)(uint32_t)c->face_group[bhe[vlist[i]] / 3] << 32) | (uint32_t)vlist[i];
        sort_u64(scratch, k);
        for (int i = 1; i < k; i++)
            if (scratch[i] >> 32 == scratch[i - 1] >> 32)
                uf_union(parent, (int)(uint32_t)scratch[i], (int)(uint32_t)scratch[i - 1]);
    }

    /* a loop is a simple cycle iff each of its indices has one out, one in */
    for (int i = 0; i < nb; i++) next[i] = -1;
    for (int v = 0; v < n; v++) {
        int k = 0;
        for (int i = vstart[v]; i < vstart[v + 1]; i++)
            scratch[k++] =
                ((uint64_t)(uint32_t)uf_find(parent, vlist[i]) << 32) | (uint32_t)vlist[i];
        sort_u64(scratch, k);
        for (int s0 = 0, s1; s0 < k; s0 = s1) {
            int r = (int)(scratch[s0] >> 32), outs = 0, ins = 0, out_b = -1, in_b = -1;
            for (s1 = s0; s1 < k && (int)(scratch[s1] >> 32) == r; s1++) {
                int b = (int)(uint32_t)scratch[s1];
                if (he_from(F, bhe[b]) == v) {
                    outs++;
                    out_b = b;
                } else {
                    ins++;
                    in_b = b;
                }
            }
            if (outs != 1 || ins != 1) bad[r] = 1;
            else next[in_b] = out_b;
        }
    }

    /* number loops by their smallest half-edge */
    int nl = 0;
    for (int i = 0; i < nb; i++) loop_of[i] = -1;
    for (int i = 0; i < nb; i++) {
        int r = uf_find(parent, i);
        if (loop_of[r] < 0) loop_of[r] = nl++;
    }
    c->nloops = nl;
    c->loop_group = malloc(((size_t)nl + 1) * sizeof(int));
    c->loop_ordered = malloc(((size_t)nl + 1) * sizeof(int));
    c->loop_start = calloc((size_t)nl + 2, sizeof(int));
    c->loop_he = malloc(((size_t)nb + 1) * sizeof(int));
    if (!c->loop_group || !c->loop_ordered || !c->loop_start || !c->loop_he) goto nomem;
    for (int i = 0; i < nb; i++) {
        int r = uf_find(parent, i), l = loop_of[r];
        c->loop_start[l + 1]++;
        if (r == i) {
            c->loop_group[l] = c->face_group[bhe[i] / 3];
            c->loop_ordered[l] = !bad[r];
            c->group_loops[c->loop_group[l]]++;
        }
    }
    for (int l = 0; l < nl; l++) c->loop_start[l + 1] += c->loop_start[l];
    /* unordered loops: ascending; ordered loops: trace from the root */
    memcpy(fill, c->loop_start, ((size_t)nl + 1) * sizeof *fill);
    for (int i = 0; i < nb; i++) {
        int r = uf_find(parent, i), l = loop_of[r];
        if (!c->loop_ordered[l]) c->loop_he[fill[l]++] = bhe[i];
    }
    for (int i = 0; i < nb; i++) {
        int l = loop_of[i];
        if (uf_find(parent, i) != i || !c->loop_ordered[l]) continue;
        int b = i, len = c->loop_start[l + 1] - c->loop_start[l], steps = 0;
        do {
            c->loop_he[fill[l]++] = bhe[b];
            b = next[b];
        } while (b != i && b >= 0 && ++steps < len);
        if (b != i || fill[l] != c->loop_start[l + 1]) {
            st = err_set(err, SCAF_ERR_INTERNAL, "boundary loop %d does not close", l);
            goto done;
        }
    }
    goto done;

nomem:
    st = err_nomem(err, "boundary loops");
done:
    free(bhe);
    free(vstart);
    free(vlist);
    free(parent);
    free(bad);
    free(next);
    free(loop_of);
    free(fill);
    free(scratch);
    return st;
}

scaf_status tri_complex_build(int n, int nf, const int *F, int ngroups, const int *face_group,
                              tri_complex *c, scaf_error *err)
{
    memset(c, 0, sizeof *c);
    c->n = n;
    c->nf = nf;
    scaf_status st = build_groups(c, ngroups, face_group, err);
    if (st) goto fail;
    st = mesh_edges_build(n, nf, F, &c->edges, err);
    if (st) goto fail;

    int **per_group[] = {&c->group_vertices,    &c->group_edges,      &c->group_loops,
                         &c->group_euler,       &c->group_nm_edges,   &c->group_nm_vertices,
                         &c->group_misoriented, &c->group_orientable, &c->group_genus,
                         &c->group_bad_edge,    &c->group_bad_vertex, &c->group_bad_orient};
    for (size_t i = 0; i < sizeof per_group / sizeof per_group[0]; i++) {
        *per_group[i] = calloc((size_t)ngroups + 1, sizeof(int));
        if (!*per_group[i]) {
            st = err_nomem(err, "group statistics");
            goto fail;
        }
    }
    for (int g = 0; g < ngroups; g++)
        c->group_bad_edge[g] = c->group_bad_vertex[g] = c->group_bad_orient[g] = -1;

    edge_stats(c, F);
    if ((st = vertex_stats(c, F, err))) goto fail;
    if ((st = orientability(c, F, err))) goto fail;
    if ((st = boundary_loops(c, F, err))) goto fail;

    for (int g = 0; g < ngroups; g++) {
        int nfg = c->group_face_start[g + 1] - c->group_face_start[g];
        int chi = c->group_vertices[g] - c->group_edges[g] + nfg;
        c->group_euler[g] = chi;
        int twice = 2 - chi - c->group_loops[g];
        int manifold = !c->group_nm_edges[g] && !c->group_nm_vertices[g];
        c->group_genus[g] =
            manifold && c->group_orientable[g] && twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
    }
    return SCAF_OK;

fail:
    tri_complex_free(c);
    return st;
}
