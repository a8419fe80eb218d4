/* tools/edit_server: the HTTP server of `scaf edit` (see edit_server.h). */
#include "edit_server.h"

#include <arpa/inet.h>
#include <errno.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>

/* The body of one request, gathered over the access handler's calls. */
typedef struct upload {
    char *buf;
    size_t len;
    int too_large;
} upload;

static void request_done(void *cls, struct MHD_Connection *c, void **con_cls,
                         enum MHD_RequestTerminationCode why)
{
    (void)cls, (void)c, (void)why;
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
    /* the page loads nothing from anywhere: its own inline script and
     * style, requests to this server only */
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'none'; script-src 'unsafe-inline'; "
                            "style-src 'unsafe-inline'; connect-src 'self'; img-src data:; "
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

scaf_status edit_server_start(edit_server *s, int port, edit_handler_fn handler, void *user,
                              scaf_error *err)
{
    s->handler = handler;
    s->user = user;
    s->port = 0;
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK); /* 127.0.0.1 only */
    errno = 0;
    s->daemon = MHD_start_daemon(
        MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_POLL, (uint16_t)port, NULL, NULL, on_request, s,
        MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr, MHD_OPTION_NOTIFY_COMPLETED, request_done,
        NULL, MHD_OPTION_CONNECTION_TIMEOUT, 30u, MHD_OPTION_CONNECTION_LIMIT, 64u, MHD_OPTION_END);
    if (!s->daemon)
        return err_set(err, SCAF_ERR_IO, "cannot listen on 127.0.0.1:%d: %s", port,
                       errno ? strerror(errno) : "the HTTP server did not start");
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(s->daemon, MHD_DAEMON_INFO_BIND_PORT);
    s->port = info ? info->port : port;
    return SCAF_OK;
}

void edit_server_stop(edit_server *s)
{
    if (s->daemon) MHD_stop_daemon(s->daemon);
    s->daemon = NULL;
}
