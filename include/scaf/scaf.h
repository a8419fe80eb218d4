/* scaf/scaf.h: the public C API of scaf.
 *
 * scaf computes bijective maps (UV parametrizations with no flipped triangle
 * and no overlap) with the Simplicial Complex Augmentation Framework
 * (Jiang, Schaefer, Panozzo 2017).
 *
 * Conventions: every function that can fail returns a scaf_status; on
 * failure a message a person can act on is available from the object that
 * failed (see each function). Indices are 0-based. Arrays are row-major:
 * "V #V by 3" means V[3*i+k] is coordinate k of vertex i.
 */
#ifndef SCAF_SCAF_H
#define SCAF_SCAF_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Marks the functions the shared library exports; everything else in it
 * is built with hidden visibility. */
#if defined(__GNUC__) || defined(__clang__)
#define SCAF_API __attribute__((visibility("default")))
#else
#define SCAF_API
#endif

/* Status codes. The `scaf` program maps each to its own exit status
 * (README.md, "Exit status of `scaf`"; tools/exit_codes.h). */
typedef enum scaf_status {
    SCAF_OK = 0,
    SCAF_ERR_USAGE,     /* invalid argument or option value */
    SCAF_ERR_IO,        /* a file cannot be opened, read or written */
    SCAF_ERR_PARSE,     /* malformed input file (syntax, index, number) */
    SCAF_ERR_MESH,      /* the mesh is invalid for the operation (topology,
                            degenerate faces, NaN, wrong chart type) */
    SCAF_ERR_NUMERIC,   /* a numerical step failed (factorization, ...) */
    SCAF_ERR_NOMEM,     /* out of memory */
    SCAF_ERR_CANCELLED, /* stopped by the caller's progress callback */
    SCAF_ERR_INTERNAL   /* a bug: an invariant of scaf itself broke */
} scaf_status;

/* A short, static English name of a status ("parse error", ...). */
SCAF_API const char *scaf_status_name(scaf_status status);

/* The version of the library, "MAJOR.MINOR.PATCH". */
SCAF_API const char *scaf_version(void);

/* Threads of an iteration's per-simplex work (assembly, energies, line
 * search) and of the sparse factorization (scaf's own POSIX threads) and
 * OpenBLAS's count outside scaf's kernels; one setting for the whole
 * process, every handle. n >= 1: n threads; n = 0: every core the process
 * may run on. Until called, the per-simplex work runs in one thread and
 * OpenBLAS's own default holds (all cores, or OPENBLAS_NUM_THREADS).
 * Results are the same run after run for the same count; every sum over
 * simplices is the same bits for any count, but the factorization's cut
 * follows the count unless scaf_set_deterministic(1) (below), so
 * different counts may differ in the last digits. Returns the BLAS's
 * count now in effect, 0 when the BLAS has no such setting (the
 * per-simplex count is set all the same), -1 for n < 0 (nothing changed). */
SCAF_API int scaf_set_threads(int n);

/* on != 0: results are the same bits for every thread count (the sparse
 * factorization's tree is cut into a fixed number of bins, which the
 * threads take in turn, instead of one per thread); costs time per
 * iteration, most with one thread.
 * Process-wide; applies to factorizations of patterns analyzed after the
 * call. Until called: off. */
SCAF_API void scaf_set_deterministic(int on);

