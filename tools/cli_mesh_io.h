/* tools/cli_mesh_io: reading the input mesh and writing the result, the
 * same way in every command.
 *
 * cli_read_mesh reads a mesh file (mesh/mesh_io), prints a failure as
 * "scaf CMD: message" and returns its exit status (3 unreadable or
 * malformed, 7 out of memory), and prints the read's warnings (polygons
 * fanned, UVs dropped) unless quiet.
 *
 * The input "-" is the standard input: read whole into memory (refused
 * when it is a terminal, exit 2; empty, exit 3), its format from
 * --input-format or sniffed from the first bytes (mesh_format_from_content);
 * the bytes are kept for the run, so the output can be the input document
 * again (OBJ rewrite) as for a file. gzip data on stdin is refused (zcat it).
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
#include "cli_options.h"
#include "mesh/mesh.h"
#include "mesh/gltf_io.h"
#include "mesh/mesh_io.h"

/* The help line of --input-format (commands that read a mesh). */
#define CLI_INPUT_FORMAT_HELP                                                                      \
    "  --input-format F       obj, off, ply, gltf or glb: the input's format whatever\n"           \
    "                         its name (default: the extension, or for \"-\" (standard\n"          \
    "                         input) and unknown names the first bytes)\n"                         \
    "  --uv-set N             glTF: the TEXCOORD_N read and written (default 0)\n"

/* The table entries of --input-format F and --uv-set N (tools/cli_options);
 * as cli_input_format_option, they apply to every later read and write. */
int cli_input_format_take(const char *cmd, const cli_option *o, const char *value);
int cli_uv_set_take(const char *cmd, const cli_option *o, const char *value);
#define CLI_INPUT_FORMAT_OPTIONS                                                                   \
    CLI_CALLBACK("input-format", 0, cli_input_format_take, NULL, "F",                              \
                 "obj, off, ply, gltf or glb: the input's format whatever its name (default: "     \
                 "the extension, or for \"-\" (standard input) and unknown names the first "       \
                 "bytes)"),                                                                        \
        CLI_CALLBACK("uv-set", 0, cli_uv_set_take, NULL, "N",                                      \
                     "glTF: the TEXCOORD_N read and written (default 0)", .min = 0, .max = 65535)

/* At argv[*i] inside an argument loop: --input-format F or --uv-set N
 * taken (1, *i advanced), not one of them (0), or a usage error printed
 * (-1). They apply to every later read and write of the process. */
int cli_input_format_option(const char *cmd, int argc, char **argv, int *i);

/* For a glTF input (info->format), one line per primitive on stderr: its
 * faces in the scaf mesh and the charts of the map o (the mesh with its
 * new UV, FT) they went to, e.g. "scaf atlas: glTF mesh 1 'cap' primitive
 * 0: faces 72-77, chart 2". Prints nothing for other inputs or when
 * quiet; a failure to re-read the document is a warning. */
/* The primitives of a glTF input in mesh order, for the report's
 * "gltf_primitives" (app/seam_report): *pieces (free it) and *n, or NULL
 * and 0 when the input is not glTF or cannot be read again (a warning
 * then, unless quiet). */
void cli_gltf_pieces_load(const char *cmd, const char *in, const mesh_read_info *info, int quiet,
                          gltf_piece **pieces, int *n);

void cli_gltf_pieces_report(const char *cmd, const char *in, const mesh_read_info *info, int quiet,
                            const mesh *o);

/* The input's bytes when it was "-" (NULL otherwise), and their size. */
const char *cli_stdin_data(size_t *size);

/* 0 (EXIT_OK) with *m and *info filled, or the exit status after printing
 * why (*m empty). */
int cli_read_mesh(const char *cmd, const char *path, int quiet, mesh *m, mesh_read_info *info);

/* cmd: command name for messages; in/info: the input path and what its
 * read said; target: the output's name as the user gave it (its extension
 * picks the format: .ply (mesh/write_ply), otherwise OBJ; "-" OBJ); out:
 * the path to write (the staged file of tools/cli_outputs); o: the mesh
 * as read with the new UV and FT. */
scaf_status cli_write_uv(const char *cmd, const char *in, const mesh_read_info *info,
                         const char *target, const char *out, const mesh *o, scaf_error *err);

/* The same with face_group (nf ids, or NULL): `g chart_N` lines for the
 * faces' groups in an OBJ output (mesh/obj_rewrite's obj_rewrite_uv_grouped,
 * or the plain writer's mesh_write_obj_grouped; a PLY has no groups). */
scaf_status cli_write_uv_grouped(const char *cmd, const char *in, const mesh_read_info *info,
                                 const char *target, const char *out, const mesh *o,
                                 const int *face_group, scaf_error *err);

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
