/* geom/tet_faces: the triangular faces of a tet mesh, looked up by their
 * corners. Every tet has four faces, face k the one opposite its corner k;
 * a face's key is its three vertex ids in increasing order, so the two
 * tets sharing a face have equal keys next to each other once sorted. */
#ifndef SCAF_GEOM_TET_FACES_H
#define SCAF_GEOM_TET_FACES_H

#include <stddef.h>

typedef struct tet_face_ref {
    int v[3]; /* the key: corner ids, increasing */
    int tet;
    int side; /* the face of tet opposite its corner `side` */
} tet_face_ref;

/* The key of triangle f (3 ids). */
void tet_face_key(const int *f, int key[3]);

/* The 4 nt faces of the tets T (nt by 4), sorted by key, then tet: the
 * entries of one face are adjacent. NULL when out of memory. */
tet_face_ref *tet_faces_sorted(int nt, const int *T);

/* Index of the first of the n sorted faces with this key, and how many
 * there are (0, index -1: none). */
int tet_faces_find(const tet_face_ref *fr, size_t n, const int key[3], int *count);

#endif /* SCAF_GEOM_TET_FACES_H */
