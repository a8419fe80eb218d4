/* tools/cli_mesh_io: input mesh and output OBJ of the commands (see cli_mesh_io.h). */
#include "cli_mesh_io.h"

#include <stdio.h>

#include "exit_codes.h"

#include "mesh/obj_rewrite.h"

int cli_read_mesh(const char *cmd, const char *path, int quiet, mesh *m, mesh_read_info *info)
{
    scaf_error err;
    err_clear(&err);
    scaf_status st = mesh_read(path, m, info, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf %s: %s%s\n", cmd, err.message,
                st == SCAF_ERR_CANCELLED ? "; nothing written" : "");
        return exit_code_for(st);
    }
    char warn[512];
    if (!quiet && mesh_read_warnings(info, warn, sizeof warn) > 0)
        fprintf(stderr, "scaf %s: warning: %s: %s\n", cmd, path, warn);
    return EXIT_OK;
}

scaf_status cli_write_uv(const char *cmd, const char *in, const mesh_read_info *info,
                         const char *out, const mesh *o, scaf_error *err)
{
    if (info && info->format == MESH_FORMAT_OBJ) {
        scaf_status st = obj_rewrite_uv(in, out, o, err);
        if (st != SCAF_ERR_MESH) return st;
        fprintf(stderr,
                "scaf %s: warning: %s; writing a plain OBJ (normals, materials and groups not "
                "kept)\n",
                cmd, err->message);
        err_clear(err);
    }
    return mesh_write_obj(out, o, err);
}
