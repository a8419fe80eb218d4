/* tools/cli_closed_surface: is the input a closed manifold triangle
 * surface (no boundary edge, manifold edges and vertices, no zero-area
 * face, no vertex outside every face)? The check of `scaf flow` and
 * `scaf inflate` before any work. */
#ifndef SCAF_TOOLS_CLI_CLOSED_SURFACE_H
#define SCAF_TOOLS_CLI_CLOSED_SURFACE_H

#include "mesh/mesh.h"

/* 0 (EXIT_OK) when m is such a surface, else the exit status (4, or 7 out
 * of memory) after printing "scaf CMD: IN: why; WHO needs a closed
 * manifold triangle surface". */
int cli_check_closed_surface(const char *cmd, const char *in, const mesh *m, const char *who);

#endif
