/* scaf/drag.h: the public C API for interactive dragging of an atlas.
 *
 * Included by scaf/scaf.h; it may also be included on its own. Same
 * conventions as scaf.h: 0-based indices, row-major arrays ("UV #UV by 2"
 * means UV[2*i+k]), every function that can fail returns a scaf_status and
 * leaves a message readable by scaf_drag_error.
 *
 * What it does (the paper's Figure 1: charts dragged while nothing ever
 * overlaps). Two kinds of motion: rigid (scaf_drag_rigid_*: charts move
 * as rigid bodies, the others are pushed by translations, no shape
 * changes; below) and deform (handles and SCAF steps, described here). A drag context holds one layout of a mesh's charts — one
 * chart, or an atlas of many (connected components, or pieces cut along
 * the UV seams, exactly as scaf_atlas_set_mesh finds them) — inside one
 * scaffold, with the atlas's padding kept between charts. The caller sets
 * soft handles (a UV vertex pulled to a target point, or a whole chart
 * pulled to a rigid motion of itself), then runs SCAF iterations with
 * scaf_drag_step: the handles pull, the charts in the way are pushed
 * aside through the scaffold, and the layout stays bijective (no flipped
 * triangle, no overlap, charts at least the padding apart) after every
 * iteration, whatever the targets: handles get as close to their targets
 * as that allows. Handles can change between steps at no rebuilding cost
 * beyond their own share of the system.
 *
 * Padding and pushing: the padding is a hard constraint (the line search
 * shortens a step until every two charts are at least the padding apart),
 * and also a barrier in the energy the steps minimize, so the charts in a
 * dragged chart's way are pushed aside with the padding between them, in
 * a layout packed to the padding too (the output of scaf_atlas_run, whose
 * charts are squeezed below their distortion optimum): a drag there gets
 * about as far as with padding 0.
 *
 * Units. Positions in and out (scaf_drag_get_uv, handle targets) are in
 * layout units: the mesh's 3D units divided by a power of two (exact; a
 * chart at rest has about its 3D size). They do not change from step to
 * step, so a viewer may fix its view transform once. The normalized output
 * for saving (scaf_drag_get_output) is the layout scaled into the unit
 * square like scaf_atlas_get_uv, certified exactly (bijective, padding).
 *
 * Typical use (an editor):
 *
 *     scaf_drag_options_t opt = scaf_drag_options_default();
 *     opt.start = SCAF_DRAG_START_INPUT;        // edit an existing atlas
 *     scaf_drag_t *d = scaf_drag_new(&opt);
 *     if (scaf_drag_set_mesh(d, V, nv, F, nf, UV, nuv, FT) != SCAF_OK)
 *         fprintf(stderr, "%s\n", scaf_drag_error(d));
 *     scaf_drag_checkpoint(d);                   // mouse down on chart c
 *     for (each mouse move)
 *         scaf_drag_move_chart(d, c, dx, dy, angle),  // total since mouse down
 *         scaf_drag_step(d, 2, NULL, NULL),
 *         scaf_drag_get_uv(d, UV, NULL, NULL);   // draw
 *     scaf_drag_clear_handles(d);                // mouse up
 *     ...
 *     int sel[2] = {3, 5};                       // rigid (see "rigid motions")
 *     scaf_drag_checkpoint(d);
 *     scaf_drag_rigid_begin(d, sel, 2);
 *     for (each mouse move)
 *         scaf_drag_motion_t m = scaf_drag_motion_identity();
 *         m.dx = dx, m.dy = dy;                  // total since mouse down
 *         scaf_drag_rigid_move(d, &m, &reached); // others pushed rigidly
 *     scaf_drag_rigid_end(d);
 *     ...
 *     scaf_drag_undo(d);                         // back to the checkpoint
 *     scaf_drag_get_output(d, UVn, FT, chart);   // [0,1]^2, certified: save
 *     scaf_drag_destroy(d);
 */
#ifndef SCAF_DRAG_H
#define SCAF_DRAG_H

