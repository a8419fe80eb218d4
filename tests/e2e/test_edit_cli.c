/* `scaf edit` over real sockets (the browser test drives the page; this
 * one the HTTP server itself, tools/edit_server, and the command line):
 * the URL printed, the page served with its security headers, bodies over
 * the limit refused with 413 (Content-Length and chunked), wrong Host /
 * Origin / token refused, a refused request changes nothing, SIGINT and
 * SIGTERM stop the server with exit 0, a second server on a taken port and
 * bad command lines exit 2, a missing input 3. Work is never lost or
 * destroyed: a save after the input was moved, deleted or replaced still
 * writes (keeping the input's other lines, or saying what was dropped), a
 * save through a link to the input made after the start is refused (409),
 * unsaved changes go to the autosave (after a quiet second and on the
 * signal) and --resume continues from it, and connections that trickle
 * their request head do not keep the user's requests out. */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "support/support.h"

typedef struct server {
    pid_t pid;
    int port;
    char token[64];
    char err[512]; /* its standard error */
} server;

/* The server running, stopped by the teardown when a test fails. */
static pid_t running;

/* Start `scaf edit ARGS` and read the URL it prints (blocking: no sleep). */
static int start(server *s, const char *args)
{
    test_tmp_path("edit_cli_stderr.txt", s->err, sizeof s->err);
    int fd[2];
    if (pipe(fd) != 0) return 0;
    s->pid = fork();
    if (s->pid == 0) {
        dup2(fd[1], 1);
        close(fd[0]);
        close(fd[1]);
        char cmd[2048];
        snprintf(cmd, sizeof cmd, "exec %s edit %s 2> %s", SCAF_BINARY, args, s->err);
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    close(fd[1]);
    running = s->pid;
    FILE *f = fdopen(fd[0], "r");
    char line[256] = "";
    int ok = fgets(line, sizeof line, f) &&
        sscanf(line, "http://127.0.0.1:%d/?token=%63[0-9a-f]", &s->port, s->token) == 2 &&
        strlen(s->token) == 32;
    fclose(f);
    return ok;
}

/* Send sig and wait: the exit status (-1: not a normal exit). */
static int stop(server *s, int sig)
{
    kill(s->pid, sig);
    int st;
    pid_t w = waitpid(s->pid, &st, 0);
    running = 0;
    if (w != s->pid) return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* One HTTP exchange: send head (then body_len bytes of body, or of
 * spaces when body is NULL); the status, and the whole response in out. */
static int http(const server *s, const char *head, const char *body, size_t body_len, char *out,
                size_t size)
{
    int c = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)s->port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(c, (struct sockaddr *)&a, sizeof a) != 0) {
        close(c);
        return -1;
    }
    size_t n = strlen(head);
    if (write(c, head, n) != (ssize_t)n) return -1;
    char spaces[4096];
    memset(spaces, ' ', sizeof spaces);
    for (size_t sent = 0; sent < body_len;) {
        size_t k = body ? body_len - sent
                        : (body_len - sent < sizeof spaces ? body_len - sent : sizeof spaces);
        ssize_t w = write(c, body ? body + sent : spaces, k);
        if (w <= 0) break; /* the server may answer and close early */
        sent += (size_t)w;
    }
    size_t got = 0;
    ssize_t r;
    while (got + 1 < size && (r = read(c, out + got, size - 1 - got)) > 0) got += (size_t)r;
    out[got] = '\0';
    close(c);
    int status = -1;
    sscanf(out, "HTTP/1.1 %d", &status);
    return status;
}

/* GET path with the token, or POST json (Connection: close). */
static int request(const server *s, const char *method, const char *path, const char *token,
                   const char *extra, const char *json, char *out, size_t size)
{
    char head[1024];
    size_t len = json ? strlen(json) : 0;
    snprintf(head, sizeof head,
             "%s %s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n%s%s%s%sContent-Length: %zu\r\n"
             "Connection: close\r\n\r\n",
             method, path, s->port, token ? "X-Scaf-Token: " : "", token ? token : "",
             token ? "\r\n" : "", extra ? extra : "", len);
    return http(s, head, json, len, out, size);
}