/* ------------------------------------------------------------------------
 * Bijective parametrization (SCAF).
 *
 * Typical use:
 *
 *     scaf_options_t opt = scaf_options_default();
 *     scaf_param_t *p = scaf_param_new(&opt);
 *     if (scaf_param_set_mesh(p, V, nv, F, nf, NULL, 0, NULL) != SCAF_OK)
 *         fprintf(stderr, "%s\n", scaf_param_error(p));
 *     scaf_param_run(p, 0, my_progress, my_data);   // 0: options' cap
 *     int nuv = scaf_param_uv_count(p);
 *     ... allocate UV (nuv by 2) and FT (nf by 3) ...
 *     scaf_param_get_uv(p, UV, FT);
 *     scaf_param_destroy(p);
 *
 * Charts: a mesh without UVs has one chart per connected component; a mesh
 * with UVs (UV + FT) has one chart per piece of the mesh cut along its UV
 * seams (edges whose two sides use different UV indices). Every chart must
 * be a manifold, orientable disk, possibly with holes: by default
 * (options.seams, scaf_seams) a component or UV chart that is not (closed,
 * with handles) is cut open automatically, so any manifold mesh goes
 * through; the returned FT then carries the new seams. Each chart starts
 * as a mean-value (or Tutte, or harmonic) embedding on a circle of the
 * chart's 3D area;
 * several charts start on a grid of circles that do not touch. Then the
 * SCAF iteration runs inside a scaffold: the UV map is bijective (no
 * flipped triangle, no overlap) after every iteration.
 * ---------------------------------------------------------------------- */

/* Distortion energies: the first three by name; every energy, these and
 * any later one, is a value 0 <= e < scaf_energy_count(), listed with its
 * name and help by scaf_energy_info and found by name with
 * scaf_energy_find (the `scaf` program's --energy and Python's energy=
 * read the same list). */
typedef enum scaf_energy {
    SCAF_ENERGY_SYMMETRIC_DIRICHLET = 0, /* ||J||^2 + ||J^-1||^2 */
    SCAF_ENERGY_ARAP,                    /* ||J - R||^2 + b(det J): ARAP alone is
                                            no barrier; b = -ln(det / 0.1)^3
                                            below det J = 0.1, 0 above, keeps
                                            triangles away from collapse */
    SCAF_ENERGY_CONFORMAL                /* MIPS: ||J||^2 / (2 det J), a barrier;
                                            scale-free, so areas may vary
                                            widely */
} scaf_energy;

/* One energy's description (pointers to static strings). */
typedef struct scaf_energy_info_t {
    const char *name;    /* identifier, e.g. "symmetric_dirichlet"; the
                            program also accepts it with '-' for '_' */
    const char *aliases; /* further accepted names, space-separated ("" none) */
    const char *help;    /* one line: the formula and what it is for */
    double scale_offset; /* added to the mean energy per unit of area in
                            the scaffold weight and the convergence test
                            (1 for an energy that is 0 at its minimum,
                            else 0) */
} scaf_energy_info_t;

/* The number of energies. */
SCAF_API int scaf_energy_count(void);

/* Energy e's description into *info. SCAF_ERR_USAGE when info is NULL or
 * e is not in [0, scaf_energy_count()). */
SCAF_API scaf_status scaf_energy_info(int e, scaf_energy_info_t *info);

/* The energy called name (its identifier, with '-' or '_', or an alias)
 * into *e. SCAF_ERR_USAGE when a pointer is NULL or no energy has that
 * name (*e unchanged). */
SCAF_API scaf_status scaf_energy_find(const char *name, scaf_energy *e);

/* Initial embedding of each chart. */
typedef enum scaf_init {
    SCAF_INIT_TUTTE = 0, /* uniform weights: always valid */
    SCAF_INIT_HARMONIC,  /* cotangent weights; if any triangle flips, falls
                            back to mean-value, then Tutte */
    SCAF_INIT_MVC        /* mean-value coordinates (Floater 2003): positive
                            weights from the 3D angles; falls back to Tutte
                            if rounding flips a triangle */
} scaf_init;

/* How each iteration computes its step (all share the flip-free line
 * search and its exact orientation checks). */
typedef enum scaf_solver {
    SCAF_SOLVER_AUTO = 0, /* SLIM until one iteration lowers the objective
                             by less than 1e-2 (relative), then projected
                             Newton */
    SCAF_SOLVER_SLIM,     /* SLIM's local/global proxy only */
    SCAF_SOLVER_NEWTON    /* projected Newton from the first iteration */
} scaf_solver;

