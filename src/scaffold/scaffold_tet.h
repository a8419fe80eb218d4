/* scaffold/scaffold_tet: the 3D scaffold provider (scaffold/scaffold_provider,
 * d = 3): tetrahedra filling a fixed box around a closed triangle surface,
 * inside and outside it, sharing the surface's vertices.
 *
 * The first refresh builds the tets with TetGen (geom/tet_box_mesh: the
 * surface kept whole, no Steiner point on it or on the box; every tet
 * checked positive with orient3d) in the box tet_box_around(X, box_scale)
 * with box_cells squares per box side edge (given at creation; the loop's
 * scaffold options are ignored), and keeps them as an editable scaffold
 * (scaffold/tet_scaffold: the surface triangles protected, the box
 * vertices fixed); the box is then fixed for the whole run: its vertices
 * are held by the loop. TetGen is not run again: it fails when parts of
 * the surface come close, which is where a run goes. TetGen's tets are
 * improved once thoroughly (no budget, up to 20 passes), and every later
 * refresh runs the improvement pass (scaffold/tet_improve: Klingner-style local
 * operations on the worst tets, each checked exactly, never touching a
 * surface triangle, a surface vertex or the box) on the tets as the
 * loop's accepted steps left them, unless it was turned off
 * (scaffold_tet_set_improve); without it the scaffold only deforms (the
 * line search keeps every tet positive; the run may lock as tets flatten).
 *
 * eps (the rest-volume guard): l^3 / (6 sqrt 6), l the shortest surface
 * edge at X: the volume of a regular tet of edge l divided by sqrt 3, as
 * the 2D guard l^2 / 4 is the equilateral triangle's area over sqrt 3.
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_TET_H
#define SCAF_SCAFFOLD_SCAFFOLD_TET_H

#include "scaffold/scaffold_provider.h"
#include "scaffold/tet_improve.h"

/* A provider over the closed surface with nmesh vertices and faces F
 * (nf by 3, copied); box_scale > 1, box_cells 1..64 (geom/tet_box_mesh).
 * The improvement pass is on with tet_improve's defaults. NULL on failure
 * (err set). */
scaffold_provider *scaffold_tet_create(int nmesh, int nf, const int *F, double box_scale,
                                       int box_cells, scaf_error *err);

/* Run the improvement pass with options o (NULL: tet_improve's defaults)
 * at every refresh after the first when enable != 0; never when 0. */
void scaffold_tet_set_improve(scaffold_provider *p, int enable, const tet_improve_options *o);

/* What the last refresh's improvement pass did (zeroed when none ran). */
const tet_improve_stats *scaffold_tet_improve_stats(const scaffold_provider *p);

/* The region of each current tet (view's n entries: 1 inside the
 * surface, 0 outside); valid until the next refresh. */
const signed char *scaffold_tet_inside(const scaffold_provider *p);

/* Minimum and 5th percentile of the quality (geom/tet_quality) over the
 * tets of view v at surface positions X (nmesh by 3); both 0 without
 * tets. Fails only with SCAF_ERR_NOMEM. */
scaf_status scaffold_tet_quality_stats(const scaffold_view *v, const double *X, double *qmin,
                                       double *qp5, scaf_error *err);

#endif /* SCAF_SCAFFOLD_SCAFFOLD_TET_H */
