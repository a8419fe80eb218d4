/* mesh/gltf_io: glTF 2.0 (.gltf JSON, .glb binary) in and out, the C face
 * of gltf_io.cpp (tinygltf, Debian libtinygltf-dev; the mesh layer's only
 * C++).
 *
 * Reading (gltf_parse): every primitive of every mesh, in order, becomes a
 * piece of one scaf mesh. A primitive must be TRIANGLES (indexed or not:
 * unindexed vertices 3t..3t+2 make triangle t), with FLOAT VEC3 POSITION;
 * POINTS, LINES*, TRIANGLE_STRIP / FAN, Draco compression
 * (KHR_draco_mesh_compression) and quantized positions are refused with
 * SCAF_ERR_MESH naming "mesh I primitive J". Positions stay in the
 * primitive's own (mesh-local) coordinates, untransformed by the nodes:
 * the surface is used only for its metric, and a mesh several nodes
 * instance has one set of UVs. Within a primitive, vertices at bitwise the
 * same position are one scaf vertex (glTF splits vertices wherever a
 * normal, colour or UV differs; those are not cuts of the surface), so a
 * primitive's charts follow its geometry. Input UVs: TEXCOORD_<uv set>
 * per glTF vertex (FLOAT, or normalized UNSIGNED_BYTE / SHORT), with v
 * flipped (glTF's v runs down, scaf's and OBJ's up: u, 1 - v), so a map
 * that is counter-clockwise in scaf is counter-clockwise in glTF viewers;
 * kept only when every primitive has them (*missing counts the faces
 * without). Every accessor read is checked against its buffer view and
 * buffer (SCAF_ERR_PARSE naming mesh, primitive and attribute), as is
 * every index.
 *
 * Writing (gltf_rewrite_uv): the input document again with the new UVs.
 * Every node, mesh, material, texture, image, sampler, skin, animation,
 * camera, extension and extra is kept as tinygltf reads and writes it
 * (docs/formats.md lists what that loses). Each primitive gets new
 * accessors: its vertices split where the new UVs differ at one glTF
 * vertex (a seam), and every vertex attribute (NORMAL, TANGENT, COLOR_n,
 * JOINTS_n, WEIGHTS_n, other TEXCOORD_n, ...) and morph target copied to
 * the new vertices byte for byte, min / max recomputed, new indices
 * (UNSIGNED_SHORT or UNSIGNED_INT), and TEXCOORD_<uv set> as FLOAT VEC2
 * (u, 1 - v). The old accessors and buffer views stay (other objects may
 * refer to them); new data is appended to buffer 0, 4-byte aligned. .glb:
 * buffer 0 is the binary chunk; .gltf: one self-contained file, every
 * buffer embedded as a base64 data URI (so the write is one atomic file;
 * images keep their URIs, relative to the output's folder). The file is
 * written atomically (base/atomic_file).
 *
 * Nothing is thrown to C: tinygltf's failures and std::bad_alloc become
 * statuses with messages "NAME: reason".
 */
#ifndef SCAF_MESH_GLTF_IO_H
#define SCAF_MESH_GLTF_IO_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

#include "base/error.h"
#include "mesh/mesh.h"

/* Which TEXCOORD_n is read and written (default 0; `--uv-set N`). */
void gltf_set_uv_set(int n);
int gltf_uv_set(void);

/* Parse a .gltf or .glb held in memory (name: its path, for messages and
 * for the folder of external buffers and images; "<stdin>": the current
 * folder). *faces_without_uv: faces of primitives lacking the UV set when
 * another has it (UVs then dropped). */
scaf_status gltf_parse(const char *data, size_t size, const char *name, mesh *m,
                       int *faces_without_uv, scaf_error *err);

/* One primitive's place in the scaf mesh. */
typedef struct gltf_piece {
    int mesh, primitive;   /* glTF indices */
    char mesh_name[64];    /* the mesh's name, "" when none (cut short) */
    int first_face, faces; /* its triangles in the scaf mesh */
} gltf_piece;

/* The primitives of the document in mesh order (malloc'd array, free it). */
scaf_status gltf_pieces(const char *data, size_t size, const char *name, gltf_piece **pieces,
                        int *n, scaf_error *err);

/* Write the document (data, size, name as for gltf_parse) with m's UVs
 * (m: the mesh gltf_parse made, with new UV, FT) to out_path: binary
 * (.glb) when binary != 0, else JSON with embedded buffers. SCAF_ERR_MESH
 * when m is not the mesh of this document, SCAF_ERR_IO from writing. */
scaf_status gltf_rewrite_uv(const char *data, size_t size, const char *name, const mesh *m,
                            const char *out_path, int binary, scaf_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SCAF_MESH_GLTF_IO_H */
