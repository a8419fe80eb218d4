/* tools/cmd_tet: `scaf tet IN -o OUT.mesh`, the initial 3D scaffold.
 *
 * A closed surface inside a box (its bounding box scaled --box-scale times
 * about its centre, each side cut into --box-cells squares) is
 * tetrahedralized by TetGen with the surface kept as it is, then checked
 * exactly (geom/tet_box_mesh) and written as a Medit .mesh whose tet
 * references are 1 inside the surface and 2 between it and the box.
 * `scaf check OUT.mesh` verifies it again. Exit status: 0 written,
 * 2 usage, 3 input unreadable, 4 the surface cannot be meshed (open,
 * non-manifold, self-intersecting: the message says which), 5 output not
 * written, 7 out of memory, 70 TetGen's output failed a check.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "cli_closed_surface.h"
#include "cli_mesh_io.h"
#include "cli_unit_scale.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "exit_codes.h"
#include "geom/tet_box_mesh.h"
#include "mesh/tet_medit.h"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: scaf tet IN -o OUT.mesh [--box-scale S] [--box-cells N] [--quiet]\n"
            "\n"
            "Tetrahedralize the space inside a box around the closed surface IN with\n"
            "TetGen, keeping every surface triangle (no point added on the surface or the\n"
            "box), and check the result exactly: every tet positively oriented, every\n"
            "surface triangle a face of one tet inside and one outside. Writes a Medit\n"
            ".mesh: tet reference 1 inside the surface, 2 outside.\n"
            "\n"
            "  -o, --output FILE  the .mesh to write (nothing is left on failure)\n"
            "  --box-scale S      box = bounding box scaled S times about its centre\n"
            "                     (default 3, > 1)\n"
            "  --box-cells N      squares per box side edge, 1..64 (default 8)\n"
            "  -q, --quiet        no summary on stderr\n"
            "\n");
    exit_codes_print(out);
}

static int tet_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    double scale = 3;
    int cells = 8, quiet = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            CLI_NEED_VALUE("tet");
            out = v;
        } else if (!strcmp(a, "--box-scale")) {
            CLI_NEED_VALUE("tet");
            if (!cli_parse_double(v, &scale) || !(scale > 1) || scale > 1e6) CLI_BAD_VALUE("tet");
        } else if (!strcmp(a, "--box-cells")) {
            CLI_NEED_VALUE("tet");
            if (!cli_parse_int(v, &cells) || cells < 1 || cells > 64) CLI_BAD_VALUE("tet");
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            quiet = 1;
        } else if (cli_take_input("tet", a, &in) != EXIT_OK) {
            return EXIT_USAGE;
        }
    }
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
    /* the same words as flow, inflate and untangle for an open surface */
    if ((status = cli_check_closed_surface("tet", in, &m, "tet")) != EXIT_OK) {
        mesh_free(&m);
        return status;
    }
    int e = 0; /* at unit scale (tools/cli_unit_scale), multiplied back below */
    if ((status = cli_unit_scale("tet", in, &m, &e)) != EXIT_OK) {
        mesh_free(&m);
        return status;
    }
    double lo[3], hi[3];
    tet_box_around(m.nv, m.V, scale, lo, hi);
    tet_box_mesh tm;
    scaf_error err;
    err_clear(&err);
    scaf_status s = tet_box_mesh_build(m.nv, m.V, m.nf, m.F, lo, hi, cells, &tm, &err);
    mesh_free(&m);
    if (s != SCAF_OK) {
        fprintf(stderr, "scaf tet: %s: %s\n", in, err.message);
        return s == SCAF_ERR_USAGE ? EXIT_MESH : exit_code_for(s);
    }
    int *label = malloc(sizeof(int) * (size_t)(tm.nt > 0 ? tm.nt : 1));
    if (!label) {
        tet_box_mesh_free(&tm);
        fprintf(stderr, "scaf tet: out of memory\n");
        return EXIT_NOMEM;
    }
    for (int t = 0; t < tm.nt; t++) label[t] = tm.inside[t] ? 1 : 2;
    if ((status = cli_unit_unscale("tet", in, tm.V, 3 * (size_t)tm.nv, e)) != EXIT_OK) {
        free(label);
        tet_box_mesh_free(&tm);
        return status;
    }
    const char *path = cli_outputs_begin(&outs, k, &err);
    s = path ? tet_medit_write(path, tm.nv, tm.V, tm.nt, tm.T, label, &err) : SCAF_ERR_IO;
    int rc = cli_outputs_end(&outs, k, s, &err);
    if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    cli_outputs_abort(&outs);
    if (rc == EXIT_OK && !quiet)
        fprintf(stderr,
                "scaf tet: %d vertices (%d surface, %d box, %d added), %d tets (%d inside)\n",
                tm.nv, tm.nsurface, tm.nbox, tm.nv - tm.nsurface - tm.nbox, tm.nt, tm.ninside);
    free(label);
    tet_box_mesh_free(&tm);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_tet(int argc, char **argv) { return cli_signal_run(tet_main, argc, argv); }