#include "scaf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Where the layout starts. */
typedef enum scaf_drag_start {
    SCAF_DRAG_START_LAYOUT = 0, /* the atlas's starting layout: every chart
                                   a Tutte embedding on a circle of its 3D
                                   area, the circles on a grid */
    SCAF_DRAG_START_INPUT,      /* the input UVs (UV + FT of set_mesh),
                                   accepted only when the exact checker
                                   proves them bijective and the padding
                                   holds there (the layout of `scaf atlas`
                                   output does) */
    SCAF_DRAG_START_ATLAS       /* the finished atlas: the starting layout
                                   run through scaf_atlas_run's phases
                                   (settle, re-placement, compaction) */
} scaf_drag_start;

/* Options, versioned as scaf_options_t: struct_size is the size the
 * caller was compiled with, set by scaf_drag_options_default(); an
 * unknown struct_size or an option out of its documented range makes
 * scaf_drag_new return NULL and scaf_drag_set_options fail with
 * SCAF_ERR_USAGE; scaf_drag_options_check names the field. */
typedef struct scaf_drag_options {
    size_t struct_size;    /* sizeof(scaf_drag_options_t), set by
                              scaf_drag_options_default() */
    scaf_drag_start start; /* (SCAF_DRAG_START_LAYOUT) */
    double padding;        /* minimum distance between two charts,
                              relative to the longest side of the layout's
                              bounding box (the unit square of the
                              normalized output); 0 or in [2^-200, 0.5)
                              (4.0 / 1024, as scaf_atlas) */
    double weight_ratio;   /* handle weight, dimensionless (see
                              scaf_param_set_handles): each handle — one
                              vertex, or one chart with its weight spread
                              over its vertices — costs weight_ratio * A
                              (A total 3D area) at a squared distance A to
                              its target; the handles share it equally
                              (SCAF_HANDLE_WEIGHT_DEFAULT, 1e4) */
    scaf_solver solver;    /* step of each iteration (SCAF_SOLVER_SLIM:
                              moving targets favour SLIM's long steps;
                              AUTO switches to Newton once SLIM slows and
                              stays there) */
    double box_scale;      /* scaffold box, times the layout's bounding
                              box, in [1, 1e6] (3) */
    double lambda_ratio;   /* scaffold weight, > 0 (0.01, the paper's) */
    int undo_depth;        /* checkpoints kept by scaf_drag_checkpoint,
                              the oldest dropped beyond, in [1, 4096]
                              (64) */
    scaf_seams seams;      /* seam source of the atlas (see scaf_seams;
                              SCAF_SEAMS_DEFAULT: the input's seams when
                              they cut the mesh into disks, else automatic
                              charts) */
} scaf_drag_options_t;

/* The documented defaults above, struct_size set. */
SCAF_API scaf_drag_options_t scaf_drag_options_default(void);

/* SCAF_OK when options (not NULL) would be accepted; else SCAF_ERR_USAGE
 * and, when message is not NULL, a sentence naming the struct_size or the
 * first field out of range (at most size bytes, NUL included). */
SCAF_API scaf_status scaf_drag_options_check(const scaf_drag_options_t *options, char *message,
                                             size_t size);

/* Opaque drag context. Not thread-safe itself; two contexts may run in
 * two threads. */
typedef struct scaf_drag scaf_drag_t;

/* A new context with a copy of the options (NULL: defaults). Returns NULL
 * when out of memory or when the options are invalid
 * (scaf_drag_options_check says which field). */
SCAF_API scaf_drag_t *scaf_drag_new(const scaf_drag_options_t *options);

/* Replace the options: SCAF_ERR_USAGE naming the first invalid value
 * (the options are then unchanged). They take effect at the next
 * scaf_drag_set_mesh. */
SCAF_API scaf_status scaf_drag_set_options(scaf_drag_t *d, const scaf_drag_options_t *options);

