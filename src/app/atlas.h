/* app/atlas: a multi-chart texture atlas optimized inside one scaffold.
 *
 * The paper's texture-atlas application (Figures 1 and 8). Charts are the
 * connected components of a mesh without UVs, or its UV charts (pieces cut
 * along UV seams); vt indices whose faces form several fans (pinch points,
 * a vt shared by two charts) are first split into one UV per fan, so
 * every chart keeps its faces and its boundary vertex sequence. Setup
 * reuses app/param (chart checks naming the chart, Tutte embedding on a
 * circle of the chart's 3D area, circles on a grid), or with init_input
 * the input's own UVs when the exact checker proves them bijective,
 * scaled by the power of two closest to the surface's scale (exact, so
 * the proof still holds).
 *
 * Then the SCAF loop (scaffold/scaf_loop) runs on all charts at once in
 * two phases:
 *   1. settle: SCAF iterations (SLIM, then Newton) to convergence: until
 *      the estimated relative distance of E to its minimum
 *      (opt/convergence) is below settle_tolerance;
 *   1b. re-placement (repack): the settled charts are moved rigidly (a
 *      translation and a multiple of 45 degrees, from their settled
 *      orientation and, with rotate, also from each chart turned to its
 *      least-area bounding rectangle, app/atlas_align) by a raster packer
 *      (app/atlas_pack: several placement strategies ranked on a coarse
 *      grid, the best pack_picks placed on the full grid) into a square, with
 *      pack_gap_factor times the padding between charts; the new layout
 *      is used only when every triangle keeps its exact orientation, the
 *      exact checker proves it bijective, the padding holds and it packs
 *      better;
 *   1c. with rotate: the whole layout turned to its smallest bounding
 *      square (kept when every triangle stays exactly positive, the
 *      padding holds and the exact checker proves it bijective);
 *   2. compaction (also for a single chart: the box shrinks its long
 *      axis, within the distortion tolerance): SCAF iterations with a tight box (compact_box_scale),
 *      a stronger scaffold (compact_lambda_ratio) and, before each solve
 *      (the loop's prepare hook, after the rest shapes are taken): the
 *      box vertices moved toward its center by a fraction of their
 *      largest flip-free step (every scaffold triangle exactly positive
 *      afterwards); scaffold triangles off the box given a rest shape
 *      shrunk by compact_rest_scale, so the free space contracts; and
 *      scaffold triangles bridging two charts closer than three paddings
 *      stiffened (and given a larger rest shape below two paddings) so
 *      close pairs hold while the others move. Each iteration still
 *      lowers its own total energy. It stops when the layout's side stops
 *      shrinking, when E rises above (1 + distortion_tolerance) times the
 *      settled E, after three iterations without a step, or at the cap.
 *   3. with rotate: the layout turned again to its smallest bounding
 *      square (same checks), before the normalization.
 * Padding: the loop's feasibility hook rejects any step after which two
 * different charts are closer than padding * side (side = the longest
 * side of the charts' UV bounding box); the loop then first retries the
 * same step with the charts of every too-close pair (and the scaffold
 * corners around them) held still (restrict hook), then halves it. So
 * the layout normalized by one uniform scale 1/side into the unit square
 * has every chart gap >= padding after every iteration (checked in the
 * floating-point distance with a 1e-6 relative margin during the run; the
 * normalized output is then certified exactly, chart_gap_certify in
 * geom/chart_gap.h, before `scaf atlas` writes it). The map stays bijective after every
 * iteration (exact checks of the loop).
 *
 * Errors: SCAF_ERR_MESH naming the chart (not a disk / disk with holes,
 * degenerate face), or saying why the input UVs cannot be the start;
 * SCAF_ERR_USAGE for a padding the initial layout cannot give;
 * SCAF_ERR_NUMERIC, SCAF_ERR_NOMEM from the loop.
 */
#ifndef SCAF_APP_ATLAS_H
#define SCAF_APP_ATLAS_H

#include "base/error.h"
#include "mesh/mesh.h"
#include "scaf/scaf.h"
#include "scaffold/scaf_loop.h"

