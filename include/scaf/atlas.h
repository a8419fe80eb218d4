/* scaf/atlas.h: the public C API of the multi-chart texture atlas.
 *
 * Included by scaf/scaf.h (so one `#include <scaf/scaf.h>` gives both the
 * parametrization and the atlas); it may also be included on its own.
 * Same conventions as scaf.h: 0-based indices, row-major arrays ("UV #UV
 * by 2" means UV[2*i+k]), every function that can fail returns a
 * scaf_status and leaves a message readable by scaf_atlas_error.
 *
 * What it computes (`scaf atlas` on the command line): every chart
 * (piece cut along the UV seams of a mesh with UVs; by default, when those
 * do not cut it into disks or there are none, automatic charts: the
 * segmentation of the surface, each cut into a disk, see scaf_seams)
 * starts as a Tutte embedding on a circle of its
 * 3D area, the circles on a grid; all charts are optimized together inside
 * one scaffold (settle phase), re-placed rigidly by a raster packer when
 * that is proved valid and packs better, then packed tightly by SCAF
 * iterations with a contracting scaffold (compact phase). The map is
 * bijective after every iteration. The output is the layout scaled by one
 * uniform factor and translated into the unit square [0,1]^2, with every
 * two different charts at least `padding` apart; before it is handed out,
 * an exact certificate (exact arithmetic on the very doubles returned)
 * proves the padding and the exact checker proves the map bijective.
 *
 * Typical use:
 *
 *     scaf_atlas_options_t opt = scaf_atlas_options_default();
 *     opt.padding = 4.0 / 1024.0;             // 4 texels at 1024
 *     scaf_atlas_t *a = scaf_atlas_new(&opt);
 *     if (scaf_atlas_set_mesh(a, V, nv, F, nf, NULL, 0, NULL) != SCAF_OK ||
 *         scaf_atlas_run(a, NULL, NULL) != SCAF_OK)
 *         fprintf(stderr, "%s\n", scaf_atlas_error(a));
 *     int nuv = scaf_atlas_uv_count(a);
 *     ... allocate UV (nuv by 2) and FT (nf by 3) ...
 *     scaf_atlas_get_uv(a, UV, FT);           // normalized, certified
 *     scaf_atlas_destroy(a);
 */
#ifndef SCAF_ATLAS_H
#define SCAF_ATLAS_H

#include "scaf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Options, versioned as scaf_options_t: struct_size is the size the
 * caller was compiled with, set by scaf_atlas_options_default(); an
 * unknown struct_size or an option out of its documented range makes
 * scaf_atlas_new return NULL and scaf_atlas_set_options fail with
 * SCAF_ERR_USAGE; scaf_atlas_options_check names the field. */
typedef struct scaf_atlas_options {
    size_t struct_size;          /* sizeof(scaf_atlas_options_t), set by
                                    scaf_atlas_options_default() */
    double padding;              /* minimum distance between two charts in
                                    the unit square, >= 0 and < 0.5; 0: the
                                    charts only never overlap (4.0 / 1024:
                                    4 texels of a 1024 texture) */
    scaf_energy energy;          /* distortion energy
                                    (SCAF_ENERGY_SYMMETRIC_DIRICHLET) */
    scaf_init init;              /* start of each chart (SCAF_INIT_TUTTE) */
    int init_input;              /* 1: start from the UVs given to
                                    scaf_atlas_set_mesh instead, accepted
                                    only when the exact checker proves them
                                    bijective (0) */
    int settle_iterations;       /* cap of the settle phase, >= 0 (200) */
    double settle_tolerance;     /* the settle phase runs to convergence:
                                    it ends when the estimated relative
                                    distance of E to its minimum (the
                                    criterion of scaf_param_run, see
                                    scaf_options_t.tolerance) is below
                                    this, >= 0; 0 disables this test (a
                                    zero step still ends the phase) (1e-4).
                                    It runs SLIM then Newton (auto), the
                                    compaction SLIM */
    int compact_iterations;      /* cap of the compact phase, >= 0; 0: no
                                    compaction (150) */
    double distortion_tolerance; /* the compact phase stops when E exceeds
                                    (1 + this) times the settled E, >= 0
                                    (0.05) */
    int repack;                  /* 1: rigid re-placement by the raster
                                    packer between the phases (1) */
    int pack_cells;              /* raster cells along the square of the
                                    packer, in [16, 8192]; fewer is faster
                                    and packs coarser (1024) */
    double box_scale;            /* scaffold box while settling, times the
                                    UV bounding box, in [1, 1e6] (3) */
    double lambda_ratio;         /* scaffold weight while settling, > 0
                                    (0.01, the paper's 1/100) */
    double compact_lambda_ratio; /* scaffold weight while compacting, > 0
                                    (1) */
    scaf_seams seams;            /* seam source (SCAF_SEAMS_DEFAULT: the
                                    input's UV seams when they cut the mesh
                                    into disks, else automatic charts: the
                                    surface segmented, each chart cut into
                                    a disk; see scaf_seams) */
} scaf_atlas_options_t;