static char atlas_path[512];

static int make_atlas(void **state)
{
    (void)state;
    char sphere[512];
    test_tmp_path("edit_cli_sphere.obj", sphere, sizeof sphere);
    test_tmp_path("edit_cli_atlas.obj", atlas_path, sizeof atlas_path);
    if (test_run("%s gen cubesphere --size 3 -o %s", SCAF_BINARY, sphere) != 0) return 1;
    return test_run("%s atlas %s -o %s --quiet", SCAF_BINARY, sphere, atlas_path) != 0;
}

static void serves_and_refuses(void **state)
{
    (void)state;
    char out[512], *resp = malloc(1 << 20);
    test_tmp_path("edit_cli_out.obj", out, sizeof out);
    remove(out);
    server s;
    char args[1200];
    snprintf(args, sizeof args, "%s -o %s", atlas_path, out);
    assert_true(start(&s, args));

    /* the page, with the headers that keep it to itself */
    char path[128];
    snprintf(path, sizeof path, "/?token=%s", s.token);
    assert_int_equal(request(&s, "GET", path, NULL, NULL, NULL, resp, 1 << 20), 200);
    assert_non_null(strstr(resp, "Content-Security-Policy: default-src 'none'"));
    assert_non_null(strstr(resp, "Referrer-Policy: no-referrer"));
    assert_non_null(strstr(resp, "<canvas id=\"view\">"));
    assert_int_equal(request(&s, "GET", "/", NULL, NULL, NULL, resp, 1 << 20), 403);

    char before[1 << 14], after[1 << 14];
    assert_int_equal(request(&s, "GET", "/api/state", s.token, NULL, NULL, resp, 1 << 20), 200);
    snprintf(before, sizeof before, "%s", strstr(resp, "\r\n\r\n"));

    /* refused: each a 4xx */
    assert_int_equal(request(&s, "POST", "/api/drag", "nope", NULL, "{\"chart\": 0, \"dx\": 0.1}",
                             resp, 1 << 20),
                     403);
    assert_int_equal(request(&s, "POST", "/api/drag", s.token, "Origin: http://evil.example\r\n",
                             "{\"chart\": 0, \"dx\": 0.1}", resp, 1 << 20),
                     403);
    assert_int_equal(
        request(&s, "POST", "/api/drag", s.token, NULL, "{\"chart\": 0, \"dx\": }", resp, 1 << 20),
        400);
    assert_int_equal(
        request(&s, "POST", "/api/drag", s.token, NULL, "{\"chart\": 6}", resp, 1 << 20), 400);
    char head[512];
    snprintf(head, sizeof head,
             "POST /api/drag HTTP/1.1\r\nHost: evil.example:%d\r\nX-Scaf-Token: %s\r\n"
             "Content-Length: 2\r\nConnection: close\r\n\r\n",
             s.port, s.token);
    assert_int_equal(http(&s, head, "{}", 2, resp, 1 << 20), 403);
    /* a body over 16 KiB: by Content-Length, and chunked (no length) */
    snprintf(head, sizeof head,
             "POST /api/drag HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Scaf-Token: %s\r\n"
             "Content-Length: 100000\r\nConnection: close\r\n\r\n",
             s.port, s.token);
    assert_int_equal(http(&s, head, NULL, 100000, resp, 1 << 20), 413);
    snprintf(head, sizeof head,
             "POST /api/drag HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Scaf-Token: %s\r\n"
             "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n",
             s.port, s.token);
    static char chunks[3 * (8200 + 16) + 8];
    size_t n = 0;
    for (int i = 0; i < 3; i++) {
        n += (size_t)sprintf(chunks + n, "2000\r\n");
        memset(chunks + n, ' ', 0x2000);
        n += 0x2000;
        n += (size_t)sprintf(chunks + n, "\r\n");
    }
    n += (size_t)sprintf(chunks + n, "0\r\n\r\n");
    assert_int_equal(http(&s, head, chunks, n, resp, 1 << 20), 413);

    /* nothing changed */
    assert_int_equal(request(&s, "GET", "/api/state", s.token, NULL, NULL, resp, 1 << 20), 200);
    snprintf(after, sizeof after, "%s", strstr(resp, "\r\n\r\n"));
    assert_string_equal(before, after);
    assert_false(test_exists(out));

    /* a second server on the same port: exit 2, the first unharmed */
    char args2[1300];
    snprintf(args2, sizeof args2, "%s -o %s --port %d --quiet", atlas_path, out, s.port);
    assert_int_equal(test_run("%s edit %s > /dev/null 2>&1", SCAF_BINARY, args2), 2);
    /* a drag, a save */
    assert_int_equal(request(&s, "POST", "/api/drag", s.token, NULL,
                             "{\"chart\": 0, \"dx\": 0.1, \"dy\": 0, \"angle\": 0, \"steps\": 3}",
                             resp, 1 << 20),
                     200);
    assert_int_equal(request(&s, "POST", "/api/save", s.token, NULL, "{}", resp, 1 << 20), 200);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);

    assert_int_equal(stop(&s, SIGINT), 0);
    char *err = test_slurp(s.err);
    assert_non_null(err);
    assert_non_null(strstr(err, "stopped by SIGINT; 1 save(s)"));
    free(err);
    free(resp);
    remove(out);
}

