/* tools/cmd_gen: `scaf gen NAME [--size N] -o FILE`, write a built-in sample.
 *
 * The samples are procedural (mesh/samples), so examples and tests need no
 * downloaded data. The OBJ goes through mesh_write_obj: written to a
 * temporary file and renamed, so a failure leaves nothing behind. Exit
 * status: 0 written, 2 bad command line (unknown sample, size out of
 * range), 5 output not written, 7 out of memory.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

static void usage(FILE *out)
{
    fprintf(out,
            "usage: scaf gen NAME [--size N] -o FILE\n"
            "       scaf gen --list\n"
            "\n"
            "Write a built-in procedural sample mesh as OBJ (with vt where the sample\n"
            "has UVs). Deterministic: the same NAME and N give the same file. `spiral`\n"
            "also writes the targets for `scaf deform` beside FILE: S.obj -> S.targets.json.\n"
            "\n"
            "options:\n"
            "  -o, --output FILE  where to write: .obj, or .obj.gz gzip-compressed, or - for\n"
            "                     the standard output (required); nothing is left on failure\n"
            "  -s, --size N       resolution (see the list; default per sample)\n"
            "  -l, --list         list the samples and their sizes\n"
            "  -h, --help         this help\n"
            "\n"
            "samples:\n");
    list_samples(out);
    fprintf(out,
            "\nExit status: 0 written, 2 usage, 5 output not written, 7 out of memory,\n"
            "8 interrupted (nothing written).\n");
}

/* Strict decimal int in [1, INT_MAX]; -1 if not one. */
static int parse_size(const char *s)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < 1 || v > INT_MAX) return -1;
    return (int)v;
}

static int gen_main(int argc, char **argv)
{
    const char *name = NULL, *out = NULL;
    int size = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "--list") || !strcmp(a, "-l")) {
            list_samples(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output") || !strcmp(a, "-s") ||
                   !strcmp(a, "--size")) {
            if (i + 1 >= argc) {
                fprintf(stderr, "scaf gen: option '%s' needs a value\n", a);
                return EXIT_USAGE;
            }
            const char *val = argv[++i];
            if (a[1] == 'o' || a[2] == 'o') {
                out = val;
            } else if ((size = parse_size(val)) < 0) {
                fprintf(stderr, "scaf gen: --size needs a positive integer, got '%s'\n", val);
                return EXIT_USAGE;
            }
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "scaf gen: unknown option '%s' (see `scaf gen --help`)\n", a);
            return EXIT_USAGE;
        } else if (name) {
            fprintf(stderr, "scaf gen: one sample NAME only ('%s' and '%s' given)\n", name, a);
            return EXIT_USAGE;
        } else {
            name = a;
        }
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