/* The documented defaults above, struct_size set. */
SCAF_API scaf_atlas_options_t scaf_atlas_options_default(void);

/* SCAF_OK when options (not NULL) would be accepted; else SCAF_ERR_USAGE
 * and, when message is not NULL, a sentence naming the struct_size or the
 * first field out of range (at most size bytes, NUL included). */
SCAF_API scaf_status scaf_atlas_options_check(const scaf_atlas_options_t *options, char *message,
                                              size_t size);

/* Which phase an iteration belongs to. */
typedef enum scaf_atlas_phase {
    SCAF_ATLAS_SETTLE = 0, /* distortion settles, charts far apart */
    SCAF_ATLAS_COMPACT     /* the scaffold contracts, charts pack */
} scaf_atlas_phase;

/* What one iteration did, passed to the progress callback. */
typedef struct scaf_atlas_iteration_info {
    scaf_atlas_phase phase;
    int iteration;              /* 1-based, counted over both phases */
    int phase_iteration;        /* 1-based within the phase */
    double energy;              /* E after the step (see scaf_iteration_info_t) */
    double efficiency;          /* packing efficiency of the current layout:
                                  chart UV area / (longest side of its UV
                                  bounding box)^2 */
    double gap;                 /* smallest distance between two charts
                                  divided by that side (the gap in the unit
                                  square); INFINITY with one chart */
    double seconds;             /* wall time of this iteration */
    scaf_iteration_info_t loop; /* the SCAF iteration's own numbers */
} scaf_atlas_iteration_info_t;

/* Progress callback: called after every iteration of scaf_atlas_run.
 * Return nonzero to stop: scaf_atlas_run then returns SCAF_ERR_CANCELLED
 * and the layout of the last finished iteration stays available. */
typedef int (*scaf_atlas_progress_fn)(const scaf_atlas_iteration_info_t *info, void *user);

/* Opaque atlas context. Not thread-safe itself; two contexts may run in
 * two threads. */
typedef struct scaf_atlas scaf_atlas_t;

/* A new context with a copy of the options (NULL: defaults). Returns NULL
 * when out of memory or when the options are invalid
 * (scaf_atlas_options_check says which field). */
SCAF_API scaf_atlas_t *scaf_atlas_new(const scaf_atlas_options_t *options);

/* Replace the options: SCAF_ERR_USAGE naming the first invalid value
 * (the options are then unchanged). They take effect at the next
 * scaf_atlas_set_mesh (the padding must hold in the starting layout). */
SCAF_API scaf_status scaf_atlas_set_options(scaf_atlas_t *a, const scaf_atlas_options_t *options);

/* Set the mesh, find and check the charts, compute the starting layout.
 *   V   #V by 3 vertex positions (nv rows), finite
 *   F   #F by 3 vertex indices per triangle, counter-clockwise (nf rows)
 *   UV  #UV by 2 texture coordinates, or NULL (with nuv = 0 and FT NULL):
 *       then each connected component is one chart
 *   FT  #F by 3 UV indices per corner (with UV): the charts are the pieces
 *       cut along the UV seams; the UV values are only used with
 *       init_input. A UV index whose faces form several fans (a pinch
 *       point) gets one output UV per fan.
 * Errors: SCAF_ERR_USAGE for NULL arrays, counts <= 0 (nuv < 0), indices
 * out of range (the face and index named), UV without FT or the reverse,
 * init_input without UVs, a padding the starting layout cannot give;
 * SCAF_ERR_MESH naming the chart and the reason when a chart is not a
 * disk (possibly with holes), is non-manifold, non-orientable, has a
 * degenerate face or a non-finite coordinate, or when init_input is set
 * and the input UVs are not bijective. On failure the context has no mesh. */
SCAF_API scaf_status scaf_atlas_set_mesh(scaf_atlas_t *a, const double *V, int nv, const int *F,
                                         int nf, const double *UV, int nuv, const int *FT);

/* Run both phases (once per scaf_atlas_set_mesh; a second call fails with
 * SCAF_ERR_USAGE). progress may be NULL. Returns SCAF_OK,
 * SCAF_ERR_CANCELLED (see the callback), SCAF_ERR_NUMERIC, SCAF_ERR_NOMEM,
 * or SCAF_ERR_INTERNAL when the final layout fails its certificate (see
 * scaf_atlas_get_uv; a bug). */