static void sigterm_stops(void **state)
{
    (void)state;
    char out[512], args[1200];
    test_tmp_path("edit_cli_out2.obj", out, sizeof out);
    snprintf(args, sizeof args, "%s -o %s", atlas_path, out);
    server s;
    assert_true(start(&s, args));
    assert_int_equal(stop(&s, SIGTERM), 0);
    char *err = test_slurp(s.err);
    assert_non_null(strstr(err, "stopped by SIGTERM"));
    free(err);
    assert_false(test_exists(out));
}

/* Input UVs that overlap (two triangles on the same spot) are not a start:
 * `auto` says why and starts from the atlas; --start input refuses (4). */
static void overlapping_uvs_start_from_the_atlas(void **state)
{
    (void)state;
    char in[512], out[512], args[1200];
    test_tmp_path("edit_cli_overlap.obj", in, sizeof in);
    test_tmp_path("edit_cli_overlap_out.obj", out, sizeof out);
    FILE *f = fopen(in, "w");
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 3 0 0\nv 4 0 0\nv 3 1 0\n"
          "vt 0 0\nvt 1 0\nvt 0 1\n"
          "f 1/1 2/2 3/3\nf 4/1 5/2 6/3\n",
          f);
    fclose(f);
    server s;
    snprintf(args, sizeof args, "%s -o %s", in, out);
    assert_true(start(&s, args));
    assert_int_equal(stop(&s, SIGTERM), 0);
    char *err = test_slurp(s.err);
    assert_non_null(strstr(err, "not starting from its UVs"));
    assert_non_null(strstr(err, "2 charts, starting from the atlas"));
    free(err);
    assert_int_equal(test_run("%s edit %s -o %s --start input 2> /dev/null", SCAF_BINARY, in, out),
                     4);
}

/* A closed mesh without vt starts from the atlas `scaf atlas` makes:
 * automatic charts, cut open. */
static void closed_mesh_starts_from_the_atlas(void **state)
{
    (void)state;
    char in[512], out[512], args[1200];
    test_tmp_path("edit_cli_ball.obj", in, sizeof in);
    test_tmp_path("edit_cli_ball_out.obj", out, sizeof out);
    assert_int_equal(test_run("%s gen icosphere --size 3 -o %s", SCAF_BINARY, in), 0);
    server s;
    snprintf(args, sizeof args, "%s -o %s", in, out);
    assert_true(start(&s, args));
    assert_int_equal(stop(&s, SIGTERM), 0);
    char *err = test_slurp(s.err);
    assert_non_null(strstr(err, "starting from the atlas"));
    free(err);
    /* the components as they are: refused, naming the chart */
    assert_int_equal(test_run("%s edit %s -o %s --seams input 2> /dev/null", SCAF_BINARY, in, out),
                     4);
}