/* Where the charts' seams come from (see docs/seams.md). */
typedef enum scaf_seams {
    SCAF_SEAMS_DEFAULT = 0, /* the input's UV seams when the mesh has UVs
                               and they cut it into disks (possibly with
                               holes); automatic seams otherwise (no UVs,
                               or a UV chart closed, with handles or not a
                               manifold) */
    SCAF_SEAMS_INPUT,       /* the input's UV seams (or the connected
                               components without UVs); a chart that is
                               not a disk is an error */
    SCAF_SEAMS_AUTO,        /* automatic seams, the input's UVs ignored:
                               the parametrization cuts each component
                               into one disk (handle loops, and on a
                               closed piece a tree of short seams through
                               its points of highest curvature); the atlas
                               segments the surface into charts first */
    SCAF_SEAMS_EXTEND       /* the input's UV seams kept, and cuts added
                               where a UV chart is not a disk; without UVs
                               as SCAF_SEAMS_AUTO */
} scaf_seams;

/* Options, versioned: struct_size is the size of the struct the caller
 * was compiled with. Start from scaf_options_default(), which sets it and
 * every documented default; a struct_size this library does not know (0,
 * or another version's) and any option out of its documented range make
 * scaf_param_new return NULL and scaf_param_set_options fail with
 * SCAF_ERR_USAGE; scaf_options_check says which field. Options are never
 * silently replaced. */
typedef struct scaf_options {
    size_t struct_size;      /* sizeof(scaf_options_t), set by
                                scaf_options_default() */
    scaf_energy energy;      /* mesh distortion energy
                                (SCAF_ENERGY_SYMMETRIC_DIRICHLET) */
    scaf_init init;          /* initial embedding (SCAF_INIT_MVC) */
    int max_iterations;      /* iteration cap of scaf_param_run, >= 0 (200) */
    double tolerance;        /* convergence test: stop when the estimated
                                relative distance of the minimized mesh
                                energy to its minimum, (E - E_min) / E, is
                                below this (SCAF_STOP_CONVERGED; ARAP,
                                whose minimum can be 0: (E - E_min) /
                                (E + 1), E per unit of area). The
                                estimate (the iteration's `criterion`) is
                                the larger of the Newton decrement of the
                                last step and the linear tail
                                d rho / (1 - rho) of the last decreases d,
                                rho their largest ratio over 3 iterations;
                                it is judged from the 4th iteration on. 0
                                disables it (a zero step still ends the
                                run: see scaf_param_run) (1e-5) */
    double box_scale;        /* scaffold box = this times the current UV
                                bounding box, same center; recomputed
                                before each iteration and fixed during its
                                solve (3) */
    int box_square;          /* 1: the box is a square around the center
                                (side = scale * longest bbox side);
                                0: a rectangle (0) */
    int box_points_per_side; /* points placed on each box side, corners
                                included in the count (5) */
    double lambda_ratio;     /* scaffold weight lambda = lambda_ratio *
                                E_M / |S| (E_M: area-weighted mesh energy,
                                plus the 3D area for ARAP, which is about 0
                                at its minimum; |S|: scaffold triangle
                                count), re-evaluated
                                each iteration; Newton iterations use a
                                tenth of it (the minimum does not depend on
                                it, convergence does) (0.01, the paper's
                                1/100) */
    double min_angle_deg;    /* scaffold quality bound in degrees (20) */
    double step_fraction;    /* line search starts at this fraction of the
                                largest flip-free step (0.8) */
    scaf_solver solver;      /* step computation (SCAF_SOLVER_AUTO) */
    scaf_seams seams;        /* seam source (SCAF_SEAMS_DEFAULT) */
} scaf_options_t;

/* The documented defaults above, struct_size set. */
SCAF_API scaf_options_t scaf_options_default(void);

/* SCAF_OK when options (not NULL) would be accepted; else SCAF_ERR_USAGE
 * and, when message is not NULL, a sentence naming the struct_size or the
 * first field out of range and its value (at most size bytes, NUL
 * included). */
SCAF_API scaf_status scaf_options_check(const scaf_options_t *options, char *message, size_t size);

