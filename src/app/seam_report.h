/* app/seam_report: the seams of a run in its JSON report, so a user can
 * see and reuse them: where they came from (and why), the chart count,
 * every seam edge as a pair of 3D vertex indices, their length (total and
 * per sqrt(area), mesh/seam_edges), and the chart of every face.
 *
 * Writes members into an open JSON object (the caller's report); cannot
 * fail itself (the report's file checks its writes).
 */
#ifndef SCAF_APP_SEAM_REPORT_H
#define SCAF_APP_SEAM_REPORT_H

#include <stdio.h>

#include "mesh/gltf_io.h"
#include "mesh/seam_edges.h"
#include "scaf/scaf.h"

typedef struct seam_report {
    scaf_seams used;
    const char *why;
    int ncharts;
    int nf;
    const int *face_chart; /* nf, or NULL: not written */
    const seam_edges *edges;
    /* a glTF input: its primitives in mesh order (mesh/gltf_io), written as
     * "gltf_primitives" with the charts of each (needs face_chart); NULL /
     * 0 for other formats */
    const gltf_piece *pieces;
    int npieces;
} seam_report;

/* ",\n  \"seams\": {...},\n  \"face_chart\": [...]" (nothing when s is NULL),
 * then for a glTF input ",\n  \"gltf_primitives\": [{\"mesh\", \"mesh_name\",
 * \"primitive\", \"first_face\", \"faces\", \"charts\": [sorted chart ids]}]":
 * which primitive went into which charts of the one atlas. */
void seam_report_json(FILE *o, const seam_report *s);

#endif /* SCAF_APP_SEAM_REPORT_H */
