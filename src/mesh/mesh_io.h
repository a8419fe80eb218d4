/* mesh/mesh_io: reading OBJ, OFF and PLY meshes, writing OBJ with UVs.
 *
 * Readers accept files by extension (.obj, .off, .ply, each optionally
 * .gz). Every malformed input gets SCAF_ERR_PARSE (or SCAF_ERR_IO when the
 * file cannot be opened/read) with a message naming file, line and reason.
 * Polygons are fan-triangulated; the info struct says how many.
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
    MESH_FORMAT_PLY
} mesh_format;

/* What a reader noticed that is not an error (reported as warnings). */
typedef struct mesh_read_info {
    mesh_format format;
    int polygons_triangulated;  /* faces with more than 3 corners, fanned */
    int normals_ignored;        /* `vn` lines (OBJ) */
    int faces_without_uv;       /* OBJ faces lacking vt while others have it */
} mesh_read_info;

/* Read a mesh file; the format comes from the extension (a trailing .gz is
 * decompressed). info may be NULL. On failure *m is left empty. */
scaf_status mesh_read(const char *path, mesh *m, mesh_read_info *info, scaf_error *err);

/* Parse a whole file already in memory; `name` is used in messages. */
scaf_status mesh_parse(const char *data, size_t size, mesh_format format, const char *name,
                       mesh *m, mesh_read_info *info, scaf_error *err);

/* Write an OBJ: `v` lines for every vertex in order (values round-trip
 * exactly), `vt` lines when the mesh has UVs, and `f v/vt` (or `f v`)
 * faces. Written to a temporary file in the target folder, then renamed:
 * on failure no partial file is left and the target is untouched. */
scaf_status mesh_write_obj(const char *path, const mesh *m, scaf_error *err);

#endif /* SCAF_MESH_MESH_IO_H */