/* Set the mesh and compute the starting layout (options.start).
 * Arguments as scaf_atlas_set_mesh:
 *   V   #V by 3 vertex positions (nv rows), finite
 *   F   #F by 3 vertex indices per triangle, counter-clockwise (nf rows)
 *   UV  #UV by 2 texture coordinates, or NULL (nuv = 0, FT NULL): then
 *       each connected component is one chart
 *   FT  #F by 3 UV indices per corner: the charts are the pieces cut
 *       along the UV seams (a UV index whose faces form several fans gets
 *       one layout vertex per fan)
 * Errors: those of scaf_atlas_set_mesh (SCAF_ERR_USAGE, SCAF_ERR_MESH
 * naming the chart or face), SCAF_ERR_USAGE for START_INPUT without UVs
 * or with a padding the input does not keep, SCAF_ERR_MESH when the input
 * UVs are not bijective. Drops handles and checkpoints. On failure the
 * context has no mesh. */
SCAF_API scaf_status scaf_drag_set_mesh(scaf_drag_t *d, const double *V, int nv, const int *F,
                                        int nf, const double *UV, int nuv, const int *FT);

/* Sizes: charts; layout vertices (#UV: one per chart corner fan, the UV
 * indices of scaf_drag_get_uv's FT); faces. 0 without a mesh. */
SCAF_API int scaf_drag_chart_count(const scaf_drag_t *d);
SCAF_API int scaf_drag_uv_count(const scaf_drag_t *d);
SCAF_API int scaf_drag_face_count(const scaf_drag_t *d);

/* The current layout, in layout units (see the banner):
 *   UV     out, #UV by 2 positions
 *   FT     out, #F by 3 layout vertex per corner of each input face (may
 *          be NULL; it never changes for a mesh)
 *   chart  out, #F chart id per face, 0..chart_count-1 (may be NULL)
 * SCAF_ERR_USAGE without a mesh or with UV NULL. */
SCAF_API scaf_status scaf_drag_get_uv(const scaf_drag_t *d, double *UV, int *FT, int *chart);

/* The chart of every layout vertex: chart out, #UV ids. SCAF_ERR_USAGE
 * without a mesh or with chart NULL. */
SCAF_API scaf_status scaf_drag_uv_charts(const scaf_drag_t *d, int *chart);

/* ---- handles --------------------------------------------------------------
 * A handle is a vertex handle (one layout vertex, an absolute target) or
 * a chart handle (every vertex of one chart, its targets the chart's pose
 * when the handle was created moved rigidly). At most one handle per
 * vertex and one per chart; a vertex of a held chart may have its own
 * vertex handle too. Handles act from the next scaf_drag_step on and stay
 * until cleared (scaf_drag_set_mesh drops them; undo and cancel do not
 * touch them). Errors (SCAF_ERR_USAGE, nothing changed): no mesh, an
 * index out of range (named with the valid range), a target or motion
 * that is not finite. */

/* Pull layout vertex uv (0..#UV-1) to (x, y), layout units. */
SCAF_API scaf_status scaf_drag_move_vertex(scaf_drag_t *d, int uv, double x, double y);

/* Pull chart c rigidly: the targets are the chart's vertices as they were
 * when its handle was created (the first move_chart since it was cleared:
 * the grab pose), rotated by `angle` radians counter-clockwise about the
 * grab pose's centroid (area-weighted, UV triangles) and translated by
 * (dx, dy) layout units. Calls while the handle exists give the motion
 * from that same grab pose (an editor passes the total motion since the
 * mouse went down), so repeated moves never drift. All the chart's
 * vertices are held, each with 1 / (its vertex count) of a handle's
 * weight: the chart follows as a whole and keeps its shape unless other
 * charts block it (the pull is soft, it then bends as little as the
 * distortion energy allows). */
SCAF_API scaf_status scaf_drag_move_chart(scaf_drag_t *d, int chart, double dx, double dy,
                                          double angle);

/* Drop one vertex handle / one chart handle (no handle there: SCAF_OK,
 * nothing changes) / every handle. */
