/* tools/cli_mesh_io: input mesh and output OBJ of the commands (see cli_mesh_io.h). */
#include "cli_mesh_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "exit_codes.h"

#include "mesh/obj_rewrite.h"

/* --input-format (MESH_FORMAT_UNKNOWN: from the name or the content) */
static mesh_format forced_format = MESH_FORMAT_UNKNOWN;
/* the standard input's bytes, kept for the output (freed at exit) */
static char *stdin_bytes;
static size_t stdin_size;

static void free_stdin_bytes(void) { free(stdin_bytes); }

int cli_input_format_option(const char *cmd, int argc, char **argv, int *i)
{
    if (strcmp(argv[*i], "--input-format") != 0) return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "scaf %s: --input-format needs a value (see --help)\n", cmd);
        return -1;
    }
    const char *v = argv[++*i];
    if (!strcmp(v, "obj")) forced_format = MESH_FORMAT_OBJ;
    else if (!strcmp(v, "off")) forced_format = MESH_FORMAT_OFF;
    else if (!strcmp(v, "ply")) forced_format = MESH_FORMAT_PLY;
    else if (!strcmp(v, "gltf") || !strcmp(v, "glb")) forced_format = MESH_FORMAT_GLTF;
    else {
        fprintf(stderr,
                "scaf %s: invalid value '%s' for --input-format (obj, off, ply, gltf or glb)\n",
                cmd, v);
        return -1;
    }
    return 1;
}

const char *cli_stdin_data(size_t *size)
{
    *size = stdin_size;
    return stdin_bytes;
}

/* The mesh of path ("-": standard input) with the format forced or found. */
static scaf_status read_input(const char *cmd, const char *path, mesh *m, mesh_read_info *info,
                              int *usage, scaf_error *err)
{
    *usage = 0;
    if (strcmp(path, "-") != 0) {
        if (forced_format == MESH_FORMAT_UNKNOWN) return mesh_read(path, m, info, err);
        char *data = NULL;
        size_t n = 0;
        scaf_status st = mesh_load_file(path, &data, &n, err);
        if (st == SCAF_OK) st = mesh_parse(data, n, forced_format, path, m, info, err);
        free(data);
        return st;
    }
    memset(m, 0, sizeof *m);
    if (info) memset(info, 0, sizeof *info);
    if (isatty(STDIN_FILENO)) {
        *usage = 1;
        return err_set(err, SCAF_ERR_USAGE,
                       "the input is \"-\" (standard input) but it is a terminal: pipe a mesh "
                       "into it (cat mesh.obj | scaf %s - ...)",
                       cmd);
    }
    if (!stdin_bytes) {
        scaf_status st = mesh_load_fd(STDIN_FILENO, "<stdin>", &stdin_bytes, &stdin_size, err);
        if (st != SCAF_OK) return st;
        atexit(free_stdin_bytes);
    }
    if (stdin_size == 0)
        return err_set(err, SCAF_ERR_PARSE,
                       "<stdin>: the standard input is empty (no mesh was piped in)");
    return mesh_parse(stdin_bytes, stdin_size, forced_format, "<stdin>", m, info, err);
}

int cli_read_mesh(const char *cmd, const char *path, int quiet, mesh *m, mesh_read_info *info)
{
    scaf_error err;
    err_clear(&err);
    int usage;
    scaf_status st = read_input(cmd, path, m, info, &usage, &err);
    if (usage) {
        fprintf(stderr, "scaf %s: %s\n", cmd, err.message);
        return EXIT_USAGE;
    }
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
                         const char *target, const char *out, const mesh *o, scaf_error *err)
{
    return cli_write_uv_grouped(cmd, in, info, target, out, o, NULL, err);
}

scaf_status cli_write_uv_grouped(const char *cmd, const char *in, const mesh_read_info *info,
                                 const char *target, const char *out, const mesh *o,
                                 const int *face_group, scaf_error *err)
{
    mesh_format to = strcmp(target, "-") ? mesh_format_from_name(target) : MESH_FORMAT_OBJ;
    if (to == MESH_FORMAT_PLY) return mesh_write_ply(out, o, err);
    if (info && info->format == MESH_FORMAT_OBJ) {
        size_t n;
        const char *text = !strcmp(in, "-") ? cli_stdin_data(&n) : NULL;
        scaf_status st = text
            ? obj_rewrite_uv_text_grouped("<stdin>", text, n, out, o, face_group, err)
            : obj_rewrite_uv_grouped(in, out, o, face_group, err);
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
