/* geom/cdt_mesh: the triangle structure behind the constrained Delaunay mesher.
 *
 * Internal to geom/cdt*. A triangulation of a big enclosing ("super")
 * triangle stored as flat per-corner arrays: triangle t has corners
 * 3t, 3t+1, 3t+2 holding its vertices in counter-clockwise order. The edge
 * "opposite corner c" runs from the next corner's vertex to the one after
 * it, so each edge is named by the corner facing it. Per corner we keep the
 * neighbour across that edge (as the facing corner in the other triangle,
 * or -1 on the super triangle's hull) and the constraint on that edge (-1,
 * or 2 * segment id + frozen bit; "frozen" marks a splittable subsegment
 * that refinement gave up splitting). Triangles are never deleted: every
 * point insertion reuses the cavity's slots and appends two, because every
 * vertex is strictly inside the super triangle.
 *
 * Every combinatorial decision uses the exact predicates orient2d/incircle.
 * Failures here are "cannot do this safely" answers (return values), not
 * errors: callers turn them into a rejected Steiner point or an error.
 */
#ifndef SCAF_GEOM_CDT_MESH_H
#define SCAF_GEOM_CDT_MESH_H

#include <stddef.h>

#include "geom/predicates.h"

/* Region of a triangle, decided after segment recovery. */
enum { CDT_REG_DOMAIN = 0, CDT_REG_EXTERIOR = 1, CDT_REG_HOLE = 2 };

typedef struct cdt_mesh {
    /* vertices */
    double *xy; /* #nv by 2 */
    int *vt;    /* #nv: a corner holding the vertex, -1 before insertion */
    int *vmark; /* #nv scratch for cavity bookkeeping */
    int nv, capv;
    /* triangles */
    int *V;             /* #nt by 3 corner vertices */
    int *N;             /* #nt by 3 neighbour corners */
    int *S;             /* #nt by 3 constraints: -1 or 2*segment+frozen */
    unsigned char *reg; /* #nt regions */
    unsigned *tmark;    /* #nt scratch stamps */
    int nt, capt;
    unsigned stamp;
    unsigned rng; /* walk randomization state (deterministic) */
    /* cavity scratch */
    int *cav, ncav, capcav; /* triangles of the cavity */
    int *bnd, nbnd, capbnd; /* boundary corners of the cavity */
    /* per-boundary-edge copies used while committing */
    int *ba, *bb, *bn, *bs, capbx;
    unsigned char *br;
} cdt_mesh;

/* Corner helpers. */
static inline int cdt_next(int c) { return ((unsigned)c % 3u == 2u) ? c - 2 : c + 1; }
static inline int cdt_prev(int c) { return ((unsigned)c % 3u == 0u) ? c + 2 : c - 1; }

/* Start an empty structure able to hold nv_hint vertices before growing. 0 or -1 (no memory). */
int cdt_mesh_init(cdt_mesh *m, int nv_hint);
void cdt_mesh_free(cdt_mesh *m);

/* Append a vertex (not yet in any triangle). Returns its index or -1. */
int cdt_mesh_add_vertex(cdt_mesh *m, double x, double y);

/* Make the first triangle from three existing vertices (counter-clockwise). */
int cdt_mesh_first_triangle(cdt_mesh *m, int a, int b, int c);

/* Walk from triangle t towards point p ignoring constraints. Returns a
 * triangle whose closure contains p, or -1 if p is outside the hull. */
int cdt_mesh_locate(cdt_mesh *m, int t, const double p[2]);

/* Walk from triangle t towards p without crossing constrained edges.
 * Returns the triangle whose closure contains p, or -1 when every way on
 * is a constrained edge; then *blocker is that edge's corner. */
int cdt_mesh_walk_constrained(cdt_mesh *m, int t, const double p[2], int *blocker);

/* Bowyer-Watson cavity of point p (not yet a vertex, given by coordinates)
 * grown from seed triangles across unconstrained edges whose neighbour's
 * circumcircle strictly contains p. With two seeds sharing a constrained
 * edge that edge is crossed too (a segment split). Fills m->cav / m->bnd.
 * Returns 1 when every new triangle (boundary edge, p) would be strictly
 * counter-clockwise and the boundary is one simple cycle, 0 otherwise. */
int cdt_mesh_cavity(cdt_mesh *m, const double p[2], int seed0, int seed1);

/* Replace the cavity found last by the fan around vertex p. When split_seg
 * >= 0, the fan edges from p to split_a and split_b become constrained with
 * code split_seg. Returns the first new triangle or -1 (no memory). New
 * triangles are m->cav[0..ncav) plus the two slots appended (nt-2, nt-1). */
int cdt_mesh_commit(cdt_mesh *m, int p, int split_seg, int split_a, int split_b);

/* Corner facing the directed edge a->b (its triangle lies left of a->b),
 * found by rotating around a; -1 if there is no such edge. */
int cdt_mesh_find_edge(const cdt_mesh *m, int a, int b);

/* Flip the edge facing corner c (must be unconstrained, with a neighbour,
 * and the quadrilateral strictly convex). */
void cdt_mesh_flip(cdt_mesh *m, int c);

/* Exact predicates on vertex indices / points. */
static inline double cdt_orient(const cdt_mesh *m, int a, int b, int c)
{
    return orient2d(m->xy + 2 * a, m->xy + 2 * b, m->xy + 2 * c);
}
static inline double cdt_orient_p(const cdt_mesh *m, int a, int b, const double p[2])
{
    return orient2d(m->xy + 2 * a, m->xy + 2 * b, p);
}
/* > 0 when p is strictly inside the circumcircle of triangle t. */
static inline double cdt_incircle_t(const cdt_mesh *m, int t, const double p[2])
{
    const int *v = m->V + 3 * t;
    return incircle(m->xy + 2 * v[0], m->xy + 2 * v[1], m->xy + 2 * v[2], p);
}

#endif /* SCAF_GEOM_CDT_MESH_H */
