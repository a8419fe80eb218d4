/* tools/edit_server: the HTTP server of `scaf edit` (see edit_server.h). */
#define _POSIX_C_SOURCE 200809L
#include "edit_server.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

/* One open connection: since when it owes a whole request. */
struct edit_connection {
    struct MHD_Connection *c;
    int fd;
    int owes;              /* waiting for a request (not being answered) */
    struct timespec since; /* opened, or its previous request answered */
    int cut;               /* shut down at the deadline already */
    edit_connection *prev, *next;
};

static long long ms_since(const struct timespec *t)
{
    struct timespec n;
    clock_gettime(CLOCK_MONOTONIC, &n);
    return (long long)(n.tv_sec - t->tv_sec) * 1000 + (n.tv_nsec - t->tv_nsec) / 1000000;
}

static void on_connection(void *cls, struct MHD_Connection *c, void **socket_context,
                          enum MHD_ConnectionNotificationCode toe)
{
    edit_server *s = cls;
    edit_connection *k = *socket_context;
    if (toe == MHD_CONNECTION_NOTIFY_STARTED) {
        k = calloc(1, sizeof *k);
        if (!k) return; /* untracked: the idle timeout still applies */
        const union MHD_ConnectionInfo *fd =
            MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD);
        k->c = c;
        k->fd = fd ? fd->connect_fd : -1;
        k->owes = 1;
        clock_gettime(CLOCK_MONOTONIC, &k->since);
        k->next = s->conns;
        if (s->conns) s->conns->prev = k;
        s->conns = k;
        *socket_context = k;
    } else if (k) { /* closed */
        if (k->prev) k->prev->next = k->next;
        else s->conns = k->next;
        if (k->next) k->next->prev = k->prev;
        free(k);
        *socket_context = NULL;
    }
}

static edit_connection *tracked(struct MHD_Connection *c)
{
    const union MHD_ConnectionInfo *i =
        MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    return i ? i->socket_context : NULL;
}

/* The body of one request, gathered over the access handler's calls. */
typedef struct upload {
    char *buf;
    size_t len;
    int too_large;
} upload;

static void request_done(void *cls, struct MHD_Connection *c, void **con_cls,
                         enum MHD_RequestTerminationCode why)
{
    (void)cls, (void)why;
    edit_connection *k = tracked(c);
    if (k) { /* the next request's time starts now */
        k->owes = 1;
        clock_gettime(CLOCK_MONOTONIC, &k->since);
    }
    upload *u = *con_cls;
    if (u) free(u->buf);
    free(u);
    *con_cls = NULL;
}

static enum MHD_Result send_response(struct MHD_Connection *c, const edit_response *rs)
{
    struct MHD_Response *r =
        MHD_create_response_from_buffer(rs->len, rs->body, MHD_RESPMEM_MUST_COPY);
    if (!r) return MHD_NO;
    MHD_add_response_header(r, "Content-Type", rs->content_type);
    MHD_add_response_header(r, "Cache-Control", "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "Referrer-Policy", "no-referrer");
    /* the page loads nothing from anywhere else: its inline script and
     * style, its two compiled-in scripts and the --texture image from this
     * server, requests to this server only */
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'none'; script-src 'self' 'unsafe-inline'; "
                            "style-src 'unsafe-inline'; connect-src 'self'; img-src 'self' data:; "
                            "frame-ancestors 'none'");
    enum MHD_Result ok = MHD_queue_response(c, (unsigned)rs->status, r);
    MHD_destroy_response(r);
    return ok;
}

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url,
                                  const char *method, const char *version, const char *upload_data,
                                  size_t *upload_data_size, void **con_cls)
{
    (void)version;
    edit_server *s = cls;
    upload *u = *con_cls;
    if (!u) { /* the headers: start gathering the body */
        u = calloc(1, sizeof *u);
        if (!u) return MHD_NO;
        const char *cl = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Content-Length");
        if (cl && strtoull(cl, NULL, 10) > EDIT_MAX_BODY) u->too_large = 1;
        *con_cls = u;
        return MHD_YES;
    }
    if (*upload_data_size) { /* a piece of the body */
        size_t n = *upload_data_size;
        *upload_data_size = 0;
        if (u->too_large || u->len + n > EDIT_MAX_BODY) {
            u->too_large = 1; /* drained, not kept */
            free(u->buf);
            u->buf = NULL;
            u->len = 0;
            return MHD_YES;
        }
        char *b = realloc(u->buf, u->len + n);
        if (!b) return MHD_NO;
        memcpy(b + u->len, upload_data, n);
        u->buf = b;
        u->len += n;
        return MHD_YES;
    }
    edit_connection *k = tracked(c);
    if (k) k->owes = 0; /* the whole request is in: no deadline while it runs */
    edit_request rq = {0};
    rq.method = method;
    rq.path = url;
    rq.token = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "X-Scaf-Token");
    if (!rq.token) rq.token = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "token");
    rq.origin = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Origin");
    rq.host = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Host");
    rq.body = u->buf ? u->buf : "";
    rq.body_len = u->len;
    rq.body_too_large = u->too_large;
    edit_response rs = {0};
    s->handler(s->user, &rq, &rs);
    enum MHD_Result ok = send_response(c, &rs);
    edit_response_free(&rs);
    return ok;
}

