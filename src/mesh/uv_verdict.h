/* mesh/uv_verdict: the one bijectivity verdict on a mesh's UV map.
 *
 * `scaf check` and `scaf atlas --init input` (and anything else judging
 * the UVs a file brings) ask the same question about the same data: the
 * UVs and UV indices exactly as read, charts by shared UV edges (no fan
 * splitting, no relabelling), decided by the exact checker
 * (geom/bijectivity). Going through this one function keeps their counts
 * equal.
 */
#ifndef SCAF_MESH_UV_VERDICT_H
#define SCAF_MESH_UV_VERDICT_H

#include "base/error.h"
#include "geom/bijectivity.h"
#include "mesh/mesh.h"

/* bij_check on m's UVs as given (m must have UVs: mesh_has_uv). Errors as
 * bij_check's (SCAF_ERR_MESH for a non-finite UV, SCAF_ERR_NOMEM). */
scaf_status mesh_uv_verdict(const mesh *m, bij_report *rep, scaf_error *err);

/* The same verdict on the UVs a glTF reader gets back from m's: glTF
 * stores (u, 1 - v) as 32-bit floats (mesh/gltf_io), so the map written is
 * the rounded one, u' = (float)u, v' = 1 - (float)(1 - v), computed exactly
 * in double. A map proved bijective in doubles can lose it there (a sliver
 * thinner than a float's step), so glTF output asks this before writing.
 * Errors as mesh_uv_verdict's. */
scaf_status mesh_uv_verdict_gltf(const mesh *m, bij_report *rep, scaf_error *err);

#endif /* SCAF_MESH_UV_VERDICT_H */
