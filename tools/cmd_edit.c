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
 *
 * Unsaved work is never dropped: after each change and a quiet second
 * (AUTOSAVE_QUIET_MS; at most AUTOSAVE_MAX_WAIT_MS after the first
 * unsaved change, for a drag that never pauses), and once more on SIGINT /
 * SIGTERM, the layout is written atomically to the autosave file beside
 * OUT (OUT's name with .autosave.obj for .obj / .obj.gz); a save removes
 * it; `--resume` starts from it. Three threads: the server's, which runs
 * the requests; one that waits for the signal (cli_signal_wait); and this
 * one, which writes the autosave when due. A mutex lets the autosave read
 * the layout only between two requests.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>

#include "cli_args.h"
#include "cli_mesh_io.h"
#include "cli_seams.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "edit_api.h"
#include "edit_start.h"
#include "base/interrupt.h"
#include "edit_page.h"
#include "edit_server.h"
#include "edit_texture.h"
#include "exit_codes.h"
#include "scaf/drag.h"

#define DEFAULT_PADDING (4.0 / 1024.0)
#define AUTOSAVE_QUIET_MS 1000     /* no change for this long: autosave */
#define AUTOSAVE_MAX_WAIT_MS 10000 /* unsaved this long: autosave anyway */

static void usage(FILE *o)
{
    fprintf(o,
            "usage: scaf edit IN.obj [-o OUT.obj] [options]\n"
            "\n"
            "The interactive atlas editor: serves a page on this machine (127.0.0.1 only)\n"
            "and prints its address, with a random token, on the standard output: open it\n"
            "in a browser. The page draws the atlas, each chart in its colour (optional\n"
            "checkerboard and distortion shading), with the energy E and the packing\n"
            "efficiency. Drag a chart to move it (the rotate mode turns it, alt: drag one\n"
            "vertex; click, shift-click or a box on empty space selects charts):\n"
            "by default it moves rigidly and the charts in its way are pushed aside by\n"
            "translations only, no chart changing shape; every frame is proved bijective\n"
            "with the padding kept (exactly). D toggles deform: SCAF iterations run here\n"
            "with the drag as soft handles, bending charts, each other chart's E capped at\n"
            "1.25 times its E at the grab. R, S, X (or the buttons) rotate by 90 degrees,\n"
            "scale by 1.1 (shift: the other way) and flip the selection or the chart under\n"
            "the pointer, rigidly; a flip mirrors, which no bijective layout can hold, so\n"
            "it is refused (shift-X: applied mirrored back, i.e. as a half turn).\n");
    fprintf(o,
            "Buttons: optimize (iterations without handles),\n"
            "compact (pack tighter; E may rise by 5%% at most, the rule of `scaf atlas`),\n"
            "undo and redo (Ctrl-Z, Ctrl-Shift-Z; the history is kept here, so a reload of\n"
            "the page keeps it), save (the layout scaled into the unit square,\n"
            "proved bijective with the padding kept exactly, written atomically to OUT).\n"
            "The wheel zooms toward the cursor; the middle button, space + drag or the arrow\n"
            "keys pan; F fits. The page draws that unit square, a texel grid for its own\n"
            "resolution setting and a legend of the distortion colours (docs/editor.md).\n"
            "Selection: click an island (shift-click adds or removes), drag on empty space\n"
            "or ctrl + drag for a box; the island / vertex toggle selects vertices instead;\n"
            "Escape clears. Pin / unpin (P, U) fix the selected vertices: a pinned vertex\n"
            "never moves. Under the layout: the checker or the --texture image in the unit\n"
            "square; beside it a 3D view of the model with that image mapped by the current\n"
            "UVs (mouse: orbit, wheel: zoom; hovering an island highlights it in both).\n"
            "The padding field sets the padding compact packs to.\n"
            "\n"
            "IN: OBJ (.obj), OFF (.off) or PLY (.ply), optionally gzip-compressed (.gz).\n"
            "Any mesh `scaf atlas` maps opens. With UVs (vt) that the exact checker proves\n"
            "bijective with the padding kept (a `scaf atlas` output, an earlier save) the\n"
            "editor starts from them as they are. Otherwise (vt flipped, overlapping or\n"
            "touching, as in many scanned or hand-made files; or no vt; or a closed mesh)\n"
            "it says why on the standard error and starts from the atlas `scaf atlas IN`\n"
            "makes with its defaults and this --padding: the charts cut along the vt when\n"
            "they cut the mesh into disks, else automatic seams (segmented, cut open where\n"
            "not a disk: --seams); each chart started by Tutte's embedding, all settled\n"
            "together, packed and compacted; the vt positions are not used.\n"
            "\n"
            "options:\n"
            "  -o, --output FILE   where save writes (default: IN's name with -edited.obj,\n"
            "                      e.g. a.obj -> a-edited.obj); checked before the start\n"
            "  --port N            the port (default 0: a free port the system picks)\n"
            "  --start S           auto (default: input when its UVs qualify, else atlas),\n"
            "                      input (refused, exit 4, when they do not; exit 2\n"
            "                      without vt), atlas (`scaf atlas`'s result) or layout\n"
            "                      (charts as circles on a grid)\n"
            "  --seams S           where the charts are cut: input (the vt seams), auto\n"
            "                      (automatic charts, the vt ignored) or extend (the vt\n"
            "                      seams plus cuts where a chart is not a disk); default:\n"
            "                      input when the vt cut the mesh into disks, else auto,\n"
            "                      as `scaf atlas`\n"
            "  --padding P         minimum distance between two charts in the unit square\n"
            "                      (default 4 / 1024 = 0.00390625)\n"
            "  --texture FILE.png  show this image under the layout and on the 3D view (a\n"
            "                      PNG of at most 64 MiB, sides up to 16384 pixels; read\n"
            "                      once at the start: 3 when missing or not such a PNG)\n"
            "  --resume            start from the autosave of an earlier session (see below)\n"
            "                      instead of --start\n"
            "  --quiet             no messages but errors\n"
            "  -h, --help          this text\n"
            "\n");
    /* several strings: C17 compilers need support only 4095 characters in one */
    fprintf(o,
            "Output: OUT ends in .obj, or .obj.gz (gzip-compressed); it is checked before\n"
            "the start (a directory, FIFO or device, a missing or read-only folder, or the\n"
            "input itself are refused) and every save replaces it atomically: a save that\n"
            "fails or is interrupted leaves the previous file as it was. Each save checks\n"
            "OUT again: a link to IN made since the start (symbolic or hard, or to where\n"
            "IN was moved) is refused, IN is never overwritten. IN is kept open: a save\n"
            "after IN was moved, deleted or replaced still keeps IN's other lines\n"
            "(normals, materials, groups, comments); when the file no longer describes\n"
            "the mesh, save writes a plain OBJ and its note on the page says so.\n");
    fprintf(o,
            "Autosave: unsaved changes are written, a second after the last one (at most\n"
            "10 s after the first) and when the editor is stopped, to OUT's name with\n"
            ".autosave.obj instead of .obj or .obj.gz (out.obj -> out.autosave.obj): a\n"
            "plain OBJ of the input's mesh with the layout, certified like a save,\n"
            "replaced atomically. A save removes it (the saved file is newer). When it\n"
            "exists at the start, the editor refuses to run unless --resume is given\n"
            "(it starts from the autosave's UVs, on the same mesh as IN) or the file is\n"
            "removed: unsaved edits are never overwritten. The page marks unsaved\n"
            "changes and asks before its tab closes.\n"
            "Stopping: Ctrl-C (SIGINT) or SIGTERM stops the server cleanly (an iteration\n"
            "run is finished first, unsaved changes go to the autosave) with exit status\n"
            "0; files saved stay. Before the\n"
            "server runs: 2 for a bad command line or a port that cannot be listened on,\n"
            "3, 4, 5, 7 and 8 as below (a save that fails later is reported on the page).\n"
            "Security: the server listens on 127.0.0.1 only; every request needs the\n"
            "token, a Host of 127.0.0.1 or localhost at this port, and no foreign Origin;\n"
            "a connection has 3 s to send a whole request (slow clients cannot hold the\n"
            "64 connections).\n"
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

/* OUT's name with .autosave.obj instead of .obj or .obj.gz (any case). */
static int autosave_name(const char *out, char *buf, size_t size)
{
    size_t n = strlen(out);
    if (n > 3 && !strcasecmp(out + n - 3, ".gz")) n -= 3;
    if (n > 4 && !strcasecmp(out + n - 4, ".obj")) n -= 4;
    return snprintf(buf, size, "%.*s.autosave.obj", (int)n, out) < (int)size;
}

/* The server, the signal and the autosave (see the banner). */
typedef struct editor {
    edit_api *api;
    int quiet;
    pthread_mutex_t layout; /* held while a request runs or the autosave reads */
    pthread_mutex_t lock;   /* the fields below */
    pthread_cond_t wake;
    int stop;                           /* a signal came */
    int pending;                        /* a change not autosaved yet */
    struct timespec first, last_change; /* of the pending changes */
} editor;

static struct timespec now_plus(const struct timespec *t, long ms)
{
    struct timespec r = *t;
    r.tv_sec += ms / 1000;
    r.tv_nsec += (ms % 1000) * 1000000L;
    if (r.tv_nsec >= 1000000000L) {
        r.tv_sec++;
        r.tv_nsec -= 1000000000L;
    }
    return r;
}

static int before(const struct timespec *a, const struct timespec *b)
{
    return a->tv_sec < b->tv_sec || (a->tv_sec == b->tv_sec && a->tv_nsec < b->tv_nsec);
}

/* Every request, one at a time (the server's thread); a change starts
 * the autosave's quiet second anew. */
static void handle(void *user, const edit_request *rq, edit_response *rs)
{
    editor *e = user;
    pthread_mutex_lock(&e->layout);
    int changes = e->api->changes;
    edit_api_handle(e->api, rq, rs);
    int changed = e->api->changes != changes;
    pthread_mutex_unlock(&e->layout);
    if (!changed) return;
    pthread_mutex_lock(&e->lock);
    clock_gettime(CLOCK_MONOTONIC, &e->last_change);
    if (!e->pending) e->first = e->last_change;
    e->pending = 1;
    pthread_cond_signal(&e->wake);
    pthread_mutex_unlock(&e->lock);
}

static void *wait_for_signal(void *user)
{
    editor *e = user;
    cli_signal_wait();
    pthread_mutex_lock(&e->lock);
    e->stop = 1;
    pthread_cond_signal(&e->wake);
    pthread_mutex_unlock(&e->lock);
    return NULL;
}

/* Write the autosave now (between two requests); a failure is printed
 * (the previous autosave stays). */
static void autosave(editor *e)
{
    scaf_error err;
    err_clear(&err);
    int written = 0;
    pthread_mutex_lock(&e->layout);
    scaf_status st = edit_api_autosave(e->api, &written, &err);
    pthread_mutex_unlock(&e->layout);
    if (st != SCAF_OK)
        fprintf(stderr, "scaf edit: autosave to %s failed: %s\n", e->api->autosave, err.message);
}

/* Until the signal: the autosave when due. */
static void autosave_loop(editor *e)
{
    pthread_mutex_lock(&e->lock);
    while (!e->stop) {
        if (!e->pending) {
            pthread_cond_wait(&e->wake, &e->lock);
            continue;
        }
        struct timespec due = now_plus(&e->last_change, AUTOSAVE_QUIET_MS);
        struct timespec cap = now_plus(&e->first, AUTOSAVE_MAX_WAIT_MS);
        if (before(&cap, &due)) due = cap;
        struct timespec t;
        clock_gettime(CLOCK_MONOTONIC, &t);
        if (before(&t, &due)) {
            pthread_cond_timedwait(&e->wake, &e->lock, &due);
            continue;
        }
        e->pending = 0;
        pthread_mutex_unlock(&e->lock);
        autosave(e);
        pthread_mutex_lock(&e->lock);
    }
    pthread_mutex_unlock(&e->lock);
}

/* Serve until SIGINT / SIGTERM. The signals are blocked while the
 * threads start (they inherit the mask and never run the handler), then
 * waited for with cli_signal_wait in a thread of their own: no poll, and
 * no lost signal whichever thread handles it (a sigsuspend here hung when
 * OpenBLAS's thread took the signal between the check and the wait). */
static int serve(edit_api *api, int port, int quiet)
{
    editor e;
    memset(&e, 0, sizeof e);
    e.api = api;
    e.quiet = quiet;
    pthread_condattr_t ca;
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    pthread_mutex_init(&e.layout, NULL);
    pthread_mutex_init(&e.lock, NULL);
    pthread_cond_init(&e.wake, &ca);
    pthread_condattr_destroy(&ca);
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    edit_server server;
    scaf_error err;
    err_clear(&err);
    api->port = port;
    int rc = EXIT_OK;
    pthread_t waiter;
    if (edit_server_start(&server, port, handle, &e, &err) != SCAF_OK) {
        fprintf(stderr, "scaf edit: %s (choose another --port)\n", err.message);
        rc = EXIT_USAGE;
    } else if (pthread_create(&waiter, NULL, wait_for_signal, &e) != 0) {
        edit_server_stop(&server);
        fprintf(stderr, "scaf edit: cannot start a thread\n");
        rc = EXIT_NOMEM;
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (rc == EXIT_OK) {
        api->port = server.port; /* handler reads it only once requests come */
        printf("http://127.0.0.1:%d/?token=%s\n", server.port, api->token);
        fflush(stdout);
        if (!quiet)
            fprintf(stderr,
                    "scaf edit: open the address above in a browser; save writes %s; unsaved "
                    "changes go to %s; Ctrl-C stops\n",
                    api->out, api->autosave);
        autosave_loop(&e);
        pthread_join(waiter, NULL);
        edit_server_stop(&server);
        autosave(&e); /* what changed since the last one */
        if (!quiet)
            fprintf(stderr, "scaf edit: stopped by %s; %d save(s)\n",
                    interrupt_signal_name(cli_signal_caught()), api->saves);
        if (edit_api_unsaved(api) && api->autosaved_changes == api->changes)
            fprintf(stderr,
                    "scaf edit: the unsaved changes are in %s: `scaf edit %s -o %s --resume` "
                    "continues from them\n",
                    api->autosave, api->in, api->out);
    }
    pthread_cond_destroy(&e.wake);
    pthread_mutex_destroy(&e.lock);
    pthread_mutex_destroy(&e.layout);
    return rc;
}

/* --resume: the autosave's UVs on the input's mesh (*m gets them). The
 * autosave must be of the same mesh: same vertices (exactly, as written)
 * and faces. 0, or the exit status after printing why. */
static int take_autosave(const char *path, const char *in, mesh *m, int quiet)
{
    mesh a;
    mesh_read_info info;
    int rc = cli_read_mesh("edit", path, 1, &a, &info);
    if (rc != EXIT_OK) return rc;
    const char *bad = NULL;
    if (a.nv != m->nv || a.nf != m->nf) bad = "a different number of vertices or faces";
    else if (memcmp(a.F, m->F, sizeof(int) * 3 * (size_t)m->nf) != 0) bad = "other faces";
    else if (memcmp(a.V, m->V, sizeof(double) * 3 * (size_t)m->nv) != 0)
        bad = "other vertex positions";
    else if (!mesh_has_uv(&a)) bad = "no texture coordinates";
    if (bad) {
        fprintf(stderr,
                "scaf edit: %s is not an autosave of %s (%s): nothing to resume; open it as "
                "the input instead\n",
                path, in, bad);
        mesh_free(&a);
        return EXIT_INPUT;
    }
    free(m->UV);
    free(m->FT);
    m->UV = a.UV;
    m->FT = a.FT;
    m->nuv = a.nuv;
    a.UV = NULL;
    a.FT = NULL;
    mesh_free(&a);
    if (!quiet) fprintf(stderr, "scaf edit: resuming from %s\n", path);
    return EXIT_OK;
}

static int edit_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *start = "auto", *texture_path = NULL;
    int port = 0, quiet = 0, resume = 0;
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
            if (!edit_start_name_ok(v)) CLI_BAD_VALUE("edit");
            start = v;
        } else if (!strcmp(a, "--seams")) {
            CLI_NEED_VALUE("edit");
            if (!cli_seams_parse(v, &seams)) CLI_BAD_VALUE("edit");
        } else if (!strcmp(a, "--padding")) {
            CLI_NEED_VALUE("edit");
            if (!cli_parse_double(v, &padding)) CLI_BAD_VALUE("edit");
            if (!(padding == 0 || (padding >= 0x1p-200 && padding < 0.5)))
                CLI_OUT_OF_RANGE("edit", "0 or in [2^-200, 0.5)");
        } else if (!strcmp(a, "--texture")) {
            CLI_NEED_VALUE("edit");
            texture_path = v;
        } else if (!strcmp(a, "--resume")) {
            resume = 1;
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
    char autosave_path[4096 + 16];
    if (!autosave_name(out, autosave_path, sizeof autosave_path)) {
        fprintf(stderr, "scaf edit: -o %s: name too long\n", out);
        return EXIT_USAGE;
    }
    /* the output and the autosave checked now, not at the first save */
    cli_outputs outs;
    cli_outputs_init(&outs, "edit", in);
    cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    cli_outputs_add(&outs, "the autosave", autosave_path, CLI_OUTPUT_MESH);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;
    struct stat sb;
    int have_autosave = lstat(autosave_path, &sb) == 0;
    if (have_autosave && !resume) {
        fprintf(stderr,
                "scaf edit: %s holds unsaved edits of an earlier session: add --resume to "
                "continue from them, or remove it\n",
                autosave_path);
        return EXIT_USAGE;
    }
    if (resume && !have_autosave) {
        fprintf(stderr, "scaf edit: --resume: there is no autosave %s (%s)\n", autosave_path,
                strerror(errno));
        return EXIT_INPUT;
    }

    /* the image, read once now: the server sends these bytes only */
    edit_texture texture = {0};
    if (texture_path) {
        char msg[4400];
        rc = edit_texture_read(texture_path, &texture, msg, sizeof msg);
        if (rc != EXIT_OK) {
            fprintf(stderr, "scaf edit: %s\n", msg);
            return rc;
        }
    }
    mesh m;
    mesh_read_info rinfo;
    rc = cli_read_mesh("edit", in, quiet, &m, &rinfo);
    if (rc != EXIT_OK) {
        edit_texture_free(&texture);
        return rc;
    }
    if (resume) {
        rc = take_autosave(autosave_path, in, &m, quiet);
        if (rc != EXIT_OK) {
            mesh_free(&m);
            edit_texture_free(&texture);
            return rc;
        }
        start = "input";
    }
    scaf_drag_t *d = NULL;
    edit_start_kind from;
    rc = edit_start_layout(in, &m, start, padding, seams, quiet, &d, &from);
    if (rc != EXIT_OK) {
        mesh_free(&m);
        edit_texture_free(&texture);
        return rc;
    }
    edit_api api;
    scaf_error err;
    err_clear(&err);
    scaf_status st = edit_api_init(&api, d, &m, in, &rinfo, out, padding, &err);
    api.autosave = autosave_path;
    if (resume) { /* the autosave is unsaved work, and it is what the file holds */
        api.changes = 1;
        api.autosaved_changes = 1;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf edit: %s\n", err.message);
        rc = exit_code_for(st);
    } else if (!make_token(api.token)) {
        fprintf(stderr, "scaf edit: cannot read /dev/urandom for the token\n");
        rc = EXIT_INTERNAL;
    } else {
        api.page = (const char *)edit_page_html;
        api.page_len = edit_page_html_len;
        api.tools_js = (const char *)edit_page_tools_js;
        api.tools_js_len = edit_page_tools_js_len;
        api.three_js = (const char *)edit_three_js;
        api.three_js_len = edit_three_js_len;
        api.texture = texture.data;
        api.texture_len = texture.len;
        api.texture_name = texture_path;
        api.texture_width = texture.width;
        api.texture_height = texture.height;
        rc = cli_signal_caught() ? EXIT_CANCELLED : serve(&api, port, quiet);
    }
    edit_api_free(&api);
    scaf_drag_destroy(d);
    mesh_free(&m);
    edit_texture_free(&texture);
    return rc;
}

/* SIGINT / SIGTERM: stop serving (tools/cli_signal) */
int cmd_edit(int argc, char **argv) { return cli_signal_run(edit_main, argc, argv); }
