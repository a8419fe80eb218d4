/* mesh/tet_medit: tetrahedral meshes in the Medit ASCII format (.mesh),
 * which Gmsh, TetGen (-g), ParaView readers and MMG read and write.
 *
 * Written: `MeshVersionFormatted 1`, `Dimension 3`, `Vertices` (x y z 0),
 * `Tetrahedra` (four 1-based indices and a label as the reference
 * number), `End`; numbers read back bit for bit; atomically (nothing is
 * left on failure). Read: the same keywords in any order, plus
 * `Triangles`, `Edges`, `Corners`, `RequiredVertices`, `Ridges` and
 * `Quadrilaterals` skipped, `#` comments; anything else is an error naming
 * the line. Indices out of range and non-finite coordinates are errors.
 */
#ifndef SCAF_MESH_TET_MEDIT_H
#define SCAF_MESH_TET_MEDIT_H

#include "base/error.h"

typedef struct tet_medit {
    int nv;
    double *V; /* #V by 3 */
    int nt;
    int *T;     /* #T by 4, 0-based */
    int *label; /* #T reference numbers */
} tet_medit;

/* Write; label may be NULL (all 0). SCAF_ERR_MESH for invalid arrays
 * (nothing written), SCAF_ERR_IO naming the path. */
scaf_status tet_medit_write(const char *path, int nv, const double *V, int nt, const int *T,
                            const int *label, scaf_error *err);

/* Read into *m (free with tet_medit_free; empty on failure).
 * SCAF_ERR_IO unreadable, SCAF_ERR_PARSE malformed (file and line named),
 * SCAF_ERR_NOMEM. */
scaf_status tet_medit_read(const char *path, tet_medit *m, scaf_error *err);

void tet_medit_free(tet_medit *m);

#endif
