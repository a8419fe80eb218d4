/* opt/arap_barrier: ARAP's barrier b(det J) and its first two derivatives.
 *
 * b(x) = -ln(x / xh)^3 below xh = OPT_ARAP_BARRIER_DET, 0 above (twice
 * continuously differentiable there, so ARAP's minimum is unchanged where
 * no simplex is squeezed that far), +INFINITY at x <= 0 (see
 * opt/energy_arap.c, which uses it for the density and its Hessian).
 * Why a power of the logarithm and not of 1/x: a Newton step on x^-p
 * moves x by the factor 1 + 1/(p + 1) only, on -ln(x)^3 it about doubles
 * x, so a start with crushed triangles (mean-value start of hand_lowres:
 * det J ~ 1e-7) leaves the barrier in a third of the iterations
 * ((xh / x - 1)^3 before: hand_lowres 200 iterations, not converged;
 * now converged after 104; bench/RESULTS-newton.md).
 */
#ifndef SCAF_OPT_ARAP_BARRIER_H
#define SCAF_OPT_ARAP_BARRIER_H

#include <math.h>

/* ARAP's barrier acts below this det J (area or volume ratio). */
#define OPT_ARAP_BARRIER_DET 0.1

static inline double arap_barrier(double x)
{
    const double xh = OPT_ARAP_BARRIER_DET;
    if (!(x > 0)) return INFINITY;
    double l = log(x / xh);
    return x < xh ? -l * l * l : 0.0;
}

/* b'(x) (<= 0). */
static inline double arap_barrier_slope(double x)
{
    const double xh = OPT_ARAP_BARRIER_DET;
    double l = log(x / xh);
    return x < xh ? -3.0 * l * l / x : 0.0;
}

/* b''(x) (>= 0). */
static inline double arap_barrier_curvature(double x)
{
    const double xh = OPT_ARAP_BARRIER_DET;
    double l = log(x / xh);
    return x < xh ? (3.0 * l * l - 6.0 * l) / (x * x) : 0.0;
}

#endif /* SCAF_OPT_ARAP_BARRIER_H */
