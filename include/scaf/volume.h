/* scaf/volume.h: the public C API of scaf's 3D functions: a closed surface
 * inflated inside a box of tets (scaf_inflate), its self-intersections
 * removed (scaf_untangle), conformalized mean curvature flow (scaf_flow),
 * the initial tet scaffold (scaf_tet_mesh), and the exact checks of a surface (scaf_check_surface) and of a tet
 * mesh (scaf_check_tets).
 *
 * Included by scaf/scaf.h; it may also be included on its own. Same
 * conventions as scaf.h: 0-based indices, row-major arrays ("V #V by 3"
 * means V[3*i+k]), every function that can fail returns a scaf_status and
 * leaves a message (scaf_volume_error, or the report's `message`).
 *
 * Options structs are versioned: their first field, struct_size, is the
 * size of the struct the caller was compiled with. Start from the
 * *_default() function (which sets it); a library reads only the first
 * struct_size bytes, so fields appended by a later version take their
 * defaults for a caller built against this one. A struct_size the library
 * does not know (0, smaller than this version's, or larger than its own)
 * and any option out of its documented range make the call fail with
 * SCAF_ERR_USAGE and a message naming the field: options are never
 * silently replaced.
 *
 * Units: inputs in any units. Coordinates beyond 2^+-60 in magnitude are
 * divided by a power of two before the work (exact: the exact checks say
 * the same) and the results multiplied back; SCAF_ERR_MESH when the input
 * spans more orders of magnitude than a double holds at once, or a result
 * in the input's units would exceed the largest double.
 *
 * Typical use:
 *
 *     scaf_inflate_options_t o = scaf_inflate_options_default();
 *     o.scale = 2.0;
 *     scaf_volume_t *h = scaf_volume_new();
 *     if (scaf_inflate(h, V, nv, F, nf, &o, NULL, NULL) != SCAF_OK)
 *         fprintf(stderr, "%s\n", scaf_volume_error(h));
 *     else
 *         scaf_volume_get_positions(h, X);   // nv by 3
 *     scaf_volume_destroy(h);
 */
#ifndef SCAF_VOLUME_H
#define SCAF_VOLUME_H

#include <stddef.h>

#include "scaf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------
 * Progress of the 3D runs
 * ---------------------------------------------------------------------- */

typedef enum scaf_volume_phase {
    SCAF_VOLUME_FLOW_STEP = 0, /* a step of the curvature flow (scaf_flow,
                                  the first phase of scaf_untangle) */
    SCAF_VOLUME_ITERATION      /* an iteration of the 3D SCAF loop
                                  (scaf_inflate, scaf_untangle's flow back) */
} scaf_volume_phase;

/* What one step did. Fields that do not apply to the step are 0 (counts
 * that were not computed are -1, as said). */
typedef struct scaf_volume_step_info {
    scaf_volume_phase phase;
    int step;              /* 1-based within its phase; scaf_flow also
                              calls with step 0, the start (the normalized
                              input, checked with until_free) */
    double seconds;        /* wall time of the step (flow steps: the step
                              alone; untangle's flow steps include the
                              check) */
    double check_seconds;  /* flow steps: the exact check after the step */
    long long defects;     /* intersecting face pairs + zero-area faces of
                              the surface after the step (0: free); -1 when
                              not checked (scaf_flow without until_free,
                              untangle iterations without verify) */
    long long pairs;       /* its intersecting face pairs (-1 unchecked) */
    int degenerate_faces;  /* its zero-area faces */
    double energy;         /* iterations: the surface energy after the step
                              (at the scale the loop works at, see Units) */
    double arap;           /* untangle iterations: its ARAP part */
    double step_length;    /* iterations: accepted step (0: none) */
    double rms, max;       /* untangle: distance of the vertices to their
                              input positions, relative to the input's
                              bounding-box diagonal (RMS, maximum) */
    int tets;              /* iterations: scaffold tets */
    int scaffold_vertices; /* inflate iterations: scaffold-only vertices */
    double quality_min;    /* iterations: minimum scaffold tet quality
                              (6 sqrt(2) V / l_rms^3, 1 for a regular tet) */
    double quality_p5;     /* inflate iterations: its 5th percentile */
    const double *X;       /* scaf_flow: the positions after the step (#V
                              by 3, normalized frame), valid during the
                              call only; NULL otherwise */
} scaf_volume_step_info_t;

