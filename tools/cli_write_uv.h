/* tools/cli_write_uv: writing the result of `scaf param` / `scaf atlas`.
 *
 * When the input was an OBJ, the output is that file again with the new
 * texture coordinates (mesh/obj_rewrite: normals, materials, groups and
 * comments kept, `v` lines byte for byte); otherwise, or when the input
 * file no longer matches the mesh read from it (a warning says so), a
 * plain OBJ (mesh/write_obj). Both are written atomically. */
#ifndef SCAF_TOOLS_CLI_WRITE_UV_H
#define SCAF_TOOLS_CLI_WRITE_UV_H

#include "base/error.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"

/* cmd: command name for messages; in/info: the input path and what its
 * read said; o: the mesh as read with the new UV and FT. */
scaf_status cli_write_uv(const char *cmd, const char *in, const mesh_read_info *info, const char *out,
                         const mesh *o, scaf_error *err);

#endif
