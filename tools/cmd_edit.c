/* tools/cmd_edit: `scaf edit IN.obj [-o OUT.obj]`: the interactive atlas
 * editor in the browser.
 *
 * Reads the mesh, makes its atlas layout a drag context (scaf/drag.h:
 * the input's own UVs when they are bijective with the padding kept,
 * else the finished atlas of `scaf atlas`), and serves the page
 * (tools/edit_page.html, compiled in) and its requests (tools/edit_api)
 * on 127.0.0.1 with libmicrohttpd (tools/edit_server) until SIGINT or
 * SIGTERM. The URL it prints carries a random token; requests without it
 * are refused. Save writes OUT atomically, certified exactly like
 * `scaf atlas` output.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "cli_mesh_io.h"
#include "cli_seams.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "edit_api.h"
#include "edit_page.h"
#include "edit_server.h"
#include "exit_codes.h"
#include "scaf/drag.h"

#define DEFAULT_PADDING (4.0 / 1024.0)

static void usage(FILE *o)
{
    fprintf(o,
            "usage: scaf edit IN.obj [-o OUT.obj] [options]\n"
            "\n"
            "The interactive atlas editor: serves a page on this machine (127.0.0.1 only)\n"
            "and prints its address, with a random token, on the standard output: open it\n"
            "in a browser. The page draws the atlas, each chart in its colour (optional\n"
            "checkerboard and distortion shading), with the energy E and the packing\n"
            "efficiency. Drag a chart to move it (shift: rotate it, alt: drag one vertex):\n"
            "while you drag, SCAF iterations run here with the drag as soft handles, so\n"
            "the other charts are pushed aside; no two charts ever overlap and the padding\n"
            "is kept at every iteration. Buttons: optimize (iterations without handles),\n"
            "compact (pack tighter), undo, save (the layout scaled into the unit square,\n"
            "proved bijective with the padding kept exactly, written atomically to OUT).\n"
            "\n"
            "IN: OBJ (.obj), OFF (.off) or PLY (.ply), optionally gzip-compressed (.gz).\n"
            "With UVs (vt) that are bijective and keep the padding (a `scaf atlas` output)\n"
            "the editor starts from them; otherwise from the atlas `scaf atlas` would make\n"
            "(on a closed mesh or one without vt: automatic charts, see --seams).\n"
            "\n"
            "options:\n"
            "  -o, --output FILE   where save writes (default: IN's name with -edited.obj,\n"
            "                      e.g. a.obj -> a-edited.obj); checked before the start\n"
            "  --port N            the port (default 0: a free port the system picks)\n"
            "  --start S           auto (default: input when its UVs qualify, else atlas),\n"
            "                      input, atlas (`scaf atlas`'s result) or layout (charts\n"
            "                      as circles on a grid)\n"
            "  --seams S           where the charts are cut: input (the vt seams), auto\n"
            "                      (automatic charts, the vt ignored) or extend (the vt\n"
            "                      seams plus cuts where a chart is not a disk); default:\n"
            "                      input when the vt cut the mesh into disks, else auto,\n"
            "                      as `scaf atlas`\n"
            "  --padding P         minimum distance between two charts in the unit square\n"
            "                      (default 4 / 1024 = 0.00390625)\n"
            "  --quiet             no messages but errors\n"
            "  -h, --help          this text\n"
            "\n"
            "Output: OUT ends in .obj, or .obj.gz (gzip-compressed); it is checked before\n"
            "the start (a directory, FIFO or device, a missing or read-only folder, or the\n"
            "input itself are refused) and every save replaces it atomically: a save that\n"
            "fails or is interrupted leaves the previous file as it was.\n"
            "Stopping: Ctrl-C (SIGINT) or SIGTERM stops the server cleanly (an iteration\n"
            "run is finished first) with exit status 0; files saved stay. Before the\n"
            "server runs: 2 for a bad command line or a port that cannot be listened on,\n"
            "3, 4, 5, 7 and 8 as below (a save that fails later is reported on the page).\n"
            "Security: the server listens on 127.0.0.1 only; every request needs the\n"
            "token, a Host of 127.0.0.1 or localhost at this port, and no foreign Origin.\n"
            "Bad requests get a 4xx answer and change nothing.\n\n");
    exit_codes_print(o);
}

/* 128 random bits as hex, from the kernel. 0 on failure. */
static int make_token(char *out)
{
    unsigned char b[EDIT_TOKEN_CHARS / 2];
    FILE *f = fopen("/dev/urandom", "rb");
    if (!f) return 0;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n != sizeof b) return 0;
    for (size_t i = 0; i < sizeof b; i++) sprintf(out + 2 * i, "%02x", b[i]);
    return 1;
}

