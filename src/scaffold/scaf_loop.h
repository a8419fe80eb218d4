/* scaffold/scaf_loop: the SCAF iteration on a set of charts.
 *
 * Works on a "working mesh": all charts side by side (vertices are chart
 * vertices; a 3D vertex on a seam appears once per chart), 3D positions
 * for the rest shapes and the current positions (UV for d = 2), which must
 * form a bijective map (positively oriented simplices, no overlaps) on
 * entry. One iteration (scaf_loop_step), over X = the mesh vertices, then
 * the scaffold-only vertices (nall = nv + nextra rows of d):
 *   1. the scaffold provider (scaffold/scaffold_provider; d = 2: the CDT
 *      scaffold, scaffold/scaffold_cdt) refreshes the scaffold around the
 *      current positions inside a box opt.scaffold.box_scale times their
 *      bounding box; its box vertices are fixed during this solve;
 *   2. scaffold rest shapes = their current shapes (guard: rest volume
 *      below the provider's eps -> regular simplex of volume eps; 2D:
 *      blended towards it between 2 eps and eps / 4, opt/simplices), energy
 *      weight lambda = lambda_ratio * E_M / |S| (times
 *      opt.newton_lambda_scale in a Newton iteration);
 *   3. the terms of the objective (opt/objective) — the mesh term (rest
 *      frames of the 3D triangles, weight = 3D area, energy opt.energy),
 *      the scaffold term (symmetric Dirichlet) and any extra terms
 *      (scaf_loop_add_term) — each fill their block of one SLIM proxy
 *      system, solved by opt/block_solver (which owns the ordering,
 *      reuse and regularization policy); or, for a Newton step
 *      (opt.solver), their Hessians (hessian_fill: exact after a full
 *      Newton step, each simplex projected PSD otherwise or when the exact
 *      sum is not positive definite, then a diagonal shift) and -gradient,
 *      in the same pattern, whose solution is the step;
 *   4. line search over all terms (opt/line_search): the largest allowed
 *      step (flip-free over mesh and scaffold), a fraction of it, Armijo
 *      backtracking on the total energy, and every term's exact validity
 *      check (orientation of every simplex) before accepting.
 * Each accepted step lowers the total energy; every simplex stays
 * positively oriented, so the map stays bijective.
 *
 * What is what in struct scaf_loop: `opt` and `hooks` are the caller's to
 * set between iterations; nv, nf, F, chart, chart_face, total_area, bedges are the
 * problem (fixed by scaf_loop_init); uv is the state (the caller may
 * replace it between iterations by another bijective map of the same
 * mesh); `iterations` counts finished ones (each reports through
 * scaf_loop_step's info); `work` is the loop's own (scaffold, terms,
 * system, solver, buffers) and is reached only through the functions below.
 * Fails with SCAF_ERR_NUMERIC (factorization), SCAF_ERR_NOMEM, or passes
 * on the scaffold provider's error; on failure the positions are unchanged.
 */
#ifndef SCAF_SCAFFOLD_SCAF_LOOP_H
#define SCAF_SCAFFOLD_SCAF_LOOP_H

#include "base/error.h"
#include "opt/objective.h"
#include "scaffold/scaffold_provider.h"

struct scaf_loop;

/* What the caller sets; scaf_loop_options_default gives the paper's and
 * the project's measured defaults. */
typedef struct scaf_loop_options {
    opt_energy energy;          /* the mesh term's energy (symmetric Dirichlet) */
    double lambda_ratio;        /* scaffold weight lambda = ratio * E_M / |S| (0.01;
                                   ARAP: E_M + mesh area) */
    double step_fraction;       /* first trial step: this fraction of the
                                  largest allowed step (0.8) */
    scaffold_options scaffold;  /* box and quality (scaffold_default_options) */
    scaf_solver solver;         /* SLIM, projected Newton, or auto: SLIM until
                                  an iteration lowers the objective by less
                                  than newton_switch (relative) or after
                                  newton_after iterations, Newton from
                                  then on (SCAF_SOLVER_SLIM here; the atlas
                                  keeps it, scaf_param chooses) */
    double newton_switch;       /* auto's threshold (1e-2, bench/RESULTS-newton.md) */
    int newton_after;           /* auto: Newton at the latest after this many
                                  SLIM iterations (8: a thin strip's SLIM
                                  keeps lowering its objective by > 1e-2 per
                                  iteration while E creeps) */
    double newton_lambda_scale; /* Newton iterations use lambda times this
                                  (0.1). The re-rested scaffold has zero
                                  gradient, so lambda does not move the
                                  minimum; it only pulls the boundary back
                                  like a proximal term (Newton then converges
                                  linearly). 0.1: camel_b 21 instead of 31
                                  iterations, the 1 x 0.001 rectangle 4.00002
                                  instead of 7.88 after 50
                                  (bench/RESULTS-newton.md) */
} scaf_loop_options;

