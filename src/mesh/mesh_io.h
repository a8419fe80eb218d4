/* mesh/mesh_io: reading OBJ, OFF and PLY meshes, writing OBJ with UVs.
 *
 * Readers accept files by extension (.obj, .off, .ply, each optionally
 * .gz; gzip is recognized by its magic bytes, an unknown extension by the
 * content). Every malformed input gets SCAF_ERR_PARSE with a message
 * "FILE:LINE: reason" (index out of range naming the index and the vertex
 * count, NaN/inf coordinate, truncated file, face with a repeated vertex or
 * fewer than 3 corners, unknown PLY format or type, garbage token, no
 * faces...); a file that cannot be opened or read gets SCAF_ERR_IO naming
 * the path. Counts in OFF/PLY headers are checked against the file size
 * before anything is allocated.
 *
 * Polygons are fan-triangulated (corners a0 ai ai+1); the info struct says
 * how many. Coordinates equal what strtod gives for the same text.
 * OBJ UV policy: the mesh gets UVs (UV, FT) when every face has texture
 * indices; when only some faces have them, the UVs are dropped and
 * info->faces_without_uv counts the faces without (a warning to print).
 * Unreferenced vertices are kept (nv counts every `v`).
 * PLY UVs: a face list `texcoord` (u v per corner; corners of one vertex
 * with the same (u, v) share a UV, mesh/uv_weld), else per-vertex
 * s,t / u,v / texture_u,texture_v / texture_s,texture_t (the first pair
 * declared).
 */
#ifndef SCAF_MESH_MESH_IO_H
#define SCAF_MESH_MESH_IO_H

#include <stddef.h>

#include "base/error.h"
#include "mesh/mesh.h"

typedef enum mesh_format {
    MESH_FORMAT_UNKNOWN = 0,
    MESH_FORMAT_OBJ,
    MESH_FORMAT_OFF,
    MESH_FORMAT_PLY,
    MESH_FORMAT_GLTF /* glTF 2.0, .gltf (JSON) or .glb (binary): mesh/gltf_mesh */
} mesh_format;

/* What a reader noticed that is not an error (reported as warnings). */
typedef struct mesh_read_info {
    mesh_format format;
    int polygons_triangulated; /* faces with more than 3 corners, fanned */
    int normals_ignored;       /* `vn` lines (OBJ) */
    int faces_without_uv;      /* OBJ faces lacking vt while others have it */
    const char *uv_source;     /* where the mesh's UVs came from ("OBJ vt", "PLY face
                                  texcoord", "PLY vertex u, v", ...), NULL: none */
} mesh_read_info;

/* The warnings of a read as one line of text for people (no trailing
 * newline; empty when there is nothing to say), e.g. "12 polygons with
 * more than 3 corners fan-triangulated". Returns the number of warnings
 * (normals are not a warning). buf may be NULL when size is 0. */
int mesh_read_warnings(const mesh_read_info *info, char *buf, size_t size);

/* Read a mesh file; the format comes from the extension (a trailing .gz is
 * decompressed). info may be NULL. On failure *m is left empty. */
scaf_status mesh_read(const char *path, mesh *m, mesh_read_info *info, scaf_error *err);

/* The whole content of a file, gzip decompressed when it starts with the
 * gzip magic bytes: *data (malloc'd, free it) of *size bytes. */
scaf_status mesh_load_file(const char *path, char **data, size_t *size, scaf_error *err);

/* Read everything from descriptor fd (a pipe, standard input) up to its
 * end: *data (malloc'd, free it) of *size bytes; `name` in messages.
 * SCAF_ERR_IO when the read fails, SCAF_ERR_PARSE when the data is
 * gzip-compressed (decompress it first: only files are inflated),
 * SCAF_ERR_CANCELLED on SIGINT / SIGTERM. An empty stream is not an error
 * here (the caller says what it expected). */
scaf_status mesh_load_fd(int fd, const char *name, char **data, size_t *size, scaf_error *err);

/* The format a file name implies (.obj, .off, .ply, .gltf, .glb, each
 * optionally .gz), MESH_FORMAT_UNKNOWN otherwise. */
mesh_format mesh_format_from_name(const char *path);

/* The format the first bytes show: "ply", an "...OFF" first token, the
 * binary glTF magic "glTF", a JSON object ('{' first) for glTF, else OBJ. */
mesh_format mesh_format_from_content(const char *data, size_t size);

/* Parse a whole file already in memory; `name` is used in messages. */
scaf_status mesh_parse(const char *data, size_t size, mesh_format format, const char *name, mesh *m,
                       mesh_read_info *info, scaf_error *err);

/* Write an OBJ: `v` lines for every vertex in order (values round-trip
 * exactly), `vt` lines when the mesh has UVs, and `f v/vt` (or `f v`)
 * faces. Written to a temporary file in the target folder, then renamed:
 * on failure no partial file is left and the target is untouched. */
scaf_status mesh_write_obj(const char *path, const mesh *m, scaf_error *err);

/* The same with face_group (nf ids >= 0, or NULL: none): `g chart_N`
 * before each run of faces of group N (OBJ groups; readers that ignore
 * groups read the same mesh). */
scaf_status mesh_write_obj_grouped(const char *path, const mesh *m, const int *face_group,
                                   scaf_error *err);

/* Write a binary little-endian PLY: double x y z per vertex, each face's
 * vertex_indices and, with UVs, its `texcoord` list (u v per corner), the
 * convention Blender and MeshLab read (mesh/write_ply). Atomic as
 * mesh_write_obj. */
scaf_status mesh_write_ply(const char *path, const mesh *m, scaf_error *err);

#endif /* SCAF_MESH_MESH_IO_H */
