/* opt/embed: initial bijective map of one chart into the plane.
 *
 * Tutte embedding: the outer boundary loop is pinned to a circle whose
 * area equals the chart's 3D surface area, its vertices spaced by 3D arc
 * length, in counter-clockwise order relative to the faces' orientation;
 * every other vertex is the uniform average of its neighbours (a sparse SPD
 * solve with opt/cholmod_solver). Harmonic: the same with cotangent
 * weights of the 3D triangles; when any triangle comes out inverted or
 * degenerate (decided with exact orient2d), or the cotangent system is not
 * positive definite, it falls back to mean-value, then Tutte. Mean-value
 * (opt/mvc): positive weights from the 3D angles, a non-symmetric solve;
 * checked exactly the same way, Tutte fallback. A chart with holes (more than
 * one boundary loop): each hole is filled with a fan around a temporary
 * vertex (at the hole's 3D centroid), the filled disk is embedded, and the
 * fill is dropped — the map of the chart stays valid.
 * Vertices not used by any face are placed at the circle's center.
 * Errors: SCAF_ERR_USAGE (bad index, empty loop), SCAF_ERR_MESH (a loop
 * edge that is not a boundary edge of exactly one face, a loop walked
 * inconsistently, a vertex on two loops, zero chart area),
 * SCAF_ERR_NUMERIC (singular system: a component not connected to the
 * outer boundary; or Tutte itself produced a non-positive triangle, which
 * happens only for an invalid disk or extreme floating-point degeneracy),
 * SCAF_ERR_NOMEM.
 */
#ifndef SCAF_OPT_EMBED_H
#define SCAF_OPT_EMBED_H

#include "base/error.h"

typedef enum opt_embed_method {
    OPT_EMBED_TUTTE = 0, /* uniform weights: always valid for a disk */
    OPT_EMBED_HARMONIC,  /* cotangent weights, mean-value then Tutte fallback */
    OPT_EMBED_MVC        /* mean-value weights (opt/mvc), Tutte fallback */
} opt_embed_method;

typedef struct opt_chart_loops {
    int nloops;          /* number of boundary loops (>= 1) */
    const int *start;    /* nloops+1 offsets into vertices */
    const int *vertices; /* loop k is vertices[start[k] .. start[k+1]) in cyclic order */
    int outer;           /* index of the outer loop, or -1: the longest in 3D */
} opt_chart_loops;

/* nv vertices V (#V by 3), nf faces F (#F by 3, consistently oriented),
 * loops: the chart's boundary loops (either direction). method: Tutte or
 * harmonic or mean-value. UV: #V by 2 out. used_fallback (may be NULL):
 * set to 1 when the requested method was not the one used (harmonic fell
 * back to mean-value or Tutte, mean-value to Tutte), else 0. */
scaf_status opt_embed_chart(int nv, const double *V, int nf, const int *F,
                            const opt_chart_loops *loops, opt_embed_method method, double *UV,
                            int *used_fallback, scaf_error *err);

/* The same, choosing which boundary loop goes on the circle: for a chart
 * with holes any loop can be the outer one, and the choice decides how
 * far the start is from a good map (bad/plane_holes.obj, 27 loops: start
 * energy 4.5e11 to 5.7e15 depending on the loop). Tries the max_tries
 * longest loops (loops->outer is ignored when more than one is tried) and
 * keeps the embedding of lowest symmetric Dirichlet energy (the longest
 * loop on ties); a loop whose embedding fails is skipped, the error is
 * returned only when every try failed. A chart with a degenerate 3D
 * triangle (no energy to compare by) gets the longest loop. energy (may
 * be NULL): the start's E (opt_term_mean_energy), NAN when unmeasurable. */
scaf_status opt_embed_chart_best(int nv, const double *V, int nf, const int *F,
                                 const opt_chart_loops *loops, opt_embed_method method,
                                 int max_tries, double *UV, int *used_fallback, double *energy,
                                 scaf_error *err);

#endif /* SCAF_OPT_EMBED_H */