static void bad_command_lines(void **state)
{
    (void)state;
    char missing[512];
    test_tmp_path("edit_cli_missing.obj", missing, sizeof missing);
    remove(missing);
    assert_int_equal(test_run("%s edit 2> /dev/null", SCAF_BINARY), 2);
    assert_int_equal(test_run("%s edit %s --port 65536 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    assert_int_equal(test_run("%s edit %s --port x 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    assert_int_equal(test_run("%s edit %s --start nope 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    assert_int_equal(test_run("%s edit %s -o - 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    assert_int_equal(test_run("%s edit %s -o %s 2> /dev/null", SCAF_BINARY, atlas_path, atlas_path),
                     2);
    assert_int_equal(test_run("%s edit %s -o x.ply 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    assert_int_equal(test_run("%s edit %s 2> /dev/null", SCAF_BINARY, missing), 3);
    assert_int_equal(test_run("%s edit --help | grep -q 'Exit status:'", SCAF_BINARY), 0);
    /* --texture: read and checked before the start; 3 naming the file */
    char notpng[512], err[512];
    test_tmp_path("edit_cli_notpng.png", notpng, sizeof notpng);
    test_tmp_path("edit_cli_texture_err.txt", err, sizeof err);
    FILE *f = fopen(notpng, "w");
    assert_non_null(f);
    fputs("GIF89a, not a PNG\n", f);
    fclose(f);
    assert_int_equal(
        test_run("%s edit %s --texture %s 2> %s", SCAF_BINARY, atlas_path, notpng, err), 3);
    assert_int_equal(test_run("grep -q 'texture .*edit_cli_notpng.png: not a PNG' %s", err), 0);
    assert_int_equal(
        test_run("%s edit %s --texture %s 2> %s", SCAF_BINARY, atlas_path, missing, err), 3);
    assert_int_equal(test_run("grep -q 'cannot open it' %s", err), 0);
    assert_int_equal(test_run("%s edit %s --texture 2> /dev/null", SCAF_BINARY, atlas_path), 2);
    remove(notpng);
    remove(err);
}

/* POST path json with the token: the status; body (may be NULL) gets the
 * response's body. */
static int post(const server *s, const char *path, const char *json, char *body, size_t size)
{
    static char resp[1 << 20];
    int st = request(s, "POST", path, s->token, NULL, json, resp, sizeof resp);
    if (body) {
        const char *b = strstr(resp, "\r\n\r\n");
        snprintf(body, size, "%s", b ? b + 4 : "");
    }
    return st;
}

static const char *drag_json = "{\"chart\": 0, \"dx\": 0.05, \"dy\": 0, \"angle\": 0, \"steps\": "
                               "2}";

/* The atlas with a line of the user's own at the end, as path. */
static void user_input(const char *path)
{
    char *text = test_slurp(atlas_path);
    assert_non_null(text);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fputs("# a line of the user's\n", f);
    fclose(f);
    free(text);
}

static int file_has(const char *path, const char *needle)
{
    char *t = test_slurp(path);
    int yes = t && strstr(t, needle);
    free(t);
    return yes;
}

/* The input moved, deleted, replaced by a folder, or rewritten in place:
 * save still writes the layout; the input's other lines are kept when the
 * file the editor opened can still be read as the mesh, else the note says
 * what was dropped. */
static void save_after_the_input_is_gone(void **state)
{
    (void)state;
    char in[512], out[512], args[1200], body[4096];
    test_tmp_path("edit_gone_in.obj", in, sizeof in);
    test_tmp_path("edit_gone_out.obj", out, sizeof out);
    remove(out);
    user_input(in);
    server s;
    snprintf(args, sizeof args, "%s -o %s", in, out);
    assert_true(start(&s, args));
    assert_int_equal(post(&s, "/api/drag", drag_json, NULL, 0), 200);

    /* moved away: the file the editor opened is read */
    char moved[600];
    snprintf(moved, sizeof moved, "%s.moved", in);
    assert_int_equal(rename(in, moved), 0);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 200);
    assert_null(strstr(body, "\"note\""));
    assert_true(file_has(out, "# a line of the user's"));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    /* deleted, and a folder in its place */
    assert_int_equal(remove(moved), 0);
    assert_int_equal(mkdir(in, 0700), 0);
    remove(out);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 200);
    assert_true(file_has(out, "# a line of the user's"));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    assert_int_equal(stop(&s, SIGTERM), 0);
    rmdir(in);

    /* rewritten in place (the same file, another mesh): a plain OBJ, and
     * the note says so */
    user_input(in);
    remove(out);
    assert_true(start(&s, args));
    FILE *f = fopen(in, "w"); /* truncates the file the editor holds */
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", f);
    fclose(f);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 200);
    assert_non_null(strstr(body, "\"note\": \"wrote a plain OBJ without the normals"));
    assert_false(file_has(out, "# a line of the user's"));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    assert_int_equal(stop(&s, SIGTERM), 0);
    remove(in);
    remove(out);
}

/* After the start, the output becomes a symbolic link to the input, a hard
 * link of it, or a link to where the input was moved: save refuses (409)
 * and the input stays as it was. */
static void save_refuses_a_link_to_the_input(void **state)
{
    (void)state;
    char in[512], out[512], args[1200], body[4096], aside[600], moved[600];
    test_tmp_path("edit_link_in.obj", in, sizeof in);
    test_tmp_path("edit_link_out.obj", out, sizeof out);
    snprintf(aside, sizeof aside, "%s.aside", out);
    snprintf(moved, sizeof moved, "%s.moved", in);
    remove(out);
    user_input(in);
    char *original = test_slurp(in);
    server s;
    snprintf(args, sizeof args, "%s -o %s", in, out);
    assert_true(start(&s, args));
    assert_int_equal(post(&s, "/api/drag", drag_json, NULL, 0), 200);
    assert_int_equal(post(&s, "/api/save", "{}", NULL, 0), 200);

    assert_int_equal(rename(out, aside), 0);
    assert_int_equal(symlink(in, out), 0);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 409);
    assert_non_null(strstr(body, "the same file"));
    remove(out);
    assert_int_equal(link(in, out), 0);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 409);
    remove(out);
    assert_int_equal(rename(in, moved), 0);
    assert_int_equal(symlink(moved, out), 0);
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 409);
    assert_non_null(strstr(body, "names the input file"));
    char *now = test_slurp(moved);
    assert_string_equal(now, original);
    free(now);
    /* the link gone: saves again */
    remove(out);
    assert_int_equal(post(&s, "/api/save", "{}", NULL, 0), 200);
    assert_int_equal(stop(&s, SIGTERM), 0);
    free(original);
    remove(moved);
    remove(out);
    remove(aside);
}

