/* geom/tet_box_mesh: surface + box -> TetGen -> exact checks (see the
 * header for what is checked and why). */
#include "geom/tet_box_mesh.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/sort_u64.h"
#include "geom/self_intersect.h"
#include "geom/tet_faces.h"
#include "geom/tet_orient.h"
#include "geom/tetgen_call.h"

#define OUTSIDE_ATTRIBUTE (-1.0)

void tet_box_around(int nv, const double *V, double scale, double lo[3], double hi[3])
{
    double blo[3] = {INFINITY, INFINITY, INFINITY}, bhi[3] = {-INFINITY, -INFINITY, -INFINITY},
           ext = 0;
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++) {
            blo[k] = fmin(blo[k], V[3 * (size_t)i + k]);
            bhi[k] = fmax(bhi[k], V[3 * (size_t)i + k]);
        }
    for (int k = 0; k < 3; k++) ext = fmax(ext, bhi[k] * 0.5 - blo[k] * 0.5);
    for (int k = 0; k < 3; k++) {
        double mid = blo[k] * 0.5 + bhi[k] * 0.5, half = bhi[k] * 0.5 - blo[k] * 0.5;
        double grow = fmax(half * scale, half + (scale - 1) * ext);
        lo[k] = mid - grow;
        hi[k] = mid + grow;
    }
}

/* ---- input checks ---- */

static scaf_status check_edges(int nf, const int *F, scaf_error *err)
{
    uint64_t *key = malloc(sizeof(uint64_t) * 3 * (size_t)nf);
    if (!key) return err_nomem(err, "surface edges");
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            uint64_t a = (uint32_t)F[3 * (size_t)f + k],
                     b = (uint32_t)F[3 * (size_t)f + (k + 1) % 3];
            key[3 * (size_t)f + k] = a < b ? a << 32 | b : b << 32 | a;
        }
    sort_u64(key, 3 * nf);
    scaf_status s = SCAF_OK;
    for (int i = 0, j; i < 3 * nf && s == SCAF_OK; i = j) {
        for (j = i; j < 3 * nf && key[j] == key[i]; j++) {}
        int a = (int)(key[i] >> 32), b = (int)(key[i] & 0xffffffffu);
        if (j - i == 1)
            s = err_set(err, SCAF_ERR_MESH, "the surface is open: edge (%d, %d) has one face", a,
                        b);
        else if (j - i > 2)
            s = err_set(err, SCAF_ERR_MESH,
                        "the surface is not manifold: edge (%d, %d) has %d faces", a, b, j - i);
    }
    free(key);
    return s;
}

static scaf_status check_input(int nv, const double *V, int nf, const int *F, const double lo[3],
                               const double hi[3], int box_cells, scaf_error *err)
{
    if (nv < 0 || nf < 0 || (nv && !V) || (nf && !F) || box_cells < 1 || box_cells > 64)
        return err_set(err, SCAF_ERR_USAGE,
                       "tet_box_mesh: bad arguments (%d vertices, %d faces, %d box cells)", nv, nf,
                       box_cells);
    if (nf == 0) return err_set(err, SCAF_ERR_MESH, "the surface has no faces");
    for (int k = 0; k < 3; k++)
        if (!(lo[k] < hi[k]) || !isfinite(lo[k]) || !isfinite(hi[k]))
            return err_set(err, SCAF_ERR_USAGE,
                           "the box is empty or not finite along axis %d (%g .. %g)", k, lo[k],
                           hi[k]);
    si_report r;
    scaf_status s = si_check(nv, V, nf, F, &r, err); /* also validates indices and coordinates */
    if (s) return s;
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            if (!(V[3 * (size_t)i + k] > lo[k] && V[3 * (size_t)i + k] < hi[k]))
                return err_set(err, SCAF_ERR_USAGE,
                               "vertex %d (%g, %g, %g) is not strictly inside the box", i,
                               V[3 * (size_t)i], V[3 * (size_t)i + 1], V[3 * (size_t)i + 2]);
    s = check_edges(nf, F, err); /* open or not manifold: said as such, before the counts */
    if (s) return s;
    if (nv < 4 || nf < 4) /* closed, but flat: a triangle twice, ... */
        return err_set(err, SCAF_ERR_MESH,
                       "the surface encloses no volume: %d vertices and %d faces (a closed "
                       "surface has at least 4 of each)",
                       nv, nf);
    if (r.degenerate_faces > 0)
        return err_set(err, SCAF_ERR_MESH,
                       "the surface has %d zero-area faces (the first: face %d)",
                       r.degenerate_faces, r.first_degenerate);
    if (r.pairs > 0)
        return err_set(err, SCAF_ERR_MESH,
                       "the surface intersects itself: %lld pairs of faces (the first: faces %d "
                       "and %d)",
                       r.pairs, r.first[0][0], r.first[0][1]);
    return SCAF_OK;
}

