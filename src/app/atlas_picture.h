/* app/atlas_picture: one picture of an atlas and where its charts lie on
 * the surface: the 3D surface from the front and from the back (app/
 * surface_render: each chart in its colour, seams drawn dark) beside the
 * packed atlas (app/uv_png: the unit UV square, the same colours, chart
 * boundaries outlined), three square panels of one height, left to right.
 * `scaf atlas --png-seams` and `scaf param --png-seams` with a UV panel.
 *
 * Written atomically (app/png_write), whole or not at all. Errors:
 * SCAF_ERR_USAGE (panel size out of SURFACE_RENDER_MIN_SIZE..MAX_SIZE),
 * SCAF_ERR_MESH (an index out of range, a non-finite position: which),
 * SCAF_ERR_NOMEM, SCAF_ERR_IO (the path and the reason).
 */
#ifndef SCAF_APP_ATLAS_PICTURE_H
#define SCAF_APP_ATLAS_PICTURE_H

#include "app/surface_render.h"
#include "base/error.h"

/* path      the PNG to write
 * views     the two 3D panels (front, back), face colours and seam lines
 *           set by the caller
 * nuv, uv   the atlas, nuv by 2 positions in the unit square
 * nf, FT    nf by 3 UV indices per triangle (the triangles of views[0])
 * colour    nf fill colours of the UV panel (0xRRGGBB)
 * panel     pixels of each panel's side */
scaf_status atlas_picture_png(const char *path, const surface_view views[2], int nuv,
                              const double *uv, int nf, const int *FT, const unsigned *colour,
                              int panel, scaf_error *err);

#endif /* SCAF_APP_ATLAS_PICTURE_H */
