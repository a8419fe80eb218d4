/* tools/deform_targets: the handle file of `scaf deform`.
 *
 *   {"handles": [{"vertex": 0, "target": [1.5, 2]}, ...], "weight": 1000}
 *
 * A handle may also carry "path": [[x, y], ...], waypoints it visits in
 * order before its target (a drag: `scaf deform` spends a few iterations
 * on each); every handle then has a path of the same length; and "hard":
 * true (or false, the default): the target must be met exactly (app/deform
 * places it there once that flips nothing, then pins it). "pins": [i, ...]
 * (optional, top level) lists vertices that never move. The checks below
 * also refuse a pin out of range, a vertex pinned twice, or pinned and a
 * handle.
 *
 * A strict reader for exactly this: one object with "handles" (required,
 * an array of objects each with an integer "vertex", 0-based, and a
 * "target" of two numbers) and "weight" (optional, a number >= 0: the
 * handle weight ratio of opt/handle_term). Any other key, a duplicate key,
 * a trailing comma or anything after the object is an error that names the
 * line and what is wrong (SCAF_ERR_PARSE, exit 3). The handles are then
 * checked against the mesh (deform_targets_check, SCAF_ERR_MESH, exit 4,
 * naming the handle): a vertex of the mesh, one handle per vertex (two
 * targets for one vertex cannot both be met), and every target and
 * waypoint within DEFORM_TARGET_RANGE mesh sizes of the mesh (farther,
 * the squared handle error overflows or swamps the energy: [1e308,
 * -1e308] used to end "max handle error inf" with the mesh unchanged).
 * Reading stops at a pending SIGINT / SIGTERM (base/interrupt:
 * SCAF_ERR_CANCELLED); paths grow geometrically. Writing: the same
 * format, one handle per line. */
#ifndef SCAF_TOOLS_DEFORM_TARGETS_H
#define SCAF_TOOLS_DEFORM_TARGETS_H

#include <stddef.h>

#include "base/error.h"

typedef struct deform_targets {
    int n;
    int *vertex;    /* n */
    double *target; /* n by 2 */
    int nframes;    /* waypoints per handle (0: none) */
    double *frames; /* nframes by n by 2: frame f of handle i at (f n + i) 2 */
    int has_weight;
    double weight;
    unsigned char *hard; /* n: 1 for "hard": true (met exactly, then pinned) */
    int npins;
    int *pins; /* npins vertices held where they are ("pins": [i, ...]) */
} deform_targets;

/* Read path into *t (free with deform_targets_free); SCAF_ERR_IO when it
 * cannot be read, SCAF_ERR_PARSE on bad content, SCAF_ERR_NOMEM. */
scaf_status deform_targets_read(const char *path, deform_targets *t, scaf_error *err);

/* The same on text[0..size) (text[size] must be the NUL that ends it; a
 * NUL before it is a parse error), name for the messages. */
scaf_status deform_targets_parse(const char *text, size_t size, const char *name, deform_targets *t,
                                 scaf_error *err);

/* Write n handles (vertex i -> T[2i..2i+1] for i < n), each with the
 * path of nframes waypoints (frames as in deform_targets; NULL when 0). */
scaf_status deform_targets_write(const char *path, int n, const double *T, int nframes,
                                 const double *frames, scaf_error *err);

/* How far a target may lie from the mesh, in mesh sizes (the larger side
 * of its bounding box): beyond any useful drag, far below overflow. */
#define DEFORM_TARGET_RANGE 1e6

/* Check t against the planar mesh of nv positions P (nv by 2): see the
 * banner. SCAF_ERR_MESH naming the handle (messages start with name). */
scaf_status deform_targets_check(const deform_targets *t, int nv, const double *P, const char *name,
                                 scaf_error *err);

void deform_targets_free(deform_targets *t);

#endif /* SCAF_TOOLS_DEFORM_TARGETS_H */
