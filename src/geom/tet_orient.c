/* geom/tet_orient: exact orientation of every tetrahedron of a mesh. */
#include "geom/tet_orient.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "geom/predicates.h"

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
    if (nv < 0 || nt < 0 || (nv > 0 && !V) || (nt > 0 && !T))
        return err_set(err, SCAF_ERR_USAGE, "tet_orient_check: bad arguments (nv %d, nt %d)", nv, nt);
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(V[3 * (size_t)i + k]))
                return err_set(err, SCAF_ERR_MESH, "vertex %d is not finite (%g, %g, %g)", i, V[3 * (size_t)i],
                               V[3 * (size_t)i + 1], V[3 * (size_t)i + 2]);
    for (int t = 0; t < nt; t++)
        for (int k = 0; k < 4; k++)
            if (T[4 * (size_t)t + k] < 0 || T[4 * (size_t)t + k] >= nv)
                return err_set(err, SCAF_ERR_MESH, "tet %d references vertex %d but there are %d vertices", t,
                               T[4 * (size_t)t + k], nv);
    r->tets = nt;
    for (int t = 0; t < nt; t++) {
        const int *q = T + 4 * (size_t)t;
        int s = tet_orientation(V + 3 * (size_t)q[0], V + 3 * (size_t)q[1], V + 3 * (size_t)q[2],
                                V + 3 * (size_t)q[3]);
        if (s > 0) {
            r->positive++;
            continue;
        }
        if (s < 0)
            r->inverted++;
        else
            r->degenerate++;
        if (r->first_bad < 0) r->first_bad = t;
    }
    return SCAF_OK;
}