/* Block until `name` appears in dir by a rename or a close after writing
 * (inotify: no polling); 1, or 0 when nothing came for 60 s. */
static int wait_for_file(int in, const char *path)
{
    const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
    for (;;) {
        struct pollfd p = {in, POLLIN, 0};
        if (poll(&p, 1, 60000) <= 0) return 0;
        ssize_t n = read(in, buf, sizeof buf);
        if (n <= 0) return 0;
        for (char *q = buf; q < buf + n;) {
            struct inotify_event *e = (struct inotify_event *)q;
            if (e->len && !strcmp(e->name, name)) return 1;
            q += sizeof *e + e->len;
        }
    }
}

/* Unsaved changes: the state says so; the autosave beside the output is
 * written after a quiet second and on the signal; a new session refuses
 * to start over it, --resume starts from it; a save removes it. */
static void autosave_and_resume(void **state)
{
    (void)state;
    char in[512], out[512], autosave[512], args[1200], body[1 << 14], dir[512];
    test_tmp_path("edit_auto_in.obj", in, sizeof in);
    test_tmp_path("edit_auto_out.obj", out, sizeof out);
    test_tmp_path("edit_auto_out.autosave.obj", autosave, sizeof autosave);
    remove(out);
    remove(autosave);
    user_input(in);
    snprintf(dir, sizeof dir, "%s", autosave);
    *strrchr(dir, '/') = '\0';
    int watch = inotify_init1(IN_CLOEXEC);
    assert_true(watch >= 0);
    assert_true(inotify_add_watch(watch, dir, IN_MOVED_TO | IN_CLOSE_WRITE) >= 0);

    server s;
    snprintf(args, sizeof args, "%s -o %s", in, out);
    assert_true(start(&s, args));
    assert_int_equal(request(&s, "GET", "/api/state", s.token, NULL, NULL, body, sizeof body), 200);
    assert_non_null(strstr(body, "\"unsaved\": false"));
    assert_int_equal(post(&s, "/api/drag", drag_json, body, sizeof body), 200);
    assert_non_null(strstr(body, "\"unsaved\": true"));
    /* a quiet second later */
    assert_true(wait_for_file(watch, autosave));
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, autosave), 0);
    char *first = test_slurp(autosave);
    /* one more change, then the signal at once: the autosave has it */
    assert_int_equal(post(&s, "/api/drag", drag_json, NULL, 0), 200);
    assert_int_equal(stop(&s, SIGTERM), 0);
    char *last = test_slurp(autosave);
    assert_non_null(last);
    assert_string_not_equal(first, last);
    free(first);
    free(last);
    assert_false(test_exists(out));
    char *err = test_slurp(s.err);
    assert_non_null(strstr(err, "--resume` continues from them"));
    free(err);

    /* unsaved edits are never overwritten by a new session */
    assert_int_equal(test_run("%s edit %s 2> /dev/null", SCAF_BINARY, args), 2);
    char resume[1300];
    snprintf(resume, sizeof resume, "%s --resume", args);
    assert_true(start(&s, resume));
    assert_int_equal(request(&s, "GET", "/api/state", s.token, NULL, NULL, body, sizeof body), 200);
    assert_non_null(strstr(body, "\"unsaved\": true"));
    assert_int_equal(post(&s, "/api/save", "{}", body, sizeof body), 200);
    assert_non_null(strstr(body, "\"unsaved\": false"));
    assert_false(test_exists(autosave));
    assert_true(file_has(out, "# a line of the user's"));
    /* nothing unsaved: no autosave at the end */
    assert_int_equal(stop(&s, SIGINT), 0);
    assert_false(test_exists(autosave));
    assert_int_equal(test_run("%s edit %s 2> /dev/null", SCAF_BINARY, resume), 3);
    close(watch);
    remove(in);
    remove(out);
}

