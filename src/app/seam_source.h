/* app/seam_source: which seams a run cuts its charts along, decided once
 * for `scaf param`, `scaf atlas` and `scaf edit` (and their API).
 *
 * The input's UV seams (today's charts) when asked, or by default when the
 * mesh has UVs that cut it into disks; otherwise automatic seams: the
 * surface's charts (one per component for a parametrization, the
 * segmentation of mesh/chart_segment for an atlas) cut open by
 * mesh/cut_graph wherever a chart is not a disk (handles, closed pieces);
 * or the input's seams extended by such cuts. The result is a UV topology
 * (FT) the rest of the run takes as if the input had it. This is the one
 * place that calls the segmentation, so a refinement of the charts hooks
 * in here.
 *
 * Non-manifold, misoriented or non-orientable input is refused (SCAF_ERR_MESH,
 * the message of mesh/uv_charts naming the edge or vertex), as is a chart
 * that is not a disk with SCAF_SEAMS_INPUT (the same message as before,
 * left to the caller's chart check). SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_SEAM_SOURCE_H
#define SCAF_APP_SEAM_SOURCE_H

#include "base/error.h"
#include "mesh/mesh.h"
#include "scaf/scaf.h"

typedef struct seam_plan {
    scaf_seams used; /* SCAF_SEAMS_INPUT, _AUTO or _EXTEND */
    int changed;     /* 1: run on nuv, UV, FT below; 0: on the input as it is */
    int nuv;
    double *UV;       /* nuv by 2: the input's UV of each index where it came from
                   one (extend), else 0 */
    int *FT;          /* nf by 3 */
    int segments;     /* charts of the segmentation (atlas, automatic) */
    int uv_start;     /* 1: UV is a layout settled by chart splitting
                         (app/atlas_charts), a warm start for the atlas */
    int cut_edges;    /* interior edges cut open by mesh/cut_graph */
    int handle_loops; /* loops cut for handles */
    int cones;        /* cone vertices of cut trees on closed pieces */
    char why[200];    /* why this source, for the terminal */
} seam_plan;

/* m: the mesh (with or without UVs); mode: the option; segment: 1 for an
 * atlas (several charts: mesh/chart_segment), 0 for a parametrization
 * (one chart per component where one suffices). On failure *plan is
 * empty. */
scaf_status seam_plan_make(const mesh *m, scaf_seams mode, int segment, seam_plan *plan,
                           scaf_error *err);

void seam_plan_free(seam_plan *plan);

/* "input", "auto", "extend" (or "default"). */
const char *seam_source_name(scaf_seams s);

#endif /* SCAF_APP_SEAM_SOURCE_H */