/* Called after every step. Return nonzero to stop: the run returns
 * SCAF_ERR_CANCELLED; scaf_inflate's and scaf_flow's positions of the last
 * finished step stay available (scaf_untangle keeps none). */
typedef int (*scaf_volume_progress_fn)(const scaf_volume_step_info_t *info, void *user);

/* An opaque 3D run: the result of the last scaf_inflate, scaf_untangle or
 * scaf_flow called with it, and the message of its last failure. Not
 * thread-safe itself; two handles may run in two threads. */
typedef struct scaf_volume scaf_volume_t;

/* A new, empty handle; NULL only when out of memory. */
SCAF_API scaf_volume_t *scaf_volume_new(void);

/* Free everything. NULL is allowed. */
SCAF_API void scaf_volume_destroy(scaf_volume_t *h);

/* The message of the last failure ("" when none). Valid until the next
 * call on h. */
SCAF_API const char *scaf_volume_error(const scaf_volume_t *h);

/* The surface's vertex count of the last run (0 without a result). */
SCAF_API int scaf_volume_vertex_count(const scaf_volume_t *h);

/* Copy the result positions out: X #V by 3 (#V = scaf_volume_vertex_count),
 * the input's faces at the new positions. SCAF_ERR_USAGE without a
 * result. */
SCAF_API scaf_status scaf_volume_get_positions(const scaf_volume_t *h, double *X);

/* ------------------------------------------------------------------------
 * scaf_inflate: grow (or shrink) a closed surface toward K times its size
 * (scaled about its area-weighted centroid) inside a fixed box of tets
 * (the SCAF paper's Figure 10). Tets fill the box inside and outside the
 * surface; every iteration pulls the surface toward the target (surface
 * ARAP) as far as the scaffold allows, and every tet stays positively
 * oriented (exact), so the surface presses against the box and itself but
 * never passes through either.
 * ---------------------------------------------------------------------- */

typedef struct scaf_inflate_options {
    size_t struct_size; /* sizeof(scaf_inflate_options_t) (see the top) */
    double scale;       /* K, the target's size factor: > 0, <= 1e6; < 1
                           shrinks (2) */
    int iterations;     /* 1..100000 (50) */
    double box_scale;   /* the box is the bounding box scaled this many
                           times about its centre: > 1, <= 1e6 (3.76) */
    scaf_solver solver; /* SCAF_SOLVER_NEWTON (projected Newton, SLIM for
                           an iteration whose Newton step fails) or
                           SCAF_SOLVER_SLIM (SCAF_SOLVER_NEWTON) */
} scaf_inflate_options_t;

SCAF_API scaf_inflate_options_t scaf_inflate_options_default(void);

/* Inflate the surface (V #V by 3, F #F by 3 counter-clockwise seen from
 * outside). options NULL: the defaults; progress may be NULL. Errors:
 * SCAF_ERR_USAGE (bad options, NULL arrays or negative counts),
 * SCAF_ERR_MESH (an index out of range, a non-finite coordinate, not a
 * closed manifold surface free of self-intersections; units, see above),
 * SCAF_ERR_NUMERIC (a solve failed), SCAF_ERR_NOMEM, SCAF_ERR_CANCELLED,
 * SCAF_ERR_INTERNAL (an exact check failed: a bug). On failure other than
 * cancellation h holds no result. */
SCAF_API scaf_status scaf_inflate(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                                  const scaf_inflate_options_t *options,
                                  scaf_volume_progress_fn progress, void *user);

/* The final tet mesh of scaf_inflate (or the mesh of scaf_tet_mesh): #P =
 * the surface's vertices (at the result positions) then the scaffold's
 * own, #T tets. Counts are 0 without an inflate or tet result. */
SCAF_API int scaf_volume_tet_vertex_count(const scaf_volume_t *h);
SCAF_API int scaf_volume_tet_count(const scaf_volume_t *h);