/* -o NAME.obj.gz: save writes gzip (the flag was never set before). */
static void save_gzips_an_obj_gz_output(void **state)
{
    (void)state;
    char out[512], args[1200];
    test_tmp_path("edit_gz_out.obj.gz", out, sizeof out);
    remove(out);
    server s;
    snprintf(args, sizeof args, "%s -o %s", atlas_path, out);
    assert_true(start(&s, args));
    assert_int_equal(post(&s, "/api/save", "{}", NULL, 0), 200);
    assert_int_equal(stop(&s, SIGTERM), 0);
    FILE *f = fopen(out, "rb");
    assert_non_null(f);
    unsigned char magic[2] = {0, 0};
    assert_int_equal(fread(magic, 1, 2, f), 2);
    fclose(f);
    assert_int_equal(magic[0], 0x1f);
    assert_int_equal(magic[1], 0x8b);
    assert_int_equal(test_run("%s check %s > /dev/null", SCAF_BINARY, out), 0);
    remove(out);
}

static double energy_of(const char *json)
{
    const char *e = strstr(json, "\"energy\": ");
    return e ? strtod(e + 10, NULL) : -1.0;
}

/* compact with 1000 steps on a fresh cube-sphere: E stays within 1.05
 * times its value at the click (the rule of `scaf atlas`; without it E
 * went from 4.61 to 1468). */
