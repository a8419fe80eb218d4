/* scaffold/scaffold_tet: the 3D scaffold provider (scaffold/scaffold_provider,
 * d = 3): tetrahedra filling a fixed box around a closed triangle surface,
 * inside and outside it, sharing the surface's vertices.
 *
 * The first refresh builds the tets with TetGen (geom/tet_box_mesh: the
 * surface kept whole, no Steiner point on it or on the box; every tet
 * checked positive with orient3d) in the box tet_box_around(X, box_scale)
 * with box_cells squares per box side edge (given at creation; the loop's
 * scaffold options are ignored); the box is then fixed for the whole run:
 * its vertices are held by the loop. TetGen is not run
 * again: it fails when parts of the surface come close, which is where a
 * run goes. Later refreshes keep the connectivity and the scaffold-only
 * vertices where the loop's accepted steps moved them, and hand the
 * scaffold to the improvement pass when one is set
 * (scaffold_tet_set_improver: local operations on the worst tets that
 * never touch a surface triangle); without one the scaffold only deforms
 * (the line search keeps every tet positive; the run may lock as tets
 * flatten). After an improvement pass every tet is checked positive
 * (exact orient3d): SCAF_ERR_INTERNAL otherwise (TetGen's tets are checked
 * by geom/tet_box_mesh, the loop's steps by its line search).
 *
 * eps (the rest-volume guard): l^3 / (6 sqrt 6), l the shortest surface
 * edge at X: the volume of a regular tet of edge l divided by sqrt 3, as
 * the 2D guard l^2 / 4 is the equilateral triangle's area over sqrt 3.
 *
 * Quality of a tet (scaffold_tet_quality): 6 sqrt 2 V / l_rms^3 (1 for a
 * regular tet, 0 for a flat one, negative inverted), the volume-length
 * measure Klingner's improvement uses.
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_TET_H
#define SCAF_SCAFFOLD_SCAFFOLD_TET_H

#include "scaffold/scaffold_provider.h"

/* The scaffold an improvement pass may change: tets (n by 4, ids < nmesh
 * are surface vertices; capacity cap_tets), scaffold-only vertices
 * (nextra by 3 positions and fixed flags, capacity cap_extra; the box's
 * are fixed), inside flags (1 = inside the surface). A pass may reorder,
 * add and remove tets and free scaffold-only vertices (realloc the arrays,
 * updating the capacities), never change a surface triangle or a surface
 * or box vertex, and must leave every tet positively oriented (exact). */
typedef struct scaffold_tets {
    int nmesh;
    int n, cap_tets;
    int *T;
    signed char *inside;
    int nextra, cap_extra;
    double *extra;
    unsigned char *extra_fixed;
} scaffold_tets;

/* The improvement pass: X the surface positions (nmesh by 3). */
typedef scaf_status (*scaffold_tet_improver)(void *user, scaffold_tets *s, const double *X,
                                             scaf_error *err);

/* A provider over the closed surface with nmesh vertices and faces F
 * (nf by 3, copied); box_scale > 1, box_cells 1..64 (geom/tet_box_mesh).
 * NULL on failure (err set). */
scaffold_provider *scaffold_tet_create(int nmesh, int nf, const int *F, double box_scale,
                                       int box_cells, scaf_error *err);

/* Set (or clear, with NULL) the pass run by every refresh after the first. */
void scaffold_tet_set_improver(scaffold_provider *p, scaffold_tet_improver fn, void *user);

/* The provider's current tets (read only: valid until the next refresh). */
const scaffold_tets *scaffold_tet_get(const scaffold_provider *p);

/* Quality of the tet a b c d (see above). */
double scaffold_tet_quality(const double *a, const double *b, const double *c, const double *d);

/* Minimum and 5th percentile of the quality over the tets of view v at
 * surface positions X (nmesh by 3); both 0 without tets. Fails only with
 * SCAF_ERR_NOMEM. */
scaf_status scaffold_tet_quality_stats(const scaffold_view *v, const double *X, double *qmin,
                                       double *qp5, scaf_error *err);

#endif /* SCAF_SCAFFOLD_SCAFFOLD_TET_H */
