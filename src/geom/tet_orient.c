/* geom/tet_orient: exact orientation of every tetrahedron of a mesh. */
#include "geom/tet_orient.h"

#include <stddef.h>
#include <string.h>

#include "geom/predicates.h"
#include "geom/simplex_arrays.h"

int tet_orientation(const double a[3], const double b[3], const double c[3], const double d[3])
{
    double o = orient3d(a, b, c, d); /* Shewchuk: > 0 for negative volume */
    return (o < 0) - (o > 0);
}

scaf_status tet_orient_check(int nv, const double *V, int nt, const int *T, tet_orient_report *r,
                             scaf_error *err)
{
    memset(r, 0, sizeof *r);
    r->first_bad = -1;
    scaf_status s = simplex_arrays_check(nv, V, nt, T, 4, "tet", err);
    if (s) return s;
    r->tets = nt;
    for (int t = 0; t < nt; t++) {
        const int *q = T + 4 * (size_t)t;
        int s = tet_orientation(V + 3 * (size_t)q[0], V + 3 * (size_t)q[1], V + 3 * (size_t)q[2],
                                V + 3 * (size_t)q[3]);
        if (s > 0) {
            r->positive++;
            continue;
        }
        if (s < 0) r->inverted++;
        else r->degenerate++;
        if (r->first_bad < 0) r->first_bad = t;
    }
    return SCAF_OK;
}