scaf_loop_options scaf_loop_options_default(void);

/* Optional hooks of one iteration (all NULL by default), used by the atlas
 * (app/atlas) for compaction and the padding constraint:
 *   prepare   after the scaffold is refreshed and its rest shapes and
 *             weights set (rest = current shape), before the solve: may
 *             move FIXED (box) vertices in X (nall by d) and change the
 *             scaffold term (scaf_loop_scaffold_rest: rest shapes and
 *             energy weights; scaf_loop_scaffold_proxy_weights). Every
 *             simplex must stay positively oriented at X (the hook checks
 *             exactly); the iteration then lowers the total energy from
 *             that state.
 *   feasible  an extra constraint on a trial state X (nall by d): 1 = ok.
 *             A line-search step it rejects is halved (exact orientation
 *             and total-energy decrease re-checked) until accepted, or no
 *             step is taken. Must hold at the state the iteration starts.
 *   restrict  optional: called with a trial state X the feasibility hook
 *             rejected; may zero rows of the direction dir (nall by d) so
 *             the offending parts stay put, returning 1 when it changed
 *             dir (the same step is then tried again, with the same exact
 *             orientation, energy and feasibility checks), 0 otherwise.
 *   user      passed to all. */
typedef struct scaf_loop_hooks {
    scaf_status (*prepare)(void *user, struct scaf_loop *L, double *X, int nall, scaf_error *err);
    int (*feasible)(void *user, const struct scaf_loop *L, const double *X, int nall);
    int (*restrict_dir)(void *user, const struct scaf_loop *L, const double *X, double *dir,
                        int nall);
    void *user;
} scaf_loop_hooks;

typedef struct scaf_loop_work scaf_loop_work;

typedef struct scaf_loop {
    /* set by the caller */
    scaf_loop_options opt;
    scaf_loop_hooks hooks; /* zero = none (see above) */
    /* the problem (read only) */
    int d; /* vertex dimension of the map (2; 3: scaf_loop_init_volume) */
    int nv, nf;
    int *F;              /* nf by 3 working faces */
    opt_simplices chart; /* rest frames of the mesh triangles, weight = 3D area,
                            ordered by their last vertex (their scatter into
                            the system then walks its columns in sequence) */
    int *chart_face;     /* nf: the face of F each chart simplex is */
    double total_area;
    int nbedges;
    int *bedges; /* nbedges by 2 chart boundary edges, chart on the left */
    /* the state */
    double *uv; /* nv by d current positions (updated) */
    /* the report */
    int iterations; /* finished iterations */
    /* the loop's own */
    scaf_loop_work *work;
} scaf_loop;

/* Set up. V3 nv by 3 rest positions, F nf by 3 faces (counter-clockwise
 * in UV), uv0 nv by 2 initial bijective UV map, opt NULL for
 * scaf_loop_options_default. Copies everything. Fails with SCAF_ERR_MESH
 * on a triangle of zero 3D area or a mesh without boundary, and with
 * SCAF_ERR_INTERNAL on a triangle not positively oriented in uv0 (the
 * callers' starts are bijective by construction). */
scaf_status scaf_loop_init(scaf_loop *L, int nv, const double *V3, int nf, const int *F,
                           const double *uv0, const scaf_loop_options *opt, scaf_error *err);

/* Set up the loop in 3D (d = 3) on a "mesh" that is only a set of nv
 * vertices (a closed triangle surface's, typically) with positions X0
 * (nv by 3, copied): there is no chart term; the mesh energy comes from
 * the terms added with scaf_loop_add_term (a surface term toward a target
 * shape, opt/surface_arap_term), and p (taken: owned by the loop, also on
 * failure) provides the scaffold of tets (scaffold/scaffold_tet). Each
 * iteration is the 2D one over tets: SLIM (Newton where every term has a
 * Hessian), the flip-free line search over every tet (a cubic per tet),
 * exact orient3d confirmation, the provider's eps guard.
 * Scaffold weight: lambda = opt.lambda_ratio * (E_terms + energy_floor) /
 * |S|, with E_terms the added terms' energy at the iteration's start. In
 * 2D lambda follows the chart's symmetric Dirichlet energy, which is at
 * least 2d times the area; a surface ARAP energy is 0 at its target, and
 * the authors' (E / area - 2d) weight turns negative with it. The floor
 * (> 0, e.g. 2d * the surface term's weight * the target area, the
 * analogue of 2D's minimum) keeps lambda positive and finite; a
 * non-finite energy fails with SCAF_ERR_NUMERIC. scaf_loop_energy is then
 * E_terms. Fails with SCAF_ERR_USAGE (provider not 3D over nv vertices,
 * floor not > 0) or SCAF_ERR_NOMEM. */