SCAF_API scaf_status scaf_atlas_run(scaf_atlas_t *a, scaf_atlas_progress_fn progress, void *user);

/* The seam source scaf_atlas_set_mesh used: SCAF_SEAMS_INPUT,
 * SCAF_SEAMS_AUTO or SCAF_SEAMS_EXTEND (SCAF_SEAMS_DEFAULT without a
 * mesh). The seams themselves are the edges whose sides get different
 * UV indices in scaf_atlas_get_uv's FT. */
SCAF_API scaf_seams scaf_atlas_seams_used(const scaf_atlas_t *a);

/* Number of charts; of output UV coordinates (one per chart corner fan:
 * a vertex on a seam gets one UV per chart); of finished iterations in
 * each phase. 0 without a mesh. */
SCAF_API int scaf_atlas_chart_count(const scaf_atlas_t *a);
SCAF_API int scaf_atlas_uv_count(const scaf_atlas_t *a);
SCAF_API int scaf_atlas_iterations(const scaf_atlas_t *a, scaf_atlas_phase phase);

/* Why a phase of the last scaf_atlas_run stopped (SCAF_STOP_NONE before
 * the run, or for a phase that did not take place: compaction with one
 * chart or compact_iterations 0, or after a cancel or failure in the
 * settle phase).
 *   settle:  SCAF_STOP_ITERATIONS (settle_iterations done),
 *            SCAF_STOP_CONVERGED (the estimated distance to the
 *            minimum fell below settle_tolerance),
 *            SCAF_STOP_ZERO_STEP, SCAF_STOP_CANCELLED, SCAF_STOP_ERROR;
 *   compact: SCAF_STOP_ITERATIONS (compact_iterations done),
 *            SCAF_STOP_DISTORTION, SCAF_STOP_PACKING_STALLED,
 *            SCAF_STOP_ZERO_STEP (three iterations in a row without a
 *            step), SCAF_STOP_CANCELLED, SCAF_STOP_ERROR. */
SCAF_API scaf_stop_reason scaf_atlas_stop_reason(const scaf_atlas_t *a, scaf_atlas_phase phase);

/* Copy the current layout out, normalized into [0,1]^2 (one scale for all
 * charts) and certified: bijective by the exact checker and every two
 * charts at least options.padding apart, decided exactly on these doubles.
 * Available after scaf_atlas_set_mesh (the starting layout), after a run,
 * and after a cancelled run (the last finished iteration).
 *   UV     out, #UV by 2 (#UV = scaf_atlas_uv_count)
 *   FT     out, #F by 3 UV index per corner of each input triangle (may be
 *          NULL)
 *   chart  out, #F chart id per input triangle, 0..chart_count-1 (may be
 *          NULL)
 * SCAF_ERR_USAGE without a mesh or with UV NULL; SCAF_ERR_INTERNAL (and
 * nothing copied) if the certificate fails, which is a bug. */
SCAF_API scaf_status scaf_atlas_get_uv(const scaf_atlas_t *a, double *UV, int *FT, int *chart);

/* Of the same normalized, certified layout: the packing efficiency (total
 * chart UV area / area of the unit square) and the smallest distance
 * between two different charts (INFINITY with one chart). NAN without a
 * mesh or when the certificate fails (scaf_atlas_error says why). */
SCAF_API double scaf_atlas_packing_efficiency(const scaf_atlas_t *a);
SCAF_API double scaf_atlas_min_chart_gap(const scaf_atlas_t *a);

/* The current energy E of all charts (see scaf_iteration_info_t); NAN
 * without a mesh. */
SCAF_API double scaf_atlas_energy(const scaf_atlas_t *a);

/* Per-chart distortion: E[c] = sum_f A_f (||J_f||^2 + ||J_f^-1||^2) /
 * sum_f A_f over the triangles f of chart c (A_f 3D area; 4 at an
 * isometry).
 *   E  out, #charts values (scaf_atlas_chart_count)
 * SCAF_ERR_USAGE without a mesh or with E NULL; SCAF_ERR_NOMEM. */
SCAF_API scaf_status scaf_atlas_chart_distortion(const scaf_atlas_t *a, double *E);

/* The message of the last failure ("" when none). Valid until the next
 * call on a. */
SCAF_API const char *scaf_atlas_error(const scaf_atlas_t *a);

/* Free everything. NULL is allowed. */
SCAF_API void scaf_atlas_destroy(scaf_atlas_t *a);

#ifdef __cplusplus
}
#endif
#endif /* SCAF_ATLAS_H */