static void compact_keeps_the_distortion_limit(void **state)
{
    (void)state;
    char sphere[512], out[512], args[1200], body[1 << 16];
    test_tmp_path("edit_cli_sphere.obj", sphere, sizeof sphere);
    test_tmp_path("edit_compact_out.obj", out, sizeof out);
    server s;
    snprintf(args, sizeof args, "%s -o %s", sphere, out);
    assert_true(start(&s, args));
    assert_int_equal(request(&s, "GET", "/api/state", s.token, NULL, NULL, body, sizeof body), 200);
    double e0 = energy_of(body);
    assert_true(e0 >= 4.0);
    assert_int_equal(post(&s, "/api/compact", "{\"steps\": 1000}", body, sizeof body), 200);
    double e1 = energy_of(body);
    assert_true(e1 >= 4.0);
    assert_true(e1 <= 1.05 * e0);
    assert_int_equal(stop(&s, SIGTERM), 0);
    char autosave[512];
    test_tmp_path("edit_compact_out.autosave.obj", autosave, sizeof autosave);
    remove(autosave);
}

/* 80 connections that send a header line every second hold every slot of
 * the server; the user's request is answered while they go on trickling
 * (each connection has a few seconds for its whole request). The trickle
 * is bounded (30 lines): on a server without the deadline the user waits
 * the whole trickle and the test fails. */
static void slow_clients_do_not_lock_the_user_out(void **state)
{
    (void)state;
    char out[512], args[1200];
    test_tmp_path("edit_slow_out.obj", out, sizeof out);
    server s;
    snprintf(args, sizeof args, "%s -o %s", atlas_path, out);
    assert_true(start(&s, args));
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)s.port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    enum { N = 80 };
    int slow[N];
    for (int i = 0; i < N; i++) {
        slow[i] = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
        assert_true(slow[i] >= 0);
        /* nonblocking: past the server's limit connects wait in the backlog */
        connect(slow[i], (struct sockaddr *)&a, sizeof a);
    }
    int user = socket(AF_INET, SOCK_STREAM, 0);
    assert_int_equal(connect(user, (struct sockaddr *)&a, sizeof a), 0);
    char head[512];
    int n = snprintf(head, sizeof head,
                     "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Scaf-Token: %s\r\n"
                     "Connection: close\r\n\r\n",
                     s.port, s.token);
    for (int i = 0; i < N; i++) {
        ssize_t w = write(slow[i], "GET / HTTP/1.1\r\n", 16);
        (void)w;
    }
    assert_int_equal(write(user, head, (size_t)n), n);
    int answered = 0;
    for (int line = 0; line < 30 && !answered; line++) {
        /* a second between two lines of the trickle, or the answer */
        struct pollfd p = {user, POLLIN, 0};
        if (poll(&p, 1, 1000) == 1) {
            answered = 1;
            break;
        }
        for (int i = 0; i < N; i++) {
            ssize_t w = send(slow[i], "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);
            (void)w;
        }
    }
    assert_true(answered);
    char resp[256] = "";
    ssize_t r = read(user, resp, sizeof resp - 1);
    assert_true(r > 0);
    assert_int_equal(strncmp(resp, "HTTP/1.1 200", 12), 0);
    close(user);
    for (int i = 0; i < N; i++) close(slow[i]);
    assert_int_equal(stop(&s, SIGTERM), 0);
}

static int stop_running(void **state)
{
    (void)state;
    if (running > 0) {
        kill(running, SIGKILL);
        waitpid(running, NULL, 0);
        running = 0;
    }
    return 0;
}

int main(void)
{
    signal(SIGPIPE, SIG_IGN); /* a server closing early is an answer, not a crash */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(serves_and_refuses, stop_running),
        cmocka_unit_test_teardown(sigterm_stops, stop_running),
        cmocka_unit_test_teardown(overlapping_uvs_start_from_the_atlas, stop_running),
        cmocka_unit_test_teardown(closed_mesh_starts_from_the_atlas, stop_running),
        cmocka_unit_test(bad_command_lines),
        cmocka_unit_test_teardown(save_after_the_input_is_gone, stop_running),
        cmocka_unit_test_teardown(save_refuses_a_link_to_the_input, stop_running),
        cmocka_unit_test_teardown(autosave_and_resume, stop_running),
        cmocka_unit_test_teardown(slow_clients_do_not_lock_the_user_out, stop_running),
        cmocka_unit_test_teardown(compact_keeps_the_distortion_limit, stop_running),
        cmocka_unit_test_teardown(save_gzips_an_obj_gz_output, stop_running),
    };
    return cmocka_run_group_tests(tests, make_atlas, NULL);
}
