/* tools/edit_server: the HTTP server of `scaf edit` (libmicrohttpd).
 *
 * Listens on 127.0.0.1 only (never another interface), on the given port
 * or, with port 0, on a free one the system picks. One thread of its own
 * (libmicrohttpd's event loop driven by epoll) serves every connection in
 * turn, so the handler runs for one request at a time and needs no lock.
 *
 * Slow clients cannot lock the user out: every connection has
 * EDIT_REQUEST_DEADLINE_S seconds, from its opening or from the end of
 * its previous request, to deliver a whole request (head and body);
 * after that it is shut down, whether or not bytes still trickle in (the
 * library's own timeout only counts silence). So connections that send a
 * header line every few seconds hold the EDIT_MAX_CONNECTIONS slots for
 * a few seconds at most, and the page's requests, queued by the system
 * meanwhile, are then served. The server reads each request's body (up to
 * EDIT_MAX_BODY bytes; a longer one is drained and flagged, never
 * stored), fills an edit_request, calls the handler and sends its
 * response with headers that keep the browser from caching or sniffing
 * it and from sending the URL (with its token) elsewhere.
 */
#ifndef SCAF_TOOLS_EDIT_SERVER_H
#define SCAF_TOOLS_EDIT_SERVER_H

#include <pthread.h>

#include "base/error.h"
#include "edit_http.h"

#define EDIT_REQUEST_DEADLINE_S 3 /* to deliver one whole request */
#define EDIT_MAX_CONNECTIONS 64   /* open at once; more wait to be accepted */
#define EDIT_IDLE_TIMEOUT_S 30    /* silence that closes a connection */

typedef struct edit_connection edit_connection;

typedef void (*edit_handler_fn)(void *user, const edit_request *rq, edit_response *rs);

typedef struct edit_server {
    struct MHD_Daemon *daemon;
    int port; /* the port listened on */
    edit_handler_fn handler;
    void *user;
    pthread_t thread;        /* the event loop */
    int running;             /* the thread was started */
    int wake[2];             /* a byte here stops the loop */
    edit_connection *conns;  /* open connections (the loop's thread only) */
    unsigned long shut_down; /* connections cut at the deadline so far */
} edit_server;

/* Start serving on 127.0.0.1:port (0: any free port; s->port tells
 * which). SCAF_ERR_IO with the reason when the port cannot be bound. */
scaf_status edit_server_start(edit_server *s, int port, edit_handler_fn handler, void *user,
                              scaf_error *err);

/* Stop: closes the socket and waits for the request being served. */
void edit_server_stop(edit_server *s);

#endif
