/* app/atlas_warm: an atlas's start from charts flattened before (a warm
 * start), so a re-run after a chart was split or merged settles from the
 * current layout instead of from Tutte.
 *
 * Every chart keeps its previous flattening as its shape when that shape
 * is valid on its own (finite, every triangle counter-clockwise, decided
 * exactly); a chart whose shape is not valid takes its fallback shape (the
 * Tutte embedding of app/param). A part of a bijectively flattened chart
 * is bijective, so the two halves of a split chart keep valid shapes --
 * but they touch along the new seam, as the pieces of any re-cut layout
 * may: all charts are therefore re-placed rigidly (translated) on shelves
 * with a gap between their bounding boxes, which no two charts can cross.
 * A translation rounds, so every placed triangle is checked exactly again
 * (a chart whose placed shape is not counter-clockwise falls back). The
 * caller proves the result bijective (geom/bijectivity) before using it.
 *
 * Fails only with SCAF_ERR_NOMEM (out untouched).
 */
#ifndef SCAF_APP_ATLAS_WARM_H
#define SCAF_APP_ATLAS_WARM_H

#include "base/error.h"

/* nw, nf, Fw   working vertices, triangles (nf by 3 working vertex ids)
 * wchart       nw chart id per working vertex, ids in [0, ncharts)
 * shape        nw by 2: the previous flattening (any placement; NaN or a
 *              clockwise / flat triangle makes a chart fall back)
 * fallback     nw by 2: a valid flattening of every chart (Tutte)
 * min_gap      the gap between charts is at least this fraction of the
 *              layout's side (the atlas's padding with its margin; 0: none)
 * out          nw by 2: the placed layout
 * warm         out (may be NULL): how many charts kept their shape */
scaf_status atlas_warm_layout(int nw, int nf, const int *Fw, const int *wchart, int ncharts,
                              const double *shape, const double *fallback, double min_gap,
                              double *out, int *warm, scaf_error *err);

#endif /* SCAF_APP_ATLAS_WARM_H */
