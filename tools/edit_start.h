/* tools/edit_start: the layout `scaf edit` starts from, as --start says.
 *
 * auto (the default) tries the input's own UVs first (only when the exact
 * checker proves them bijective and the padding is kept: a `scaf atlas`
 * output, or an earlier save) and otherwise makes the atlas `scaf atlas`
 * makes with its defaults (charts cut along the vt where they cut the mesh
 * into disks, else automatic seams; Tutte start, settle, pack, compact),
 * so any mesh `scaf atlas` maps opens: flipped or overlapping vt (spot,
 * human_neutral), no vt, closed or of higher genus. input, atlas and
 * layout (charts as circles on a grid) try only that one.
 *
 * Fails with the exit status of tools/exit_codes.h after printing why on
 * the standard error: --start input on a mesh without vt (EXIT_USAGE) or
 * with vt that are not bijective (EXIT_MESH, naming what the checker
 * found); a mesh no start can map (EXIT_MESH, the atlas's message naming
 * the edge or vertex). Kept apart from cmd_edit so tests can start the
 * editor's layout without a server.
 */
#ifndef SCAF_TOOLS_EDIT_START_H
#define SCAF_TOOLS_EDIT_START_H

#include "mesh/mesh.h"
#include "scaf/drag.h"

typedef enum edit_start_kind {
    EDIT_START_FROM_INPUT, /* the input's UVs as they are */
    EDIT_START_FROM_ATLAS, /* the atlas `scaf atlas` makes */
    EDIT_START_FROM_LAYOUT /* charts as circles on a grid */
} edit_start_kind;

/* "auto", "input", "atlas" or "layout": 1; else 0. */
int edit_start_name_ok(const char *start);

/* The drag context on m (in: its file name, for messages) started as
 * start says; *from tells which start it is. EXIT_OK and *out, or the
 * exit status after printing why (nothing to free). */
int edit_start_layout(const char *in, const mesh *m, const char *start, double padding,
                      scaf_seams seams, int quiet, scaf_drag_t **out, edit_start_kind *from);

#endif /* SCAF_TOOLS_EDIT_START_H */
