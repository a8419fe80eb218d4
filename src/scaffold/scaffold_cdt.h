/* scaffold/scaffold_cdt: the 2D scaffold provider (scaffold/scaffold_provider).
 *
 * Each refresh throws the last scaffold away and triangulates the box
 * (box_scale times the bounding box of the current positions, see
 * scaffold_box) around the mesh's boundary edges with scaffold_build
 * (constrained Delaunay, no Steiner point on a boundary edge, refined to
 * the minimum angle). The box vertices are fixed, the Steiner points free.
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_CDT_H
#define SCAF_SCAFFOLD_SCAFFOLD_CDT_H

#include "scaffold/scaffold_provider.h"

/* nmesh mesh vertices; edges: nedges by 2 boundary edges, oriented with
 * the mesh on the left (copied). NULL on failure (err set). */
scaffold_provider *scaffold_cdt_create(int nmesh, const int *edges, int nedges, scaf_error *err);

#endif /* SCAF_SCAFFOLD_SCAFFOLD_CDT_H */