/* Shut down every connection past its deadline (the loop then sees it
 * closed and frees it); the milliseconds until the next deadline, or -1. */
static long long enforce_deadlines(edit_server *s)
{
    long long next = -1, limit = 1000LL * EDIT_REQUEST_DEADLINE_S;
    int open = 0;
    for (edit_connection *k = s->conns; k; k = k->next, open++) {
        if (!k->owes || k->cut || k->fd < 0) continue;
        long long left = limit - ms_since(&k->since);
        if (left <= 0) {
            shutdown(k->fd, SHUT_RDWR);
            k->cut = 1;
            s->shut_down++;
        } else if (next < 0 || left < next) {
            next = left;
        }
    }
    /* at the limit, a slot freed must be seen soon even if the library
     * did not put the listening socket back yet (belt and braces for the
     * second run in event_loop) */
    if (open >= EDIT_MAX_CONNECTIONS && (next < 0 || next > 200)) next = 200;
    return next;
}

static void *event_loop(void *user)
{
    edit_server *s = user;
    const union MHD_DaemonInfo *ep = MHD_get_daemon_info(s->daemon, MHD_DAEMON_INFO_EPOLL_FD);
    struct pollfd p[2] = {{ep ? ep->epoll_fd : -1, POLLIN, 0}, {s->wake[0], POLLIN, 0}};
    for (;;) {
        long long wait = enforce_deadlines(s);
        MHD_UNSIGNED_LONG_LONG t;
        if (MHD_get_timeout(s->daemon, &t) == MHD_YES && (wait < 0 || (long long)t < wait))
            wait = (long long)t;
        if (wait > 60000) wait = 60000;
        int n = poll(p, 2, (int)wait);
        if (n < 0 && errno != EINTR) break;
        if (p[1].revents) break; /* edit_server_stop */
        MHD_run(s->daemon);
        /* again at once: connections closed by the first run free slots
         * only at its end, and the listening socket, taken out of the
         * epoll set at the connection limit, goes back in only at the
         * start of a run (else new connections would wait in the
         * backlog with nothing to wake this loop) */
        MHD_run(s->daemon);
    }
    return NULL;
}

scaf_status edit_server_start(edit_server *s, int port, edit_handler_fn handler, void *user,
                              scaf_error *err)
{
    memset(s, 0, sizeof *s);
    s->handler = handler;
    s->user = user;
    s->wake[0] = s->wake[1] = -1;
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK); /* 127.0.0.1 only */
    if (pipe(s->wake) != 0)
        return err_set(err, SCAF_ERR_IO, "cannot start the HTTP server: %s", strerror(errno));
    for (int k = 0; k < 2; k++) fcntl(s->wake[k], F_SETFD, FD_CLOEXEC);
    errno = 0;
    s->daemon = MHD_start_daemon(
        MHD_USE_EPOLL, (uint16_t)port, NULL, NULL, on_request, s, MHD_OPTION_SOCK_ADDR,
        (struct sockaddr *)&addr, MHD_OPTION_NOTIFY_COMPLETED, request_done, NULL,
        MHD_OPTION_NOTIFY_CONNECTION, on_connection, s, MHD_OPTION_CONNECTION_TIMEOUT,
        (unsigned)EDIT_IDLE_TIMEOUT_S, MHD_OPTION_CONNECTION_LIMIT, (unsigned)EDIT_MAX_CONNECTIONS,
        MHD_OPTION_END);
    if (!s->daemon) {
        int e = errno;
        edit_server_stop(s);
        return err_set(err, SCAF_ERR_IO, "cannot listen on 127.0.0.1:%d: %s", port,
                       e ? strerror(e) : "the HTTP server did not start");
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(s->daemon, MHD_DAEMON_INFO_BIND_PORT);
    s->port = info ? info->port : port;
    if (pthread_create(&s->thread, NULL, event_loop, s) != 0) {
        edit_server_stop(s);
        return err_set(err, SCAF_ERR_IO, "cannot start the HTTP server's thread");
    }
    s->running = 1;
    return SCAF_OK;
}

void edit_server_stop(edit_server *s)
{
    if (s->running) {
        ssize_t r = write(s->wake[1], "", 1);
        (void)r;
        pthread_join(s->thread, NULL); /* after the request being served */
        s->running = 0;
    }
    if (s->daemon) MHD_stop_daemon(s->daemon);
    s->daemon = NULL;
    for (int k = 0; k < 2; k++) {
        if (s->wake[k] >= 0) close(s->wake[k]);
        s->wake[k] = -1;
    }
}
