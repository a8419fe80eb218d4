/* geom/simplex_arrays: see simplex_arrays.h. */
#include "geom/simplex_arrays.h"

#include <math.h>
#include <stddef.h>

scaf_status simplex_arrays_check(int nv, const double *V, int n, const int *S, int corners,
                                 const char *what, scaf_error *err)
{
    if (nv < 0 || n < 0 || (nv > 0 && !V) || (n > 0 && !S))
        return err_set(err, SCAF_ERR_USAGE, "bad mesh arrays (%d vertices, %d %ss)", nv, n, what);
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(V[3 * (size_t)i + k]))
                return err_set(err, SCAF_ERR_MESH, "vertex %d is not finite (%g, %g, %g)", i,
                               V[3 * (size_t)i], V[3 * (size_t)i + 1], V[3 * (size_t)i + 2]);
    for (int s = 0; s < n; s++)
        for (int k = 0; k < corners; k++) {
            int v = S[(size_t)corners * s + k];
            if (v < 0 || v >= nv)
                return err_set(err, SCAF_ERR_MESH,
                               "%s %d references vertex %d but there are %d vertices", what, s, v,
                               nv);
        }
    return SCAF_OK;
}
