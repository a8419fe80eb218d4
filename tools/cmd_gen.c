/* tools/cmd_gen: `scaf gen NAME [--size N] -o FILE`, write a built-in sample.
 *
 * The samples are procedural (mesh/samples), so examples and tests need no
 * downloaded data. The OBJ goes through mesh_write_obj: written to a
 * temporary file and renamed, so a failure leaves nothing behind. Exit
 * status: 0 written, 2 bad command line (unknown sample, size out of
 * range), 5 output not written, 7 out of memory.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_options.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "commands.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "mesh/spiral_strip.h"
#include "deform_targets.h"

static void list_samples(FILE *out)
{
    fprintf(out, "%-12s %-9s %s\n", "name", "size", "what");
    for (int i = 0; i < mesh_sample_count(); i++) {
        const mesh_sample_info *s = mesh_sample_get(i);
        char range[32];
        snprintf(range, sizeof range, "%d..%d", s->min_size, s->max_size);
        fprintf(out, "%-12s %-9s %s (default size %d)\n", s->name, range, s->summary,
                s->default_size);
    }
}

static void about(FILE *out)
{
    fputs("Write a built-in procedural sample mesh as OBJ (with vt where the sample\n"
          "has UVs). Deterministic: the same NAME and N give the same file. `spiral`\n"
          "also writes the targets for `scaf deform` beside FILE: S.obj -> S.targets.json.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fprintf(out, "\nsamples:\n");
    list_samples(out);
    fprintf(out,
            "\nExit status: 0 written, 2 usage, 5 output not written, 7 out of memory,\n"
            "8 interrupted (nothing written).\n");
}

static int gen_main(int argc, char **argv)
{
    const char *name = NULL, *out = NULL;
    int size = 0, list = 0;
    const cli_option options[] = {CLI_GROUP("options:"),
                                  CLI_STRING("output", 'o', &out, "FILE",
                                             "where to write: .obj, or .obj.gz gzip-compressed, or "
                                             "- for the standard "
                                             "output (required); nothing is left on failure"),
                                  CLI_INT("size", 's', &size, "N", 1, INT_MAX,
                                          "resolution (see the list; default per sample)"),
                                  CLI_FLAG("list", 'l', &list, "list the samples and their sizes"),
                                  CLI_OPTION_HELP,
                                  {0}};
    const cli_command_options cmd = {.cmd = "gen",
                                     .usage = "usage: scaf gen NAME [--size N] -o FILE\n"
                                              "       scaf gen --list\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .help_column = 21,
                                     .positionals = &name,
                                     .max_positionals = 1,
                                     .positional_name = "sample NAME"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) return cli_options_done(&cmd, parsed);
    if (list) {
        list_samples(stdout);
        return EXIT_OK;
    }
    if (!name) {
        fprintf(stderr, "scaf gen: missing sample NAME (see `scaf gen --list`)\n");
        return EXIT_USAGE;
    }
    if (!out) {
        fprintf(stderr, "scaf gen: missing -o FILE\n");
        return EXIT_USAGE;
    }

    /* spiral: its targets beside it, S.obj -> S.targets.json */
    char targets[4096] = "";
    if (!strcmp(name, "spiral")) {
        size_t len = strlen(out);
        size_t stem = len >= 7 && !strcmp(out + len - 7, ".obj.gz") ? len - 7
            : len >= 4 && !strcmp(out + len - 4, ".obj")            ? len - 4
                                                                    : len;
        if (!strcmp(out, "-") || stem + 14 > sizeof targets) {
            fprintf(stderr,
                    "scaf gen: spiral writes its targets beside -o FILE: give a file name\n");
            return EXIT_USAGE;
        }
        memcpy(targets, out, stem);
        strcpy(targets + stem, ".targets.json");
    }
    cli_outputs outs;
    cli_outputs_init(&outs, "gen", NULL);
    int k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    int kt = cli_outputs_add(&outs, "targets", targets[0] ? targets : NULL, CLI_OUTPUT_FILE);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;
    mesh m;
    scaf_error err;
    err_clear(&err);
    scaf_status st = mesh_sample_make(name, size, &m, &err);
    if (st) {
        fprintf(stderr, "scaf gen: %s\n", err.message);
        return exit_code_for(st);
    }
    const char *path = cli_outputs_begin(&outs, k, &err);
    rc = cli_outputs_end(&outs, k, path ? mesh_write_obj(path, &m, &err) : SCAF_ERR_IO, &err);
    if (rc == EXIT_OK && kt >= 0) {
        /* the drag: frames 1 .. FRAMES-1 as the path, then the spiral */
        int nseg = (m.nv - 2) / 2, nfr = SPIRAL_STRIP_FRAMES - 1;
        double *T = malloc(sizeof(double) * 2 * (size_t)m.nv * SPIRAL_STRIP_FRAMES);
        path = cli_outputs_begin(&outs, kt, &err);
        if (T) {
            for (int f = 0; f < nfr; f++)
                spiral_strip_curl(nseg, (f + 1.0) / SPIRAL_STRIP_FRAMES,
                                  T + 2 * (size_t)m.nv * (size_t)(f + 1));
            spiral_strip_curl(nseg, 1.0, T);
        }
        st = !T    ? err_nomem(&err, "spiral targets")
            : path ? deform_targets_write(path, m.nv, T, nfr, T + 2 * (size_t)m.nv, &err)
                   : SCAF_ERR_IO;
        free(T);
        rc = cli_outputs_end(&outs, kt, st, &err);
    }
    mesh_free(&m);
    if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    cli_outputs_abort(&outs);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_gen(int argc, char **argv) { return cli_signal_run(gen_main, argc, argv); }
