/* mesh/mesh_readers: the per-format parsers behind mesh_parse (internal).
 *
 * Each parses a whole file held in memory ([data, data+size), not
 * NUL-terminated), names `name` in messages ("NAME:LINE: reason"), fills
 * *m on success and leaves it empty on failure. info is never NULL here
 * (mesh_parse passes a scratch struct) and is zeroed by the caller.
 */
#ifndef SCAF_MESH_MESH_READERS_H
#define SCAF_MESH_MESH_READERS_H

#include <stddef.h>

#include "base/error.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"

scaf_status mesh_parse_obj(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err);
scaf_status mesh_parse_off(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err);
scaf_status mesh_parse_ply(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err);

/* Whether the n corner indices repeat a value (O(n) for small n, sorts a
 * copy for large n; returns -1 if the copy cannot be allocated). On a repeat
 * *dup receives the repeated index. */
int mesh_corners_repeat(const int *idx, size_t n, int *dup);

/* Set SCAF_ERR_PARSE with message "NAME:LINE: reason". */
scaf_status mesh_parse_fail(scaf_error *err, const char *name, long line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* The token starting at p (up to blank/newline/end) as printable text in
 * buf (at most ~40 characters, control bytes escaped). Returns buf. */
const char *mesh_quote_token(const char *p, const char *end, char *buf, size_t size);

#endif /* SCAF_MESH_MESH_READERS_H */
