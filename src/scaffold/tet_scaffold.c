/* scaffold/tet_scaffold: the editable 3D scaffold (see the header): its
 * construction from a checked tet mesh, its face adjacency, and the
 * cavity replacement every local operation goes through. */
#include "scaffold/tet_scaffold.h"

#include <stdlib.h>
#include <string.h>

#include "geom/simplex_arrays.h"
#include "geom/tet_faces.h"
#include "geom/tet_orient.h"

const int tet_face_corner[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

void tet_scaffold_free(tet_scaffold *s)
{
    free(s->P);
    free(s->fixed);
    free(s->T);
    free(s->region);
    free(s->vertex_map);
    free(s->nbr);
    free(s->protect);
    free(s->vtet);
    free(s->dead);
    free(s->free_slots);
    free(s->q);
    free(s->mark);
    memset(s, 0, sizeof *s);
}

/* ---- storage ---- */

static int grow(void **p, size_t elem, int have, int want)
{
    void *n = realloc(*p, elem * (size_t)(want > 0 ? want : 1));
    if (!n) return -1;
    if (want > have) memset((char *)n + elem * (size_t)have, 0, elem * (size_t)(want - have));
    *p = n;
    return 0;
}

scaf_status tet_scaffold_reserve(tet_scaffold *s, int tets, int vertices, scaf_error *err)
{
    if (s->nt + tets > s->cap_t) {
        int want = s->cap_t + s->cap_t / 2 + tets + 16;
        if (grow((void **)&s->T, 4 * sizeof(int), s->cap_t, want) ||
            grow((void **)&s->region, 1, s->cap_t, want) ||
            grow((void **)&s->nbr, 4 * sizeof(int), s->cap_t, want) ||
            grow((void **)&s->protect, 1, s->cap_t, want) ||
            grow((void **)&s->dead, 1, s->cap_t, want) ||
            grow((void **)&s->free_slots, sizeof(int), s->cap_t, want) ||
            grow((void **)&s->q, sizeof(double), s->cap_t, want) ||
            grow((void **)&s->mark, sizeof(int), s->cap_t, want))
            return err_nomem(err, "scaffold tets");
        s->cap_t = want;
    }
    if (s->nv + vertices > s->cap_v) {
        int want = s->cap_v + s->cap_v / 2 + vertices + 16;
        if (grow((void **)&s->P, 3 * sizeof(double), s->cap_v, want) ||
            grow((void **)&s->fixed, 1, s->cap_v, want) ||
            grow((void **)&s->vtet, sizeof(int), s->cap_v, want) ||
            grow((void **)&s->vertex_map, sizeof(int), s->cap_v, want))
            return err_nomem(err, "scaffold vertices");
        s->cap_v = want;
    }
    return SCAF_OK;
}

int tet_scaffold_add_vertex(tet_scaffold *s, const double p[3])
{
    int v = s->nv++;
    memcpy(s->P + 3 * (size_t)v, p, 3 * sizeof(double));
    s->fixed[v] = 0;
    s->vtet[v] = -1;
    return v;
}

void tet_scaffold_remove_vertex(tet_scaffold *s, int v) { s->vtet[v] = -2; }

/* ---- faces ---- */

/* 0 or 1: the parity of the permutation that sorts (a, b, c). Two tets
 * see a shared face from opposite sides iff their outward corner orders
 * have different parities. */
static int parity3(const int *f) { return ((f[0] > f[1]) + (f[0] > f[2]) + (f[1] > f[2])) & 1; }

static void face_of(const int *q, int f, int out[3])
{
    for (int k = 0; k < 3; k++) out[k] = q[tet_face_corner[f][k]];
}

/* Adjacency and protected flags from scratch. */
static scaf_status build_faces(tet_scaffold *s, int nprot, const int *prot, scaf_error *err)
{
    size_t nref = 4 * (size_t)s->nt;
    tet_face_ref *fr = tet_faces_sorted(s->nt, s->T);
    if (!fr) return err_nomem(err, "scaffold faces");
    scaf_status st = SCAF_OK;
    for (size_t i = 0, j; i < nref && st == SCAF_OK; i = j) {
        for (j = i + 1; j < nref && !memcmp(fr[j].v, fr[i].v, sizeof fr[0].v); j++) {}
        int a = 4 * fr[i].tet + fr[i].side;
        if (j - i == 1) {
            s->nbr[a] = -1;
            continue;
        }
        int b = 4 * fr[i + 1].tet + fr[i + 1].side, ca[3], cb[3];
        face_of(s->T + 4 * (size_t)(a / 4), a % 4, ca);
        face_of(s->T + 4 * (size_t)(b / 4), b % 4, cb);
        if (j - i > 2)
            st = err_set(err, SCAF_ERR_MESH, "face (%d, %d, %d) is shared by %d tets", fr[i].v[0],
                         fr[i].v[1], fr[i].v[2], (int)(j - i));
        else if (parity3(ca) == parity3(cb))
            st = err_set(err, SCAF_ERR_MESH,
                         "tets %d and %d lie on the same side of their face (%d, %d, %d)", a / 4,
                         b / 4, fr[i].v[0], fr[i].v[1], fr[i].v[2]);
        else s->nbr[a] = b, s->nbr[b] = a;
    }
    for (int p = 0; p < nprot && st == SCAF_OK; p++) {
        int key[3], count;
        tet_face_key(prot + 3 * (size_t)p, key);
        int at = tet_faces_find(fr, nref, key, &count);
        if (at < 0) {
            st = err_set(err, SCAF_ERR_MESH,
                         "protected triangle %d (%d, %d, %d) is no face of the tet mesh", p,
                         prot[3 * (size_t)p], prot[3 * (size_t)p + 1], prot[3 * (size_t)p + 2]);
            break;
        }
        for (int k = at; k < at + count; k++)
            s->protect[fr[k].tet] |= (unsigned char)(1u << fr[k].side);
    }
    free(fr);
    return st;
}

scaf_status tet_scaffold_init(tet_scaffold *s, int nmesh, int nv, const double *V,
                              const unsigned char *fixed, int nt, const int *T,
                              const signed char *region, int nprot, const int *prot,
                              scaf_error *err)
{
    memset(s, 0, sizeof *s);
    if (nmesh < 0 || nmesh > nv || nt < 0 || nprot < 0 || (nt > 0 && !region) ||
        (nprot > 0 && !prot))
        return err_set(err, SCAF_ERR_USAGE,
                       "tet scaffold: bad counts (nmesh %d, vertices %d, tets %d, protected %d)",
                       nmesh, nv, nt, nprot);
    scaf_status st = simplex_arrays_check(nv, V, nt, T, 4, "tet", err);
    if (st == SCAF_OK) st = simplex_arrays_check(nv, V, nprot, prot, 3, "protected triangle", err);
    if (st) return st;
    for (int t = 0; t < nt; t++)
        if (region[t] != 0 && region[t] != 1)
            return err_set(err, SCAF_ERR_USAGE, "tet %d has region %d, not 0 or 1", t, region[t]);
    if (tet_scaffold_reserve(s, nt, nv, err)) return SCAF_ERR_NOMEM;
    s->nmesh = nmesh, s->nv = nv, s->nt = nt, s->nv_before = nv;
    memcpy(s->P, V, sizeof(double) * 3 * (size_t)nv);
    if (fixed) memcpy(s->fixed, fixed, (size_t)nv);
    memcpy(s->T, T, sizeof(int) * 4 * (size_t)nt);
    memcpy(s->region, region, (size_t)nt);
    for (int v = 0; v < nv; v++) s->vertex_map[v] = v, s->vtet[v] = -1;
    for (int t = 0; t < nt; t++) {
        const int *q = T + 4 * (size_t)t;
        if (tet_orientation(V + 3 * (size_t)q[0], V + 3 * (size_t)q[1], V + 3 * (size_t)q[2],
                            V + 3 * (size_t)q[3]) <= 0) {
            st = err_set(err, SCAF_ERR_MESH, "tet %d (%d, %d, %d, %d) is not positively oriented",
                         t, q[0], q[1], q[2], q[3]);
            break;
        }
        for (int k = 0; k < 4; k++) s->vtet[q[k]] = t;
    }
    if (st == SCAF_OK) st = build_faces(s, nprot, prot, err);
    if (st) tet_scaffold_free(s);
    return st;
}

scaf_status tet_scaffold_from_box_mesh(tet_scaffold *s, const tet_box_mesh *m, int nf, const int *F,
                                       scaf_error *err)
{
    unsigned char *fixed = calloc((size_t)(m->nv > 0 ? m->nv : 1), 1);
    if (!fixed) return err_nomem(err, "scaffold fixed flags");
    for (int v = m->nsurface; v < m->nsurface + m->nbox && v < m->nv; v++) fixed[v] = 1;
    scaf_status st =
        tet_scaffold_init(s, m->nsurface, m->nv, m->V, fixed, m->nt, m->T, m->inside, nf, F, err);
    free(fixed);
    return st;
}

/* ---- editing ---- */

typedef struct boundary_face {
    int key[3];
    int outside; /* 4 t + f across, -1 hull */
    unsigned char protect;
    int used;
} boundary_face;

#define MAX_CAVITY 64

static int in_list(int x, const int *list, int n)
{
    for (int i = 0; i < n; i++)
        if (list[i] == x) return 1;
    return 0;
}

scaf_status tet_scaffold_replace(tet_scaffold *s, int nold, const int *old, int nnew,
                                 const int *newT, int *ids, scaf_error *err)
{
    if (nold > MAX_CAVITY || nnew > MAX_CAVITY)
        return err_set(err, SCAF_ERR_INTERNAL, "cavity of %d -> %d tets too large", nold, nnew);
    boundary_face bf[4 * MAX_CAVITY];
    int nbf = 0;
    for (int i = 0; i < nold; i++)
        for (int f = 0; f < 4; f++) {
            int o = old[i], n = s->nbr[4 * o + f];
            if (n >= 0 && in_list(n / 4, old, nold)) continue;
            int c[3];
            face_of(s->T + 4 * (size_t)o, f, c);
            tet_face_key(c, bf[nbf].key);
            bf[nbf].outside = n;
            bf[nbf].protect = (unsigned char)((s->protect[o] >> f) & 1);
            bf[nbf].used = 0;
            nbf++;
        }
    /* match every face of the new tets: another new tet's, or a boundary
     * face; checked before anything changes */
    int match[4 * MAX_CAVITY]; /* >= 0: 4 i' + f' of a new tet; < 0: -2 - boundary face */
    int keys[4 * MAX_CAVITY][3];
    for (int i = 0; i < nnew; i++)
        for (int f = 0; f < 4; f++) {
            int c[3];
            face_of(newT + 4 * i, f, c);
            tet_face_key(c, keys[4 * i + f]);
        }
    int inner = 0;
    for (int a = 0; a < 4 * nnew; a++) {
        match[a] = -1;
        for (int b = 0; b < 4 * nnew; b++)
            if (b / 4 != a / 4 && !memcmp(keys[a], keys[b], sizeof keys[a])) {
                if (match[a] != -1)
                    return err_set(err, SCAF_ERR_INTERNAL, "new tets share a face thrice");
                match[a] = b;
            }
        if (match[a] >= 0) {
            inner++;
            continue;
        }
        for (int k = 0; k < nbf; k++)
            if (!bf[k].used && !memcmp(keys[a], bf[k].key, sizeof keys[a])) {
                bf[k].used = 1;
                match[a] = -2 - k;
                break;
            }
        if (match[a] == -1)
            return err_set(err, SCAF_ERR_INTERNAL, "a new tet's face is not in the cavity");
    }
    if (inner + nbf != 4 * nnew)
        return err_set(err, SCAF_ERR_INTERNAL, "the new tets do not fill the cavity");
    /* apply: free the old slots, take slots for the new tets */
    signed char region = s->region[old[0]];
    for (int i = 0; i < nold; i++) {
        s->dead[old[i]] = 1;
        s->free_slots[s->nfree++] = old[i];
    }
    int id[MAX_CAVITY];
    for (int i = 0; i < nnew; i++) {
        int t = s->nfree > 0 ? s->free_slots[--s->nfree] : s->nt++;
        id[i] = t;
        memcpy(s->T + 4 * (size_t)t, newT + 4 * i, 4 * sizeof(int));
        s->region[t] = region;
        s->dead[t] = 0;
        s->protect[t] = 0;
        for (int k = 0; k < 4; k++) s->vtet[newT[4 * i + k]] = t;
    }
    for (int a = 0; a < 4 * nnew; a++) {
        int t = id[a / 4], f = a % 4, m = match[a];
        if (m >= 0) {
            s->nbr[4 * t + f] = 4 * id[m / 4] + m % 4;
            continue;
        }
        const boundary_face *b = &bf[-2 - m];
        s->nbr[4 * t + f] = b->outside;
        if (b->outside >= 0) s->nbr[b->outside] = 4 * t + f;
        s->protect[t] |= (unsigned char)(b->protect << f);
    }
    if (ids) memcpy(ids, id, sizeof(int) * (size_t)nnew);
    return SCAF_OK;
}

void tet_scaffold_compact(tet_scaffold *s)
{
    /* the visit stamps and the vertex map have the room: no allocation */
    int *tmap = s->mark, *vmap = s->vertex_map;
    int nt = 0, nv = 0, removed = 0;
    for (int v = 0; v < s->nv; v++) removed += s->vtet[v] == -2;
    s->nv_before = s->nv;
    if (s->nfree == 0 && removed == 0) { /* every dead slot was refilled: dense */
        for (int v = 0; v < s->nv; v++) vmap[v] = v;
        return;
    }
    for (int t = 0; t < s->nt; t++) tmap[t] = s->dead[t] ? -1 : nt++;
    for (int v = 0; v < s->nv; v++) vmap[v] = s->vtet[v] == -2 ? -1 : nv++;
    for (int t = 0; t < s->nt; t++) {
        int u = tmap[t];
        if (u < 0) continue;
        for (int k = 0; k < 4; k++) {
            int n = s->nbr[4 * t + k];
            s->T[4 * u + k] = vmap[s->T[4 * t + k]];
            s->nbr[4 * u + k] = n < 0 ? -1 : 4 * tmap[n / 4] + n % 4;
        }
        s->region[u] = s->region[t];
        s->protect[u] = s->protect[t];
        s->q[u] = s->q[t];
        s->dead[u] = 0;
    }
    for (int v = 0; v < s->nv; v++) {
        int u = vmap[v];
        if (u < 0) continue;
        memmove(s->P + 3 * (size_t)u, s->P + 3 * (size_t)v, 3 * sizeof(double));
        s->fixed[u] = s->fixed[v];
        s->vtet[u] = s->vtet[v] < 0 ? -1 : tmap[s->vtet[v]];
    }
    memset(s->mark, 0, sizeof(int) * (size_t)s->cap_t);
    s->mark_now = 0;
    s->nt = nt, s->nv = nv, s->nfree = 0;
}
