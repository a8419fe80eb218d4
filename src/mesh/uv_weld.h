/* mesh/uv_weld: per-corner texture coordinates joined into shared ones.
 *
 * Formats that store a UV per face corner (PLY's face `texcoord` lists)
 * give every corner its own UV entry, so no two faces would share one and
 * every triangle would be a chart of its own. Two corners are the same UV
 * point when they use the same vertex and bitwise the same (u, v): those
 * get one UV index. Corners of one vertex with different (u, v) stay apart:
 * that is a seam. The order of the remaining UVs is that of their first
 * corner, so the result does not depend on the sort.
 *
 * Fails only with SCAF_ERR_NOMEM (the mesh is then unchanged).
 */
#ifndef SCAF_MESH_UV_WELD_H
#define SCAF_MESH_UV_WELD_H

#include "base/error.h"
#include "mesh/mesh.h"

/* m has nuv UVs and FT (typically nuv = 3 nf, FT[k] = k); on return UV is
 * shrunk to the distinct (vertex, u, v) points and FT renumbered. */
scaf_status uv_weld_corners(mesh *m, scaf_error *err);

#endif
