/* app/chart_init: the initial UV embedding of one chart.
 *
 * Tutte's embedding (uniform weights) or a harmonic one (cotangent weights)
 * of a chart whose first boundary loop is pinned, by 3D arc length, to a
 * counter-clockwise circle whose area equals the chart's 3D area, centered
 * at the origin. Holes (the other loops) are filled with a fan around a
 * temporary vertex at the loop's 3D centroid before solving, and the fill
 * is dropped after: every chart triangle is then inside the circle and
 * positively oriented (Tutte's theorem). Harmonic falls back to Tutte when
 * a triangle flips; every result is confirmed with exact orient2d.
 * Fails with SCAF_ERR_NUMERIC when even Tutte's embedding is not valid in
 * floating point (extremely degenerate input), SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_CHART_INIT_H
#define SCAF_APP_CHART_INIT_H

#include "base/error.h"

/* n        chart vertices (local ids 0..n-1)
 * P        n by 3 positions
 * m, T     m by 3 chart faces (local ids, counter-clockwise)
 * nloops, loop_start (nloops+1), loop_v: boundary loops in order, chart on
 *          the left; loop 0 is pinned to the circle
 * harmonic 1: cotangent weights (with Tutte fallback), 0: Tutte
 * uv       out: n by 2
 * used_harmonic  out (may be NULL): 1 when the harmonic result was kept */
scaf_status chart_embed(int n, const double *P, int m, const int *T, int nloops, const int *loop_start,
                        const int *loop_v, int harmonic, double *uv, int *used_harmonic,
                        scaf_error *err);

#endif /* SCAF_APP_CHART_INIT_H */