typedef struct atlas_options {
    scaf_options_t base;         /* loop options (energy, lambda, box, ...);
                                    base.max_iterations unused */
    double padding;              /* minimum gap between charts in the unit
                                    square (0: charts only never overlap) */
    int init_input;              /* 1: start from the input UVs (0) */
    int init_warm;               /* 1: start every chart from the input UVs
                                    as its shape when that is valid (a layout
                                    settled before, app/atlas_warm), charts
                                    re-placed on shelves; the others from
                                    Tutte; the whole start from Tutte unless
                                    the exact checker proves it bijective (0;
                                    chart splitting sets it between rounds) */
    int settle_iterations;       /* cap of phase 1 (200) */
    double settle_tolerance;     /* phase 1 ends when the estimated
                                    relative distance to the minimum is
                                    below this (1e-4) */
    int compact_iterations;      /* cap of phase 2; 0 = no compaction (150) */
    double compact_box_scale;    /* box during compaction (1.05) */
    double compact_fraction;     /* fraction of the box's flip-free step
                                    taken per iteration (0.65; 0.5 before:
                                    human_neutral 34 iterations to 0.713,
                                    now 16 to 0.718) */
    double compact_rest_scale;   /* during compaction, scaffold triangles
                                    off the box and not bridging two close
                                    charts take their current shape scaled
                                    by this as rest shape, so the free space
                                    contracts (0.8; 1 = box push only) */
    double distortion_tolerance; /* phase 2 stops when E > (1 + this) times
                                    the settled E (0.05) */
    int repack;                  /* 1: between the phases, re-place the
                                    settled charts rigidly with the raster
                                    packer (app/atlas_pack), kept only when
                                    the exact checks pass and it packs
                                    better (1) */
    int rotate;                  /* 1: turn charts beyond multiples of 45
                                    degrees: the packer starts from each
                                    chart's least-area bounding rectangle,
                                    and the layout is turned to its
                                    smallest bounding square after the
                                    re-placement and after compaction
                                    (app/atlas_align; each turn checked
                                    exactly, kept only when valid) (1) */
    int pack_cells;              /* raster cells along the square (1024) */
    int pack_picks;              /* strategies ranked on a grid of
                                    pack_cells / 2 whose best this many are
                                    placed again at full resolution (2; 4
                                    before: the same layouts on the seam
                                    meshes, twice the full-grid work) */
    double pack_gap_factor;      /* the packer leaves this times the padding
                                    between charts, for compaction to close
                                    (2) */
    double compact_lambda_ratio; /* lambda_ratio during compaction: a
                                    stronger scaffold moves charts further
                                    per iteration (1; was 0.3: on
                                    human_neutral 40 compaction iterations
                                    to 0.701 and E +1.1%, with 1: 22 to
                                    0.713 and E +3.2%; bench/RESULTS-atlas.md) */
    double progress_tolerance;   /* phase 2 stops when the side shrank by
                                    less than this relatively over the last
                                    progress_window iterations (1.5e-3) */
    int progress_window;         /* see progress_tolerance (4; 1..64; 8
                                    before: human_neutral gained 0.0004
                                    efficiency in its last 18 iterations) */
    /* chart splitting before the run (app/atlas_charts): */
    double max_distortion; /* split charts settling above this E; < 0 (default):
                              ATLAS_CHARTS_MAX_DISTORTION for automatic seams,
                              never for input seams; 0: never */
    int split_charts;      /* split charts filling little of their box; < 0
                              (default): for automatic seams only; 0 never; 1 always */
} atlas_options;

atlas_options atlas_options_default(void);

typedef enum atlas_phase { ATLAS_SETTLE = 0, ATLAS_COMPACT = 1 } atlas_phase;

typedef struct atlas_iteration {
    scaf_iteration_info_t info; /* the loop's numbers */
    atlas_phase phase;
    double side;       /* longest side of the charts' UV bbox */
    double gap;        /* smallest chart gap / side (normalized);
                                   INFINITY with one chart */
    double efficiency; /* chart UV area / side^2 */
} atlas_iteration;

typedef struct atlas {
    atlas_options opt;
    int nv, nf; /* input vertices and faces */
    int ncharts;
    int nw;        /* working vertices = output UVs */
    int *Fw;       /* nf by 3 working vertex (output UV) per corner */
    int *chart;    /* nf chart id per face */
    int *wchart;   /* nw chart id per working vertex */
    int split_uvs; /* vt indices split at pinch points */
    int *seg;      /* nseg by 3 boundary segments (a, b, chart) */
    int nseg;
    scaf_loop loop;
    double settled_energy;         /* E at the end of phase 1 */
    double eff_before, eff_after;  /* packing efficiency before / after phase 2 */
    double gap_before, gap_after;  /* normalized smallest gap, same times */
    double eff_packed;             /* after the raster re-placement (NAN: not done / rejected) */
    int settle_done, compact_done; /* iterations run in each phase */
    int compact_restored;          /* 1: the result is an earlier compaction
                                   layout (the last iterations overshot the
                                   distortion tolerance or packed worse);
                                   the scaffold is rebuilt at the next step */
    int turns;                     /* layout turns kept (rotate) */
    int stiffened;                 /* scaffold triangles stiffened (last iteration) */
    long padding_rejects;          /* steps the padding test rejected (each
                                   trial of the loop's shortening counts) */
    scaf_stop_reason settle_stop, compact_stop; /* why each phase stopped
                                   (SCAF_STOP_NONE: not run) */
    scaf_seams seams_used;                      /* the seam source (app/seam_source) */
    int seam_segments;                          /* charts of the segmentation (automatic) */
    int warm_charts;                            /* charts started from their previous
                                                   flattening (init_warm, or after
                                                   chart splitting) */
    char seams_why[200];                        /* why that source, for the terminal */
} atlas;

