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
    const double *points;         /* #P by 2 coordinates (finite, distinct) */
    int nsegments;
    const int *segments;          /* #S by 2 point indices */
    const unsigned char *splittable; /* #S flags: 1 = Steiner points may be
                                        inserted on the segment (box edges),
                                        0 = keep it whole (chart edges).
                                        NULL: no segment is splittable */
    const unsigned char *left_is_hole; /* #S flags: 1 = the region to the
                                          left of segment a->b is a hole
                                          (chart interior: charts' boundary
                                          edges oriented with the chart on
                                          their left). NULL: none */
    int nholes;
    const double *holes;          /* #H by 2 seed points inside holes; may be 0 */
} cdt_input;

typedef struct cdt_options {
    double min_angle_deg;   /* quality bound; 0 disables refinement (20) */
    double max_area;        /* upper bound on triangle area; 0 = none (0) */
    int max_steiner;        /* safety cap on inserted points; 0 = no cap (0) */
} cdt_options;

/* The defaults above. */
cdt_options cdt_default_options(void);

typedef struct cdt_output {
    int npoints;
    double *points;   /* #P by 2: the input points first, in input order,
                         then the Steiner points */
    int ntriangles;
    int *triangles;   /* #T by 3 point indices, counter-clockwise */
} cdt_output;

/* Triangulate. Fails with SCAF_ERR_MESH (message names the segments) on
 * invalid input: crossing segments, a point in the interior of a segment,
 * duplicate points, non-finite coordinates. On failure *out is empty. */
scaf_status cdt_triangulate(const cdt_input *in, const cdt_options *opt, cdt_output *out,
                            scaf_error *err);

void cdt_output_free(cdt_output *out);

#endif /* SCAF_GEOM_CDT_H */
