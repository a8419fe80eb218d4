/* app/atlas_align: rigid turns of charts and of the whole layout that
 * make them fit a square better (geom/min_box chooses the angles).
 *
 * - atlas_align_charts: each chart turned about its bounding-box center
 *   to the orientation of its least-area bounding rectangle, before the
 *   raster packer (app/atlas_pack), which then tries multiples of 45
 *   degrees on top of it. A chart that is already axis aligned in that
 *   sense (angle 0) is copied unchanged.
 * - atlas_turn_to_square: the whole layout turned about its bounding-box
 *   center to the orientation of its smallest bounding square, before the
 *   normalization into [0, 1]^2.
 * Rotated coordinates are rounded, so a turn is a rigid motion only up to
 * rounding: every triangle of a turned chart is checked with the exact
 * orient2d, and a chart (or layout) with a triangle that is not strictly
 * positive afterwards keeps its old coordinates. Gaps between charts are
 * the caller's to verify (app/atlas does, exactly, before using a turned
 * layout). */
#ifndef SCAF_APP_ATLAS_ALIGN_H
#define SCAF_APP_ATLAS_ALIGN_H

#include "base/error.h"

/* uv (nw by 2) -> out (nw by 2); F nf by 3, wchart nw chart per vertex
 * (< 0: no chart, copied), chart nf chart per face. *turned (may be NULL)
 * gets the number of charts turned. SCAF_ERR_NOMEM only. */
scaf_status atlas_align_charts(int nw, const double *uv, int nf, const int *F, const int *chart,
                               const int *wchart, int ncharts, double *out, int *turned,
                               scaf_error *err);

/* uv -> out turned to the smallest bounding square; *turned = 1 when out
 * differs from uv (its square is smaller by more than rounding and every
 * triangle stays strictly positive), else out = uv. SCAF_ERR_NOMEM only. */
scaf_status atlas_turn_to_square(int nw, const double *uv, int nf, const int *F, double *out,
                                 int *turned, scaf_error *err);

#endif /* SCAF_APP_ATLAS_ALIGN_H */
