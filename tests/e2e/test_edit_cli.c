/* `scaf edit` over real sockets (the browser test drives the page; this
 * one the HTTP server itself, tools/edit_server, and the command line):
 * the URL printed, the page served with its security headers, bodies over
 * the limit refused with 413 (Content-Length and chunked), wrong Host /
 * Origin / token refused, a refused request changes nothing, SIGINT and
 * SIGTERM stop the server with exit 0, a second server on a taken port and
 * bad command lines exit 2, a missing input 3. */
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
#include <sys/socket.h>
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
    };
    return cmocka_run_group_tests(tests, make_atlas, NULL);
}
