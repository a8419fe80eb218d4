/* app/atlas_output: the normalized, verified output of an atlas.
 *
 * One place for what must hold before an atlas layout leaves the library
 * (the `scaf atlas` program writing a file, scaf_atlas_get_uv handing out
 * arrays): the layout is normalized into the unit square with one uniform
 * scale (atlas_normalized_uv), the exact checker proves it bijective
 * (geom/bijectivity), and the exact certificate (chart_gap_certify in
 * geom/chart_gap.h) proves every two charts at least the padding apart on
 * the very doubles produced. It also measures the floating-point smallest
 * chart gap and the packing efficiency of the normalized layout.
 *
 * Fails with SCAF_ERR_INTERNAL (message: which property failed, the gap and
 * the padding) when the layout is not bijective or not certified, which
 * the atlas' own constraints should make impossible; SCAF_ERR_NUMERIC when
 * a coordinate is outside the certificate's exact range; SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_ATLAS_OUTPUT_H
#define SCAF_APP_ATLAS_OUTPUT_H

#include "app/atlas.h"
#include "base/error.h"
#include "geom/bijectivity.h"

typedef struct atlas_output {
    bij_report bij;    /* the exact checker's report on the output */
    int certified;     /* 1: every chart pair >= padding (exact) */
    int pair[2];       /* charts of a failing pair (certified == 0) */
    double gap;        /* smallest distance between two charts of the
                            output (floating point; INFINITY: one chart) */
    double efficiency; /* packing efficiency of the output (chart UV area
                            / unit square) */
} atlas_output;

/* Normalize and verify the current layout of a.
 *   a    an initialized atlas (atlas_init), run or not
 *   UV   out, a->nw by 2 normalized coordinates (filled also on failure,
 *        so callers can draw what failed; never hand them out then)
 *   out  out, the verdicts and measures above (may not be NULL)
 * Returns SCAF_OK only when the layout is bijective and certified. */
scaf_status atlas_output_verify(const atlas *a, double *UV, atlas_output *out, scaf_error *err);

#endif /* SCAF_APP_ATLAS_OUTPUT_H */
