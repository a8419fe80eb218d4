/* tools/cli_mesh_io: input mesh and output OBJ of the commands (see cli_mesh_io.h). */
#include "cli_mesh_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    return cli_write_uv_grouped(cmd, in, info, out, o, NULL, err);
}

scaf_status cli_write_uv_grouped(const char *cmd, const char *in, const mesh_read_info *info,
                                 const char *out, const mesh *o, const int *face_group,
                                 scaf_error *err)
{
    if (info && info->format == MESH_FORMAT_OBJ) {
        scaf_status st = obj_rewrite_uv_grouped(in, out, o, face_group, err);
        if (st != SCAF_ERR_MESH) return st;
        fprintf(stderr,
                "scaf %s: warning: %s; writing a plain OBJ (normals, materials and groups not "
                "kept)\n",
                cmd, err->message);
        err_clear(err);
    }
    return mesh_write_obj_grouped(out, o, face_group, err);
}

scaf_status cli_write_uv_from(const char *in, const char *source, const mesh_read_info *info,
                              const char *out, const mesh *o, char *note, size_t note_size,
                              scaf_error *err)
{
    if (note_size) note[0] = '\0';
    if (!info || info->format != MESH_FORMAT_OBJ) return mesh_write_obj(out, o, err);
    char *data = NULL;
    size_t size = 0;
    scaf_status st = mesh_load_file(source, &data, &size, err);
    if (st == SCAF_ERR_NOMEM) return st;
    if (st == SCAF_OK) {
        st = obj_rewrite_uv_text(in, data, size, out, o, err);
        free(data);
        if (st != SCAF_ERR_MESH) return st;
    }
    if (st == SCAF_ERR_MESH) {
        snprintf(note, note_size,
                 "wrote a plain OBJ without the normals, materials, groups and comments of the "
                 "input: %s",
                 err->message);
    } else { /* the read's message names `source`: say `in` instead */
        const char *why = err->message;
        size_t ns = strlen(source);
        if (!strncmp(why, source, ns) && !strncmp(why + ns, ": ", 2)) why += ns + 2;
        snprintf(note, note_size,
                 "wrote a plain OBJ without the normals, materials, groups and comments of the "
                 "input: %s cannot be read again (%s)",
                 in, why);
    }
    err_clear(err);
    return mesh_write_obj(out, o, err);
}
