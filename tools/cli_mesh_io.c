/* tools/cli_mesh_io: input mesh and output OBJ of the commands (see cli_mesh_io.h). */
#include "cli_mesh_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "cli_args.h"
#include "exit_codes.h"
#include "geom/chart_gap.h"

#include "mesh/gltf_io.h"
#include "mesh/obj_rewrite.h"
#include "mesh/uv_verdict.h"

/* --input-format (MESH_FORMAT_UNKNOWN: from the name or the content) */
static mesh_format forced_format = MESH_FORMAT_UNKNOWN;
/* the standard input's bytes, kept for the output (freed at exit) */
static char *stdin_bytes;
static size_t stdin_size;

static void free_stdin_bytes(void) { free(stdin_bytes); }

int cli_input_format_option(const char *cmd, int argc, char **argv, int *i)
{
    if (!strcmp(argv[*i], "--uv-set")) {
        int n;
        if (*i + 1 >= argc || !cli_parse_int(argv[*i + 1], &n) || n > 65535) {
            fprintf(stderr, "scaf %s: --uv-set needs a number 0..65535 (TEXCOORD_N)\n", cmd);
            return -1;
        }
        ++*i;
        gltf_set_uv_set(n);
        return 1;
    }
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

void cli_gltf_pieces_load(const char *cmd, const char *in, const mesh_read_info *info, int quiet,
                          gltf_piece **pieces, int *n)
{
    *pieces = NULL;
    *n = 0;
    if (!info || info->format != MESH_FORMAT_GLTF) return;
    scaf_error err;
    err_clear(&err);
    char *data = NULL;
    size_t size = 0;
    const char *bytes = !strcmp(in, "-") ? cli_stdin_data(&size) : NULL;
    scaf_status st = bytes ? SCAF_OK : mesh_load_file(in, &data, &size, &err);
    if (st == SCAF_OK) st = gltf_pieces(bytes ? bytes : data, size, in, pieces, n, &err);
    if (st != SCAF_OK && !quiet)
        fprintf(stderr, "scaf %s: warning: no glTF primitive table in the report: %s\n", cmd,
                err.message);
    if (st != SCAF_OK) *pieces = NULL, *n = 0;
    free(data);
}

int cli_input_format_take(const char *cmd, const cli_option *o, const char *v)
{
    static const char *const names[] = {"obj", "off", "ply", "gltf", "glb", NULL};
    static const int formats[] = {MESH_FORMAT_OBJ, MESH_FORMAT_OFF, MESH_FORMAT_PLY,
                                  MESH_FORMAT_GLTF, MESH_FORMAT_GLTF};
    int f = MESH_FORMAT_UNKNOWN;
    cli_option e = *o;
    e.kind = CLI_OPT_ENUM;
    e.choices = names;
    e.values = formats;
    e.dest = &f;
    int rc = cli_option_apply(cmd, &e, v);
    if (rc == EXIT_OK) forced_format = (mesh_format)f;
    return rc;
}

int cli_uv_set_take(const char *cmd, const cli_option *o, const char *v)
{
    int n = 0;
    cli_option e = *o;
    e.kind = CLI_OPT_INT;
    e.dest = &n;
    int rc = cli_option_apply(cmd, &e, v);
    if (rc == EXIT_OK) gltf_set_uv_set(n);
    return rc;
}

void cli_gltf_pieces_report(const char *cmd, const char *in, const mesh_read_info *info, int quiet,
                            const mesh *o)
{
    if (quiet || !info || info->format != MESH_FORMAT_GLTF || !mesh_has_uv(o)) return;
    scaf_error err;
    err_clear(&err);
    char *data = NULL;
    size_t n = 0;
    const char *bytes = !strcmp(in, "-") ? cli_stdin_data(&n) : NULL;
    scaf_status st = bytes ? SCAF_OK : mesh_load_file(in, &data, &n, &err);
    gltf_piece *pc = NULL;
    int np = 0, nc = 0;
    int *chart = malloc(sizeof(int) * (size_t)(o->nf ? o->nf : 1));
    if (st == SCAF_OK) st = gltf_pieces(bytes ? bytes : data, n, in, &pc, &np, &err);
    if (st == SCAF_OK && !chart) st = err_nomem(&err, "chart labels");
    if (st == SCAF_OK) st = chart_gap_labels(o->nuv, o->nf, o->FT, chart, &nc, &err);
    if (st != SCAF_OK)
        fprintf(stderr, "scaf %s: warning: no glTF primitive table: %s\n", cmd, err.message);
    for (int k = 0; st == SCAF_OK && k < np; k++) {
        /* the charts of the primitive's faces, as ranges (charts are numbered
         * in face order, so a primitive's are mostly consecutive) */
        char *seen = calloc((size_t)nc + 1, 1);
        int count = 0;
        for (int f = pc[k].first_face; seen && f < pc[k].first_face + pc[k].faces; f++)
            if (!seen[chart[f]]++) count++;
        fprintf(stderr, "scaf %s: glTF mesh %d '%s' primitive %d: faces %d-%d, chart%s", cmd,
                pc[k].mesh, pc[k].mesh_name, pc[k].primitive, pc[k].first_face,
                pc[k].first_face + pc[k].faces - 1, count == 1 ? "" : "s");
        for (int c = 0, first = 1; seen && c < nc; c++) {
            if (!seen[c] || (c > 0 && seen[c - 1])) continue; /* not the start of a run */
            int e = c;
            while (e + 1 < nc && seen[e + 1]) e++;
            fprintf(stderr, "%s %d", first ? "" : ",", c);
            if (e > c) fprintf(stderr, "-%d", e);
            first = 0;
        }
        free(seen);
        fputc('\n', stderr);
    }
    free(chart);
    free(pc);
    free(data);
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
    if (to == MESH_FORMAT_GLTF) { /* the input document again, with the UVs */
        /* glTF keeps 32-bit floats: the map written must be bijective too */
        bij_report rep;
        scaf_status vs = mesh_uv_verdict_gltf(o, &rep, err);
        if (vs != SCAF_OK) return vs;
        if (!rep.bijective)
            return err_set(err, SCAF_ERR_NUMERIC,
                           "the UVs rounded to glTF's 32-bit floats are not bijective (%d "
                           "flipped, %d degenerate, %lld crossings): nothing written; write OBJ "
                           "or PLY, which keep doubles",
                           rep.flipped, rep.degenerate, rep.boundary_crossings);
        size_t n = 0, tl = strlen(target);
        int binary = (tl >= 4 && !strcasecmp(target + tl - 4, ".glb")) ||
            (tl >= 7 && !strcasecmp(target + tl - 7, ".glb.gz"));
        if (!strcmp(in, "-")) {
            const char *bytes = cli_stdin_data(&n);
            return gltf_rewrite_uv(bytes, n, "<stdin>", o, out, binary, err);
        }
        char *bytes = NULL;
        scaf_status st = mesh_load_file(in, &bytes, &n, err);
        if (st == SCAF_OK) st = gltf_rewrite_uv(bytes, n, in, o, out, binary, err);
        free(bytes);
        return st;
    }
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