/* ---- the box ---- */

static double lerp(double a, double b, int i, int n)
{
    return a * ((double)(n - i) / n) + b * ((double)i / n);
}

/* Points of the box surface grid appended after the nv surface points;
 * grid[(i * (n + 1) + j) * (n + 1) + k] = point index of lattice point
 * (i, j, k) on the surface of the lattice cube, -1 inside. */
static scaf_status build_box(int nv, const double lo[3], const double hi[3], int n, tet_box_mesh *m,
                             double *P, scaf_error *err)
{
    size_t side = (size_t)n + 1;
    int *grid = malloc(sizeof(int) * side * side * side);
    if (!grid) return err_nomem(err, "box grid");
    int np = nv;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            for (int k = 0; k <= n; k++) {
                int c[3] = {i, j, k}, on = 0;
                for (int a = 0; a < 3; a++) on |= c[a] == 0 || c[a] == n;
                grid[((size_t)i * side + j) * side + k] = on ? np : -1;
                if (!on) continue;
                for (int a = 0; a < 3; a++) P[3 * (size_t)np + a] = lerp(lo[a], hi[a], c[a], n);
                np++;
            }
    m->nbox = np - nv;
    int nt = 0;
    for (int a = 0; a < 3; a++) {
        int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int s = 0; s <= n; s += n)
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    int q[4], c[3];
                    const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
                    for (int corner = 0; corner < 4; corner++) {
                        c[a] = s;
                        c[u] = i + du[corner];
                        c[v] = j + dv[corner];
                        q[corner] = grid[((size_t)c[0] * side + c[1]) * side + c[2]];
                    }
                    /* e_u x e_v = e_a: outward on the high side, reversed on the low */
                    int t0[3] = {q[0], q[1], q[2]}, t1[3] = {q[0], q[2], q[3]};
                    if (s == 0) t0[1] = q[2], t0[2] = q[1], t1[1] = q[3], t1[2] = q[2];
                    memcpy(m->box_F + 3 * (size_t)nt++, t0, sizeof t0);
                    memcpy(m->box_F + 3 * (size_t)nt++, t1, sizeof t1);
                }
    }
    m->nbox_faces = nt;
    free(grid);
    return SCAF_OK;
}

/* ---- output checks ---- */

/* Face structure and labels. nb[4t + k]: the tet across face k of tet t
 * (-1 on the hull); cross[4t + k]: that face is a surface triangle. The
 * labels come from a walk from the hull tets (outside, 0) flipping at
 * every surface triangle, so nested shells label right (a cavity is
 * outside); the walk fails if the surface does not separate consistently.
 * TetGen's region attribute is a cross-check: its seeded outer region
 * must be labelled outside. */