SCAF_API scaf_status scaf_drag_clear_vertex(scaf_drag_t *d, int uv);
SCAF_API scaf_status scaf_drag_clear_chart(scaf_drag_t *d, int chart);
SCAF_API scaf_status scaf_drag_clear_handles(scaf_drag_t *d);

/* Number of handles (vertex handles + chart handles); 0 without a mesh. */
SCAF_API int scaf_drag_handle_count(const scaf_drag_t *d);

/* ---- pins -----------------------------------------------------------------
 * A pinned layout vertex never moves in a step or a compaction: it is
 * eliminated from every iteration's system and its step is zero, so its
 * coordinates keep their bits (a handle on it, or on its chart, has no
 * effect on it). Undo and cancel restore whole layouts, pinned vertices
 * included; pins stay until unpinned (scaf_drag_set_mesh drops them).
 * Errors (SCAF_ERR_USAGE, nothing changed): no mesh, uv out of range. */

/* Pin layout vertex uv (pinned nonzero) or unpin it (0). */
SCAF_API scaf_status scaf_drag_pin_vertex(scaf_drag_t *d, int uv, int pinned);

/* A hard vertex target: uv is pulled to (x, y) as by
 * scaf_drag_move_vertex, and after every step from then on, as soon as it
 * can be placed exactly on (x, y) with no triangle of the layout or of the
 * scaffold flipped (decided exactly) and the padding kept, it is put there
 * and pinned: it then is exactly (x, y), bit for bit, until unpinned.
 * scaf_drag_hard_pending says how many hard targets are not met yet
 * (a new hard target for uv replaces its pending one; unpinning or
 * clearing its handle drops it). Errors as scaf_drag_move_vertex. */
SCAF_API scaf_status scaf_drag_move_vertex_hard(scaf_drag_t *d, int uv, double x, double y);
SCAF_API int scaf_drag_hard_pending(const scaf_drag_t *d);

/* Whether uv is pinned (0 for no mesh or uv out of range); how many are. */
SCAF_API int scaf_drag_is_pinned(const scaf_drag_t *d, int uv);
SCAF_API int scaf_drag_pinned_count(const scaf_drag_t *d);

/* ---- padding ---------------------------------------------------------------
 * Change the padding (as options.padding, in (0, 0.5), at least 2^-200)
 * for every later step, compaction and output, without a new mesh. The
 * current layout must already keep it: a padding larger than its smallest
 * chart gap (relative to the longest side) is refused with SCAF_ERR_USAGE
 * saying that gap, nothing changed (compaction never spreads charts).
 * SCAF_ERR_USAGE too for no mesh, a value out of range, or a context made
 * with padding 0 (it has no padding term to change). */
SCAF_API scaf_status scaf_drag_set_padding(scaf_drag_t *d, double padding);
SCAF_API double scaf_drag_padding(const scaf_drag_t *d);

/* Largest distance of a handled vertex to its target (layout units); 0
 * without handles, NAN without a mesh. */
SCAF_API double scaf_drag_max_handle_error(const scaf_drag_t *d);

/* ---- iterations ------------------------------------------------------------ */

/* Run up to n >= 1 SCAF iterations with the current handles (SLIM or
 * Newton as options.solver says; the scaffold re-meshed every iteration,
 * the padding kept). Stops early, with SCAF_OK, when an iteration finds
 * no step that lowers the energy (the layout is then a minimum and more
 * iterations would not move it). After every iteration the layout is
 * bijective and padded. progress (may be NULL) is called after each
 * iteration; its nonzero return stops with SCAF_ERR_CANCELLED, keeping
 * the last finished iteration. The layout before the call is kept for
 * scaf_drag_cancel. Errors: SCAF_ERR_USAGE (no mesh, n < 1),
 * SCAF_ERR_NUMERIC, SCAF_ERR_NOMEM (the layout of the last finished
 * iteration stays). */
SCAF_API scaf_status scaf_drag_step(scaf_drag_t *d, int n, scaf_param_progress_fn progress,
                                    void *user);

