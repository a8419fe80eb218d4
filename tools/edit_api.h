/* tools/edit_api: the requests `scaf edit` answers, on one drag context.
 *
 * The whole protocol between the page (tools/edit_page.html) and the
 * program, without sockets: tools/edit_server hands each request over as
 * an edit_request and sends back the edit_response filled here.
 *
 *   GET  /?token=T      the page
 *   GET  /api/mesh      faces, chart of each face, 3D positions (once);
 *                       "texture" (the --texture name or null, with its
 *                       "texture_size"), "three" (whether the 3D view's
 *                       script is built in)
 *   GET  /api/state     the layout: uv, E, packing efficiency, iterations
 *   GET  /api/distortion  per-face ||J||^2 + ||J^-1||^2 (4: isometric)
 *   POST /api/grab      {"chart": c} | {"vertex": i}: mouse down; saves
 *                       the layout for undo, drops every handle
 *   POST /api/drag      {"chart": c, "dx", "dy", "angle", "steps"} |
 *                       {"vertex": i, "x", "y", "steps"}: the total motion
 *                       since the grab as soft handles, then `steps`
 *                       SCAF iterations (1..20, default 1); the new state
 *                       "mode": "rigid" moves the chart (or the charts
 *                       grabbed with "mode": "rigid") as a rigid body and
 *                       pushes the others rigidly (scaf_drag_rigid_move;
 *                       "steps" not taken; the state has "reached", the
 *                       fraction of the motion kept); "mode": "deform"
 *                       (the default of this request; the page sends
 *                       rigid unless its deform toggle is on) is the soft
 *                       handle drag, each other chart's E capped at 1.25
 *                       times its E at the grab (scaf_drag_set_energy_cap)
 *   POST /api/grab      also {"chart": c, "mode": "rigid", "charts"?:
 *                       [ids]}: grabs the selection (default [c]) for
 *                       rigid drags
 *   POST /api/transform {"charts": [ids], "op": "translate" | "rotate" |
 *                       "scale" | "flip", "dx", "dy" | "angle" (radians)
 *                       | "factor" | "axis": "u" | "v", "pivot"?: [u, v]
 *                       (default: the selection's centroid), "remirror"?:
 *                       true}: one rigid operation on the selection
 *                       (scaf_drag_transform) after a checkpoint (undo and
 *                       redo cover it); a flip without "remirror": true is
 *                       refused with 409 (a mirrored chart is not
 *                       bijective and can never be saved), with it it is
 *                       applied as a half turn; the state with "reached"
 *   POST /api/release   {}: mouse up: drops the handles (and a rigid grab)
 *   POST /api/optimize  {"steps"?}: iterations without handles until E
 *                       decreases by less than 1e-4 relatively (cap
 *                       `steps`, default 100)
 *   POST /api/compact   {"steps"?}: compaction iterations (default 30),
 *                       E kept within 1.05 times its value at the click
 *                       (scaf_drag_compact: the rule of `scaf atlas`)
 *   POST /api/pin       {"vertex": i, "pinned": 1 | 0}: pin or unpin a
 *                       layout vertex: a pinned vertex keeps its bits
 *                       through every drag, optimize and compact
 *                       (scaf_drag_pin_vertex); the state's "pinned" is
 *                       their count, "pinned_vertices" their ids
 *   POST /api/undo      {}: back to the layout before the last grab,
 *                       optimize or compact (409 when there is none)
 *   POST /api/redo      {}: the layout the last undo left, bit for bit
 *                       (409 when there is none: nothing undone since
 *                       the last grab, optimize or compact)
 *   GET  /edit_page_tools.js  the page's script for selection, pins,
 *                       texture, the 3D view and the padding (compiled in)
 *   GET  /three.min.js  three.js for the 3D view (compiled in from
 *                       libjs-three; 404 when the build had none)
 *   GET  /texture.png   the --texture image, read once at start-up (404
 *                       when none was given); no other file is ever sent
 *   POST /api/save      {}: the layout normalized into the unit square,
 *                       proved bijective with the padding kept (exact),
 *                       written atomically to the output OBJ: the input
 *                       again with the new UVs (read through a descriptor
 *                       kept open since the start, so a moved or deleted
 *                       input still gives its other lines), or a plain
 *                       OBJ and a "note" saying what was not kept. The
 *                       output is checked again at each save (409 when it
 *                       now names the input or the autosave, through a
 *                       link, a hard link or the input moved away), and a
 *                       successful save removes the autosave.
 *
 * The state carries "unsaved": whether the layout differs from the last
 * save (the page's mark and its warning before the tab closes). The
 * autosave (edit_api_autosave, called by tools/cmd_edit after a quiet
 * second and on SIGINT / SIGTERM) writes the normalized, certified layout
 * as a plain OBJ beside the output, atomically.
 *
 * Every request must come from this server's page: the Host header names
 * 127.0.0.1 or localhost at this port (a DNS-rebinding page cannot), an
 * Origin header, when sent, is this server's own, and the token printed
 * at start-up comes as the X-Scaf-Token header or the token query
 * argument (compared in constant time). Refused requests get a 4xx and a
 * JSON {"error": "..."} that says why, before anything is touched:
 * 400 malformed JSON, unknown key, unknown chart or vertex, a value out
 * of range (a drag farther than 1000 times the layout's size); 403 wrong Host, Origin or token; 404 unknown path; 405 wrong
 * method; 409 nothing to undo or redo; 413 a body over EDIT_MAX_BODY bytes.
 * 500: the library failed (its message; the layout of the last finished
 * iteration stays).
 */
