/* app/volume_deform: pull a closed triangle surface toward target
 * positions inside a fixed box, never letting it pass through itself or
 * the box (the 3D SCAF loop: scaffold/scaf_loop's volume loop, the
 * surface ARAP term opt/surface_arap_term, the tet scaffold
 * scaffold/scaffold_tet).
 *
 * The surface (nv vertices, faces F) starts at positions V, which must be
 * a closed manifold surface free of self-intersections (TetGen meshes the
 * box around it: geom/tet_box_mesh refuses anything else, naming the
 * reason); its target is any nv positions with the same faces (a scaled
 * copy for `scaf inflate`, the original shape for `scaf untangle`) whose
 * triangles have non-zero area. Every iteration moves the surface toward
 * the target as far as the scaffold allows: every tet stays positively
 * oriented (exact), so the surface stays free of self-intersections and
 * inside the box at every iteration.
 *
 * Defaults and why (bench/RESULTS-inflate.md):
 *   box_scale 3.76    the box is the initial bounding box scaled 3.76
 *                     times about its centre (geom/tet_box_around: each
 *                     side at least 2.76 times the largest extent away),
 *                     which gives the bunny a box of 3.97 times its
 *                     diagonal, the authors' box;
 *   box_cells 8       squares per box side edge, the authors' 8 x 8;
 *   lambda_ratio      scaffold weight lambda = ratio * (E + 6 w A) / |S|
 *                     (scaf_loop_init_volume; E the surface energy, w A its
 *                     weight times the target area): 0.003 lets the
 *                     bunny x30 come closest to the walls in 50
 *                     iterations (0.001: slower; 0.01, 0.03: 0.3-1% less
 *                     growth);
 *   solver newton     grows further than SLIM in the same iterations
 *                     (bunny x30: 99.2% of the box diagonal, SLIM 97.3%);
 *   weight_ratio 1    the surface term's weight ratio (only its ratio to
 *                     lambda matters, and lambda follows it).
 * Errors: SCAF_ERR_USAGE (bad options or arguments), SCAF_ERR_MESH (the
 * surface cannot be meshed, a target face of zero area), SCAF_ERR_NOMEM,
 * SCAF_ERR_NUMERIC, SCAF_ERR_INTERNAL (an exact check failed: a bug).
 */
#ifndef SCAF_APP_VOLUME_DEFORM_H
#define SCAF_APP_VOLUME_DEFORM_H

#include "opt/surface_arap_term.h"
#include "scaffold/scaf_loop.h"
#include "scaffold/tet_improve.h"

#define VOLUME_DEFORM_LAMBDA_RATIO_DEFAULT 0.003

typedef struct volume_deform_options {
    double box_scale;                /* 3.76 (> 1) */
    int box_cells;                   /* 8 (1..64) */
    double lambda_ratio;             /* VOLUME_DEFORM_LAMBDA_RATIO_DEFAULT (> 0) */
    double weight_ratio;             /* 1 (> 0) */
    scaf_solver solver;              /* SCAF_SOLVER_NEWTON (falls back to SLIM when a
                            Newton step fails) or SCAF_SOLVER_SLIM */
    int improve;                     /* 1: the scaffold improvement pass every iteration
                            (scaffold/scaffold_tet) */
    tet_improve_options improve_opt; /* its options (tet_improve's
                                        defaults, at most 1000 tries) */
} volume_deform_options;

volume_deform_options volume_deform_options_default(void);

/* One iteration's numbers. */
typedef struct volume_deform_iteration {
    int iteration;         /* 1-based */
    double energy;         /* surface energy after the step (its rotations) */
    double step;           /* accepted step (0: none) */
    int tets;              /* scaffold tets */
    int scaffold_vertices; /* scaffold-only vertices (box + interior) */
    double quality_min;    /* tet quality after the step (scaffold_tet) */
    double quality_p5;     /* its 5th percentile */
    double seconds;        /* wall time of the iteration */
} volume_deform_iteration;

typedef struct volume_deform {
    scaf_loop loop;              /* loop.uv: the current positions (nv by 3) */
    opt_surface_arap arap;       /* the surface term */
    scaffold_provider *scaffold; /* owned by the loop */
    int nv, nf;
} volume_deform;

/* Set up and build the scaffold around V.
 *   nv, V      #V by 3 start positions (a closed surface, no
 *              self-intersection)
 *   nf, F      #F by 3 faces
 *   target     #V by 3 target positions
 *   opt        NULL for the defaults */
scaf_status volume_deform_init(volume_deform *vd, int nv, const double *V, int nf, const int *F,
                               const double *target, const volume_deform_options *opt,
                               scaf_error *err);

/* One iteration; it may be NULL. On failure the positions are those of
 * the last finished iteration. */
scaf_status volume_deform_step(volume_deform *vd, volume_deform_iteration *it, scaf_error *err);

/* The current positions (nv by 3) and the scaffold (tets over the surface
 * vertices and the scaffold-only ones; valid until the next step). */
static inline const double *volume_deform_positions(const volume_deform *vd) { return vd->loop.uv; }
const scaffold_view *volume_deform_scaffold(const volume_deform *vd);

void volume_deform_free(volume_deform *vd);

#endif /* SCAF_APP_VOLUME_DEFORM_H */
