/* app/atlas_pack: rigid re-placement of settled charts into a square.
 *
 * Between SCAF iterations the atlas may move whole charts rigidly (a
 * translation and a rotation by a multiple of 90 degrees, both exact in
 * floating point up to the final rounding of the translation) to fill the
 * square better than the initial grid: a raster packer. Each chart is
 * rasterized conservatively (every cell its triangles' boxes touch) on a
 * grid of cell h, charts are placed largest first at the position and
 * rotation that keep the occupied square smallest (ties: lowest row, then
 * column), never on a cell within `dilate` cells (Chebyshev) of a placed
 * chart, so different charts end at least dilate * h apart, more than the
 * padding.
 *
 * The caller verifies the result (exact bijectivity checker, chart gap)
 * before using it; nothing here is trusted. Fails only with SCAF_ERR_NOMEM
 * (or SCAF_ERR_NUMERIC when the layout is empty or not finite).
 */
#ifndef SCAF_APP_ATLAS_PACK_H
#define SCAF_APP_ATLAS_PACK_H

#include "base/error.h"

/* nw, uv     working vertices, nw by 2 positions (read)
 * nf, F      nf by 3 working vertex ids per triangle
 * chart      nf chart id per triangle; wchart nw chart per vertex
 * ncharts    number of charts
 * cells      target cells along the side of the estimated square (e.g. 512)
 * gap        wanted distance between charts in uv units (>= 0)
 * strategy   -1: try every placement strategy (chart order: area, longest
 *            side, perturbed; rotations: 90 / 45 degrees; tie rule) and
 *            keep the smallest square; k: only strategy k
 * chosen     out (may be NULL): the strategy kept
 * keep       with strategy -1 and keep > 0: a strategy is abandoned as
 *            soon as its square is larger than the keep-th smallest square
 *            of the strategies completed before it (it cannot be among the
 *            keep best; the best is never abandoned); 0: run all fully
 * strat_side out (may be NULL): atlas_pack_strategies(ncharts) entries, the
 *            square side in cells each strategy reached (-1: not run or
 *            abandoned)
 * out        nw by 2 new positions (write) */
scaf_status atlas_pack(int nw, const double *uv, int nf, const int *F, const int *chart,
                       const int *wchart, int ncharts, int cells, double gap, int strategy,
                       int keep, int *chosen, long *strat_side, double *out, scaf_error *err);

/* Number of strategies tried for ncharts charts. */
int atlas_pack_strategies(int ncharts);

#endif /* SCAF_APP_ATLAS_PACK_H */