/* What one iteration did, passed to the progress callback. */
typedef enum scaf_phase {
    SCAF_PHASE_ASSEMBLY = 0,  /* Jacobians, weights, sparse system */
    SCAF_PHASE_ANALYSIS,      /* fill-reducing ordering, symbolic analysis */
    SCAF_PHASE_FACTORIZATION, /* numerical Cholesky factorization */
    SCAF_PHASE_SOLVE,         /* triangular solves */
    SCAF_PHASE_LINE_SEARCH,   /* flip-free step, Armijo, exact checks */
    SCAF_PHASE_SCAFFOLD,      /* rebuilding the scaffold (CDT) */
    SCAF_PHASE_OTHER,         /* everything else */
    SCAF_PHASE_COUNT
} scaf_phase;

/* A static English name of a phase ("assembly", ...). */
SCAF_API const char *scaf_phase_name(scaf_phase phase);

typedef struct scaf_iteration_info {
    int iteration;                          /* 1-based count of finished iterations */
    double energy;                          /* E after the step: sum_f A_f (||J_f||^2 +
                                 ||J_f^-1||^2) / sum_f A_f over mesh
                                 triangles (A_f 3D area); 4 at an isometry */
    double energy_before;                   /* E before this iteration */
    double total_before;                    /* E_M + lambda E_S before the step */
    double total_after;                     /* E_M + lambda E_S after the step (same
                                 scaffold, same lambda) */
    double lambda;                          /* scaffold weight used */
    double step;                            /* accepted step length (1 = full proxy step) */
    int scaffold_triangles;                 /* |S| */
    int scaffold_vertices;                  /* scaffold-only vertices (box + Steiner) */
    double seconds;                         /* wall time of this iteration */
    double phase_seconds[SCAF_PHASE_COUNT]; /* split of `seconds` */
    scaf_solver solver;                     /* the step of this iteration:
                                 SCAF_SOLVER_SLIM or SCAF_SOLVER_NEWTON */
    double decrement;                       /* Newton steps: -g.p / (2 total_before), the
                                 relative decrease the model predicted (the
                                 convergence criterion); SLIM steps: 0 */
    double criterion;                       /* the estimated relative distance of the
                                 minimized mesh energy to its minimum
                                 after this iteration (see `tolerance`);
                                 +INFINITY while not yet judged */
} scaf_iteration_info_t;

/* Why a run (or a phase of the atlas) stopped. Values never change
 * meaning; new ones are only appended. */
typedef enum scaf_stop_reason {
    SCAF_STOP_NONE = 0,        /* not run (yet): no iteration was asked for
                                 or the phase did not take place */
    SCAF_STOP_ITERATIONS,      /* the iteration cap was reached */
    SCAF_STOP_TOLERANCE,       /* the relative decrease of the energy over
                                 one iteration fell below the tolerance
                                 (no longer given by scaf_param_run, which
                                 stops SCAF_STOP_CONVERGED) */
    SCAF_STOP_ZERO_STEP,       /* no step lowers the energy any more (the
                                 line search accepted none): converged to
                                 floating-point precision */
    SCAF_STOP_CANCELLED,       /* the progress callback returned nonzero */
    SCAF_STOP_ERROR,           /* an iteration failed (see its status) */
    SCAF_STOP_DISTORTION,      /* atlas compaction: E exceeded (1 +
                                 distortion_tolerance) times the settled E */
    SCAF_STOP_PACKING_STALLED, /* atlas compaction: the layout's side shrank
                                 by less than 0.15% over the last 4
                                 iterations */
    SCAF_STOP_CONVERGED,       /* the estimated relative distance to the
                                 minimum (the iteration's criterion: Newton
                                 decrement or linear tail, see the
                                 tolerance) is below the tolerance */
    SCAF_STOP_NOISE_FLOOR      /* atlas settling: E found no new low in
                                 the last 10 iterations (it only moves up
                                 and down in its last digits, the loop's
                                 noise floor: the scaffold is remeshed
                                 every iteration); ends a run with
                                 tolerance 0 that no zero step ends */
} scaf_stop_reason;

