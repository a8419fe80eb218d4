/* app/unit_scale: see unit_scale.h. */
#include "app/unit_scale.h"

#include <float.h>
#include <math.h>

#include "geom/coord_scale.h"

scaf_status unit_scale_down(int nv, double *V, int nf, const int *F, int *e, scaf_error *err)
{
    *e = coord_scale_exponent(V, 3, 3 * (size_t)nf, F);
    /* inputs in everyday units are left exactly as they are (the same
     * bits as before); only those whose squares would leave the range */
    if (*e >= -UNIT_SCALE_SAFE && *e <= UNIT_SCALE_SAFE) {
        *e = 0;
        return SCAF_OK;
    }
    double lo = INFINITY, hi = 0.0;
    for (size_t i = 0; i < 3 * (size_t)nv; i++) {
        double a = fabs(V[i]);
        if (a > 0.0 && a < lo) lo = a;
        if (a > hi) hi = a;
    }
    for (size_t i = 0; i < 3 * (size_t)nv; i++) {
        double s = ldexp(V[i], -*e);
        if (V[i] != 0.0 && fabs(s) < DBL_MIN) {
            /* put back what was already divided: the caller's V unchanged */
            for (size_t j = 0; j < i; j++) V[j] = ldexp(V[j], *e);
            return err_set(err, SCAF_ERR_MESH,
                           "the coordinates range from %g to %g in magnitude: more orders of "
                           "magnitude than a double holds at once (the smallest would lose its "
                           "precision at the largest's scale)",
                           lo, hi);
        }
        V[i] = s;
    }
    return SCAF_OK;
}

scaf_status unit_scale_up(double *X, size_t n, int e, scaf_error *err)
{
    for (size_t i = 0; i < n; i++) {
        double s = ldexp(X[i], e);
        if (!isfinite(s))
            return err_set(err, SCAF_ERR_MESH,
                           "a result coordinate (%g x 2^%d) is beyond the largest double (%g): "
                           "the input is too close to it; scale it down",
                           X[i], e, DBL_MAX);
        X[i] = s;
    }
    return SCAF_OK;
}