/* IN without .gz and its extension, then -edited.obj. */
static int default_output(const char *in, char *out, size_t size)
{
    size_t n = strlen(in);
    if (n > 3 && !strcmp(in + n - 3, ".gz")) n -= 3;
    const char *slash = strrchr(in, '/');
    for (size_t i = n; i > 0; i--) {
        if (in[i - 1] == '/') break;
        if (in[i - 1] == '.' && in + i - 1 > (slash ? slash + 1 : in)) {
            n = i - 1;
            break;
        }
    }
    return snprintf(out, size, "%.*s-edited.obj", (int)n, in) < (int)size;
}

/* The drag context on m: start as asked; auto tries the input first. */
static int make_layout(const char *in, const mesh *m, const char *start, double padding,
                       scaf_seams seams, int quiet, scaf_drag_t **out)
{
    scaf_drag_options_t opt = scaf_drag_options_default();
    opt.padding = padding;
    opt.seams = seams;
    int tries[2], ntries = 0;
    if (!strcmp(start, "auto")) {
        if (m->nuv > 0) tries[ntries++] = SCAF_DRAG_START_INPUT;
        tries[ntries++] = SCAF_DRAG_START_ATLAS;
    } else {
        tries[ntries++] = !strcmp(start, "input") ? SCAF_DRAG_START_INPUT
            : !strcmp(start, "atlas")             ? SCAF_DRAG_START_ATLAS
                                                  : SCAF_DRAG_START_LAYOUT;
    }
    scaf_status st = SCAF_OK;
    for (int t = 0; t < ntries; t++) {
        opt.start = (scaf_drag_start)tries[t];
        scaf_drag_t *d = scaf_drag_new(&opt);
        if (!d) {
            fprintf(stderr, "scaf edit: out of memory\n");
            return EXIT_NOMEM;
        }
        /* the vt give the seams of every start (as `scaf atlas`), and
         * the positions of the input start */
        int uvs = opt.start == SCAF_DRAG_START_INPUT;
        st = scaf_drag_set_mesh(d, m->V, m->nv, m->F, m->nf, m->nuv ? m->UV : NULL, m->nuv,
                                m->nuv ? m->FT : NULL);
        if (st == SCAF_OK) {
            if (!quiet)
                fprintf(stderr, "scaf edit: %s: %d faces, %d charts, starting from %s\n", in, m->nf,
                        scaf_drag_chart_count(d),
                        uvs                                      ? "its UVs"
                            : opt.start == SCAF_DRAG_START_ATLAS ? "the atlas (`scaf atlas`)"
                                                                 : "circles on a grid");
            *out = d;
            return EXIT_OK;
        }
        if (t + 1 < ntries && !quiet)
            fprintf(stderr, "scaf edit: %s: not starting from its UVs: %s\n", in,
                    scaf_drag_error(d));
        else if (t + 1 == ntries) fprintf(stderr, "scaf edit: %s: %s\n", in, scaf_drag_error(d));
        scaf_drag_destroy(d);
    }
    return exit_code_for(st);
}

/* Serve until SIGINT / SIGTERM. The signals are blocked while the server
 * thread starts (it inherits the mask and never runs the handler), then
 * waited for with cli_signal_wait: no poll, and no lost signal whichever
 * thread handles it (a sigsuspend here hung when OpenBLAS's thread took
 * the signal between the check and the wait). */
