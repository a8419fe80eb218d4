/* mesh/samples: procedural sample meshes (no downloaded data needed).
 *
 * Deterministic: the same name and size always give the same bits. Every
 * face is counter-clockwise seen from outside / from +z. The samples:
 *
 *   triangle    1 face, 3 vertices, UVs = xy                (size ignored)
 *   grid        flat n x n square grid, 2n^2 faces, UVs = xy; a disk
 *   hemisphere  bumpy open hemisphere, n rings, 6n^2 faces; a disk, no UVs
 *   holes       curved plate with 6 circular holes (3 x 2 cells, n points
 *               per cell side): genus 0, 7 boundary loops, no UVs
 *   cubesphere  closed bumpy sphere made of the 6 faces of a cube, each an
 *               n x n grid and its own UV chart (3 x 2 atlas, all CCW, no
 *               overlap): genus 0, 6 charts, 12n seam edges
 *   tetrahedron closed tetrahedron, 4 faces                 (size ignored)
 *   spiral      thin open strip along a circle, n segments, 2n faces: the
 *               stress test of the paper's Figure 4 (mesh/spiral_strip)
 *   icosphere   closed unit geodesic sphere: each icosahedron face cut
 *               into n x n triangles, 20n^2 faces, 10n^2 + 2 vertices, no UVs
 */
#ifndef SCAF_MESH_SAMPLES_H
#define SCAF_MESH_SAMPLES_H

#include "base/error.h"
#include "mesh/mesh.h"

typedef struct mesh_sample_info {
    const char *name;
    const char *summary; /* one line for `scaf gen --list` */
    int default_size;
    int min_size, max_size;
} mesh_sample_info;

/* Number of samples, and sample i (0 <= i < count). */
int mesh_sample_count(void);
const mesh_sample_info *mesh_sample_get(int i);

/* The sample called name, or NULL. */
const mesh_sample_info *mesh_sample_find(const char *name);

/* Build sample `name` at resolution `size` (0 = its default) into *m
 * (allocated here; free with mesh_free). Unknown name or size outside
 * [min_size, max_size]: SCAF_ERR_USAGE with a message listing what is
 * allowed. Out of memory: SCAF_ERR_NOMEM. On failure *m is left empty. */
scaf_status mesh_sample_make(const char *name, int size, mesh *m, scaf_error *err);

#endif /* SCAF_MESH_SAMPLES_H */
