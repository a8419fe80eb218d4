/* tools/cli_write_uv: the output OBJ of param and atlas (see cli_write_uv.h). */
#include "cli_write_uv.h"

#include <stdio.h>

#include "mesh/obj_rewrite.h"

scaf_status cli_write_uv(const char *cmd, const char *in, const mesh_read_info *info, const char *out,
                         const mesh *o, scaf_error *err)
{
    if (info && info->format == MESH_FORMAT_OBJ) {
        scaf_status st = obj_rewrite_uv(in, out, o, err);
        if (st != SCAF_ERR_MESH) return st;
        fprintf(stderr, "scaf %s: warning: %s; writing a plain OBJ (normals, materials and groups not kept)\n", cmd,
                err->message);
        err_clear(err);
    }
    return mesh_write_obj(out, o, err);
}
