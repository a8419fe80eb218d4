/* tools/cmd_tet: `scaf tet IN -o OUT.mesh`, the initial 3D scaffold.
 *
 * A closed surface inside a box (its bounding box scaled --box-scale times
 * about its centre, each side cut into --box-cells squares) is
 * tetrahedralized by TetGen with the surface kept as it is, then checked
 * exactly (scaf_tet_mesh of scaf/volume.h) and written as a Medit .mesh whose tet
 * references are 1 inside the surface and 2 between it and the box.
 * `scaf check OUT.mesh` verifies it again. Exit status: 0 written,
 * 2 usage, 3 input unreadable, 4 the surface cannot be meshed (open,
 * non-manifold, self-intersecting: the message says which), 5 output not
 * written, 7 out of memory, 70 TetGen's output failed a check.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_mesh_io.h"
#include "cli_options.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "exit_codes.h"
#include "mesh/tet_medit.h"
#include "scaf/volume.h"

static void about(FILE *out)
{
    fputs("Tetrahedralize the space inside a box around the closed surface IN with\n"
          "TetGen, keeping every surface triangle (no point added on the surface or the\n"
          "box), and check the result exactly: every tet positively oriented, every\n"
          "surface triangle a face of one tet inside and one outside. Writes a Medit\n"
          ".mesh: tet reference 1 inside the surface, 2 outside.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fputc('\n', out);
    exit_codes_print(out);
}

static int tet_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    double scale = 3;
    int cells = 8, quiet = 0;
    const cli_option options[] = {
        CLI_STRING("output", 'o', &out, "FILE", "the .mesh to write (nothing is left on failure)"),
        CLI_DOUBLE("box-scale", 0, &scale, "S", 1, 1e6,
                   "box = bounding box scaled S times about its centre (default 3, > 1)",
                   .open_min = 1),
        CLI_INT("box-cells", 0, &cells, "N", 1, 64, "squares per box side edge, 1..64 (default 8)"),
        CLI_FLAG("quiet", 'q', &quiet, "no summary on stderr"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "tet",
                                     .usage = "usage: scaf tet IN -o OUT.mesh [--box-scale S] "
                                              "[--box-cells N] [--quiet]\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .help_column = 21,
                                     .positionals = &in,
                                     .max_positionals = 1,
                                     .positional_name = "input"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) return cli_options_done(&cmd, parsed);
    if (!in || !out) {
        fprintf(stderr, "scaf tet: %s\n", in ? "missing -o OUT.mesh" : "missing the input surface");
        return EXIT_USAGE;
    }
    /* the output checked before any work (device, folder, same file as the input) */
    cli_outputs outs;
    cli_outputs_init(&outs, "tet", in);
    int k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_FILE);
    int status = cli_outputs_check(&outs);
    if (status != EXIT_OK) return status;
    mesh m;
    mesh_read_info info;
    status = cli_read_mesh("tet", in, quiet, &m, &info);
    if (status != EXIT_OK) return status;
    scaf_volume_t *h = scaf_volume_new();
    scaf_tet_options_t o = scaf_tet_options_default();
    o.box_scale = scale;
    o.box_cells = cells;
    scaf_status s = h ? scaf_tet_mesh(h, m.V, m.nv, m.F, m.nf, &o) : SCAF_ERR_NOMEM;
    int nv = m.nv;
    mesh_free(&m);
    if (s != SCAF_OK) {
        fprintf(stderr, "scaf tet: %s: %s\n", in, h ? scaf_volume_error(h) : "out of memory");
        scaf_volume_destroy(h);
        return exit_code_for(s);
    }
    int np = scaf_volume_tet_vertex_count(h), nt = scaf_volume_tet_count(h);
    double *P = malloc(sizeof(double) * 3 * (size_t)(np > 0 ? np : 1));
    int *T = malloc(sizeof(int) * 4 * (size_t)(nt > 0 ? nt : 1));
    int *label = malloc(sizeof(int) * (size_t)(nt > 0 ? nt : 1));
    scaf_volume_summary_t sum = {.struct_size = sizeof sum};
    if (!P || !T || !label) {
        free(P);
        free(T);
        free(label);
        scaf_volume_destroy(h);
        fprintf(stderr, "scaf tet: out of memory\n");
        return EXIT_NOMEM;
    }
    scaf_volume_get_tets(h, P, T, label);
    scaf_volume_get_summary(h, &sum);
    scaf_volume_destroy(h);
    scaf_error err;
    err_clear(&err);
    const char *path = cli_outputs_begin(&outs, k, &err);
    s = path ? tet_medit_write(path, np, P, nt, T, label, &err) : SCAF_ERR_IO;
    int rc = cli_outputs_end(&outs, k, s, &err);
    if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    cli_outputs_abort(&outs);
    if (rc == EXIT_OK && !quiet)
        fprintf(stderr,
                "scaf tet: %d vertices (%d surface, %d box, %d added), %d tets (%d inside)\n", np,
                nv, sum.box_vertices, np - nv - sum.box_vertices, nt, sum.tets_inside);
    free(P);
    free(T);
    free(label);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_tet(int argc, char **argv) { return cli_signal_run(tet_main, argc, argv); }