static int serve(edit_api *api, int port, int quiet)
{
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigprocmask(SIG_BLOCK, &block, &old);
    edit_server server;
    scaf_error err;
    err_clear(&err);
    api->port = port;
    if (edit_server_start(&server, port, edit_api_handle, api, &err) != SCAF_OK) {
        sigprocmask(SIG_SETMASK, &old, NULL);
        fprintf(stderr, "scaf edit: %s (choose another --port)\n", err.message);
        return EXIT_USAGE;
    }
    api->port = server.port; /* handler reads it only once requests come */
    printf("http://127.0.0.1:%d/?token=%s\n", server.port, api->token);
    fflush(stdout);
    if (!quiet)
        fprintf(stderr,
                "scaf edit: open the address above in a browser; save writes %s; Ctrl-C stops\n",
                api->out);
    sigprocmask(SIG_SETMASK, &old, NULL);
    cli_signal_wait();
    edit_server_stop(&server);
    if (!quiet)
        fprintf(stderr, "scaf edit: stopped by %s; %d save(s)\n",
                cli_signal_caught() == SIGTERM ? "SIGTERM" : "SIGINT", api->saves);
    return EXIT_OK;
}

static int edit_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *start = "auto";
    int port = 0, quiet = 0;
    scaf_seams seams = SCAF_SEAMS_DEFAULT;
    double padding = DEFAULT_PADDING;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            CLI_NEED_VALUE("edit");
            out = v;
        } else if (!strcmp(a, "--port")) {
            CLI_NEED_VALUE("edit");
            if (!cli_parse_int(v, &port)) CLI_BAD_VALUE("edit");
            if (port > 65535) CLI_OUT_OF_RANGE("edit", "in 0..65535");
        } else if (!strcmp(a, "--start")) {
            CLI_NEED_VALUE("edit");
            if (strcmp(v, "auto") && strcmp(v, "input") && strcmp(v, "atlas") &&
                strcmp(v, "layout"))
                CLI_BAD_VALUE("edit");
            start = v;
        } else if (!strcmp(a, "--seams")) {
            CLI_NEED_VALUE("edit");
            if (!cli_seams_parse(v, &seams)) CLI_BAD_VALUE("edit");
        } else if (!strcmp(a, "--padding")) {
            CLI_NEED_VALUE("edit");
            if (!cli_parse_double(v, &padding)) CLI_BAD_VALUE("edit");
            if (!(padding == 0 || (padding >= 0x1p-200 && padding < 0.5)))
                CLI_OUT_OF_RANGE("edit", "0 or in [2^-200, 0.5)");
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (cli_take_input("edit", a, &in) != EXIT_OK) {
            return EXIT_USAGE;
        }
    }
    if (!in) {
        fprintf(stderr, "scaf edit: no input file (see --help)\n");
        return EXIT_USAGE;
    }
    char derived[4096];
    if (!out) {
        if (!default_output(in, derived, sizeof derived)) {
            fprintf(stderr, "scaf edit: input name too long for a default output: use -o\n");
            return EXIT_USAGE;
        }
        out = derived;
    }
    if (!strcmp(out, "-")) {
        fprintf(stderr, "scaf edit: -o - (standard output) is not possible: the URL goes there\n");
        return EXIT_USAGE;
    }
    /* the output checked now, not at the first save */
    cli_outputs outs;
    cli_outputs_init(&outs, "edit", in);
    cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;

    mesh m;
    mesh_read_info rinfo;
    rc = cli_read_mesh("edit", in, quiet, &m, &rinfo);
    if (rc != EXIT_OK) return rc;
    scaf_drag_t *d = NULL;
    rc = make_layout(in, &m, start, padding, seams, quiet, &d);
    if (rc != EXIT_OK) {
        mesh_free(&m);
        return rc;
    }
    edit_api api;
    scaf_error err;
    err_clear(&err);
    scaf_status st = edit_api_init(&api, d, &m, in, &rinfo, out, padding, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf edit: %s\n", err.message);
        rc = exit_code_for(st);
    } else if (!make_token(api.token)) {
        fprintf(stderr, "scaf edit: cannot read /dev/urandom for the token\n");
        rc = EXIT_INTERNAL;
    } else {
        api.page = (const char *)edit_page_html;
        api.page_len = edit_page_html_len;
        rc = cli_signal_caught() ? EXIT_CANCELLED : serve(&api, port, quiet);
    }
    edit_api_free(&api);
    scaf_drag_destroy(d);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: stop serving (tools/cli_signal) */
int cmd_edit(int argc, char **argv) { return cli_signal_run(edit_main, argc, argv); }
