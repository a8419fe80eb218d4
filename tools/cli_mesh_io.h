/* tools/cli_mesh_io: reading the input mesh and writing the result, the
 * same way in every command.
 *
 * cli_read_mesh reads a mesh file (mesh/mesh_io), prints a failure as
 * "scaf CMD: message" and returns its exit status (3 unreadable or
 * malformed, 7 out of memory), and prints the read's warnings (polygons
 * fanned, UVs dropped) unless quiet.
 *
 * cli_write_uv writes the result of `scaf param` / `scaf atlas`: when the
 * input was an OBJ, the output is that file again with the new texture
 * coordinates (mesh/obj_rewrite: normals, materials, groups and comments
 * kept, `v` lines byte for byte); otherwise, or when the input file no
 * longer matches the mesh read from it (a warning says so), a plain OBJ
 * (mesh/write_obj). Both are written atomically. */
#ifndef SCAF_TOOLS_CLI_MESH_IO_H
#define SCAF_TOOLS_CLI_MESH_IO_H

#include "base/error.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"

/* 0 (EXIT_OK) with *m and *info filled, or the exit status after printing
 * why (*m empty). */
int cli_read_mesh(const char *cmd, const char *path, int quiet, mesh *m, mesh_read_info *info);

/* cmd: command name for messages; in/info: the input path and what its
 * read said; o: the mesh as read with the new UV and FT. */
scaf_status cli_write_uv(const char *cmd, const char *in, const mesh_read_info *info,
                         const char *out, const mesh *o, scaf_error *err);

/* The same with face_group (nf ids, or NULL): `g chart_N` lines for the
 * faces' groups (mesh/obj_rewrite's obj_rewrite_uv_grouped, or the plain
 * writer's mesh_write_obj_grouped). */
scaf_status cli_write_uv_grouped(const char *cmd, const char *in, const mesh_read_info *info,
                                 const char *out, const mesh *o, const int *face_group,
                                 scaf_error *err);

/* The same for `scaf edit`, whose input may be moved, deleted or replaced
 * while it runs: the input's text is read from `source` (a path to the
 * same file; the editor passes /proc/self/fd/N of a descriptor it keeps
 * open, so a deleted or moved input is still read), and when that text
 * cannot be read or no longer describes the mesh, a plain OBJ is written
 * and `note` (note_size bytes, "" otherwise) says what was not kept and
 * why, instead of the warning on the standard error. */
scaf_status cli_write_uv_from(const char *in, const char *source, const mesh_read_info *info,
                              const char *out, const mesh *o, char *note, size_t note_size,
                              scaf_error *err);

#endif