/* Copy them out: P #P by 3, T #T by 4 (positively oriented), label #T
 * (1 inside the surface, 2 outside); any may be NULL. SCAF_ERR_USAGE
 * without an inflate or tet result. */
SCAF_API scaf_status scaf_volume_get_tets(const scaf_volume_t *h, double *P, int *T, int *label);

/* ------------------------------------------------------------------------
 * scaf_tet_mesh: the initial 3D scaffold alone. The space inside a box
 * around a closed surface (its bounding box scaled box_scale times about
 * its centre, each side cut into box_cells squares) tetrahedralized by
 * TetGen with every surface triangle kept (no point added on the surface
 * or the box), then checked exactly: every tet positive, every surface
 * triangle a face of one tet inside and one outside. The tets are read
 * with scaf_volume_get_tets (the surface's vertices first, unmoved).
 * ---------------------------------------------------------------------- */

typedef struct scaf_tet_options {
    size_t struct_size; /* sizeof(scaf_tet_options_t) (see the top) */
    double box_scale;   /* > 1, <= 1e6 (3) */
    int box_cells;      /* squares per box side edge, 1..64 (8) */
} scaf_tet_options_t;

SCAF_API scaf_tet_options_t scaf_tet_options_default(void);

/* Errors: SCAF_ERR_USAGE (bad options, NULL arrays), SCAF_ERR_MESH (an
 * index out of range, a non-finite coordinate, the surface cannot be
 * meshed: open, non-manifold, self-intersecting, the message says which;
 * units), SCAF_ERR_NOMEM, SCAF_ERR_INTERNAL (TetGen's output failed a
 * check). */
SCAF_API scaf_status scaf_tet_mesh(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                                   const scaf_tet_options_t *options);

/* ------------------------------------------------------------------------
 * scaf_untangle: remove the self-intersections of a closed genus-0
 * surface (the SCAF paper's Figure 9): conformalized mean curvature flow
 * until the exact checker proves the surface free, then the 3D SCAF loop
 * pulls it back toward the input (surface ARAP + an anchor toward the
 * input positions), never letting it pass through itself. The result is
 * the iterate of lowest energy; an input already free is returned as it
 * is. Genus > 0 is refused (the flow thins a handle into a ring).
 * ---------------------------------------------------------------------- */

typedef struct scaf_untangle_options {
    size_t struct_size; /* sizeof(scaf_untangle_options_t) (see the top) */
    double delta;       /* flow time step on the unit-area surface, in
                           (0, 1e6] (1e-3) */
    int flow_steps;     /* at most this many flow steps; SCAF_ERR_NUMERIC
                           when the surface is still not free, 1..100000
                           (1000) */
    int iterations;     /* at most this many iterations back, 1..100000
                           (300) */
    double tolerance;   /* the flow back stops when SCAF_UNTANGLE_WINDOW
                           iterations lowered
                           the lowest energy so far by at most this times
                           it, in [0, 1) (1e-2) */
    double anchor;      /* weight of the pull of every vertex toward its
                           input position, in [0, 1e12]; 0: ARAP alone,
                           which lets the surface drift (1000) */
    int verify;         /* 1: also prove the surface free after every
                           iteration (exact; SCAF_ERR_INTERNAL if it ever
                           is not), 0: no (0) */
} scaf_untangle_options_t;

#define SCAF_UNTANGLE_WINDOW 10

SCAF_API scaf_untangle_options_t scaf_untangle_options_default(void);

/* Untangle the surface (V #V by 3, F #F by 3). options NULL: defaults;
 * progress may be NULL (called after every flow step, then every
 * iteration). Errors: SCAF_ERR_USAGE (bad options or arrays),
 * SCAF_ERR_MESH (not a closed manifold genus-0 surface, naming why;
 * units), SCAF_ERR_NUMERIC (the flow did not free the surface in
 * flow_steps, a solve failed), SCAF_ERR_NOMEM, SCAF_ERR_CANCELLED,
 * SCAF_ERR_INTERNAL. On failure h holds no result. The options are
 * checked before the arrays, so a call with no surface (nv = nf = 0)
 * checks them alone: SCAF_ERR_USAGE for a bad one, SCAF_ERR_MESH ("no
 * face") when they are all valid. */
