/* tools/cli_closed_surface: the input check of the commands that work on a
 * closed surface (see cli_closed_surface.h); the check itself is
 * mesh/closed_surface, shared with app/untangle. */
#include "cli_closed_surface.h"

#include <stdio.h>

#include "exit_codes.h"
#include "mesh/closed_surface.h"

int cli_check_closed_surface(const char *cmd, const char *in, const mesh *m, const char *who)
{
    scaf_error err;
    err_clear(&err);
    scaf_status st = closed_surface_check(m, 0, &err);
    if (st == SCAF_OK) return EXIT_OK;
    if (st == SCAF_ERR_MESH)
        fprintf(stderr, "scaf %s: %s: %s; %s needs a closed manifold triangle surface\n", cmd, in,
                err.message, who);
    else fprintf(stderr, "scaf %s: %s: %s\n", cmd, in, err.message);
    return exit_code_for(st);
}
