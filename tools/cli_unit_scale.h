/* tools/cli_unit_scale: the 3D commands that do not go through the public
 * API (tet, deform) work on the input at unit scale: app/unit_scale with
 * the CLI's messages ("scaf CMD: IN: ...") and exit status (4). */
#ifndef SCAF_TOOLS_CLI_UNIT_SCALE_H
#define SCAF_TOOLS_CLI_UNIT_SCALE_H

#include "mesh/mesh.h"

/* Divide m->V by 2^*e (app/unit_scale).
 * Exit status (0, or 4 with a message "scaf CMD: IN: ..."). */
int cli_unit_scale(const char *cmd, const char *in, mesh *m, int *e);

/* Multiply the n values X by 2^e. Exit status (0, or 4 with a message
 * when one is not finite). */
int cli_unit_unscale(const char *cmd, const char *in, double *X, size_t n, int e);

#endif /* SCAF_TOOLS_CLI_UNIT_SCALE_H */