SCAF_API scaf_status scaf_untangle(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                                   const scaf_untangle_options_t *options,
                                   scaf_volume_progress_fn progress, void *user);

/* Copy out the freed surface of the flow (#V by 3, in the input's frame:
 * the input itself when already free). SCAF_ERR_USAGE without an untangle
 * result. */
SCAF_API scaf_status scaf_volume_get_flowed(const scaf_volume_t *h, double *X);

/* Why the flow back of scaf_untangle stopped. */
typedef enum scaf_untangle_stop {
    SCAF_UNTANGLE_ALREADY_FREE = 0, /* the input had no self-intersection */
    SCAF_UNTANGLE_CONVERGED,        /* the energy stopped decreasing */
    SCAF_UNTANGLE_ZERO_STEP,        /* the loop could not move the surface */
    SCAF_UNTANGLE_ITERATION_LIMIT   /* `iterations` done */
} scaf_untangle_stop;

/* A static word: "already_free", "converged", "zero_step",
 * "iteration_limit"; "unknown" for other values. */
SCAF_API const char *scaf_untangle_stop_name(scaf_untangle_stop stop);

/* ------------------------------------------------------------------------
 * scaf_flow: conformalized mean curvature flow (Kazhdan, Solomon,
 * Ben-Chen 2012) of a closed surface. The surface is moved and scaled to
 * unit area (area-weighted centroid at the origin); every step solves
 * (M - delta L) U' = M U (L: the input's cotangent Laplacian, M: the mass
 * of the current shape) and normalizes again. The result is in that
 * normalized frame.
 * ---------------------------------------------------------------------- */

typedef struct scaf_flow_options {
    size_t struct_size; /* sizeof(scaf_flow_options_t) (see the top) */
    int steps;          /* steps to run, 1..100000 (with until_free: at
                           most this many) (10) */
    double delta;       /* time step, in (0, 1e6] (1e-3) */
    int until_free;     /* 1: stop at the first step whose surface the
                           exact checker proves free of self-intersections
                           (and zero-area faces), checking the input
                           first; SCAF_ERR_NUMERIC when none of the steps
                           is (positions of the last step available);
                           0: run every step unchecked (0) */
} scaf_flow_options_t;

SCAF_API scaf_flow_options_t scaf_flow_options_default(void);

/* Flow the surface (V #V by 3, F #F by 3). Errors: SCAF_ERR_USAGE,
 * SCAF_ERR_MESH (not a closed manifold surface, a zero-area face; units),
 * SCAF_ERR_NUMERIC (a solve failed; with until_free: not free after
 * `steps`), SCAF_ERR_NOMEM, SCAF_ERR_CANCELLED. Arrays as scaf_inflate. */
SCAF_API scaf_status scaf_flow(scaf_volume_t *h, const double *V, int nv, const int *F, int nf,
                               const scaf_flow_options_t *options, scaf_volume_progress_fn progress,
                               void *user);

/* ------------------------------------------------------------------------
 * What the last run found (scaf_volume_get_summary). Fields not filled by
 * that run are 0.
 * ---------------------------------------------------------------------- */

typedef struct scaf_volume_summary {
    size_t struct_size;      /* set by the caller: sizeof(scaf_volume_summary_t) */
    int steps;               /* flow steps done (scaf_flow, scaf_untangle) */
    int iterations;          /* iterations done (scaf_inflate, scaf_untangle) */
    long long input_defects; /* intersecting face pairs (+ zero-area faces
                                  for scaf_flow) of the input; -1 when not
                                  checked (scaf_flow without until_free;
                                  scaf_inflate) */
    long long defects;       /* scaf_flow with until_free: of the result */
    double box_lo[3];        /* scaf_inflate, scaf_tet_mesh: the box
                                (input's units) */
    double box_hi[3];
    double diagonal_before;  /* bounding-box diagonal of the input (all) */
    double diagonal_after;   /* scaf_inflate: ... of the result */
    int best_iteration;      /* scaf_untangle: the iteration of the result */
    scaf_untangle_stop stop; /* scaf_untangle: why the flow back stopped */
    double flowed_rms;       /* scaf_untangle: distances of the flowed */
    double flowed_max;       /* and of the result surface to the input, */
    double rms, max;         /* relative to diagonal_before */
    int box_vertices;        /* scaf_tet_mesh: the box's vertices (after
                                the surface's in the tets' points) */
    int tets_inside;         /* scaf_tet_mesh, scaf_inflate: tets inside
                                the surface (label 1) */
} scaf_volume_summary_t;

