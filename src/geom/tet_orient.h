/* geom/tet_orient: are the tetrahedra of a tet mesh positively oriented?
 *
 * A tetrahedron (a, b, c, d) is POSITIVE when d lies on the side of the
 * plane of a, b, c toward which (b - a) x (c - a) points, i.e. its signed
 * volume det[b - a, c - a, d - a] / 6 is > 0 (right-handed). With
 * Shewchuk's orient3d (geom/predicates) that is orient3d(a, b, c, d) < 0.
 * Inverted: volume < 0; degenerate: exactly 0 (coplanar corners, repeated
 * indices). Decided exactly.
 */
#ifndef SCAF_GEOM_TET_ORIENT_H
#define SCAF_GEOM_TET_ORIENT_H

#include "base/error.h"

typedef struct tet_orient_report {
    int tets; /* tetrahedra checked */
    int positive;
    int inverted;
    int degenerate;
    int first_bad; /* lowest inverted or degenerate tet, -1 when none */
} tet_orient_report;

/* The exact sign of the signed volume of tet (a, b, c, d): +1, 0 or -1. */
int tet_orientation(const double a[3], const double b[3], const double c[3], const double d[3]);

/* Check every tet.
 *   nv, V   #V by 3 vertex positions (finite)
 *   nt, T   #T by 4 vertex indices, 0-based
 * Errors: SCAF_ERR_MESH for an index out of range or a non-finite
 * coordinate (naming it). */
scaf_status tet_orient_check(int nv, const double *V, int nt, const int *T, tet_orient_report *r,
                             scaf_error *err);

#endif /* SCAF_GEOM_TET_ORIENT_H */