/* Iterations finished since scaf_drag_set_mesh (not counting those of
 * SCAF_DRAG_START_ATLAS; lowered by cancel and undo to the count of the
 * state they restore). */
SCAF_API int scaf_drag_iterations(const scaf_drag_t *d);

/* Restore the layout before the last scaf_drag_step (bit for bit); a
 * second cancel without a step in between does nothing. SCAF_ERR_USAGE
 * without a mesh or when no step was made since set_mesh / the last
 * undo. */
SCAF_API scaf_status scaf_drag_cancel(scaf_drag_t *d);

/* Undo: scaf_drag_checkpoint saves the current layout on a stack (at
 * most options.undo_depth, the oldest dropped); scaf_drag_undo restores
 * the last saved layout bit for bit and removes it from the stack
 * (SCAF_ERR_USAGE when the stack is empty). scaf_drag_undo_count: layouts
 * on the stack. */
SCAF_API scaf_status scaf_drag_checkpoint(scaf_drag_t *d);
SCAF_API scaf_status scaf_drag_undo(scaf_drag_t *d);
SCAF_API int scaf_drag_undo_count(const scaf_drag_t *d);

/* Redo: each undo keeps the layout it left; scaf_drag_redo restores the
 * last one bit for bit (and checkpoints the current one, so undo goes back
 * again). A checkpoint, a step or a compaction drops what can be redone
 * (SCAF_ERR_USAGE when nothing is left). scaf_drag_redo_count: layouts
 * that can be redone. */
SCAF_API scaf_status scaf_drag_redo(scaf_drag_t *d);
SCAF_API int scaf_drag_redo_count(const scaf_drag_t *d);

/* Compaction, the atlas's second phase, from the current layout: n >= 1
 * iterations with a contracting scaffold (the box pushed inward), charts
 * packing tighter with the padding kept, handles ignored; stops early when
 * no step is found. The distortion rule of scaf_atlas_run's compaction:
 * E may rise to 1.05 times (the atlas's default distortion_tolerance 0.05)
 * its value when this call starts; the first iteration above stops it,
 * and the layout left is the best packed one within that limit (maybe the
 * start), so one call never raises E by more than 5%. A checkpoint-able state like scaf_drag_step (cancel
 * restores the layout before it). Same errors as scaf_drag_step. */
SCAF_API scaf_status scaf_drag_compact(scaf_drag_t *d, int n, scaf_param_progress_fn progress,
                                       void *user);

/* ---- rigid motions ----------------------------------------------------------
 * The editor's default way to move islands (issue 34): a selection of
 * charts moves as a rigid body (translation, rotation, uniform scale, or a
 * flip turned back into a half turn; below), and every other chart only
 * translates, as little as it must, to keep the padding: it is pushed when
 * closer than the padding to a chart placed before it, in order of
 * distance from the selection, along the direction (away from the
 * selection, the drag direction, or one of eight compass directions) that
 * needs the shortest push; pushes propagate to the charts behind. No chart
 * changes shape (the selection changes only by the similarity asked for);
 * the other charts' UVs are their previous UVs translated (to the
 * rounding of one addition per coordinate). Charts with a pinned vertex
 * never move (they cannot be selected and are never pushed). The padding
 * is relative to the layout's side, so a motion that makes the layout
 * larger needs the gaps inside the selection to grow too: the selection's
 * charts other than the first one given may be translated off the
 * motion, placed before any other chart and by the smallest push that
 * keeps the padding (a tiny one for a growing layout; a real one when a
 * scale below 1 brings two of them too close); each stays a similarity
 * of its grab pose.
 *
 * Every layout a rigid motion leaves is decided exactly before it is
 * kept: every triangle of a moved chart positively oriented (orient2d),
 * the padding test of the steps, and the certificate of the saved output
 * (scaf_drag_get_output: the exact checker and the exact padding
 * certificate on the normalized layout), whose result is kept, so saving
 * right after costs nothing. When the full motion fails a check (a pinned
 * chart in the way, a push that cannot be resolved), the largest fraction
 * of it that passes is taken (bisection on the fraction, 8 halvings; the
 * grab pose, fraction 0, always passes): `reached` says which.
 *
 * The padding is relative to the layout's longest side, so when pushes
 * make the layout larger, all charts closer than the new padding are
 * pushed too (by about the growth times the padding: tiny), rounds
 * repeating until the padding of the final side holds.
 *
 * Undo: the caller checkpoints (scaf_drag_checkpoint) before the motion,
 * as for a handle drag; scaf_drag_cancel returns to the grab pose. A
 * rigid motion drops what could be redone. */