/* Fill s (its first s->struct_size bytes). SCAF_ERR_USAGE without a
 * result or with a struct_size this library does not know. */
SCAF_API scaf_status scaf_volume_get_summary(const scaf_volume_t *h, scaf_volume_summary_t *s);

/* ------------------------------------------------------------------------
 * Exact checks. The caller sets struct_size = sizeof(the report); the
 * message says why the check could not run.
 * ---------------------------------------------------------------------- */

#define SCAF_REPORT_MESSAGE_MAX 512
#define SCAF_SURFACE_FIRST_PAIRS 16

typedef struct scaf_surface_report {
    size_t struct_size;                     /* sizeof(scaf_surface_report_t) */
    char message[SCAF_REPORT_MESSAGE_MAX];  /* why the check failed ("" on success) */
    int faces;                              /* faces checked */
    int vertices;                           /* vertices referenced by faces */
    int boundary_edges;                     /* edges with one face */
    int closed;                             /* 1: no boundary edge */
    int manifold;                           /* 1: no non-manifold edge nor vertex */
    int degenerate_faces;                   /* zero-area faces (exact) */
    int first_degenerate;                   /* the lowest one, -1 when none */
    long long pairs;                        /* intersecting face pairs: the sum of */
    long long crossing_pairs;               /*   pairs sharing no vertex, */
    long long vertex_pairs;                 /*   sharing a vertex, */
    long long edge_pairs;                   /*   folded on an edge, */
    long long duplicate_pairs;              /*   on the same three vertices */
    int nfirst;                             /* entries of first used */
    int first[SCAF_SURFACE_FIRST_PAIRS][2]; /* the intersecting pairs (i < j)
                                               smallest in (i, j) order */
    int intersection_free;                  /* 1: no pair and no zero-area face */
} scaf_surface_report_t;

/* Exact self-intersection check of the triangle surface (V #V by 3,
 * F #F by 3; any surface, closed or not). SCAF_OK whatever the verdict
 * (r->intersection_free); SCAF_ERR_USAGE (NULL arrays, negative counts;
 * r NULL or its struct_size too small for the message: then nothing is
 * written), SCAF_ERR_MESH (an index out of range, a non-finite
 * coordinate), SCAF_ERR_NOMEM, with r->message. */
SCAF_API scaf_status scaf_check_surface(const double *V, int nv, const int *F, int nf,
                                        scaf_surface_report_t *r);

typedef struct scaf_tets_report {
    size_t struct_size;                    /* sizeof(scaf_tets_report_t) */
    char message[SCAF_REPORT_MESSAGE_MAX]; /* why the check failed */
    int tets;                              /* tetrahedra checked */
    int positive;                          /* positively oriented (exact orient3d) */
    int inverted;
    int degenerate; /* flat */
    int first_bad;  /* lowest inverted or flat tet, -1 when none */
    int valid;      /* 1: every tet positive */
} scaf_tets_report_t;

/* Exact orientation check of the tets (V #V by 3, T #T by 4; positive:
 * d on the side of the triangle (a, b, c) it sees counter-clockwise, the
 * MEDIT convention). SCAF_OK whatever the verdict (r->valid); errors as
 * scaf_check_surface. */
SCAF_API scaf_status scaf_check_tets(const double *V, int nv, const int *T, int nt,
                                     scaf_tets_report_t *r);

#ifdef __cplusplus
}
#endif

#endif /* SCAF_VOLUME_H */