/* A short, static name of a stop reason, one word in snake case
 * ("iteration_limit", "tolerance", "zero_step", "cancelled", "error",
 * "distortion_limit", "packing_stalled", "converged", "noise_floor", "not_run"), as in the JSON
 * reports of `scaf param` / `scaf atlas`; "unknown" for other values. */
SCAF_API const char *scaf_stop_reason_name(scaf_stop_reason reason);

/* Progress callback: called after every iteration. Return nonzero to stop
 * the run (scaf_param_run then returns SCAF_ERR_CANCELLED; the UV map of
 * the last finished iteration stays available and bijective). */
typedef int (*scaf_param_progress_fn)(const scaf_iteration_info_t *info, void *user);

/* Opaque parametrization context. Not thread-safe itself; two contexts
 * may run in two threads. */
typedef struct scaf_param scaf_param_t;

/* A new context with a copy of the options (NULL: defaults). Returns NULL
 * when out of memory or when the options are invalid (scaf_options_check
 * says which field). */
SCAF_API scaf_param_t *scaf_param_new(const scaf_options_t *options);

/* Replace the options (validated: SCAF_ERR_USAGE naming the field, the
 * options then unchanged). Takes
 * effect at the next scaf_param_run; `init` only at scaf_param_set_mesh. */
SCAF_API scaf_status scaf_param_set_options(scaf_param_t *p, const scaf_options_t *options);

/* Set the mesh and compute the initial embedding.
 *   V   #V by 3 vertex positions (nv rows)
 *   F   #F by 3 vertex indices per triangle, counter-clockwise (nf rows)
 *   UV  #UV by 2 texture coordinates, or NULL (nuv = 0): then each
 *       connected component is one chart
 *   FT  #F by 3 UV indices per corner (with UV), defining the charts by
 *       their seams; only the connectivity is used, not the UV values.
 *       Where the faces around one UV index form several fans (a chart
 *       touching itself at a vertex), each fan gets its own output UV. 
 * Fails with SCAF_ERR_MESH naming the chart and the reason when a chart is
 * closed, has genus, is non-manifold or non-orientable, or has a
 * degenerate triangle (exactly zero area, the test `scaf info` counts);
 * SCAF_ERR_USAGE on out-of-range indices. */
SCAF_API scaf_status scaf_param_set_mesh(scaf_param_t *p, const double *V, int nv, const int *F,
                                         int nf, const double *UV, int nuv, const int *FT);

/* Run up to `iterations` SCAF iterations (<= 0: options.max_iterations).
 * It stops at the first of (scaf_param_stop_reason tells which):
 *   - the cap: `iterations` done (SCAF_STOP_ITERATIONS);
 *   - the tolerance (when > 0): the iteration's criterion, the estimated
 *     relative distance to the minimum, is below it (SCAF_STOP_CONVERGED);
 *   - a zero step, whatever the tolerance (also 0): the line search found
 *     no step that lowers the objective and keeps every triangle
 *     positive; the map is a minimum to floating-point precision and
 *     further iterations would not change it (SCAF_STOP_ZERO_STEP);
 *   - the progress callback returns nonzero (SCAF_STOP_CANCELLED);
 *   - an iteration fails (SCAF_STOP_ERROR, with its status).
 * progress may be NULL. */
SCAF_API scaf_status scaf_param_run(scaf_param_t *p, int iterations,
                                    scaf_param_progress_fn progress, void *user);

/* Soft positional constraints for interactive or deformation-like use:
 * from the next scaf_param_run on, the objective also has
 *   w * sum_i ||uv[idx[i]] - targets[i]||^2,  w = weight_ratio / n
 * (idx: n output UV indices, 0 <= idx[i] < scaf_param_uv_count; targets:
 * n by 2 in the units of the UVs of scaf_param_get_uv). weight_ratio is
 * dimensionless: the distortion energy is an area and a mean squared
 * handle error of A (A the total 3D area) costs weight_ratio * A, so the
 * result does not depend on the mesh's scale; SCAF_HANDLE_WEIGHT_DEFAULT
 * (1e4) makes the handles dominate (what `scaf deform` uses). The map
 * stays bijective whatever the targets: handles get as close as that
 * allows. Call again to move handles or change them (n = 0: none);
 * nothing but the handles' own share of the system is rebuilt. Dropped by
 * scaf_param_set_mesh. SCAF_ERR_USAGE without a mesh, on an index out of
 * range, a target that is not finite or a weight ratio < 0. */