scaf_status scaf_loop_init_volume(scaf_loop *L, int nv, const double *X0, scaffold_provider *p,
                                  double energy_floor, const scaf_loop_options *opt,
                                  scaf_error *err);

/* Replace the scaffold provider (by default, for d = 2, the CDT scaffold
 * of scaffold/scaffold_cdt around the mesh's boundary edges) by p, which
 * must have the loop's dimension and nv mesh vertices (SCAF_ERR_USAGE
 * otherwise; p is then not taken). The loop owns p from then on (destroyed
 * by scaf_loop_free). */
scaf_status scaf_loop_set_scaffold_provider(scaf_loop *L, scaffold_provider *p, scaf_error *err);

/* Add a term to the objective (after the mesh and scaffold terms; at most
 * OPT_PROXY_MAX_BLOCKS terms in all, else SCAF_ERR_USAGE). The loop copies
 * *t and frees its block; t->self stays the caller's and must live as long
 * as L. The term sees X with the dofs of the iteration (mesh vertices
 * first, indices 0..nv-1). */
scaf_status scaf_loop_add_term(scaf_loop *L, const opt_obj_term *t, scaf_error *err);

/* Whether a Newton step is possible: every term with a system block has
 * a Hessian (hessian_fill; the mesh term has one for every opt_energy). */
int scaf_loop_newton_available(const scaf_loop *L);

/* Pin mesh vertex v (pinned 1) or free it (0): a pinned vertex never
 * moves; its coordinates stay bit for bit through every iteration (it is
 * eliminated from the system and its step is zero; the caller may still
 * move it between iterations, as any position). SCAF_ERR_USAGE for v not
 * a mesh vertex, SCAF_ERR_NOMEM. Positions the pins make impossible to
 * improve give zero steps, never a flip. */
scaf_status scaf_loop_pin(scaf_loop *L, int v, int pinned, scaf_error *err);
int scaf_loop_pinned(const scaf_loop *L, int v);
int scaf_loop_pinned_count(const scaf_loop *L);

/* Move mesh vertex v to exactly p (2D, between iterations) when that
 * keeps every mesh and scaffold triangle around v positively oriented,
 * decided exactly (geom/predicates): the mesh and the scaffold then still
 * tile the fixed box, so the map stays bijective; and the feasibility hook
 * (when set: the atlas's padding) accepts the moved state. 1: moved; 0:
 * not (a flip, the hook, a non-finite p, no scaffold yet: before the
 * first iteration, or after a failed one), nothing changed. The scaffold
 * is the last step's: call it right after a step (or a place), not after
 * the caller replaced uv. How a hard target is reached
 * exactly (app/deform, app/drag). */
int scaf_loop_place(scaf_loop *L, int v, const double p[2]);

/* One iteration; fills info (may be NULL; info->solver says which step
 * was taken, info->decrement the relative Newton decrement). A Newton
 * step that the line search cannot use (zero step) is replaced by a SLIM
 * step in the same iteration. */
scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err);

/* Reported energy E = sum A_f SD(J_f) / sum A_f of the current map (a
 * volume loop: the added terms' energy). */
double scaf_loop_energy(const scaf_loop *L);

/* The mesh term's own energy (opt.energy, the one being minimized) of the
 * current map, per unit of 3D area: scaf_loop_energy for symmetric
 * Dirichlet (a volume loop: the added terms' energy, as scaf_loop_energy). */
double scaf_loop_mesh_energy(const scaf_loop *L);

/* Per-triangle symmetric Dirichlet energy of the current map (nf values). */
void scaf_loop_face_energy(const scaf_loop *L, double *E);

/* The scaffold of the last iteration (moved with its accepted step; n = 0
 * before the first iteration or after a failed one). Valid until the next
 * step. */
const scaffold_view *scaf_loop_scaffold_view(const scaf_loop *L);

/* For the prepare hook: the scaffold term of the iteration — rest shapes
 * (grad, vol) and energy weights, and the weights its proxy uses. */
opt_simplices *scaf_loop_scaffold_rest(scaf_loop *L);
double *scaf_loop_scaffold_proxy_weights(scaf_loop *L);

/* For measurements (bench/bench_factor): the system of the last iteration
 * (upper CSC, d unknowns per free vertex, mesh vertices first) and the
 * fill-reducing order of its mesh part (d nv entries; NULL before the
 * first iteration). Valid until the next step. */
const opt_csc *scaf_loop_last_system(const scaf_loop *L);
const int *scaf_loop_mesh_ordering(const scaf_loop *L);

void scaf_loop_free(scaf_loop *L);

#endif /* SCAF_SCAFFOLD_SCAF_LOOP_H */