static scaf_status label_and_check(tet_box_mesh *m, int nf, const int *F, const double *attribute,
                                   scaf_error *err)
{
    size_t nref = 4 * (size_t)m->nt;
    tet_face_ref *fr = tet_faces_sorted(m->nt, m->T);
    int *nb = malloc(sizeof(int) * (nref > 0 ? nref : 1));
    int *queue = malloc(sizeof(int) * (size_t)(m->nt > 0 ? m->nt : 1));
    signed char *cross = calloc(nref > 0 ? nref : 1, 1);
    m->inside = malloc((size_t)(m->nt > 0 ? m->nt : 1));
    if (!fr || !nb || !queue || !cross || !m->inside) {
        free(fr);
        free(nb);
        free(queue);
        free(cross);
        return err_nomem(err, "tet faces");
    }
    scaf_status s = SCAF_OK;
    int hull = 0;
    for (size_t i = 0, j; i < nref && s == SCAF_OK; i = j) {
        for (j = i + 1; j < nref && !memcmp(fr[j].v, fr[i].v, sizeof fr[0].v); j++) {}
        size_t a = 4 * (size_t)fr[i].tet + fr[i].side;
        if (j - i == 1) {
            hull++;
            nb[a] = -1;
        } else if (j - i == 2) {
            nb[a] = fr[i + 1].tet;
            nb[4 * (size_t)fr[i + 1].tet + fr[i + 1].side] = fr[i].tet;
        } else {
            s = err_set(err, SCAF_ERR_INTERNAL, "TetGen face (%d, %d, %d) bounds %d tets",
                        fr[i].v[0], fr[i].v[1], fr[i].v[2], (int)(j - i));
        }
    }
    /* every input triangle: a face of two tets; every box triangle: of one */
    for (int f = 0; f < nf && s == SCAF_OK; f++) {
        int key[3], c;
        tet_face_key(F + 3 * (size_t)f, key);
        int at = tet_faces_find(fr, nref, key, &c);
        if (c != 2)
            s = err_set(err, SCAF_ERR_INTERNAL,
                        "TetGen lost surface face %d (%d, %d, %d): it bounds %d tets, not 2", f,
                        F[3 * (size_t)f], F[3 * (size_t)f + 1], F[3 * (size_t)f + 2], c);
        else
            for (int e = 0; e < 2; e++) cross[4 * (size_t)fr[at + e].tet + fr[at + e].side] = 1;
    }
    for (int f = 0; f < m->nbox_faces && s == SCAF_OK; f++) {
        int key[3], c;
        tet_face_key(m->box_F + 3 * (size_t)f, key);
        tet_faces_find(fr, nref, key, &c);
        if (c != 1)
            s = err_set(err, SCAF_ERR_INTERNAL, "TetGen lost box face %d: it bounds %d tets, not 1",
                        f, c);
    }
    if (s == SCAF_OK && hull != m->nbox_faces)
        s = err_set(err, SCAF_ERR_INTERNAL, "the TetGen mesh has %d hull faces, the box %d", hull,
                    m->nbox_faces);
    /* the walk */
    int head = 0, tail = 0;
    for (int t = 0; t < m->nt; t++) {
        m->inside[t] = -1;
        for (int k = 0; k < 4 && s == SCAF_OK; k++)
            if (nb[4 * (size_t)t + k] < 0 && m->inside[t] < 0) {
                m->inside[t] = 0;
                queue[tail++] = t;
            }
    }
    while (head < tail && s == SCAF_OK) {
        int t = queue[head++];
        for (int k = 0; k < 4 && s == SCAF_OK; k++) {
            int u = nb[4 * (size_t)t + k];
            if (u < 0) continue;
            signed char want = (signed char)(m->inside[t] ^ cross[4 * (size_t)t + k]);
            if (m->inside[u] < 0) {
                m->inside[u] = want;
                queue[tail++] = u;
            } else if (m->inside[u] != want) {
                s = err_set(err, SCAF_ERR_INTERNAL,
                            "the surface does not separate inside from outside at tet %d", u);
            }
        }
    }
    if (s == SCAF_OK && tail != m->nt)
        s = err_set(err, SCAF_ERR_INTERNAL, "%d tets are not connected to the box", m->nt - tail);
    for (int t = 0; t < m->nt && s == SCAF_OK; t++) {
        if (attribute[t] == OUTSIDE_ATTRIBUTE && m->inside[t])
            s = err_set(err, SCAF_ERR_INTERNAL,
                        "tet %d is in TetGen's outer region but inside the surface", t);
        m->ninside += m->inside[t];
    }
    free(fr);
    free(nb);
    free(queue);
    free(cross);
    return s;
}

