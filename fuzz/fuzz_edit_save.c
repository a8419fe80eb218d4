/* fuzz/fuzz_edit_save: libFuzzer target for the save path of `scaf edit`
 * (tools/edit_api: the request handler the server calls), in-process, on
 * the sample cube-sphere's atlas (the drag context is made once; requests
 * change it).
 *
 *   byte 0     what happens to the files before the requests (% 8): nothing;
 *              the input deleted; a folder in its place; the input
 *              rewritten in place with the rest of the data as its text
 *              (random OBJ text through the save's rewrite); the output a
 *              symbolic link to the input; a hard link of it; the input
 *              moved and the output a link to where it went; the output
 *              a folder
 *   then       requests separated by 0xFF: one byte picks the route
 *              (mostly POST /api/save; also drag, compact, undo, grab,
 *              release, state) and the rest is the JSON body as given
 *
 * Whatever the input, the handler must never crash, hang or leak; answer
 * 200, 400, 409 (nothing to undo, or an output that names the input) or
 * 500 with a JSON body; never write the input file (its bytes, wherever
 * it went, stay as they were unless the fuzzer rewrote it on purpose); a
 * save answered 200 leaves an output that reads back as the mesh with UVs
 * (the layout was certified before writing) and no temporary file.
 * Anything else aborts.
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "edit_api.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"
#include "scaf/drag.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define TOKEN "0123456789abcdef0123456789abcdef"
#define PORT 8123

static char dir[256];
static mesh m;
static scaf_drag_t *drag;
static char *input_text; /* the input file as written at every run */

static void path_of(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

/* Empty the scratch folder (files and folders one level deep). */
static void clear_dir(void)
{
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    char p[512];
    while ((e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        path_of(p, sizeof p, e->d_name);
        if (remove(p) != 0) rmdir(p);
    }
    closedir(d);
}

static void remove_scratch(void)
{
    clear_dir();
    rmdir(dir);
    scaf_drag_destroy(drag);
    mesh_free(&m);
    free(input_text);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/scaf_fuzz_edit_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(dir)) abort();
    scaf_error err;
    err_clear(&err);
    mesh one;
    if (mesh_sample_make("cubesphere", 1, &one, &err) != SCAF_OK) abort();
    m = one;
    scaf_drag_options_t opt = scaf_drag_options_default();
    opt.start = SCAF_DRAG_START_INPUT; /* the sample's UVs: its seams and layout */
    drag = scaf_drag_new(&opt);
    if (!drag || scaf_drag_set_mesh(drag, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT) != SCAF_OK)
        abort();
    /* the input: the mesh as an OBJ with a line of the user's */
    char p[512];
    path_of(p, sizeof p, "in.obj");
    mesh plain = m;
    plain.nuv = 0;
    plain.UV = NULL;
    plain.FT = NULL;
    if (mesh_write_obj(p, &plain, &err) != SCAF_OK) abort();
    FILE *f = fopen(p, "a");
    if (!f) abort();
    fputs("# a line of the user's\n", f);
    fclose(f);
    f = fopen(p, "rb");
    if (!f) abort();
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    input_text = calloc((size_t)n + 1, 1);
    if (!input_text || fread(input_text, 1, (size_t)n, f) != (size_t)n) abort();
    fclose(f);
    atexit(remove_scratch);
    return 0;
}

static int same_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    size_t n = strlen(text);
    char *b = malloc(n + 2);
    size_t got = b ? fread(b, 1, n + 1, f) : 0;
    fclose(f);
    int same = b && got == n && memcmp(b, text, n) == 0;
    free(b);
    return same;
}

/* No hidden temporary file (".NAME.tmpXXXXXX") left in the folder. */
static int temporaries_left(void)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    struct dirent *e;
    int left = 0;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] == '.' && strstr(e->d_name, ".tmp")) left = 1;
    closedir(d);
    return left;
}

