/* tools/edit_server: the HTTP server of `scaf edit` (libmicrohttpd).
 *
 * Listens on 127.0.0.1 only (never another interface), on the given port
 * or, with port 0, on a free one the system picks. One internal thread
 * serves every connection in turn, so the handler runs for one request at
 * a time and needs no lock. The server reads each request's body (up to
 * EDIT_MAX_BODY bytes; a longer one is drained and flagged, never
 * stored), fills an edit_request, calls the handler and sends its
 * response with headers that keep the browser from caching or sniffing
 * it and from sending the URL (with its token) elsewhere.
 */
#ifndef SCAF_TOOLS_EDIT_SERVER_H
#define SCAF_TOOLS_EDIT_SERVER_H

#include "base/error.h"
#include "edit_http.h"

typedef void (*edit_handler_fn)(void *user, const edit_request *rq, edit_response *rs);

typedef struct edit_server {
    struct MHD_Daemon *daemon;
    int port; /* the port listened on */
    edit_handler_fn handler;
    void *user;
} edit_server;

/* Start serving on 127.0.0.1:port (0: any free port; s->port tells
 * which). SCAF_ERR_IO with the reason when the port cannot be bound. */
scaf_status edit_server_start(edit_server *s, int port, edit_handler_fn handler, void *user,
                              scaf_error *err);

/* Stop: closes the socket and waits for the request being served. */
void edit_server_stop(edit_server *s);

#endif
