/* mesh/position_scale: see position_scale.h. */
#include "mesh/position_scale.h"

#include <math.h>
#include <string.h>

int position_scale_exponent(const double *V, int nf, const int *F)
{
    double m = 0.0;
    for (size_t i = 0; i < 3 * (size_t)nf; i++)
        for (int k = 0; k < 3; k++) m = fmax(m, fabs(V[3 * (size_t)F[i] + k]));
    return m > 0.0 && isfinite(m) ? ilogb(m) : 0;
}

void position_scale_apply(double *Vs, const double *V, int nv, int nf, const int *F, int e)
{
    memcpy(Vs, V, sizeof(double) * 3 * (size_t)nv);
    /* from V, not Vs: a vertex used by several faces is scaled once */
    for (size_t i = 0; i < 3 * (size_t)nf; i++)
        for (int k = 0; k < 3; k++) Vs[3 * (size_t)F[i] + k] = ldexp(V[3 * (size_t)F[i] + k], -e);
}
