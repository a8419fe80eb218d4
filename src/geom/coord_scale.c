/* geom/coord_scale: see coord_scale.h. */
#include "geom/coord_scale.h"

#include <math.h>
#include <string.h>

int coord_scale_exponent(const double *X, int dim, size_t ncorner, const int *idx)
{
    double m = 0.0;
    for (size_t i = 0; i < ncorner; i++)
        for (int k = 0; k < dim; k++) m = fmax(m, fabs(X[(size_t)dim * (size_t)idx[i] + k]));
    return m > 0.0 && isfinite(m) ? ilogb(m) : 0;
}

void coord_scale_apply(double *Xs, const double *X, int dim, int n, size_t ncorner, const int *idx,
                       int e)
{
    memcpy(Xs, X, sizeof(double) * (size_t)dim * (size_t)n);
    /* from X, not Xs: a point used by several corners is scaled once */
    for (size_t i = 0; i < ncorner; i++)
        for (int k = 0; k < dim; k++) {
            size_t j = (size_t)dim * (size_t)idx[i] + k;
            Xs[j] = ldexp(X[j], -e);
        }
}
