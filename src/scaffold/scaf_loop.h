/* scaffold/scaf_loop: the SCAF iteration on a set of UV charts.
 *
 * Works on a "working mesh": all charts side by side (vertices are chart
 * vertices; a 3D vertex on a seam appears once per chart), 3D positions
 * for the rest shapes and the current UV positions, which must form a
 * bijective map (positively oriented triangles, no overlaps) on entry.
 * One iteration (scaf_loop_step):
 *   1. build the scaffold around the current chart boundaries inside a box
 *      box_scale times the UV bounding box (fixed during this solve);
 *   2. scaffold rest shapes = their current shapes (guard: rest area below
 *      eps = l^2/4 -> equilateral of area eps), lambda = lambda_ratio *
 *      E_M / |S|;
 *   3. one SLIM proxy solve of E_M + lambda E_S with the box fixed
 *      (opt's proxy blocks and CHOLMOD wrapper, supernodal);
 *   4. line search: largest flip-free step over mesh and scaffold, a
 *      fraction of it, Armijo backtracking on the total energy, and an
 *      exact orient2d confirmation of every triangle before accepting.
 * Each accepted step lowers the total energy; every triangle stays
 * positively oriented, so the map stays bijective.
 * Fails with SCAF_ERR_NUMERIC (factorization), SCAF_ERR_NOMEM, or passes on
 * the scaffold mesher's error; on failure the UV positions are unchanged.
 */
#ifndef SCAF_SCAFFOLD_SCAF_LOOP_H
#define SCAF_SCAFFOLD_SCAF_LOOP_H

#include "base/error.h"
#include "opt/cholmod_solver.h"
#include "opt/line_search.h"
#include "opt/proxy_block.h"
#include "opt/proxy_system.h"
#include "opt/simplices.h"
#include "scaffold/scaffold_build.h"

struct scaf_loop;

/* Optional hooks of one iteration (all NULL by default), used by the atlas
 * (app/atlas) for compaction and the padding constraint:
 *   prepare   after the scaffold is built and its rest shapes and weights
 *             set (rest = current shape), before the solve: may move FIXED
 *             (box) vertices in X (nall by 2) and change scaffold weights
 *             (L->scaf.weight, L->scaf_pw). Every triangle must stay
 *             positively oriented at X (the hook checks exactly); the
 *             iteration then lowers the total energy from that state.
 *   feasible  an extra constraint on a trial state X (nall by 2): 1 = ok.
 *             A line-search step it rejects is halved (exact orientation
 *             and total-energy decrease re-checked) until accepted, or no
 *             step is taken. Must hold at the state the iteration starts.
 *   restrict  optional: called with a trial state X the feasibility hook
 *             rejected; may zero rows of the direction dir (nall by 2) so
 *             the offending parts stay put, returning 1 when it changed
 *             dir (the same step is then tried again, with the same exact
 *             orientation, energy and feasibility checks), 0 otherwise.
 *   user      passed to all. */
typedef struct scaf_loop_hooks {
    scaf_status (*prepare)(void *user, struct scaf_loop *L, double *X, int nall, scaf_error *err);
    int (*feasible)(void *user, const struct scaf_loop *L, const double *X, int nall);
    int (*restrict_dir)(void *user, const struct scaf_loop *L, const double *X, double *dir, int nall);
    void *user;
} scaf_loop_hooks;

typedef struct scaf_loop {
    int nv, nf;
    int *F;              /* nf by 3 working faces */
    double *uv;          /* nv by 2 current UV positions (updated) */
    opt_simplices chart; /* rest frames of the mesh triangles, weight = 3D area */
    double total_area;
    int nbedges;
    int *bedges;         /* nbedges by 2 chart boundary edges, chart on the left */
    scaf_options_t opt;
    scaffold sc;         /* the scaffold of the last iteration (moved with the step) */
    opt_simplices scaf;  /* its rest frames (current shape), weight = lambda */
    double *scaf_pw;     /* |S| proxy weights of the scaffold (see scaf_loop.c) */
    opt_proxy_block blk_chart, blk_scaf; /* SLIM proxy patterns: chart (kept
                                            while the unknown count stays) and scaffold */
    opt_proxy_system sys;/* their sum */
    opt_chol *chol;      /* CHOLMOD, analysis reused while the pattern stays */
    int *mesh_perm;      /* 2 nv: fill-reducing order of the mesh unknowns,
                            from the first (METIS) analysis; reused */
    int *perm;           /* scratch: full permutation */
    size_t cap_perm;
    double *rhs, *sol, *dir;
    size_t cap_n, cap_x;
    int iterations;
    scaf_loop_hooks hooks; /* zero = none (see above) */
} scaf_loop;

/* Set up. V3 nv by 3 rest positions, F nf by 3 faces (counter-clockwise
 * in UV), uv0 nv by 2 initial bijective UV map. Copies everything.
 * Fails with SCAF_ERR_MESH on a triangle of zero 3D area or a triangle
 * not positively oriented in uv0. */
scaf_status scaf_loop_init(scaf_loop *L, int nv, const double *V3, int nf, const int *F,
                           const double *uv0, const scaf_options_t *opt, scaf_error *err);

/* One iteration; fills info (may be NULL). */
scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err);

/* Reported energy E = sum A_f SD(J_f) / sum A_f of the current map. */
double scaf_loop_energy(const scaf_loop *L);

/* Per-triangle symmetric Dirichlet energy of the current map (nf values). */
void scaf_loop_face_energy(const scaf_loop *L, double *E);

/* Build a scaffold around the current map (for pictures); sc freed by the
 * caller with scaffold_free. */
scaf_status scaf_loop_scaffold(const scaf_loop *L, scaffold *sc, scaf_error *err);

void scaf_loop_free(scaf_loop *L);

#endif /* SCAF_SCAFFOLD_SCAF_LOOP_H */
