/* app/atlas_output: the normalized, verified output of an atlas (see
 * atlas_output.h).
 *
 * Order: normalize, exact checker, floating-point gap (for the message and
 * the report), exact certificate, efficiency. Every verdict is taken on the
 * normalized doubles, the ones that are written or handed out.
 */
#include "app/atlas_output.h"

#include <math.h>
#include <string.h>

#include "geom/chart_gap.h"

scaf_status atlas_output_verify(const atlas *a, double *UV, atlas_output *out, scaf_error *err)
{
    memset(out, 0, sizeof *out);
    out->gap = INFINITY;
    out->pair[0] = out->pair[1] = -1;
    atlas_normalized_uv(a, UV);
    scaf_status st = bij_check(a->nw, UV, a->nf, a->Fw, a->chart, NULL, &out->bij, err);
    if (st != SCAF_OK) return st;
    st = chart_gap_min(a->nw, UV, a->nf, a->Fw, a->chart, 0.0, &out->gap, NULL, err);
    if (st != SCAF_OK) return st;
    /* the padding decided exactly on the normalized doubles (chart_gap.h) */
    st = chart_gap_certify(UV, a->seg, a->nseg, a->opt.padding, &out->certified, out->pair, err);
    if (st != SCAF_OK) return st;
    out->efficiency = chart_packing_efficiency(a->nw, UV, a->nf, a->Fw);
    if (!out->bij.bijective)
        return err_set(err, SCAF_ERR_INTERNAL,
                       "internal error: the normalized atlas is not bijective (%d flipped, %d "
                       "degenerate "
                       "triangles, %lld boundary crossings, %lld touchings)",
                       out->bij.flipped, out->bij.degenerate, out->bij.boundary_crossings,
                       out->bij.boundary_touchings);
    if (!out->certified)
        return err_set(err, SCAF_ERR_INTERNAL,
                       "internal error: the normalized atlas is bijective but not certified >= "
                       "padding "
                       "(charts %d and %d; gap %g, padding %g)",
                       out->pair[0], out->pair[1], out->gap, a->opt.padding);
    return SCAF_OK;
}
