/* tools/cli_seams: the --seams option of `scaf param`, `atlas` and `edit`,
 * and the line that says which seams a run used.
 *
 * One parser and one help text for the three commands, so the names and
 * the default read the same everywhere; the line gives the source, why,
 * the chart count and the seam length (total 3D length / sqrt(area):
 * mesh/seam_edges), measured on the UV topology the run writes.
 */
#ifndef SCAF_TOOLS_CLI_SEAMS_H
#define SCAF_TOOLS_CLI_SEAMS_H

#include "cli_outputs.h"
#include "mesh/mesh.h"
#include "mesh/seam_edges.h"
#include "scaf/scaf.h"

#define CLI_SEAMS_HELP                                                                             \
    "  --seams S              where the charts are cut: input (the vt seams; each\n"               \
    "                         chart must be a disk, possibly with holes), auto\n"                  \
    "                         (automatic seams, the vt ignored), extend (the vt\n"                 \
    "                         seams plus cuts where a chart is not a disk); default:\n"            \
    "                         input when the vt cut the mesh into disks, else auto\n"

#define CLI_SEAMS_PNG_HELP                                                                         \
    "  --png-seams FILE       the 3D surface from the front and from the back, each\n"             \
    "                         chart in its own colour, the seams drawn dark\n"

/* "input" / "auto" / "extend": 1 and *out set; else 0. */
int cli_seams_parse(const char *v, scaf_seams *out);

/* Seams of m cut as FT (nf by 3): print "scaf CMD: seams: SOURCE (WHY),
 * N chart(s), E seam edges, length L" on stderr unless quiet, and fill *s
 * (may be NULL; free with seam_edges_free). Returns 0, or 1 out of memory
 * (message printed). */
int cli_seams_report(const char *cmd, const mesh *m, const int *FT, scaf_seams used,
                     const char *why, int charts, int quiet, seam_edges *s);

/* --png-seams: two panels of 512 x 512 (the surface seen from the front
 * and, turned half a turn about the vertical, from the back; app/
 * surface_render), faces in the colour of their chart (face_chart, the
 * atlas's colours), the seams s drawn dark, and with atlas (the mesh with
 * its UVs in the unit square, or NULL) a third panel: the atlas in the
 * same colours (app/atlas_picture); into output k of outs (k < 0:
 * nothing). 0, or the exit status after printing why. */
int cli_seams_png(cli_outputs *outs, int k, const mesh *m, const int *face_chart,
                  const seam_edges *s, const mesh *atlas);

#endif