#define SCAF_HANDLE_WEIGHT_DEFAULT 1e4
SCAF_API scaf_status scaf_param_set_handles(scaf_param_t *p, int n, const int *idx,
                                            const double *targets, double weight_ratio);

/* Why the last scaf_param_run stopped (SCAF_STOP_NONE before any run or
 * after scaf_param_set_mesh). */
SCAF_API scaf_stop_reason scaf_param_stop_reason(const scaf_param_t *p);

/* The current reported energy E (see scaf_iteration_info_t). */
SCAF_API double scaf_param_energy(const scaf_param_t *p);

/* Number of charts, of finished iterations. */
SCAF_API int scaf_param_chart_count(const scaf_param_t *p);
/* The seam source scaf_param_set_mesh used: SCAF_SEAMS_INPUT (the input's
 * UV seams, or the components), SCAF_SEAMS_AUTO or SCAF_SEAMS_EXTEND;
 * SCAF_SEAMS_DEFAULT without a mesh. */
SCAF_API scaf_seams scaf_param_seams_used(const scaf_param_t *p);
SCAF_API int scaf_param_iterations(const scaf_param_t *p);

/* Number of output UV coordinates: one per (chart, vertex) pair. */
SCAF_API int scaf_param_uv_count(const scaf_param_t *p);

/* Copy the current map out:
 *   UV  #UV by 2 (#UV = scaf_param_uv_count), in the units of V: the
 *       optimizer works on V divided by a power of two (exact), so V scaled
 *       by 2^k gives these UVs scaled by exactly 2^k
 *   FT  #F by 3 UV index per corner of each input triangle (may be NULL)
 * SCAF_ERR_NUMERIC (UV still filled) when a coordinate cannot be written
 * exactly in V's units (it would overflow or fall into the subnormal
 * range: meshes near 1e300 or 1e-300). */
SCAF_API scaf_status scaf_param_get_uv(const scaf_param_t *p, double *UV, int *FT);

/* The message of the last failure ("" when none). Valid until the next
 * call on p. */
SCAF_API const char *scaf_param_error(const scaf_param_t *p);

/* Free everything. NULL is allowed. */
SCAF_API void scaf_param_destroy(scaf_param_t *p);

/* The distortion figure every command, report and the editor show
 * (docs/energy.md): the symmetric Dirichlet energy of the map with its UVs
 * scaled uniformly so that their total area equals the surface's,
 *   E = sum_f A_f (||s J_f||_F^2 + ||(s J_f)^-1||_F^2) / sum_f A_f,
 *   s^2 = sum_f A_f / sum_f a_f    (A_f 3D area, a_f UV area of face f),
 * 4 at an isometry and the same for any uniform scaling, rotation or
 * translation of the UVs. V nv by 3, F nf by 3, UV nuv by 2, FT nf by 3
 * (NULL: F indexes UV too, nuv = nv). Sets *E (+INFINITY when a face of
 * positive 3D area has a UV area <= 0). SCAF_ERR_USAGE on a NULL array,
 * a count < 1 or an index out of range; SCAF_ERR_MESH when the surface
 * has no area. */
SCAF_API scaf_status scaf_area_matched_energy(const double *V, int nv, const int *F, int nf,
                                              const double *UV, int nuv, const int *FT, double *E);

#ifdef __cplusplus
}
#endif

/* The multi-chart texture atlas (scaf_atlas_*). */
#include "atlas.h"
/* Interactive dragging of an atlas's charts and vertices (scaf_drag_*). */
#include "drag.h"
/* The 3D functions: inflate, untangle, flow, exact surface and tet checks
 * (scaf_inflate, scaf_untangle, scaf_flow, scaf_check_*). */
#include "volume.h"

#endif /* SCAF_SCAF_H */