#ifndef SCAF_TOOLS_EDIT_API_H
#define SCAF_TOOLS_EDIT_API_H

#include <stddef.h>

#include "edit_http.h"
#include "mesh/mesh.h"
#include "mesh/mesh_io.h"
#include "scaf/drag.h"

#define EDIT_TOKEN_CHARS 32 /* 128 random bits, hex */

typedef struct edit_api {
    scaf_drag_t *drag; /* the layout (not owned) */
    const mesh *m;     /* the input as read (not owned) */
    const char *in;    /* the input path, for cli_write_uv */
    const mesh_read_info *rinfo;
    const char *out;  /* where save writes (checked at start-up) */
    const char *name; /* shown by the page */
    double padding;   /* the drag context's padding (for messages) */
    char token[EDIT_TOKEN_CHARS + 1];
    int port;         /* the server's port: Host and Origin checks */
    const char *page; /* the page, page_len bytes */
    size_t page_len;
    const char *tools_js; /* the page's second script (edit_page_tools.js) */
    size_t tools_js_len;
    const char *three_js; /* three.js for the 3D view; three_js_len 0: not
                             built in (libjs-three missing at build time) */
    size_t three_js_len;
    const unsigned char *texture; /* --texture: the PNG's bytes, texture_len
                                     (NULL: none); read once at start-up */
    size_t texture_len;
    const char *texture_name; /* its path as given (shown by the page) */
    int texture_width, texture_height;
    int nuv, nf, ncharts;
    int *FT, *chart;       /* nf by 3, nf: fixed for the mesh */
    double *uv;            /* nuv by 2: scratch for the state */
    double diagonal;       /* of the 3D bounding box: the page's checker */
    double reach;          /* largest |dx|, |dy|, |x|, |y| of a drag: 1000
                              times the starting layout's extent */
    int saves;             /* files written */
    const char *autosave;  /* the autosave file (NULL: none) */
    int in_fd;             /* the input, open since the start (-1: it could
                             not be opened): save reads it through this */
    int changes;           /* layout changes so far (a resumed start counts
                             as one) */
    int saved_changes;     /* `changes` at the last save */
    int autosaved_changes; /* `changes` the autosave file holds */
    int rigid_grab;        /* a rigid grab is active (scaf_drag_rigid_begin) */
} edit_api;

/* Set up the handler for a drag context that has its mesh; the token,
 * port and page are filled by the caller. SCAF_ERR_NOMEM. */
scaf_status edit_api_init(edit_api *a, scaf_drag_t *d, const mesh *m, const char *in,
                          const mesh_read_info *rinfo, const char *out, double padding,
                          scaf_error *err);

void edit_api_free(edit_api *a);

/* Whether the layout differs from the last save (or, before any, from the
 * output's start: a resumed layout is unsaved). */
int edit_api_unsaved(const edit_api *a);

/* Write the layout to a->autosave when it holds unsaved changes not yet
 * autosaved: SCAF_OK (also when nothing was to do), else the failure in
 * err (the previous autosave stays). *written (may be NULL): 1 when the
 * file was written now. Not thread-safe with edit_api_handle: the caller
 * serializes them. */
scaf_status edit_api_autosave(edit_api *a, int *written, scaf_error *err);

/* Answer one request (user: the edit_api). Always fills rs. */
void edit_api_handle(void *user, const edit_request *rq, edit_response *rs);

#endif
