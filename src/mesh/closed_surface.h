/* mesh/closed_surface: is a mesh a closed manifold triangle surface that
 * the 3D commands (`scaf flow`, `scaf untangle`) can work on?
 *
 * Refused, in this order, with the reason in words: no face; an open
 * surface (boundary edges, in how many loops); non-manifold edges or
 * vertices; fewer than 4 vertices or faces (closed, but no volume: a
 * triangle twice); zero-area faces (no cotangent weights, no plane for the
 * exact checks); vertices used by no face. With `genus0` also: more than
 * one connected component, and a genus other than 0 (cMCF rounds a
 * genus-0 surface into a sphere; a handle instead thins into a ring, see
 * app/untangle.h).
 */
#ifndef SCAF_MESH_CLOSED_SURFACE_H
#define SCAF_MESH_CLOSED_SURFACE_H

#include "base/error.h"
#include "mesh/mesh.h"

/* SCAF_OK, or SCAF_ERR_MESH with the reason (SCAF_ERR_NOMEM). */
scaf_status closed_surface_check(const mesh *m, int genus0, scaf_error *err);

#endif
