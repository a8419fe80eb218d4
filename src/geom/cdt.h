/* geom/cdt: 2D constrained Delaunay triangulation with quality refinement.
 *
 * The scaffold mesher of SCAF. Triangulates the region bounded by the
 * constrained segments, leaves out the hole regions (chart interiors), and
 * refines to a minimum angle wherever the input allows. Segments flagged as
 * not splittable (chart boundary edges) appear in the output exactly as
 * given: no Steiner point is ever inserted on them. Splittable segments
 * (the box) and the free space may receive Steiner points.
 */
#ifndef SCAF_GEOM_CDT_H
#define SCAF_GEOM_CDT_H

#include "base/error.h"

typedef struct cdt_input {
    int npoints;
    const double *points; /* #P by 2 coordinates (finite, distinct) */
    int nsegments;
    const int *segments;               /* #S by 2 point indices */
    const unsigned char *splittable;   /* #S flags: 1 = Steiner points may be
                                        inserted on the segment (box edges),
                                        0 = keep it whole (chart edges).
                                        NULL: no segment is splittable */
    const unsigned char *left_is_hole; /* #S flags: 1 = the region to the
                                          left of segment a->b is a hole
                                          (chart interior: charts' boundary
                                          edges oriented with the chart on
                                          their left). NULL: none */
    int nholes;
    const double *holes; /* #H by 2 seed points inside holes; may be 0 */
} cdt_input;

typedef struct cdt_options {
    double min_angle_deg; /* quality bound in [0, 60); 0 disables angle
                               refinement (20) */
    double max_area;      /* upper bound on triangle area; 0 = none (0) */
    int max_steiner;      /* safety cap on inserted points; 0 = no cap (0).
                               Whatever this says, an internal cap
                               proportional to the input size (and to
                               box area / max_area) guarantees termination;
                               refinement stops quietly at a cap. */
} cdt_options;

/* The defaults above. */
cdt_options cdt_default_options(void);

typedef struct cdt_output {
    int npoints;
    double *points; /* #P by 2: the input points first, in input order,
                         then the Steiner points */
    int ntriangles;
    int *triangles; /* #T by 3 point indices, counter-clockwise */
    int *neighbors; /* #T by 3: neighbors[3t+i] = triangle across the edge
                         opposite corner i (from corner i+1 to i+2), or -1
                         where that edge bounds the domain */
    int nsubsegments;
    int *subsegments;   /* #SS by 2 point indices: the output edges lying on
                         input segments that border at least one output
                         triangle, oriented like their segment; an
                         unsplittable segment is exactly one subsegment */
    int *subsegment_of; /* #SS: index of the input segment */
    int nsteiner;       /* = npoints - input npoints */
    int nrejected;      /* refinement steps refused (a Steiner point would
                         encroach an unsplittable segment, leave the domain,
                         or break orientation); quality is best-effort there */
    int capped;         /* 1 when refinement stopped at the Steiner cap */
} cdt_output;

/* Triangulate the region enclosed by the segments: triangles that can be
 * reached from far away without crossing a segment are not output, nor are
 * holes (the left side of segments flagged left_is_hole, and the regions
 * containing hole seeds, each up to the enclosing segments). Splittable
 * segments may come out as chains of subsegments. A segment given twice
 * (either direction) is kept once, as the first index, unsplittable if
 * either copy is.
 *
 * Refinement (Ruppert / Chew style with off-centers, graded: fine near the
 * charts, coarse towards the box): triangles get a minimum angle of
 * min_angle_deg and area <= max_area, except where that would need a
 * Steiner point that an unsplittable segment forbids: one in the segment's
 * diametral lens (it would see the segment under more than 180 - 2 *
 * min_angle degrees), or nearly on its line close to one of its ends, or
 * beyond it. Such points are refused (counted in nrejected), so quality is
 * best-effort next to chart edges (narrow gaps, sharp chart corners) and
 * complete elsewhere. Triangles whose smallest angle lies between two
 * segments (input angles) are left alone. Splittable segments that are
 * encroached (diametral circle) are split at midpoints or concentric
 * shells; split points lie exactly on the segment (a segment where no
 * double does, which cannot happen for axis-aligned ones, stays whole).
 * Input points inside holes are not used by any triangle.
 * Deterministic: same input, same output.
 *
 * Fails with SCAF_ERR_MESH (message names the segments) on
 * invalid input: crossing segments, a point in the interior of a segment,
 * duplicate points, non-finite coordinates (or beyond 2^500 in magnitude),
 * segment indices out of range. Bad arguments (negative counts, missing
 * arrays, min_angle_deg outside [0, 60)) give SCAF_ERR_USAGE. On failure
 * *out is empty. */
scaf_status cdt_triangulate(const cdt_input *in, const cdt_options *opt, cdt_output *out,
                            scaf_error *err);

void cdt_output_free(cdt_output *out);

#endif /* SCAF_GEOM_CDT_H */
