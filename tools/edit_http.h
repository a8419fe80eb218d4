/* tools/edit_http: one HTTP request and its response, as `scaf edit`'s
 * request handler (tools/edit_api) sees them: plain data, no sockets, so
 * the handler is tested without a server (tests/tools/test_edit_api.c)
 * and the server (tools/edit_server, libmicrohttpd) only copies fields in
 * and out. */
#ifndef SCAF_TOOLS_EDIT_HTTP_H
#define SCAF_TOOLS_EDIT_HTTP_H

#include <stddef.h>

/* The largest request body the editor reads; a longer one is answered 413
 * without being looked at (every request of the page is a few hundred
 * bytes). */
#define EDIT_MAX_BODY 16384

typedef struct edit_request {
    const char *method; /* "GET", "POST", ... */
    const char *path;   /* the URL's path, without the query */
    const char *token;  /* the X-Scaf-Token header, else the "token" query
                             argument; NULL when neither */
    const char *origin; /* the Origin header, NULL when absent */
    const char *host;   /* the Host header, NULL when absent */
    const char *body;   /* body_len bytes, not NUL-terminated */
    size_t body_len;
    int body_too_large; /* the body exceeded EDIT_MAX_BODY (not kept) */
} edit_request;

typedef struct edit_response {
    int status;               /* 200, 400, ... */
    const char *content_type; /* static string */
    char *body;               /* len bytes */
    size_t len;
    int body_static; /* 1: body is not to be freed (the page) */
} edit_response;

/* Free the body of a response (unless static) and clear it. */
void edit_response_free(edit_response *rs);

#endif
