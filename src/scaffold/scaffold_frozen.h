/* scaffold/scaffold_frozen: a scaffold whose connectivity never changes.
 *
 * Wraps another provider (scaffold/scaffold_provider): the first refresh
 * is the inner provider's (2D: the constrained Delaunay scaffold), later
 * refreshes keep its simplices, its box and its scaffold-only vertices
 * where the loop's accepted steps moved them. This is the "no re-meshing"
 * baseline of the paper's Figure 4: the scaffold then only deforms with
 * the mesh, its triangles get squeezed and the optimization locks.
 * Options given to later refreshes are ignored (the scaffold is frozen).
 * A later refresh fails with SCAF_ERR_INTERNAL when a simplex is not
 * positively oriented at X (someone moved the mesh outside the loop's
 * line search; only d = 2 is checked, exactly).
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_FROZEN_H
#define SCAF_SCAFFOLD_SCAFFOLD_FROZEN_H

#include "scaffold/scaffold_provider.h"

/* Takes inner (destroyed with the wrapper, or here on failure). NULL on
 * failure (err set). */
scaffold_provider *scaffold_frozen_create(scaffold_provider *inner, scaf_error *err);

#endif /* SCAF_SCAFFOLD_SCAFFOLD_FROZEN_H */
