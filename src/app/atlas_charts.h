/* app/atlas_charts: charts refined for distortion and packing before the
 * atlas is built -- a chart too distorted, or filling too little of its
 * least-area box, is split in two.
 *
 * SCAF keeps every chart bijective whatever its shape, so a chart never
 * needs cutting because its flattening would overlap; it is split only
 * when its settled distortion E exceeds max_distortion (then the
 * segmentation, mesh/chart_segment, cuts it into two normal cones: the
 * cut runs between the two regions whose normals differ most, where the
 * curvature that causes the distortion is; or, with slit_cones, it is cut
 * open along the shortest path from its boundary to its worst vertex,
 * staying one chart), or when it fills less than
 * min_fill of its least-area bounding rectangle (a long snake: the two
 * farthest-apart parts become charts, the cut falls across the middle).
 * Round by round: settle all charts together in one scaffold (the atlas's
 * first phase, capped, without packing), measure every chart, split the
 * worst offenders, until none is left or max_rounds.
 *
 * Only the first round starts from Tutte: a later round starts from the
 * layout the previous one settled, every chart (both halves of a split
 * one too) keeping its flattened shape, re-placed apart (app/atlas_warm),
 * so it settles in a few iterations. A slit chart's two sides coincide,
 * so a round after slits starts from Tutte.
 *
 * Works on the mesh's UV charts: m must have FT (vt seams) whose charts
 * are disks (with holes); a part of a disk is planar, so every chart
 * stays a disk with holes. On return m's vt indices are those of the last
 * settled atlas (one per working vertex: pinch points split, indices
 * renumbered, the seams the same up to the new cuts) and its UVs that
 * layout (in the atlas's units), both halves of a new seam at the same
 * place: the warm start of the final atlas (seam_plan.uv_start).
 * Fails with the atlas's errors (SCAF_ERR_MESH naming the chart,
 * SCAF_ERR_NUMERIC, SCAF_ERR_NOMEM) or SCAF_ERR_USAGE (no vt); on failure
 * m keeps the charts of the last round that completed.
 */
#ifndef SCAF_APP_ATLAS_CHARTS_H
#define SCAF_APP_ATLAS_CHARTS_H

#include "app/atlas.h"
#include "app/seam_source.h"
#include "base/error.h"
#include "mesh/mesh.h"

/* The default bound of a chart's E: about what a quarter of a sphere
 * settles to (4.02), with room for the compaction's 5%. */
#define ATLAS_CHARTS_MAX_DISTORTION 4.2
/* The default least fill of a chart's least-area box. */
#define ATLAS_CHARTS_MIN_FILL 0.45

typedef struct atlas_charts_options {
    double max_distortion; /* split charts settling above this E (<= 0: never) */
    double min_fill;       /* split charts filling less of their least-area box (<= 0: never) */
    int max_rounds;        /* settle / split rounds (3) */
    int max_splits;        /* splits per round at most (0: no limit) */
    int slit_cones;        /* 1: cut a distorted chart open from its boundary to its
                              worst vertex (largest area-weighted excess of E over 4)
                              instead of splitting it (0; measured: splitting gives
                              the lower E, spot 4.23 against 4.30) */
    int merge;             /* 1: after the splitting rounds, join pairs of neighbours
                              (a common seam, their union a disk) within the bound
                              whose area-weighted mean E is below 4 + 1/2 (bound - 4);
                              one round settles them, the next parts again every
                              joined chart settling above 4 + 3/4 (bound - 4), or
                              filling its least-area box less than its parts did
                              (area-weighted) or less than min_fill (0; on for
                              automatic seams) */
} atlas_charts_options;

typedef struct atlas_charts_info {
    int charts_before, charts_after;
    int rounds;                         /* rounds run */
    int distortion_splits, fill_splits; /* charts split for each reason */
    int distortion_slits;               /* cuts from a boundary to a cone */
    int merges;                         /* pairs of charts joined for good */
    int warm_charts;                    /* charts of the last round started from
                                           the previous round's layout */
} atlas_charts_info;

atlas_charts_options atlas_charts_options_default(void);

/* Refine the UV charts of m (see the banner); base gives the loop
 * options of the settling (energy, threads, ...). info may be NULL. */
scaf_status atlas_charts_refine(mesh *m, const atlas_options *base, const atlas_charts_options *o,
                                atlas_charts_info *info, scaf_error *err);

/* The hook of atlas_init: with the atlas options' max_distortion and
 * split_charts (defaults: both for automatic seams, neither for input
 * seams, nothing with init_input), refine the charts of the planned mesh
 * (the input with the seam plan's UV topology) and hand the new seams and
 * the last settled layout to the plan (which then owns them, uv_start
 * set: the atlas starts from that layout) and to planned. */
scaf_status atlas_charts_apply(mesh *planned, const atlas_options *opt, seam_plan *plan,
                               scaf_error *err);

#endif /* SCAF_APP_ATLAS_CHARTS_H */
