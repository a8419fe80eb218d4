/* geom/tet_faces: faces of a tet mesh by their corners (see the header). */
#include "geom/tet_faces.h"

#include <stdlib.h>
#include <string.h>

void tet_face_key(const int *f, int key[3])
{
    int a = f[0], b = f[1], c = f[2], t;
    if (a > b) t = a, a = b, b = t;
    if (b > c) t = b, b = c, c = t;
    if (a > b) t = a, a = b, b = t;
    key[0] = a, key[1] = b, key[2] = c;
}

static int cmp_face(const void *pa, const void *pb)
{
    const tet_face_ref *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a->v[k] != b->v[k]) return a->v[k] < b->v[k] ? -1 : 1;
    return (a->tet > b->tet) - (a->tet < b->tet);
}

tet_face_ref *tet_faces_sorted(int nt, const int *T)
{
    size_t nref = 4 * (size_t)nt;
    tet_face_ref *fr = malloc(sizeof *fr * (nref > 0 ? nref : 1));
    if (!fr) return NULL;
    for (int t = 0; t < nt; t++)
        for (int k = 0; k < 4; k++) {
            int f[3], o = 0;
            for (int l = 0; l < 4; l++)
                if (l != k) f[o++] = T[4 * (size_t)t + l];
            tet_face_ref *r = &fr[4 * (size_t)t + k];
            tet_face_key(f, r->v);
            r->tet = t;
            r->side = k;
        }
    qsort(fr, nref, sizeof *fr, cmp_face);
    return fr;
}

int tet_faces_find(const tet_face_ref *fr, size_t n, const int key[3], int *count)
{
    size_t lo = 0, hi = n;
    tet_face_ref probe = {{key[0], key[1], key[2]}, -1, 0};
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cmp_face(&fr[mid], &probe) < 0) lo = mid + 1;
        else hi = mid;
    }
    int c = 0;
    while (lo + (size_t)c < n && !memcmp(fr[lo + (size_t)c].v, key, sizeof fr[0].v)) c++;
    *count = c;
    return c > 0 ? (int)lo : -1;
}
