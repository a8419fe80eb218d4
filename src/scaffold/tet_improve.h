/* scaffold/tet_improve: better-shaped scaffold tets by local operations,
 * once per iteration of the 3D loop, instead of re-running TetGen (which
 * fails when parts of the surface come close).
 *
 * After Klingner & Shewchuk 2009 ("Aggressive tetrahedral mesh
 * improvement"): the tets whose quality (geom/tet_quality, 1 = regular) is
 * below a goal are visited worst first; for each, the operations are tried
 *   edge removal   an edge and its ring of m tets replaced by 2(m - 2) tets
 *                  (the best triangulation of the ring, by dynamic
 *                  programming); m = 3 is the 3-2 flip
 *   2-3 flip       two tets sharing a face replaced by three around the
 *                  edge joining their apexes
 *   multi-face     the same for k >= 2 faces sandwiched between two
 *   removal        apexes: 2k tets replaced by k + 2 (grown greedily from
 *                  the bad tet's face)
 *   smoothing      a free scaffold-only vertex moved to raise the worst
 *                  quality of the tets around it (gradient of the worst,
 *                  then of the near-worst, then the centroid; line search)
 *   contraction    a free scaffold-only vertex merged into a neighbour
 *   split          an edge split at its midpoint (a new free vertex, then
 *                  smoothed)
 * and an operation is applied only when it raises the worst quality of the
 * tets it replaces (hill climbing) AND every new tet is positively
 * oriented, decided exactly with orient3d. A tet that no operation improves
 * is skipped, not the end of the pass; new tets still below the goal are
 * visited again in the next pass.
 * What no operation ever does: change a tet's region (every operation
 * replaces tets of one region by tets of that region), remove or change a
 * protected face or remove an edge of one, move or remove a mesh vertex or
 * a fixed one (mesh vertices may gain or lose tets around them), or remove
 * a hull (box) face. So after the call every tet is positive (exactly),
 * the protected triangles are still faces, the inside and the outside
 * each cover the same region as before (same hull faces, same volume up
 * to rounding).
 * Deterministic: no clock, no randomness; the budget counts operations
 * (one try: one operation evaluated on one edge, face or vertex).
 *
 * Use: TetGen's scaffold has no free vertex (surface and box only) and
 * many slivers; improve it once thoroughly (max_tries 0, max_passes 20:
 * bunny 0.1 s, quality 0.002 -> 0.13, 4.7k -> 6.6k tets; see
 * bench/RESULTS-tet.md), then once per iteration with the defaults (bunny:
 * 2-6 ms). Splits make the mesh grow; leave TET_OP_SPLIT out of ops to
 * keep the vertex count.
 */
#ifndef SCAF_SCAFFOLD_TET_IMPROVE_H
#define SCAF_SCAFFOLD_TET_IMPROVE_H

#include "base/error.h"
#include "scaffold/tet_scaffold.h"

/* Operations (bit mask of tet_improve_options.ops). */
enum {
    TET_OP_EDGE_REMOVAL = 1, /* includes the 3-2 flip */
    TET_OP_FLIP23 = 2,
    TET_OP_SMOOTH = 4,
    TET_OP_CONTRACT = 8,
    TET_OP_SPLIT = 16,
    TET_OP_MULTI_FACE = 32,
    TET_OP_ALL = 63
};

typedef struct tet_improve_options {
    double quality_goal; /* tets below this are worked on (default 0.2) */
    int max_passes;      /* sweeps over the tets below the goal (default 3) */
    long long max_tries; /* budget: operations evaluated per call, counted
                            deterministically; <= 0 unlimited (default
                            3000, about 5 ms) */
    unsigned ops;        /* TET_OP_* allowed (default TET_OP_ALL) */
} tet_improve_options;

void tet_improve_options_default(tet_improve_options *o);

typedef struct tet_improve_stats {
    int tets_before, tets_after;
    int vertices_before, vertices_after;
    double min_before, p5_before; /* quality: worst, 5th percentile */
    double min_after, p5_after;
    int below_goal_before, below_goal_after; /* tets under quality_goal */
    long long flip23, flip32;                /* 2-3 and 3-2 flips applied */
    long long edge_removal;                  /* edge removals with rings of 4 or more */
    long long multi_face;                    /* multi-face removals (2 faces or more) */
    long long smooth;                        /* vertex moves */
    long long contract, split;               /* vertices removed, added */
    long long tries;                         /* operations evaluated */
    int passes;
} tet_improve_stats;

/* Improve the scaffold.
 *   s      the scaffold (input/output); on success dense again, vertices
 *          renumbered as tet_scaffold.h says (s->vertex_map)
 *   X      nmesh by 3 current positions of the mesh vertices, copied into
 *          s->P first (NULL: keep s->P's)
 *   o      options (NULL: defaults)
 *   stats  filled when not NULL
 * Every tet must be positively oriented at entry (checked exactly).
 * Errors: SCAF_ERR_USAGE (a goal not finite, unknown ops bits; s
 * unchanged), SCAF_ERR_MESH (a tet not positive at entry: the message
 * names it; s unchanged), SCAF_ERR_NOMEM (s still valid: the operations applied
 * so far are kept, each of them whole). */
scaf_status tet_improve(tet_scaffold *s, const double *X, const tet_improve_options *o,
                        tet_improve_stats *stats, scaf_error *err);

#endif /* SCAF_SCAFFOLD_TET_IMPROVE_H */