/* What a rigid motion does to the selection, about a pivot: p ->
 * pivot + factor * R(angle) * M * (p - pivot) + (dx, dy), where M is the
 * identity, or for a flip the half turn -I (see flip). */
typedef enum scaf_drag_flip {
    SCAF_DRAG_FLIP_NONE = 0,
    SCAF_DRAG_FLIP_U, /* mirror u -> -u (across the vertical line through the pivot) */
    SCAF_DRAG_FLIP_V  /* mirror v -> -v */
} scaf_drag_flip;

typedef struct scaf_drag_motion {
    double dx, dy;       /* translation, layout units (0) */
    double angle;        /* counter-clockwise rotation, radians (0) */
    double factor;       /* uniform scale, in [1/1024, 1024] (1) */
    scaf_drag_flip flip; /* (SCAF_DRAG_FLIP_NONE) A mirror turns every
                            triangle clockwise: a mirrored chart is not a
                            bijective map of its surface and could never
                            be certified or saved, so a flip is refused
                            (SCAF_ERR_USAGE) unless remirror is set */
    int remirror;        /* 1: a flip is mirrored back across the other
                            axis, i.e. applied as a half turn about the
                            pivot (what stays of a flip in a bijective
                            layout); there is no way to save a mirrored
                            chart: mirror the mesh itself instead (0) */
    int has_pivot;       /* 1: pivot below; 0: the area-weighted centroid
                            of the selection's UV triangles at the grab */
    double pivot[2];
} scaf_drag_motion_t;

/* The identity motion (factor 1, everything else 0). */
SCAF_API scaf_drag_motion_t scaf_drag_motion_identity(void);

/* Grab the selection: charts[0..n) (ids 0..chart_count-1, repeats
 * allowed), n >= 1. The current layout becomes the grab pose every
 * scaf_drag_rigid_move starts from. SCAF_ERR_USAGE (nothing changed): no
 * mesh, n < 1 or charts NULL, an id out of range (named), a chart with a
 * pinned vertex (named). */
SCAF_API scaf_status scaf_drag_rigid_begin(scaf_drag_t *d, const int *charts, int n);

/* Move the selection by *m from the grab pose (an editor passes the total
 * motion since the mouse went down, so moves never drift) and make room
 * as described above. reached (may be NULL) gets the fraction of the
 * motion applied: 1 the whole, 0 none (the layout is then the grab
 * pose); a flip is all or nothing. SCAF_ERR_USAGE (nothing changed): no
 * rigid_begin since the mesh was set, m NULL or not finite, factor out of
 * range, a flip without remirror. SCAF_ERR_NOMEM. */
SCAF_API scaf_status scaf_drag_rigid_move(scaf_drag_t *d, const scaf_drag_motion_t *m,
                                          double *reached);

/* Drop the grab (SCAF_OK without one). The layout stays. */
SCAF_API scaf_status scaf_drag_rigid_end(scaf_drag_t *d);

/* One whole rigid operation: rigid_begin, rigid_move, rigid_end (the grab
 * is dropped also on failure). What an editor's rotate / scale / flip
 * button calls. */
SCAF_API scaf_status scaf_drag_transform(scaf_drag_t *d, const int *charts, int n,
                                         const scaf_drag_motion_t *m, double *reached);

