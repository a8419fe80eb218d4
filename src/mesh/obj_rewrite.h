/* mesh/obj_rewrite: the input OBJ again, with new texture coordinates.
 *
 * `scaf param` and `scaf atlas` change only the UVs of a mesh; a user's
 * OBJ also carries normals, materials, groups, smoothing groups and
 * comments that a plain writer would drop. obj_rewrite_uv copies the
 * input file line by line:
 *   - every line that is not `vt` or `f` byte for byte (so `v` lines are
 *     untouched, and `vn`, `mtllib`, `usemtl`, `o`, `g`, `s`, `l`,
 *     comments and blank lines stay where they were);
 *   - the old `vt` lines are dropped; the new ones are written as one
 *     block just before the first `f` line;
 *   - each `f` line becomes the triangles the reader made of it (a polygon
 *     is fanned a0 ai ai+1), each corner keeping its vertex and normal
 *     tokens as written (relative indices stay valid: no `v`/`vn` line
 *     moves) with the new texture index. A comment at the end of an `f`
 *     line is not kept.
 * Line endings follow the input's first line (LF or CRLF); a UTF-8 BOM is
 * kept; a comment naming scaf is added as the first line.
 *
 * Every corner's vertex index is checked against the mesh (F) and the
 * number of faces must match: when the file does not describe the mesh
 * (it changed since it was read) SCAF_ERR_MESH names the line and nothing
 * is written. The output is written atomically (base/atomic_file), so
 * out_path may be in_path. SCAF_ERR_IO / SCAF_ERR_PARSE (gzip) from
 * reading, SCAF_ERR_IO from writing, SCAF_ERR_NOMEM.
 */
#ifndef SCAF_MESH_OBJ_REWRITE_H
#define SCAF_MESH_OBJ_REWRITE_H

#include "base/error.h"
#include "mesh/mesh.h"

/* in_path  the OBJ the mesh was read from (plain or .gz)
 * out_path the file to write (plain OBJ)
 * m        the mesh as read (nv, nf, F) with the new UVs (nuv, UV nuv by 2,
 *          FT nf by 3) */
scaf_status obj_rewrite_uv(const char *in_path, const char *out_path, const mesh *m,
                           scaf_error *err);

/* The same with face_group (nf ids >= 0, or NULL): the input's `g` lines
 * are dropped and `g chart_N` is written before the first triangle and
 * before every triangle whose group N differs from the previous one's. */
scaf_status obj_rewrite_uv_grouped(const char *in_path, const char *out_path, const mesh *m,
                                   const int *face_group, scaf_error *err);

/* obj_rewrite_uv_text with face groups (as obj_rewrite_uv_grouped). */
scaf_status obj_rewrite_uv_text_grouped(const char *name, const char *data, size_t size,
                                        const char *out_path, const mesh *m, const int *face_group,
                                        scaf_error *err);

/* The same with the input's text already in memory (size bytes of data,
 * decompressed; name for messages): for a caller that read the file
 * itself, e.g. through a descriptor it kept open. */
scaf_status obj_rewrite_uv_text(const char *name, const char *data, size_t size,
                                const char *out_path, const mesh *m, scaf_error *err);

#endif /* SCAF_MESH_OBJ_REWRITE_H */