typedef int (*atlas_progress_fn)(const atlas *a, const atlas_iteration *it, void *user);

/* SCAF_OK, or SCAF_ERR_USAGE with msg (size bytes, may be NULL) saying
 * which option is out of which range: the loop options (app/param's
 * check), the atlas knobs, and the padding (0 or in [2^-200, 0.5), the
 * range the exact certificate of the output takes). atlas_init runs it;
 * callers run it before reading a mesh to refuse bad options up front. */
scaf_status atlas_options_check(const atlas_options *o, char *msg, size_t size);

/* Set up from a mesh (UVs used for the charts' seams, and as the start
 * with init_input). On failure *a is empty and err says why. */
scaf_status atlas_init(atlas *a, const mesh *m, const atlas_options *o, scaf_error *err);

/* Run both phases; progress (may be NULL) after every iteration; a
 * nonzero return stops (SCAF_ERR_CANCELLED). */
scaf_status atlas_run(atlas *a, atlas_progress_fn progress, void *user, scaf_error *err);

/* Phase 2's setup of the loop (tight box, compaction scaffold weight,
 * the prepare hook that pushes the box inward and stiffens close pairs)
 * and back to the loop options of phase 1 (base). atlas_run brackets its
 * compaction with them; app/drag runs compaction iterations on demand. */
void atlas_compact_begin(atlas *a);
void atlas_compact_end(atlas *a);

/* The compaction's distortion rule, one for `scaf atlas` (atlas_run) and
 * the editor's compact (scaf_drag_compact): E may rise to (1 +
 * distortion_tolerance) times e_start, E when the compaction starts (the
 * settled E in atlas_run); the first iteration above that stops the
 * compaction, and the layout kept is the best packed one within the limit
 * (the start qualifies), so the result never exceeds it. */
typedef struct atlas_compact_rule {
    double e_max;    /* the limit */
    double best_eff; /* packing efficiency of best */
    double *best;    /* 2 nw: the layout kept */
} atlas_compact_rule;

/* SCAF_ERR_NOMEM (nothing to end) or SCAF_OK. */
scaf_status atlas_compact_rule_begin(const atlas *a, atlas_compact_rule *r, double e_start,
                                     scaf_error *err);

/* After an iteration with energy E and this efficiency: 1 when E is over
 * the limit (stop: atlas_compact_rule_end puts the kept layout back),
 * else 0 (the layout kept when it packs better). */
int atlas_compact_rule_after(const atlas *a, atlas_compact_rule *r, double energy,
                             double efficiency);

/* restore: put the kept layout back when the loop's differs (returns 1
 * then, 0 otherwise); frees r either way. */
int atlas_compact_rule_end(atlas *a, atlas_compact_rule *r, int restore);

/* Why the run stopped: the compaction's reason when it ran, else the
 * settle phase's. */
scaf_stop_reason atlas_stop_reason(const atlas *a);

/* Normalized output: UV (nw by 2) = (uv - lo) / side, in [0, 1]^2. */
void atlas_normalized_uv(const atlas *a, double *UV);

/* Side and gap (normalized) of the current layout. */
double atlas_side(const atlas *a);

/* The smallest chart gap the padding test accepts at positions X (the
 * layout's vertices first): padding * side, with the margin that keeps
 * the normalized output's gaps >= padding. */
double atlas_padding_need(const atlas *a, const double *X);

/* Reported energy E (symmetric Dirichlet, 4 at an isometry) of the current layout. */
double atlas_energy(const atlas *a);
scaf_status atlas_gap(const atlas *a, double *gap, scaf_error *err);

/* Per-chart energy sum A_f SD(J_f) / sum A_f (ncharts values). */
void atlas_chart_energy(const atlas *a, double *E);

void atlas_free(atlas *a);

#endif /* SCAF_APP_ATLAS_H */