/* ---- the deform cap -----------------------------------------------------------
 * In the deform mode (handles and scaf_drag_step), any iteration after
 * which a chart that has no handle (neither a chart handle nor a vertex
 * handle on one of its vertices) has its energy E (scaf_drag_chart_info)
 * above ratio times its E when the drag started (at the first step after
 * the last checkpoint, undo, redo, cancel, clearing the handles or
 * setting the cap) is refused: its layout is put back and the step stops
 * (SCAF_OK; the iteration count is that of the layout kept). So a drag
 * never squashes a neighbour beyond the cap; the dragged charts
 * themselves are not capped. Compaction keeps its own rule. */
#define SCAF_DRAG_ENERGY_CAP_DEFAULT 1.25

/* ratio >= 1, or 0 for no cap; SCAF_ERR_USAGE otherwise. Kept across
 * scaf_drag_set_mesh. */
SCAF_API scaf_status scaf_drag_set_energy_cap(scaf_drag_t *d, double ratio);
/* The cap in force (0: none); NAN for NULL. */
SCAF_API double scaf_drag_energy_cap(const scaf_drag_t *d);
/* Iterations refused by the cap since the mesh was set. */
SCAF_API long scaf_drag_capped_count(const scaf_drag_t *d);

/* ---- measures -------------------------------------------------------------- */

/* The current energy E of all charts (see scaf_iteration_info_t; 4 at an
 * isometry), NAN without a mesh. */
SCAF_API double scaf_drag_energy(const scaf_drag_t *d);

/* Packing efficiency of the current layout: chart UV area / (longest side
 * of its bounding box)^2, as the normalized output would have it
 * (floating point, cheap enough for every frame); NAN without a mesh. */
SCAF_API double scaf_drag_packing_efficiency(const scaf_drag_t *d);

/* Per-face distortion: E out, #F values ||J||^2 + ||J^-1||^2 (4 at an
 * isometry). SCAF_ERR_USAGE without a mesh or with E NULL. */
SCAF_API scaf_status scaf_drag_face_energy(const scaf_drag_t *d, double *E);

/* One chart's numbers. */
typedef struct scaf_drag_chart_info {
    int faces;          /* its faces */
    int uvs;            /* its layout vertices */
    double centroid[2]; /* area-weighted centroid of its UV triangles
                           (layout units): the pivot of move_chart */
    double uv_area;     /* total UV area (layout units squared) */
    double energy;      /* sum_f A_f (||J_f||^2 + ||J_f^-1||^2) / sum_f A_f
                           over its faces (A_f 3D area) */
    int held;           /* 1: it has a chart handle */
} scaf_drag_chart_info_t;

/* SCAF_ERR_USAGE without a mesh, info NULL or chart out of range. */
SCAF_API scaf_status scaf_drag_chart_info(const scaf_drag_t *d, int chart,
                                          scaf_drag_chart_info_t *info);

/* ---- output ---------------------------------------------------------------- */

/* The current layout normalized into [0,1]^2 (one uniform scale, as
 * scaf_atlas_get_uv) and certified: bijective by the exact checker and
 * every two charts at least options.padding apart, decided exactly on
 * these doubles. What an editor saves.
 *   UV     out, #UV by 2
 *   FT     out, #F by 3 (may be NULL)
 *   chart  out, #F chart id per face (may be NULL)
 *   efficiency, gap  out (may be NULL): packing efficiency and smallest
 *          chart distance of these coordinates (INFINITY with one chart)
 * SCAF_ERR_USAGE without a mesh or with UV NULL; SCAF_ERR_INTERNAL (and
 * nothing copied) when the certificate fails, which is a bug. */
SCAF_API scaf_status scaf_drag_get_output(const scaf_drag_t *d, double *UV, int *FT, int *chart,
                                          double *efficiency, double *gap);

/* The message of the last failure ("" when none). Valid until the next
 * call on d. */
SCAF_API const char *scaf_drag_error(const scaf_drag_t *d);

/* Free everything. NULL is allowed. */
SCAF_API void scaf_drag_destroy(scaf_drag_t *d);

#ifdef __cplusplus
}
#endif
#endif /* SCAF_DRAG_H */
