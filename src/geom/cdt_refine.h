/* geom/cdt_refine: Ruppert/Chew-style quality refinement of a constrained Delaunay mesh.
 *
 * Internal to geom/cdt*. Works on a cdt_mesh whose segments are recovered
 * and whose regions are classified; only CDT_REG_DOMAIN triangles are
 * refined. Encroached splittable subsegments are split first (midpoint, or
 * concentric shells at a vertex shared with another segment); then bad
 * triangles (smallest angle below the bound, or area above max_area) get an
 * off-center / circumcenter. A Steiner point that would lie beyond a
 * constrained edge, on one, or inside the diametral circle of an
 * unsplittable segment is refused; one encroaching a splittable segment
 * splits that segment instead. Termination: every step either inserts a
 * point (bounded by max_steiner) or drops a queued item, and each triangle
 * is retried a bounded number of times.
 */
#ifndef SCAF_GEOM_CDT_REFINE_H
#define SCAF_GEOM_CDT_REFINE_H

#include "geom/cdt_mesh.h"

typedef struct cdt_refine_params {
    int ninput;                      /* vertices 0..ninput-1 are input points */
    const int *segments;             /* #S by 2 input segments */
    const unsigned char *splittable; /* #S effective flags */
    double min_angle_deg;            /* 0: no angle refinement */
    double max_area;                 /* 0: none */
    long max_steiner;                /* hard cap (> 0) */
} cdt_refine_params;

typedef struct cdt_refine_stats {
    int nsteiner;
    int nrejected;
    int capped;
} cdt_refine_stats;

/* Refine in place. Returns 0, or -1 when memory ran out. */
int cdt_refine(cdt_mesh *m, const cdt_refine_params *prm, cdt_refine_stats *st);

#endif /* SCAF_GEOM_CDT_REFINE_H */