/* ---- the build ---- */

scaf_status tet_box_mesh_build(int nv, const double *V, int nf, const int *F, const double lo[3],
                               const double hi[3], int box_cells, tet_box_mesh *out,
                               scaf_error *err)
{
    memset(out, 0, sizeof *out);
    scaf_status s = check_input(nv, V, nf, F, lo, hi, box_cells, err);
    if (s) return s;
    int n = box_cells;
    size_t nbox_max = 6 * (size_t)n * n + 2;
    double *P = malloc(sizeof(double) * 3 * ((size_t)nv + nbox_max));
    out->box_F = malloc(sizeof(int) * 3 * 12 * (size_t)n * n);
    int *all_F = malloc(sizeof(int) * 3 * ((size_t)nf + 12 * (size_t)n * n));
    if (!P || !out->box_F || !all_F) {
        free(P);
        free(all_F);
        tet_box_mesh_free(out);
        return err_nomem(err, "surface and box");
    }
    memcpy(P, V, sizeof(double) * 3 * (size_t)nv);
    out->nsurface = nv;
    double *attribute = NULL;
    s = build_box(nv, lo, hi, n, out, P, err);
    if (s == SCAF_OK) {
        memcpy(all_F, F, sizeof(int) * 3 * (size_t)nf);
        memcpy(all_F + 3 * (size_t)nf, out->box_F, sizeof(int) * 3 * (size_t)out->nbox_faces);
        /* the outside seed: halfway between the box's and the surface's low corners */
        double blo[3] = {INFINITY, INFINITY, INFINITY};
        for (int i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++) blo[k] = fmin(blo[k], V[3 * (size_t)i + k]);
        double seed[4] = {lo[0] * 0.5 + blo[0] * 0.5, lo[1] * 0.5 + blo[1] * 0.5,
                          lo[2] * 0.5 + blo[2] * 0.5, OUTSIDE_ATTRIBUTE};
        tetgen_result tr;
        memset(&tr, 0, sizeof tr);
        s = tetgen_call(nv + out->nbox, P, nf + out->nbox_faces, all_F, 1, seed, &tr, err);
        if (s == SCAF_OK) {
            out->nv = tr.np;
            out->V = tr.P;
            out->nt = tr.nt;
            out->T = tr.T;
            attribute = tr.attribute;
            if (s == SCAF_OK &&
                (out->nv < nv + out->nbox ||
                 memcmp(out->V, P, sizeof(double) * 3 * (size_t)(nv + out->nbox))))
                s = err_set(err, SCAF_ERR_INTERNAL, "TetGen changed or dropped input points");
        }
    }
    free(P);
    free(all_F);
    if (s == SCAF_OK) {
        tet_orient_report r;
        s = tet_orient_check(out->nv, out->V, out->nt, out->T, &r, err);
        if (s == SCAF_OK && r.positive != out->nt)
            s = err_set(err, SCAF_ERR_INTERNAL,
                        "TetGen produced %d inverted and %d flat tets (the first: tet %d)",
                        r.inverted, r.degenerate, r.first_bad);
    }
    if (s == SCAF_OK) s = label_and_check(out, nf, F, attribute, err);
    free(attribute);
    if (s != SCAF_OK) tet_box_mesh_free(out);
    return s;
}

void tet_box_mesh_free(tet_box_mesh *m)
{
    free(m->V);
    free(m->T);
    free(m->inside);
    free(m->box_F);
    memset(m, 0, sizeof *m);
}