static const char *const routes[][2] = {{"POST", "/api/save"},    {"POST", "/api/save"},
                                        {"POST", "/api/save"},    {"POST", "/api/drag"},
                                        {"POST", "/api/grab"},    {"POST", "/api/release"},
                                        {"POST", "/api/compact"}, {"POST", "/api/undo"},
                                        {"GET", "/api/state"},    {"POST", "/api/optimize"}};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    clear_dir();
    char in[512], out[512], moved[512];
    path_of(in, sizeof in, "in.obj");
    path_of(out, sizeof out, "out.obj");
    path_of(moved, sizeof moved, "moved.obj");
    FILE *f = fopen(in, "wb");
    if (!f) abort();
    fputs(input_text, f);
    fclose(f);
    mesh_read_info rinfo;
    memset(&rinfo, 0, sizeof rinfo);
    rinfo.format = MESH_FORMAT_OBJ;
    edit_api api;
    scaf_error err;
    err_clear(&err);
    if (edit_api_init(&api, drag, &m, in, &rinfo, out, scaf_drag_options_default().padding, &err) !=
        SCAF_OK)
        abort();
    strcpy(api.token, TOKEN);
    api.port = PORT;
    api.page = "";
    api.page_len = 0;

    size_t at = 0;
    unsigned action = size ? data[at++] % 8 : 0;
    const char *input_now = in; /* where the input's bytes are */
    const char *expect = input_text;
    char *rewritten = NULL;
    switch (action) {
    case 1:
        remove(in);
        input_now = NULL;
        break;
    case 2:
        remove(in);
        if (mkdir(in, 0700) != 0) abort();
        input_now = NULL;
        break;
    case 3: /* the rest of the data is the new text (and no request) */
        rewritten = calloc(size - at + 1, 1);
        if (!rewritten) abort();
        memcpy(rewritten, data + at, size - at);
        f = fopen(in, "wb");
        if (!f) abort();
        fwrite(data + at, 1, size - at, f);
        fclose(f);
        expect = NULL; /* its text may hold NULs: checked by length below */
        at = size;
        break;
    case 4:
        if (symlink(in, out) != 0) abort();
        break;
    case 5:
        if (link(in, out) != 0) abort();
        break;
    case 6:
        if (rename(in, moved) != 0 || symlink(moved, out) != 0) abort();
        input_now = moved;
        break;
    case 7:
        if (mkdir(out, 0700) != 0) abort();
        break;
    }
    int links = action >= 4 && action <= 6;
    int requests = 0;
    /* action 3: one save of the rewritten input */
    do {
        size_t end = at;
        while (end < size && data[end] != 0xFF) end++;
        unsigned r = at < end ? data[at] : 0;
        const char *const *route = routes[action == 3 ? 0 : r % (sizeof routes / sizeof routes[0])];
        const char *body = at < end ? (const char *)data + at + 1 : "{}";
        size_t body_len = at < end ? end - at - 1 : 2;
        edit_request rq = {route[0], route[1], TOKEN, NULL, "127.0.0.1:8123", body, body_len, 0};
        edit_response rs;
        edit_api_handle(&api, &rq, &rs);
        int save = !strcmp(route[1], "/api/save");
        int ok_status =
            rs.status == 200 || rs.status == 400 || rs.status == 409 || rs.status == 500;
        if (!ok_status || !rs.body || rs.len == 0 || rs.body[0] != '{') abort();
        if (save && links && rs.status == 200) abort(); /* wrote through to the input */
        if (save && rs.status == 200) {
            mesh back;
            scaf_error e2;
            err_clear(&e2);
            if (mesh_read(out, &back, NULL, &e2) != SCAF_OK) abort();
            if (back.nf != m.nf || back.nuv == 0) abort();
            mesh_free(&back);
        }
        edit_response_free(&rs);
        at = end + 1;
        requests++;
    } while (at < size && requests < 8);
    if (input_now && expect && !same_text(input_now, expect)) abort();
    if (rewritten) {
        struct stat st;
        if (stat(in, &st) != 0 || (size_t)st.st_size != size - 1) abort();
    }
    if (temporaries_left()) abort();
    free(rewritten);
    edit_api_free(&api);
    return 0;
}
